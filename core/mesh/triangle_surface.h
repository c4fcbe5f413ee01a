#pragma once
// TriangleSurface: a triangle mesh, used for anatomy surfaces (input to the mesher) and
// for the embedded high-resolution visual surface.

#include "core/mesh/tet_mesh.h"

#include <Eigen/Core>

#include <array>
#include <cstdint>
#include <span>
#include <vector>

namespace resect {

struct TriangleSurface {
    std::vector<Vec3> positions;          ///< #V positions
    std::vector<Tri> triangles;           ///< #F triangles, counter-clockwise seen from outside
    std::vector<Eigen::Vector2d> uvs;     ///< empty, or #V texture coordinates
    /// Cut faces (section 5.2), filled by cutSurface: empty, or #F flags, 1 for triangles
    /// that close a cut (their texture comes from the sweep's (u, v), not from `uvs`).
    std::vector<std::uint8_t> cutFaces;
    /// Empty, or #V: the (u, v) on the sweep of every vertex a cut created (the texture
    /// coordinates of cut faces); NaN for the other vertices. A vertex where two cuts cross
    /// keeps the (u, v) of the later cut.
    std::vector<Eigen::Vector2d> cutUvs;

    int vertexCount() const { return static_cast<int>(positions.size()); }
    int triangleCount() const { return static_cast<int>(triangles.size()); }
    bool isCutFace(int f) const { return !cutFaces.empty() && cutFaces[f] != 0; }
};

/// Signed volume enclosed by a closed, outward-oriented surface (divergence theorem:
/// sum over triangles of p0 . (p1 x p2) / 6). Meaningless for open surfaces.
double enclosedVolume(const TriangleSurface& surface);

/// Sum of the triangles' areas.
double surfaceArea(const TriangleSurface& surface);

/// Axis-aligned bounding box of the positions; {min, max}. Both zero for an empty surface.
std::array<Vec3, 2> boundingBox(std::span<const Vec3> points);

} // namespace resect
