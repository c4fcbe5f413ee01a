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

/// Groups of coincident copies: a node and the copies separation made of it. Every node of
/// a group moves with its leader (the group's first node).
struct CopyGroups {
    std::unordered_map<int, int> leader;               ///< node -> first node of its group
    std::unordered_map<int, std::vector<int>> groupOf; ///< leader -> its group

    int lead(int n) const {
        const auto it = leader.find(n);
        return it == leader.end() ? n : it->second;
    }
    /// The nodes of leader n's group ({n} for a node that was not duplicated).
    std::vector<int> members(int n) const {
        const auto it = groupOf.find(n);
        return it == groupOf.end() ? std::vector<int>{n} : it->second;
    }
};

CopyGroups copyGroups(const CutChanges& changes) {
    CopyGroups groups;
    for (const auto& [orig, copy] : changes.duplicatedNodes) {
        const int l = groups.leader.count(orig) ? groups.leader[orig] : orig;
        groups.leader[orig] = l;
        groups.leader[copy] = l;
        auto& g = groups.groupOf[l];
        if (g.empty())
            g.push_back(l);
        g.push_back(copy);
    }
    return groups;
}

/// S: the `rings`-ring neighbourhood of the nodes on the cut, as sorted group leaders.
std::vector<int> neighbourhoodOfCut(const TetMesh& mesh, const CopyGroups& groups,
                                    const CutChanges& changes, int rings) {
    std::unordered_set<int> region;
    std::vector<int> frontier;
    for (int n : changes.cutSurfaceNodes)
        if (region.insert(groups.lead(n)).second)
            frontier.push_back(groups.lead(n));
    for (int ring = 0; ring < rings; ++ring) {
        std::vector<int> next;
        for (int n : frontier)
            for (int m : groups.members(n))
                for (int u : mesh.nodeNeighbours(m))
                    if (region.insert(groups.lead(u)).second)
                        next.push_back(groups.lead(u));
        frontier = std::move(next);
    }
    std::vector<int> nodes(region.begin(), region.end());
    std::sort(nodes.begin(), nodes.end());
    return nodes;
}

/// The nodes of S that move (in order), counting them in `result`: nodes on the cut move
/// within the sweep, interior nodes freely; `fixed` nodes, and nodes on the boundary that
/// are not on this cut (the original surface or an earlier cut), stay.
std::vector<int> movableNodes(const TetMesh& mesh, const std::vector<int>& region,
                              const std::unordered_set<int>& onCut,
                              const std::unordered_set<int>& fixed, RelaxResult& result) {
    std::vector<int> movable;
    for (int n : region) {
        const bool cutNode = onCut.count(n) > 0;
        if (fixed.count(n) || (!cutNode && isBoundaryNode(mesh, n))) {
            ++result.fixed;
            continue;
        }
        movable.push_back(n);
        ++(cutNode ? result.onSweep : result.movable);
    }
    return movable;
}

/// Rest length of all springs (section 4.6): the mean length of the edges at movable nodes
/// (over all copies); 0 if there is no edge or they all have zero length.
double restLength(const TetMesh& mesh, const CopyGroups& groups, const std::vector<int>& movable) {
    double rest = 0;
    int edgeCount = 0;
    for (int n : movable)
        for (int m : groups.members(n))
            for (int u : mesh.nodeNeighbours(m)) {
                rest += (mesh.pos(u) - mesh.pos(m)).norm();
                ++edgeCount;
            }
    if (edgeCount == 0 || !(rest > 0))
        return 0.0;
    return rest / edgeCount;
}

/// A movable node, its copies and its neighbours over all copies. The topology does not
/// change while nodes relax, so these are gathered once, not in every step.
struct Relaxing {
    int node;
    std::vector<int> group;
    std::vector<int> neighbours;
};

/// The movable nodes that have neighbours, in order.
std::vector<Relaxing> gatherRelaxing(const TetMesh& mesh, const CopyGroups& groups,
                                     const std::vector<int>& movable) {
    std::vector<Relaxing> relaxing;
    relaxing.reserve(movable.size());
    for (int n : movable) {
        Relaxing r{n, groups.members(n), {}};
        for (int m : r.group)
            for (int u : mesh.nodeNeighbours(m))
                if (groups.lead(u) != n)
                    r.neighbours.push_back(u);
        std::sort(r.neighbours.begin(), r.neighbours.end());
        r.neighbours.erase(std::unique(r.neighbours.begin(), r.neighbours.end()),
                           r.neighbours.end());
        if (!r.neighbours.empty())
            relaxing.push_back(std::move(r));
    }
    return relaxing;
}

/// One heavily damped step of Eq. 2 for `item`: x + h rest F / #neighbours with h = 1 / c,
/// F the weighted spring and Lennard-Jones forces in units of the rest length (linear
/// springs; a Lennard-Jones potential whose minimum is at the rest length, sigma = rest /
/// 2^(1/6)).
Vec3 dampedStepTarget(const TetMesh& mesh, const Relaxing& item, double rest,
                      const RelaxOptions& options) {
    const Vec3 x = mesh.pos(item.node);
    Vec3 force = Vec3::Zero();
    for (int u : item.neighbours) {
        const Vec3 d = mesh.pos(u) - x;
        const double r = d.norm() / rest;
        if (!(r > 0))
            continue;
        const Vec3 dir = d / (r * rest);
        const double spring = r - 1.0;
        const double r2 = r * r;
        const double s6 = 0.5 / (r2 * r2 * r2); // (sigma / r)^6 with 2^(1/6) sigma = 1
        const double lj = -24.0 * (2.0 * s6 * s6 - s6) / r;
        force += (options.wSpring * spring + options.wParticle * lj / 12.0) * dir;
    }
    const double stepSize = 1.0 / options.damping;
    return x + stepSize * rest * force / static_cast<double>(item.neighbours.size());
}

