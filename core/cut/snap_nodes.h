#pragma once
// Step 6 of the cut (section 4.5): node snapping. Each cut node is projected orthogonally
// onto the sweep in the deformed configuration; its new reference position comes from its
// barycentric coordinates in an incident tet (the paper's ref. [16]). All copies of a
// separated cut node move together, so they stay coincident. A snap that would make any
// incident tet inverted or flat (exact predicates, both configurations) or worse than the
// quality floor is refused and counted.

#include "core/cut/cut_types.h"
#include "core/sweep/sweep_surface.h"

#include <span>
#include <vector>

namespace resect {

struct SnapOptions {
    /// A snap may not push an incident tet's radius ratio below min(floor, its ratio before).
    double qualityFloor = 0.05;
};

struct SnapResult {
    int snapped = 0;
    int refused = 0;
    double maxDistanceAfter = 0;  ///< largest remaining cut-node distance (refused ones)
};

/// `changes` gives the cut nodes and their copies (duplicatedNodes). Cut nodes listed in
/// `onSurface` (on the mesh boundary before the cut: the original surface or an earlier cut)
/// are not moved, so the body's shape and total volume are kept; they count as refused.
SnapResult snapNodes(TetMesh& mesh, const SweepSurface& sweep, const CutChanges& changes,
                     const std::vector<int>& onSurface, const SnapOptions& options);

/// The nodes of `nodes` that lie on the mesh boundary (have an incident face in one tet).
std::vector<int> boundaryNodesAmong(const TetMesh& mesh, const std::vector<int>& nodes);

/// Reference position for a node of `group` (coincident copies) moved to `pos` in the deformed
/// configuration: barycentric coordinates of `pos` in the incident tet that contains it best
/// (largest smallest coordinate, the first of equals), applied to that tet's reference
/// positions (the paper's ref. [16]). Non-finite if every incident tet is flat.
Vec3 referenceFromDeformed(const TetMesh& mesh, const std::vector<int>& group, const Vec3& pos);

/// The same, given the tets incident to the group (in the order of its nodes, each node's
/// tets in mesh order), for a caller that moves the same group many times.
Vec3 referenceFromDeformedIn(const TetMesh& mesh, std::span<const int> incidentTets,
                             const Vec3& pos);

/// The same mapping for a point in one tet.
Vec3 referenceInTet(const TetMesh& mesh, const Tet& tet, const Vec3& pos);

/// The other way: the current position of the point at reference position `ref` under the
/// tet's map (barycentric coordinates in its reference corners, applied to its current ones).
Vec3 currentInTet(const TetMesh& mesh, const Tet& tet, const Vec3& ref);

/// (l1, l2, l3) with x = p0 + l1 (p1 - p0) + l2 (p2 - p0) + l3 (p3 - p0); the fourth
/// barycentric coordinate is 1 - l1 - l2 - l3. Non-finite for a flat tet.
inline Vec3 tetCoordinates(const Vec3& x, const Vec3& p0, const Vec3& p1, const Vec3& p2,
                           const Vec3& p3) {
    // Cramer's rule on [p1-p0, p2-p0, p3-p0] l = x-p0 with triple products: a tenth of the
    // cost of a pivoting LU, which matters in relaxation (every trial move maps its target
    // through each incident tet). A degenerate tet gives non-finite coordinates (callers
    // skip those).
    const Vec3 a = p1 - p0, b = p2 - p0, c = p3 - p0, y = x - p0;
    const Vec3 bc = b.cross(c);
    const double det = a.dot(bc);
    return Vec3(y.dot(bc), a.dot(y.cross(c)), a.dot(b.cross(y))) / det;
}

} // namespace resect
