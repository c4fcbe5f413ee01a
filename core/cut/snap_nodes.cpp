#include "core/cut/snap_nodes.h"

#include "core/mesh/predicates.h"
#include "core/mesh/quality.h"
#include "core/mesh/topology.h"

#include <Eigen/LU>

#include <algorithm>
#include <cmath>
#include <limits>
#include <unordered_map>
#include <unordered_set>

namespace resect {

Vec3 tetCoordinates(const Vec3& x, const Vec3& p0, const Vec3& p1, const Vec3& p2, const Vec3& p3) {
    // Cramer's rule on [p1-p0, p2-p0, p3-p0] l = x-p0 with triple products: a tenth of the
    // cost of a pivoting LU, which mattered in relaxation (every trial move maps its target
    // through each incident tet). A degenerate tet gives non-finite coordinates (callers
    // skip those).
    const Vec3 a = p1 - p0, b = p2 - p0, c = p3 - p0, y = x - p0;
    const Vec3 bc = b.cross(c);
    const double det = a.dot(bc);
    return Vec3(y.dot(bc), a.dot(y.cross(c)), a.dot(b.cross(y))) / det;
}

Vec3 referenceInTet(const TetMesh& mesh, const Tet& q, const Vec3& pos) {
    const Vec3 l = tetCoordinates(pos, mesh.pos(q[0]), mesh.pos(q[1]), mesh.pos(q[2]), mesh.pos(q[3]));
    return mesh.ref(q[0]) + l[0] * (mesh.ref(q[1]) - mesh.ref(q[0])) + l[1] * (mesh.ref(q[2]) - mesh.ref(q[0])) +
           l[2] * (mesh.ref(q[3]) - mesh.ref(q[0]));
}

Vec3 referenceFromDeformed(const TetMesh& mesh, const std::vector<int>& group, const Vec3& pos) {
    double bestMin = -std::numeric_limits<double>::infinity();
    Vec3 ref = Vec3::Constant(std::numeric_limits<double>::quiet_NaN());
    for (int v : group)
        for (int t : mesh.nodeTets(v)) {
            const Tet& q = mesh.tet(t);
            const Vec3 l = tetCoordinates(pos, mesh.pos(q[0]), mesh.pos(q[1]), mesh.pos(q[2]), mesh.pos(q[3]));
            if (!l.allFinite())
                continue;
            const double smallest = std::min({1.0 - l.sum(), l[0], l[1], l[2]});
            if (smallest > bestMin) {
                bestMin = smallest;
                ref = mesh.ref(q[0]) + l[0] * (mesh.ref(q[1]) - mesh.ref(q[0])) + l[1] * (mesh.ref(q[2]) - mesh.ref(q[0])) +
                      l[2] * (mesh.ref(q[3]) - mesh.ref(q[0]));
            }
        }
    return ref;
}

std::vector<int> boundaryNodesAmong(const TetMesh& mesh, const std::vector<int>& nodes) {
    std::vector<int> result;
    for (int n : nodes)
        if (isBoundaryNode(mesh, n))
            result.push_back(n);
    return result;
}

SnapResult snapNodes(TetMesh& mesh, const SweepSurface& sweep, const CutChanges& changes,
                     const std::vector<int>& onSurface, const SnapOptions& options) {
    SnapResult result;
    const std::unordered_set<int> fixed(onSurface.begin(), onSurface.end());
    std::unordered_map<int, std::vector<int>> copies;
    for (int n : changes.cutNodes)
        copies[n].push_back(n);
    for (const auto& [orig, copy] : changes.duplicatedNodes)
        if (copies.count(orig))
            copies[orig].push_back(copy);

    for (int n : changes.cutNodes) {
        const std::vector<int>& group = copies[n];
        const SweepSurface::Closest target = sweep.closestPoint(mesh.pos(n));
        if (fixed.count(n)) {
            ++result.refused;
            result.maxDistanceAfter = std::max(result.maxDistanceAfter, target.distance);
            continue;
        }
        const Vec3 newPos = target.point;
        const Vec3 newRef = referenceFromDeformed(mesh, group, newPos);
        // Check every tet around every copy with the node moved.
        bool ok = newRef.allFinite();
        for (int v : group) {
            for (int t : mesh.nodeTets(v)) {
                if (!ok)
                    break;
                Tet q = mesh.tet(t);
                Vec3 r[4], p[4];
                for (int i = 0; i < 4; ++i) {
                    r[i] = q[i] == v ? newRef : mesh.ref(q[i]);
                    p[i] = q[i] == v ? newPos : mesh.pos(q[i]);
                }
                if (orient3d(r[0], r[1], r[2], r[3]) <= 0 || orient3d(p[0], p[1], p[2], p[3]) <= 0) {
                    ok = false;
                    break;
                }
                const double before = radiusRatio(mesh.ref(q[0]), mesh.ref(q[1]), mesh.ref(q[2]), mesh.ref(q[3]));
                const double after = radiusRatio(r[0], r[1], r[2], r[3]);
                if (after < std::min(options.qualityFloor, before))
                    ok = false;
            }
        }
        if (!ok) {
            ++result.refused;
            result.maxDistanceAfter = std::max(result.maxDistanceAfter, target.distance);
            continue;
        }
        for (int v : group)
            mesh.setNodePosition(v, newRef, newPos);
        ++result.snapped;
    }
    return result;
}

} // namespace resect