/// The smallest radius ratio of the tets at the nodes of `group`; each tet's ratio is
/// appended to `ratios` (cleared first).
double minQualityAround(const TetMesh& mesh, const std::vector<int>& group,
                        std::vector<std::pair<int, double>>* ratios) {
    double q = std::numeric_limits<double>::infinity();
    ratios->clear();
    for (int v : group)
        for (int t : mesh.nodeTets(v)) {
            const Tet& k = mesh.tet(t);
            const double r =
                radiusRatio(mesh.ref(k[0]), mesh.ref(k[1]), mesh.ref(k[2]), mesh.ref(k[3]));
            ratios->emplace_back(t, r);
            q = std::min(q, r);
        }
    return q;
}

/// Radius ratios of the tets around relaxing nodes, kept current as moves are accepted, so
/// that each move computes only the ratios after it.
class QualityCache {
public:
    explicit QualityCache(const TetMesh& mesh) : m_mesh(mesh) {}

    /// The smallest radius ratio of the tets at the nodes of `group`.
    double minAround(const std::vector<int>& group) {
        double q = std::numeric_limits<double>::infinity();
        for (int v : group)
            for (int t : m_mesh.nodeTets(v)) {
                auto [it, inserted] = m_ratio.try_emplace(t, 0.0);
                if (inserted) {
                    const Tet& k = m_mesh.tet(t);
                    it->second = radiusRatio(m_mesh.ref(k[0]), m_mesh.ref(k[1]), m_mesh.ref(k[2]),
                                             m_mesh.ref(k[3]));
                }
                q = std::min(q, it->second);
            }
        return q;
    }
    void update(const std::vector<std::pair<int, double>>& ratios) {
        for (const auto& [t, q] : ratios)
            m_ratio[t] = q;
    }

private:
    const TetMesh& m_mesh;
    std::unordered_map<int, double> m_ratio;
};

/// Moves the node of `item` and its copies to (target, targetRef) if no tet around them
/// inverts or goes flat (exact, both configurations) and their smallest radius ratio does
/// not drop; otherwise puts them back. Returns whether the move was kept.
bool tryMove(TetMesh& mesh, const Relaxing& item, const Vec3& target, const Vec3& targetRef,
             QualityCache& quality, std::vector<std::pair<int, double>>& scratch) {
    const std::vector<int>& group = item.group;
    const double before = quality.minAround(group);
    const Vec3 oldRef = mesh.ref(item.node), oldPos = mesh.pos(item.node);
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
    if (ok && minQualityAround(mesh, group, &scratch) < before)
        ok = false;
    if (!ok) {
        for (int m : group)
            mesh.setNodePosition(m, oldRef, oldPos);
        return false;
    }
    quality.update(scratch);
    return true;
}

/// `steps` sweeps over the relaxing nodes, one node after another (section 4.6): each takes
/// its damped step, projected back onto the sweep for nodes on the cut, if tryMove keeps it.
void relaxSweeps(TetMesh& mesh, const SweepSurface& sweep, const std::vector<Relaxing>& relaxing,
                 const std::unordered_set<int>& onCut, double rest, const RelaxOptions& options,
                 RelaxResult& result) {
    QualityCache quality(mesh);
    std::vector<std::pair<int, double>> scratch;
    for (int step = 0; step < options.steps; ++step)
        for (const Relaxing& item : relaxing) {
            const Vec3 x = mesh.pos(item.node);
            Vec3 target = dampedStepTarget(mesh, item, rest, options);
            if (onCut.count(item.node))
                target = sweep.closestPoint(target).point; // stay within the sweep
            if (!target.allFinite() || target == x)
                continue;
            const Vec3 targetRef = referenceFromDeformed(mesh, item.group, target);
            if (!targetRef.allFinite())
                continue;
            if (tryMove(mesh, item, target, targetRef, quality, scratch)) {
                ++result.acceptedMoves;
                result.movedNodes.insert(result.movedNodes.end(), item.group.begin(),
                                         item.group.end());
            } else {
                ++result.rejectedMoves;
            }
        }
    std::sort(result.movedNodes.begin(), result.movedNodes.end());
    result.movedNodes.erase(std::unique(result.movedNodes.begin(), result.movedNodes.end()),
                            result.movedNodes.end());
}

} // namespace

RelaxResult relaxNodes(TetMesh& mesh, const SweepSurface& sweep, const CutChanges& changes,
                       const std::vector<int>& fixedNodes, const RelaxOptions& options) {
    // Section 4.6 in order: the set S around the cut, which of its nodes move, the springs'
    // rest length, then the damped steps of Eq. 2.
    RelaxResult result;
    if (options.steps <= 0 || !(options.damping > 0))
        return result;
    const CopyGroups groups = copyGroups(changes);
    const std::unordered_set<int> onCut(changes.cutSurfaceNodes.begin(),
                                        changes.cutSurfaceNodes.end());
    std::unordered_set<int> fixed;
    for (int n : fixedNodes)
        fixed.insert(groups.lead(n));
    const std::vector<int> region = neighbourhoodOfCut(mesh, groups, changes, options.rings);
    const std::vector<int> movable = movableNodes(mesh, region, onCut, fixed, result);
    const double rest = restLength(mesh, groups, movable);
    if (!(rest > 0))
        return result;
    relaxSweeps(mesh, sweep, gatherRelaxing(mesh, groups, movable), onCut, rest, options, result);
    return result;
}

} // namespace resect
