#include "core/cut/snap_nodes.h"

#include "core/mesh/node_star.h"
#include "core/mesh/predicates.h"
#include "core/mesh/quality.h"
#include "core/mesh/vec3_lanes.h"

#include <Eigen/LU>

#include <algorithm>
#include <cmath>
#include <limits>
#include <unordered_map>
#include <unordered_set>

namespace resect {

Vec3 referenceInTet(const TetMesh& mesh, const Tet& q, const Vec3& pos) {
    const Vec3 l = tetCoordinates(pos, mesh.pos(q[0]), mesh.pos(q[1]), mesh.pos(q[2]), mesh.pos(q[3]));
    return mesh.ref(q[0]) + l[0] * (mesh.ref(q[1]) - mesh.ref(q[0])) + l[1] * (mesh.ref(q[2]) - mesh.ref(q[0])) +
           l[2] * (mesh.ref(q[3]) - mesh.ref(q[0]));
}

Vec3 currentInTet(const TetMesh& mesh, const Tet& q, const Vec3& ref) {
    const Vec3 l = tetCoordinates(ref, mesh.ref(q[0]), mesh.ref(q[1]), mesh.ref(q[2]), mesh.ref(q[3]));
    return mesh.pos(q[0]) + l[0] * (mesh.pos(q[1]) - mesh.pos(q[0])) + l[1] * (mesh.pos(q[2]) - mesh.pos(q[0])) +
           l[2] * (mesh.pos(q[3]) - mesh.pos(q[0]));
}

namespace {

/// Of the tets offered in turn, the one containing `pos` best (largest smallest barycentric
/// coordinate, the first of equals), and `pos` mapped into its reference configuration.
class BestContainingTet {
public:
    explicit BestContainingTet(const Vec3& pos) : m_pos(pos) {}
    void offer(const TetMesh& mesh, const Tet& q) {
        consider(
            mesh, q,
            tetCoordinates(m_pos, mesh.pos(q[0]), mesh.pos(q[1]), mesh.pos(q[2]), mesh.pos(q[3])));
    }
    /// offer(q) then offer(r), their coordinates computed side by side (tetCoordinates lane by
    /// lane, the same values).
    void offerPair(const TetMesh& mesh, const Tet& q, const Tet& r) {
        const Vec3Lanes p0(mesh.pos(q[0]), mesh.pos(r[0]));
        const Vec3Lanes a = Vec3Lanes(mesh.pos(q[1]), mesh.pos(r[1])) - p0;
        const Vec3Lanes b = Vec3Lanes(mesh.pos(q[2]), mesh.pos(r[2])) - p0;
        const Vec3Lanes c = Vec3Lanes(mesh.pos(q[3]), mesh.pos(r[3])) - p0;
        const Vec3Lanes y = Vec3Lanes(m_pos, m_pos) - p0;
        const Vec3Lanes bc = cross(b, c);
        const Lanes det = dot(a, bc);
        const Vec3Lanes l = Vec3Lanes(dot(y, bc), dot(a, cross(y, c)), dot(a, cross(b, y))) / det;
        consider(mesh, q, l.lane(0));
        consider(mesh, r, l.lane(1));
    }
    const Vec3& reference() const { return m_ref; }

private:
    void consider(const TetMesh& mesh, const Tet& q, const Vec3& l) {
        if (!l.allFinite())
            return;
        const double smallest = std::min({1.0 - l.sum(), l[0], l[1], l[2]});
        if (smallest > m_bestMin) {
            m_bestMin = smallest;
            m_ref = mesh.ref(q[0]) + l[0] * (mesh.ref(q[1]) - mesh.ref(q[0])) +
                    l[1] * (mesh.ref(q[2]) - mesh.ref(q[0])) +
                    l[2] * (mesh.ref(q[3]) - mesh.ref(q[0]));
        }
    }

    Vec3 m_pos;
    double m_bestMin = -std::numeric_limits<double>::infinity();
    Vec3 m_ref = Vec3::Constant(std::numeric_limits<double>::quiet_NaN());
};

} // namespace

Vec3 referenceFromDeformed(const TetMesh& mesh, const std::vector<int>& group, const Vec3& pos) {
    BestContainingTet best(pos);
    for (int v : group)
        for (int t : mesh.nodeTets(v))
            best.offer(mesh, mesh.tet(t));
    return best.reference();
}

Vec3 referenceFromDeformedIn(const TetMesh& mesh, std::span<const int> incidentTets,
                             const Vec3& pos) {
    BestContainingTet best(pos);
    std::size_t k = 0;
    for (; k + 1 < incidentTets.size(); k += 2)
        best.offerPair(mesh, mesh.tet(incidentTets[k]), mesh.tet(incidentTets[k + 1]));
    if (k < incidentTets.size())
        best.offer(mesh, mesh.tet(incidentTets[k]));
    return best.reference();
}

std::vector<int> boundaryNodesAmong(const TetMesh& mesh, const std::vector<int>& nodes) {
    std::vector<int> result;
    NodeStar star;
    for (int n : nodes) {
        star.gather(mesh, n);
        if (star.onBoundary())
            result.push_back(n);
    }
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
