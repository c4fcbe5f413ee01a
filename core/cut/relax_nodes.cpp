#include "core/cut/relax_nodes.h"

#include "core/cut/snap_nodes.h"
#include "core/mesh/predicates.h"
#include "core/mesh/quality.h"
#include "core/mesh/topology.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <unordered_map>
#include <unordered_set>

namespace resect {
namespace {

/// The smallest radius ratio of the tets at the nodes of `group`; each tet's ratio is
/// appended to `ratios` (cleared first).
double minQualityAround(const TetMesh& mesh, const std::vector<int>& group, std::vector<std::pair<int, double>>* ratios) {
    double q = std::numeric_limits<double>::infinity();
    ratios->clear();
    for (int v : group)
        for (int t : mesh.nodeTets(v)) {
            const Tet& k = mesh.tet(t);
            const double r = radiusRatio(mesh.ref(k[0]), mesh.ref(k[1]), mesh.ref(k[2]), mesh.ref(k[3]));
            ratios->emplace_back(t, r);
            q = std::min(q, r);
        }
    return q;
}

} // namespace

RelaxResult relaxNodes(TetMesh& mesh, const SweepSurface& sweep, const CutChanges& changes,
                       const std::vector<int>& fixedNodes, const RelaxOptions& options) {
    RelaxResult result;
    if (options.steps <= 0 || !(options.damping > 0))
        return result;

    // Groups of coincident copies: a node and the copies separation made of it.
    std::unordered_map<int, int> leader;  // node -> first node of its group
    std::unordered_map<int, std::vector<int>> groupOf;
    for (const auto& [orig, copy] : changes.duplicatedNodes) {
        const int l = leader.count(orig) ? leader[orig] : orig;
        leader[orig] = l;
        leader[copy] = l;
        auto& g = groupOf[l];
        if (g.empty())
            g.push_back(l);
        g.push_back(copy);
    }
    const auto lead = [&](int n) { auto it = leader.find(n); return it == leader.end() ? n : it->second; };
    const std::unordered_set<int> onCut(changes.cutSurfaceNodes.begin(), changes.cutSurfaceNodes.end());
    std::unordered_set<int> fixed;
    for (int n : fixedNodes) {
        fixed.insert(lead(n));
    }

    // S: the k-ring neighbourhood of the cut (by group leaders).
    std::unordered_set<int> region;
    std::vector<int> frontier;
    for (int n : changes.cutSurfaceNodes)
        if (region.insert(lead(n)).second)
            frontier.push_back(lead(n));
    for (int ring = 0; ring < options.rings; ++ring) {
        std::vector<int> next;
        for (int n : frontier) {
            auto it = groupOf.find(n);
            const std::vector<int> members = it == groupOf.end() ? std::vector<int>{n} : it->second;
            for (int m : members)
                for (int u : mesh.nodeNeighbours(m))
                    if (region.insert(lead(u)).second)
                        next.push_back(lead(u));
        }
        frontier = std::move(next);
    }
    std::vector<int> nodes(region.begin(), region.end());
    std::sort(nodes.begin(), nodes.end());

    const auto members = [&](int n) {
        auto it = groupOf.find(n);
        return it == groupOf.end() ? std::vector<int>{n} : it->second;
    };
    // A node on the boundary that is not on this cut lies on an earlier surface: fixed too.
    std::vector<int> movable;
    for (int n : nodes) {
        const bool cutNode = onCut.count(n) > 0;
        if (fixed.count(n) || (!cutNode && isBoundaryNode(mesh, n))) {
            ++result.fixed;
            continue;
        }
        movable.push_back(n);
        ++(cutNode ? result.onSweep : result.movable);
    }

    // Rest length of all springs: the mean length of the edges at movable nodes.
    double rest = 0;
    int edgeCount = 0;
    for (int n : movable)
        for (int m : members(n))
            for (int u : mesh.nodeNeighbours(m)) {
                rest += (mesh.pos(u) - mesh.pos(m)).norm();
                ++edgeCount;
            }
    if (edgeCount == 0 || !(rest > 0))
        return result;
    rest /= edgeCount;
    const double stepSize = 1.0 / options.damping;

    // The topology does not change while nodes relax: each movable node's copies and its
    // neighbours over all copies are gathered once, not in every step.
    struct Relaxing {
        int node;
        std::vector<int> group;
        std::vector<int> neighbours;
    };
    std::vector<Relaxing> relaxing;
    relaxing.reserve(movable.size());
    for (int n : movable) {
        Relaxing r{n, members(n), {}};
        for (int m : r.group)
            for (int u : mesh.nodeNeighbours(m))
                if (lead(u) != n)
                    r.neighbours.push_back(u);
        std::sort(r.neighbours.begin(), r.neighbours.end());
        r.neighbours.erase(std::unique(r.neighbours.begin(), r.neighbours.end()), r.neighbours.end());
        if (!r.neighbours.empty())
            relaxing.push_back(std::move(r));
    }

    // Radius ratios of the tets around relaxing nodes, kept current as moves are accepted, so
    // each move computes only the ratios after it.
    std::unordered_map<int, double> tetQuality;
    const auto cachedMinQuality = [&](const std::vector<int>& group) {
        double q = std::numeric_limits<double>::infinity();
        for (int v : group)
            for (int t : mesh.nodeTets(v)) {
                auto [it, inserted] = tetQuality.try_emplace(t, 0.0);
                if (inserted) {
                    const Tet& k = mesh.tet(t);
                    it->second = radiusRatio(mesh.ref(k[0]), mesh.ref(k[1]), mesh.ref(k[2]), mesh.ref(k[3]));
                }
                q = std::min(q, it->second);
            }
        return q;
    };
    std::vector<std::pair<int, double>> moved;

    for (int step = 0; step < options.steps; ++step) {
        for (const Relaxing& item : relaxing) {
            const int n = item.node;
            const std::vector<int>& group = item.group;
            const std::vector<int>& neighbours = item.neighbours;
            const Vec3 x = mesh.pos(n);
            // Eq. 2 forces in units of the rest length: linear springs and a Lennard-Jones
            // potential whose minimum is at the rest length (sigma = rest / 2^(1/6)).
            Vec3 force = Vec3::Zero();
            for (int u : neighbours) {
                const Vec3 d = mesh.pos(u) - x;
                const double r = d.norm() / rest;
                if (!(r > 0))
                    continue;
                const Vec3 dir = d / (r * rest);
                const double spring = r - 1.0;
                const double r2 = r * r;
                const double s6 = 0.5 / (r2 * r2 * r2);  // (sigma / r)^6 with 2^(1/6) sigma = 1
                const double lj = -24.0 * (2.0 * s6 * s6 - s6) / r;
                force += (options.wSpring * spring + options.wParticle * lj / 12.0) * dir;
            }
            Vec3 target = x + stepSize * rest * force / static_cast<double>(neighbours.size());
            if (onCut.count(n))
                target = sweep.closestPoint(target).point;  // stay within the sweep
            if (!target.allFinite() || target == x)
                continue;
            const Vec3 targetRef = referenceFromDeformed(mesh, group, target);
            if (!targetRef.allFinite())
                continue;
            const double before = cachedMinQuality(group);
            const Vec3 oldRef = mesh.ref(n), oldPos = mesh.pos(n);
            for (int m : group)
                mesh.setNodePosition(m, targetRef, target);
            bool ok = true;
            for (int m : group)
                for (int t : mesh.nodeTets(m)) {
                    const Tet& q = mesh.tet(t);
                    if (orient3d(mesh.ref(q[0]), mesh.ref(q[1]), mesh.ref(q[2]), mesh.ref(q[3])) <= 0 ||
                        orient3d(mesh.pos(q[0]), mesh.pos(q[1]), mesh.pos(q[2]), mesh.pos(q[3])) <= 0)
                        ok = false;
                }
            if (ok && minQualityAround(mesh, group, &moved) < before)
                ok = false;
            if (!ok) {
                for (int m : group)
                    mesh.setNodePosition(m, oldRef, oldPos);
                ++result.rejectedMoves;
            } else {
                for (const auto& [t, q] : moved)
                    tetQuality[t] = q;
                ++result.acceptedMoves;
                result.movedNodes.insert(result.movedNodes.end(), group.begin(), group.end());
            }
        }
    }
    std::sort(result.movedNodes.begin(), result.movedNodes.end());
    result.movedNodes.erase(std::unique(result.movedNodes.begin(), result.movedNodes.end()), result.movedNodes.end());
    return result;
}

} // namespace resect
