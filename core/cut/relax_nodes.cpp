#include "core/cut/relax_nodes.h"

#include "core/cut/snap_nodes.h"
#include "core/mesh/index_marks.h"
#include "core/mesh/node_star.h"
#include "core/mesh/predicates.h"
#include "core/mesh/quality.h"
#include "core/mesh/vec3_lanes.h"

#include <algorithm>
#include <cassert>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <span>

namespace resect {
namespace {

// Relaxation runs after every cut, on a few hundred nodes, for ten steps: its set-up reads
// each node's star once and keeps per-node and per-tet state in marks indexed by node or tet
// (RelaxMarks: kept between cuts, cleared in proportion to what a relaxation set), and its
// inner loop allocates nothing.

/// Per-node marks of one relaxation.
enum NodeMark : std::uint8_t { kOnCut = 1, kFixed = 2, kInRegion = 4, kMoved = 8 };

/// The marks of one relaxation, per mesh node and tet. relaxNodes keeps one per thread between
/// cuts (see "Marks" at HybridCutter::cut) and begins a use of each, which ends (clearing what
/// the relaxation set) when it returns.
struct RelaxMarks {
    IndexMarks<int> groupOf{-1};       ///< per node: its copy group (CopyGroups), -1 if none
    IndexMarks<int> starSlot{-1};      ///< per node: its StarCache entry, -1 until read
    IndexMarks<int> tetSlot{-1};       ///< per tet: its slot in RelaxingNodes::ratio, -1 if none
    IndexMarks<std::uint32_t> movedAt; ///< per node: Relaxation's clock at its last move, 0: never
    IndexMarks<std::uint8_t> node;     ///< per node: NodeMark bits
};

/// Groups of coincident copies: a node and the copies separation made of it. Every node of
/// a group moves with its leader (the group's first node).
class CopyGroups {
public:
    /// `groupOf`: clear marks over the mesh's nodes, kept as this object's.
    CopyGroups(const CutChanges& changes, IndexMarks<int>& groupOf) : m_groupOf(groupOf) {
        std::vector<std::array<int, 2>> entries; // (group, node), the leader first
        int groups = 0;
        for (const auto& [orig, copy] : changes.duplicatedNodes) {
            int g = m_groupOf[orig];
            if (g < 0) {
                g = groups++;
                m_groupOf.set(orig, g);
                entries.push_back({g, orig});
            }
            m_groupOf.set(copy, g);
            entries.push_back({g, copy});
        }
        // By group, in the order the nodes joined it.
        m_start.assign(groups + 1, 0);
        for (const auto& e : entries)
            ++m_start[e[0] + 1];
        for (int g = 0; g < groups; ++g)
            m_start[g + 1] += m_start[g];
        m_nodes.resize(entries.size());
        std::vector<int> fill(m_start.begin(), m_start.end() - 1);
        for (const auto& e : entries)
            m_nodes[fill[e[0]]++] = e[1];
    }

    int lead(int n) const {
        const int g = m_groupOf[n];
        return g < 0 ? n : m_nodes[m_start[g]];
    }
    /// The nodes of leader n's group ({n} for a node that was not duplicated).
    template <class Visit> void forMembers(int n, const Visit& visit) const {
        const int g = m_groupOf[n];
        if (g < 0) {
            visit(n);
            return;
        }
        for (int k = m_start[g]; k < m_start[g + 1]; ++k)
            visit(m_nodes[k]);
    }

private:
    IndexMarks<int>& m_groupOf; ///< per node: its group, -1 if it has no copies
    std::vector<int> m_start;   ///< CSR offsets of the groups in m_nodes
    std::vector<int> m_nodes;
};

/// Neighbours and boundary flags of the nodes relaxation looks at, each star read once.
class StarCache {
public:
    /// `slot`: clear marks over the mesh's nodes, kept as this object's.
    StarCache(const TetMesh& mesh, IndexMarks<int>& slot) : m_mesh(mesh), m_slot(slot) {}

