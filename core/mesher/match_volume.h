#pragma once
// Volume matching of a freshly meshed body: the boundary of a coarse mesh whose boundary
// nodes lie on a curved surface is inscribed in it (every facet is a chord), so the mesh
// is 3-8 % smaller than the body and so is its mass. This pass moves each boundary node
// along its normal in proportion to the gap between its facets and the surface, scaled
// so that the mesh volume equals the surface's: the boundary then crosses the surface
// (nodes a little outside, facet centres a little inside) instead of lying inside it,
// which also halves the largest distance between the two.
//
// No tet is inverted and no tet's smallest dihedral angle is lowered below
// min(its own, `minDihedralDeg`): a node whose move would do so moves less (halved until
// it does not, down to not at all), and the remaining nodes take up the volume.

#include "core/mesh/tet_mesh.h"

#include <functional>

namespace resect {

struct VolumeMatchResult {
    double volumeBefore = 0;   ///< mesh volume before the pass
    double volumeAfter = 0;    ///< mesh volume after it
    double maxOffset = 0;      ///< largest distance a node moved
    int movedNodes = 0;        ///< boundary nodes that moved
    int restrainedNodes = 0;   ///< boundary nodes that moved less than asked (quality guard)
};

/// Moves the boundary nodes of `mesh` (reference and current positions alike) so that its
/// volume is `targetVolume` as closely as the quality guard allows. `closestPoint` returns
/// the point of the body's surface closest to a point. Cost O(tets + boundary faces x
/// closestPoint).
VolumeMatchResult matchVolume(TetMesh& mesh, double targetVolume,
                              const std::function<Vec3(const Vec3&)>& closestPoint,
                              double minDihedralDeg);

} // namespace resect
