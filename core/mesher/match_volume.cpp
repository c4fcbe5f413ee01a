#include "core/mesher/match_volume.h"

#include "core/mesh/predicates.h"
#include "core/mesh/quality.h"
#include "core/mesh/topology.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <vector>

namespace resect {

namespace {

/// A node whose move was halved this often moves not at all.
constexpr int kMaxHalvings = 5;
/// Rounds of "solve for the scale, check the tets, restrain the offenders".
constexpr int kMaxRounds = 24;

double tetVolume(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d) {
    return (b - a).dot((c - a).cross(d - a)) / 6.0;
}

} // namespace

VolumeMatchResult matchVolume(TetMesh& mesh, double targetVolume,
                              const std::function<Vec3(const Vec3&)>& closestPoint,
                              double minDihedralDeg) {
    VolumeMatchResult result;
    result.volumeBefore = mesh.totalReferenceVolume();
    result.volumeAfter = result.volumeBefore;
    if (mesh.empty() || !(targetVolume > 0.0) || !std::isfinite(targetVolume))
        return result;

    // Each boundary node's direction (area-weighted normal of its facets) and the mean gap
    // between those facets' centres and the surface, measured along each facet's normal:
    // positive where the surface lies outside the mesh.
    const int n = mesh.nodeCount();
    const std::span<const Vec3> ref = mesh.referencePositions();
    std::vector<Vec3> normalSum(n, Vec3::Zero());
    std::vector<double> gapSum(n, 0.0), areaSum(n, 0.0);
    for (const BoundaryFace& f : boundaryFaces(mesh)) {
        const Vec3& a = ref[f.nodes[0]];
        const Vec3& b = ref[f.nodes[1]];
        const Vec3& c = ref[f.nodes[2]];
        const Vec3 normal = (b - a).cross(c - a); // outward, length twice the area
        const double area2 = normal.norm();
        if (!(area2 > 0.0))
            continue;
        const Vec3 centre = (a + b + c) / 3.0;
        const double gap = (closestPoint(centre) - centre).dot(normal / area2);
        if (!std::isfinite(gap))
            continue;
        for (const int v : f.nodes) {
            normalSum[v] += normal;
            gapSum[v] += area2 * gap;
            areaSum[v] += area2;
        }
    }
    std::vector<int> boundary;
    std::vector<Vec3> offset(n, Vec3::Zero()); // the move at scale 1
    for (int v = 0; v < n; ++v) {
        const double len = normalSum[v].norm();
        if (!(areaSum[v] > 0.0) || !(len > 0.0))
            continue;
        offset[v] = normalSum[v] / len * (gapSum[v] / areaSum[v]);
        if (offset[v].squaredNorm() > 0.0)
            boundary.push_back(v);
    }
    if (boundary.empty())
        return result;

    // The tets that move, with the smallest dihedral angle each may reach.
    std::vector<char> moves(n, 0);
    for (const int v : boundary)
        moves[v] = 1;
    std::vector<int> affected;
    std::vector<double> floorDeg;
    double fixedVolume = 0.0;
    for (int t = 0; t < mesh.tetCount(); ++t) {
        const Tet& k = mesh.tet(t);
        if (moves[k[0]] || moves[k[1]] || moves[k[2]] || moves[k[3]]) {
            affected.push_back(t);
            const double before =
                tetQuality(ref[k[0]], ref[k[1]], ref[k[2]], ref[k[3]]).minDihedral * 180.0 / std::numbers::pi;
            floorDeg.push_back(std::min(before, minDihedralDeg));
        } else {
            fixedVolume += mesh.referenceVolume(t);
        }
    }

    const std::vector<Vec3> original(ref.begin(), ref.end());
    std::vector<Vec3> p = original;
    std::vector<double> weight(n, 1.0);
    std::vector<int> halvings(n, 0);
    const auto place = [&](double scale) {
        for (const int v : boundary)
            p[v] = original[v] + (scale * weight[v]) * offset[v];
    };
    const auto volumeAt = [&](double scale) {
        place(scale);
        double v = fixedVolume;
        for (const int t : affected) {
            const Tet& k = mesh.tet(t);
            v += tetVolume(p[k[0]], p[k[1]], p[k[2]], p[k[3]]);
        }
        return v;
    };
    // The volume is a cubic in the scale, close to linear for these small moves: secant
    // steps from 0 and 1 converge in a few iterations.
    const auto solveScale = [&] {
        double s0 = 0.0, f0 = volumeAt(s0) - targetVolume;
        double s1 = 1.0, f1 = volumeAt(s1) - targetVolume;
        for (int it = 0; it < 40 && std::abs(f1) > 1e-13 * targetVolume && f1 != f0; ++it) {
            const double s2 = std::clamp(s1 - f1 * (s1 - s0) / (f1 - f0), -8.0, 8.0);
            s0 = s1;
            f0 = f1;
            s1 = s2;
            f1 = volumeAt(s1) - targetVolume;
        }
        return s1;
    };

    bool accepted = false;
    for (int round = 0; round < kMaxRounds && !accepted; ++round) {
        const double scale = solveScale();
        place(scale);
        accepted = true;
        for (std::size_t i = 0; i < affected.size(); ++i) {
            const Tet& k = mesh.tet(affected[i]);
            const bool positive = orient3d(p[k[0]], p[k[1]], p[k[2]], p[k[3]]) > 0;
            if (positive &&
                tetQuality(p[k[0]], p[k[1]], p[k[2]], p[k[3]]).minDihedral * 180.0 / std::numbers::pi >=
                    floorDeg[i])
                continue;
            accepted = false;
            for (const int v : k) {
                if (!moves[v] || weight[v] == 0.0)
                    continue;
                weight[v] = ++halvings[v] > kMaxHalvings ? 0.0 : weight[v] * 0.5;
            }
        }
    }
    if (!accepted)
        return result; // nothing moved: the mesh is as it was

    for (const int v : boundary) {
        const double moved = (p[v] - original[v]).norm();
        if (moved > 0.0)
            ++result.movedNodes;
        if (weight[v] < 1.0)
            ++result.restrainedNodes;
        result.maxOffset = std::max(result.maxOffset, moved);
        mesh.setNodePosition(v, p[v], p[v]);
    }
    result.volumeAfter = mesh.totalReferenceVolume();
    return result;
}

} // namespace resect