    /// Node n's neighbours, sorted; valid until a node not read before is asked for.
    std::span<const int> neighbours(int n) { return entry(n).neighbours(m_flat); }
    bool onBoundary(int n) { return entry(n).onBoundary; }

private:
    struct Entry {
        int first, count;
        bool onBoundary;
        std::span<const int> neighbours(const std::vector<int>& flat) const {
            return {flat.data() + first, static_cast<std::size_t>(count)};
        }
    };
    const Entry& entry(int n) {
        if (m_slot[n] < 0) {
            m_star.gather(m_mesh, n);
            const auto nb = m_star.neighbours();
            m_slot.set(n, static_cast<int>(m_entries.size()));
            m_entries.push_back({static_cast<int>(m_flat.size()), static_cast<int>(nb.size()),
                                 m_star.onBoundary()});
            m_flat.insert(m_flat.end(), nb.begin(), nb.end());
        }
        return m_entries[m_slot[n]];
    }

    const TetMesh& m_mesh;
    IndexMarks<int>& m_slot; ///< per node: its entry, -1 until read
    std::vector<Entry> m_entries;
    std::vector<int> m_flat;
    NodeStar m_star;
};

/// S: the `rings`-ring neighbourhood of the nodes on the cut, as sorted group leaders.
std::vector<int> neighbourhoodOfCut(const CopyGroups& groups, StarCache& stars,
                                    const CutChanges& changes, int rings,
                                    IndexMarks<std::uint8_t>& marks) {
    std::vector<int> region, frontier, next;
    const auto add = [&](int n, std::vector<int>& to) {
        const int l = groups.lead(n);
        if (marks[l] & kInRegion)
            return;
        marks.set(l, static_cast<std::uint8_t>(marks[l] | kInRegion));
        region.push_back(l);
        to.push_back(l);
    };
    for (int n : changes.cutSurfaceNodes)
        add(n, frontier);
    for (int ring = 0; ring < rings; ++ring) {
        next.clear();
        for (int n : frontier)
            groups.forMembers(n, [&](int m) {
                for (int u : stars.neighbours(m))
                    add(u, next);
            });
        frontier.swap(next);
    }
    std::sort(region.begin(), region.end());
    return region;
}

/// The nodes of S that move (in order), counting them in `result`: nodes on the cut move
/// within the sweep, interior nodes freely; `fixed` nodes, and nodes on the boundary that
/// are not on this cut (the original surface or an earlier cut), stay.
std::vector<int> movableNodes(StarCache& stars, const std::vector<int>& region,
                              const IndexMarks<std::uint8_t>& marks, RelaxResult& result) {
    std::vector<int> movable;
    for (int n : region) {
        const bool cutNode = marks[n] & kOnCut;
        if ((marks[n] & kFixed) || (!cutNode && stars.onBoundary(n))) {
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
double restLength(const TetMesh& mesh, const CopyGroups& groups, StarCache& stars,
                  const std::vector<int>& movable) {
    double rest = 0;
    int edgeCount = 0;
    for (int n : movable)
        groups.forMembers(n, [&](int m) {
            for (int u : stars.neighbours(m)) {
                rest += (mesh.pos(u) - mesh.pos(m)).norm();
                ++edgeCount;
            }
        });
    if (edgeCount == 0 || !(rest > 0))
        return 0.0;
    return rest / edgeCount;
}

/// The movable nodes with what each trial move reads, gathered once (the topology does not
/// change while nodes relax), in flat arrays: per node its copies, its neighbours over all
/// copies, and the tets at its copies with their slots in `ratio` and which of their corners
/// are copies.
struct RelaxingNodes {
    struct Node {
        int node;
        bool onCut;
        int groupFirst, groupCount;
        int neighbourFirst, neighbourCount;
        int tetFirst, tetCount;
    };
    std::vector<Node> nodes;
    std::vector<int> groupNodes, neighbourNodes;
    std::vector<int> tets, tetSlot;
    std::vector<std::uint8_t> tetCopyCorners; ///< bit i: corner i is one of the node's copies
    /// Radius ratio of every tet around a relaxing node (by slot), kept current as moves are
    /// accepted: a trial move computes the ratios of its own tets only.
    std::vector<double> ratio;

    std::span<const int> group(const Node& r) const {
        return {groupNodes.data() + r.groupFirst, std::size_t(r.groupCount)};
    }
    std::span<const int> neighbours(const Node& r) const {
        return {neighbourNodes.data() + r.neighbourFirst, std::size_t(r.neighbourCount)};
    }
    std::span<const int> tetsOf(const Node& r) const {
        return {tets.data() + r.tetFirst, std::size_t(r.tetCount)};
    }
};

/// The movable nodes that have neighbours, in order. `tetSlot`: clear marks over the mesh's
/// tets, left marking each tet's slot.
RelaxingNodes gatherRelaxing(const TetMesh& mesh, const CopyGroups& groups, StarCache& stars,
                             const std::vector<int>& movable,
                             const IndexMarks<std::uint8_t>& marks, IndexMarks<int>& tetSlot) {
    RelaxingNodes r;
    std::vector<int> slotTets;
    for (int n : movable) {
        RelaxingNodes::Node item{};
        item.node = n;
        item.onCut = (marks[n] & kOnCut) != 0;
        item.groupFirst = static_cast<int>(r.groupNodes.size());
        item.neighbourFirst = static_cast<int>(r.neighbourNodes.size());
        item.tetFirst = static_cast<int>(r.tets.size());
        groups.forMembers(n, [&](int m) {
            r.groupNodes.push_back(m);
            for (int u : stars.neighbours(m))
                if (groups.lead(u) != n)
                    r.neighbourNodes.push_back(u);
        });
        item.groupCount = static_cast<int>(r.groupNodes.size()) - item.groupFirst;
        for ([[maybe_unused]] int m : r.group(item))
            assert(mesh.ref(m) == mesh.ref(n) && mesh.pos(m) == mesh.pos(n)); // copies coincide
        const auto nbBegin = r.neighbourNodes.begin() + item.neighbourFirst;
        std::sort(nbBegin, r.neighbourNodes.end());
        r.neighbourNodes.erase(std::unique(nbBegin, r.neighbourNodes.end()),
                               r.neighbourNodes.end());
        item.neighbourCount = static_cast<int>(r.neighbourNodes.size()) - item.neighbourFirst;
        if (item.neighbourCount == 0) {
            r.groupNodes.resize(item.groupFirst);
            continue;
        }
        const std::span<const int> group = r.group(item);
        for (int m : group)
            for (int t : mesh.nodeTets(m)) {
                if (tetSlot[t] < 0) {
                    tetSlot.set(t, static_cast<int>(slotTets.size()));
                    slotTets.push_back(t);
                }
                std::uint8_t copies = 0;
                for (int i = 0; i < 4; ++i)
                    if (std::find(group.begin(), group.end(), mesh.tet(t)[i]) != group.end())
                        copies |= static_cast<std::uint8_t>(1 << i);
                r.tets.push_back(t);
                r.tetSlot.push_back(tetSlot[t]);
                r.tetCopyCorners.push_back(copies);
            }
        item.tetCount = static_cast<int>(r.tets.size()) - item.tetFirst;
        r.nodes.push_back(item);
    }
    // The ratios before any move, two at a time.
    const auto corners = [&](int t) {
        const Tet& k = mesh.tet(t);
        return std::array<Vec3, 4>{mesh.ref(k[0]), mesh.ref(k[1]), mesh.ref(k[2]), mesh.ref(k[3])};
    };
    r.ratio.resize(slotTets.size());
    std::size_t k = 0;
    for (; k + 1 < slotTets.size(); k += 2) {
        const auto [first, second] =
            radiusRatioPair(corners(slotTets[k]), corners(slotTets[k + 1]));
        r.ratio[k] = first;
        r.ratio[k + 1] = second;
    }
    if (k < slotTets.size()) {
        const auto c = corners(slotTets[k]);
        r.ratio[k] = radiusRatio(c[0], c[1], c[2], c[3]);
    }
    return r;
}

/// One heavily damped step of Eq. 2 for node x with these neighbours: x + h rest F /
/// #neighbours with h = 1 / c, F the weighted spring and Lennard-Jones forces in units of the
/// rest length (linear springs; a Lennard-Jones potential whose minimum is at the rest
/// length, sigma = rest / 2^(1/6)).
Vec3 dampedStepTarget(const TetMesh& mesh, int node, std::span<const int> neighbours, double rest,
                      const RelaxOptions& options) {
    const Vec3 x = mesh.pos(node);
    Vec3 force = Vec3::Zero();
    // The neighbours' forces two at a time (each lane rounds as the scalar formula would),
    // added to `force` one after another in order.
    const auto add = [&](const Lanes& r, const Lanes& coefficient, const Vec3Lanes& dir, int lane) {
        if (r[lane] > 0)
            force += coefficient[lane] * dir.lane(lane);
    };
    const auto forces = [&](const Vec3Lanes& d, int lanes) {
        const Lanes r = dot(d, d).sqrt() / rest;
        const Vec3Lanes dir = d / (r * rest);
        const Lanes spring = r - 1.0;
        const Lanes r2 = r * r;
        const Lanes s6 = 0.5 / (r2 * r2 * r2); // (sigma / r)^6 with 2^(1/6) sigma = 1
        const Lanes lj = -24.0 * (2.0 * s6 * s6 - s6) / r;
        const Lanes coefficient = options.wSpring * spring + options.wParticle * lj / 12.0;
        for (int lane = 0; lane < lanes; ++lane)
            add(r, coefficient, dir, lane);
    };
    const Vec3Lanes xx(x, x);
    std::size_t k = 0;
    for (; k + 1 < neighbours.size(); k += 2)
        forces(Vec3Lanes(mesh.pos(neighbours[k]), mesh.pos(neighbours[k + 1])) - xx, 2);
    if (k < neighbours.size())
        forces(Vec3Lanes(mesh.pos(neighbours[k]), x) - xx, 1);
    const double stepSize = 1.0 / options.damping;
    return x + stepSize * rest * force / static_cast<double>(neighbours.size());
}

/// The trial moves of one relaxation and what they leave behind.
class Relaxation {
public:
    /// `movedAt`: clear marks (0) over the mesh's nodes, kept as this object's.
    Relaxation(TetMesh& mesh, RelaxingNodes& relaxing, IndexMarks<std::uint32_t>& movedAt)
        : m_mesh(mesh), m_relaxing(relaxing), m_lastTry(relaxing.nodes.size()), m_movedAt(movedAt) {
        std::size_t most = 0;
        for (const auto& r : relaxing.nodes)
            most = std::max(most, static_cast<std::size_t>(r.tetCount));
        m_trialRatio.resize(most);
        m_trialCorners.resize(most);
    }

    enum class Outcome : std::uint8_t { None, Skipped, Rejected, Accepted };

    /// Node k's trial move of this step: its damped step (projected back onto the sweep for
    /// a node on the cut), kept if `keeps` allows it. A trial whose inputs (the positions of
    /// the node's copies and neighbours, which fix its target, the tets it checks and their
    /// ratios) have not changed since the node's last trial ends as that one did, so it is
    /// not recomputed.
    Outcome step(int k, const SweepSurface& sweep, double rest, const RelaxOptions& options) {
        const RelaxingNodes::Node& item = m_relaxing.nodes[k];
        LastTry& last = m_lastTry[k];
        if (last.outcome != Outcome::None && unchangedSince(item, last.clock))
            return last.outcome;
        last.clock = m_clock;
        last.outcome = tryStep(item, last, sweep, rest, options);
        return last.outcome;
    }

    /// Whether the kept ratios of the tets around `item` (around every relaxing node if null)
    /// are bit for bit those computed afresh from the mesh: the invariant that lets a trial
    /// move compute only its own tets' ratios. Checked in debug builds.
    bool ratiosMatchMesh(const RelaxingNodes::Node* item = nullptr) const {
        const auto matches = [&](const RelaxingNodes::Node& r) {
            for (int i = 0; i < r.tetCount; ++i) {
                const Tet& q = m_mesh.tet(m_relaxing.tets[r.tetFirst + i]);
                const double fresh = radiusRatio(m_mesh.ref(q[0]), m_mesh.ref(q[1]),
                                                 m_mesh.ref(q[2]), m_mesh.ref(q[3]));
                const double kept = m_relaxing.ratio[m_relaxing.tetSlot[r.tetFirst + i]];
                if (std::memcmp(&fresh, &kept, sizeof fresh) != 0)
                    return false;
            }
            return true;
        };
        if (item)
            return matches(*item);
        return std::all_of(m_relaxing.nodes.begin(), m_relaxing.nodes.end(), matches);
    }

private:
    struct LastTry {
        std::uint32_t clock = 0;
        Outcome outcome = Outcome::None;
        int failedTet = 0; ///< the tet (index among the node's) that refused the last rejected move
    };

    /// Whether none of the node's copies and neighbours (the corners of every tet it checks)
    /// moved after `clock`.
    bool unchangedSince(const RelaxingNodes::Node& item, std::uint32_t clock) const {
        for (int m : m_relaxing.group(item))
            if (m_movedAt[m] > clock)
                return false;
        for (int u : m_relaxing.neighbours(item))
            if (m_movedAt[u] > clock)
                return false;
        return true;
    }

    /// The trial move itself. The node's copies are coincident (separation copies a node,
    /// snapping and relaxation move a group together), so a refused move leaves them as they
    /// were without being written back.
    Outcome tryStep(const RelaxingNodes::Node& item, LastTry& last, const SweepSurface& sweep,
                    double rest, const RelaxOptions& options) {
        const Vec3 x = m_mesh.pos(item.node);
        Vec3 target =
            dampedStepTarget(m_mesh, item.node, m_relaxing.neighbours(item), rest, options);
        if (item.onCut)
            target = sweep.closestPoint(target).point; // stay within the sweep
        if (!target.allFinite() || target == x)
            return Outcome::Skipped;
        const Vec3 targetRef = referenceFromDeformedIn(m_mesh, m_relaxing.tetsOf(item), target);
        if (!targetRef.allFinite())
            return Outcome::Skipped;
        if (!keeps(item, target, targetRef, last.failedTet))
            return Outcome::Rejected;
        for (int i = 0; i < item.tetCount; ++i)
            m_relaxing.ratio[m_relaxing.tetSlot[item.tetFirst + i]] = m_trialRatio[i];
        ++m_clock;
        for (int m : m_relaxing.group(item)) {
            m_mesh.setNodePosition(m, targetRef, target);
            m_movedAt.set(m, m_clock);
        }
        assert(ratiosMatchMesh(&item));
        return Outcome::Accepted;
    }

    /// Whether the node of `item` and its copies may move to (target, targetRef): no tet
    /// around them inverts or goes flat (exact, both configurations) and their smallest radius
    /// ratio does not drop. Fills m_trialRatio with the tets' ratios after the move. Each tet
    /// is checked with its moved corners substituted; the mesh is not touched.
    bool keeps(const RelaxingNodes::Node& item, const Vec3& target, const Vec3& targetRef,
               int& failedTet) {
        double before = std::numeric_limits<double>::infinity();
        for (int i = 0; i < item.tetCount; ++i)
            before = std::min(before, m_relaxing.ratio[m_relaxing.tetSlot[item.tetFirst + i]]);
        // "No ratio below `before`" is "the smallest ratio does not drop", and any one tet that
        // fails a check decides, so the order is free: the tet that refused this node's last
        // move first, alone (it usually refuses again), then the others, their ratios two at a
        // time (radiusRatioPair); the first failure ends the trial.
        const int first = failedTet < item.tetCount ? failedTet : 0;
        if (!movedTetIsPositive(item, first, target, targetRef)) {
            failedTet = first;
            return false;
        }
        const auto& r = m_trialCorners;
        m_trialRatio[first] = radiusRatio(r[first][0], r[first][1], r[first][2], r[first][3]);
        if (m_trialRatio[first] < before)
            return false;
        int pending = -1;
        for (int i = 0; i < item.tetCount; ++i) {
            if (i == first)
                continue;
            if (!movedTetIsPositive(item, i, target, targetRef)) {
                failedTet = i;
                return false;
            }
            if (pending < 0) {
                pending = i;
                continue;
            }
            const auto [rp, ri] = radiusRatioPair(r[pending], r[i]);
            m_trialRatio[pending] = rp;
            m_trialRatio[i] = ri;
            if (rp < before || ri < before) {
                failedTet = rp < before ? pending : i;
                return false;
            }
            pending = -1;
        }
        if (pending >= 0) {
            m_trialRatio[pending] =
                radiusRatio(r[pending][0], r[pending][1], r[pending][2], r[pending][3]);
            if (m_trialRatio[pending] < before) {
                failedTet = pending;
                return false;
            }
        }
        return true;
    }

    /// Whether tet i of `item` stays positive in both configurations after the move (the
    /// orientation filters decide almost always, cheaply); its reference corners after the
    /// move are left in m_trialCorners[i].
    bool movedTetIsPositive(const RelaxingNodes::Node& item, int i, const Vec3& target,
                            const Vec3& targetRef) {
        const Tet& q = m_mesh.tet(m_relaxing.tets[item.tetFirst + i]);
        const std::uint8_t copies = m_relaxing.tetCopyCorners[item.tetFirst + i];
        std::array<Vec3, 4>& r = m_trialCorners[i];
        const Vec3* p[4];
        for (int c = 0; c < 4; ++c) {
            const bool moved = copies >> c & 1;
            r[c] = moved ? targetRef : m_mesh.ref(q[c]);
            p[c] = moved ? &target : &m_mesh.pos(q[c]);
        }
        return orient3d(r[0], r[1], r[2], r[3]) > 0 && orient3d(*p[0], *p[1], *p[2], *p[3]) > 0;
    }

    TetMesh& m_mesh;
    RelaxingNodes& m_relaxing;
    std::vector<LastTry> m_lastTry;
    IndexMarks<std::uint32_t>& m_movedAt; ///< per node: m_clock after its last move (0: never)
    std::uint32_t m_clock = 0;            ///< accepted moves so far
    std::vector<double> m_trialRatio;
    std::vector<std::array<Vec3, 4>> m_trialCorners;
};

/// `steps` sweeps over the relaxing nodes, one node after another (section 4.6).
void relaxSweeps(TetMesh& mesh, const SweepSurface& sweep, RelaxingNodes& relaxing, double rest,
                 const RelaxOptions& options, RelaxMarks& marks, RelaxResult& result) {
    Relaxation relaxation(mesh, relaxing, marks.movedAt);
    assert(relaxation.ratiosMatchMesh());
    for (int step = 0; step < options.steps; ++step) {
        for (int k = 0; k < static_cast<int>(relaxing.nodes.size()); ++k) {
            switch (relaxation.step(k, sweep, rest, options)) {
            case Relaxation::Outcome::Accepted:
                ++result.acceptedMoves;
                for (int m : relaxing.group(relaxing.nodes[k]))
                    if (!(marks.node[m] & kMoved)) {
                        marks.node.set(m, static_cast<std::uint8_t>(marks.node[m] | kMoved));
                        result.movedNodes.push_back(m);
                    }
                break;
            case Relaxation::Outcome::Rejected:
                ++result.rejectedMoves;
                break;
            default:
                break;
            }
        }
        assert(relaxation.ratiosMatchMesh());
    }
    std::sort(result.movedNodes.begin(), result.movedNodes.end());
}

} // namespace

RelaxResult relaxNodes(TetMesh& mesh, const SweepSurface& sweep, const CutChanges& changes,
                       const std::vector<int>& fixedNodes, const RelaxOptions& options) {
    // Section 4.6 in order: the set S around the cut, which of its nodes move, the springs'
    // rest length, then the damped steps of Eq. 2.
    RelaxResult result;
    if (options.steps <= 0 || !(options.damping > 0))
        return result;
    thread_local RelaxMarks marks;
    const auto groupScope = marks.groupOf.use(mesh.nodeCount());
    const auto starScope = marks.starSlot.use(mesh.nodeCount());
    const auto tetScope = marks.tetSlot.use(mesh.tetCount());
    const auto movedScope = marks.movedAt.use(mesh.nodeCount());
    const auto nodeScope = marks.node.use(mesh.nodeCount());
    const CopyGroups groups(changes, marks.groupOf);
    IndexMarks<std::uint8_t>& node = marks.node;
    for (int n : changes.cutSurfaceNodes)
        node.set(n, static_cast<std::uint8_t>(node[n] | kOnCut));
    for (int n : fixedNodes)
        node.set(groups.lead(n), static_cast<std::uint8_t>(node[groups.lead(n)] | kFixed));
    StarCache stars(mesh, marks.starSlot);
    const std::vector<int> region = neighbourhoodOfCut(groups, stars, changes, options.rings, node);
    const std::vector<int> movable = movableNodes(stars, region, node, result);
    const double rest = restLength(mesh, groups, stars, movable);
    if (!(rest > 0))
        return result;
    RelaxingNodes relaxing = gatherRelaxing(mesh, groups, stars, movable, node, marks.tetSlot);
    relaxSweeps(mesh, sweep, relaxing, rest, options, marks, result);
    return result;
}

} // namespace resect
