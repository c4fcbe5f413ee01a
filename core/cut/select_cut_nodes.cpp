#include "core/cut/select_cut_nodes.h"

#include "core/mesh/index_marks.h"
#include "core/mesh/validity.h"

#include <algorithm>
#include <array>
#include <cassert>
#include <cmath>

namespace resect {
namespace {

/// Groups of the nodes in `nodes` (4-bit mask) joined by the tet edges NOT in `cut` (6-bit).
/// Returns a group id per local node (-1 for nodes outside the mask) and the group count.
/// Groups are numbered in the order of their lowest local node. (Called for every touched
/// tet, in the fixed-point loop too: a flood fill over the four nodes, nothing allocated.)
int groupNodes(std::uint8_t nodes, std::uint8_t cut, std::array<int, 4>& group) {
    group.fill(-1);
    int count = 0;
    for (int start = 0; start < 4; ++start) {
        if (!(nodes >> start & 1) || group[start] >= 0)
            continue;
        group[start] = count;
        for (bool grew = true; grew;) {
            grew = false;
            for (int e = 0; e < 6; ++e) {
                const int i = kTetEdges[e][0], j = kTetEdges[e][1];
                if (!(nodes >> i & 1) || !(nodes >> j & 1) || (cut >> e & 1))
                    continue;
                if (group[i] == count && group[j] < 0) {
                    group[j] = count;
                    grew = true;
                } else if (group[j] == count && group[i] < 0) {
                    group[i] = count;
                    grew = true;
                }
            }
        }
        ++count;
    }
    return count;
}

/// Complete cut: the crossed edges are exactly the edges between two groups of the nodes
/// outside `onCut`, and none touches a node in `onCut`.
bool isComplete(std::uint8_t crossed, std::uint8_t onCut) {
    for (int e = 0; e < 6; ++e)
        if ((crossed >> e & 1) && ((onCut >> kTetEdges[e][0] & 1) || (onCut >> kTetEdges[e][1] & 1)))
            return false;
    const std::uint8_t rest = static_cast<std::uint8_t>(~onCut & 0xF);
    std::array<int, 4> group;
    const int groups = groupNodes(rest, crossed, group);
    if (groups > 2)
        return false;
    for (int e = 0; e < 6; ++e) {
        const int i = kTetEdges[e][0], j = kTetEdges[e][1];
        if (!(rest >> i & 1) || !(rest >> j & 1))
            continue;
        const bool across = group[i] != group[j];
        if (across != static_cast<bool>(crossed >> e & 1))
            return false;
    }
    return true;
}

Scheme classify(int cutNodes, int cutEdges, bool partial) {
    if (partial)
        return cutEdges == 1 ? Scheme::C : cutEdges == 2 ? Scheme::D : Scheme::E;
    switch (cutNodes) {
    case 0: return cutEdges == 3 ? Scheme::A : cutEdges == 4 ? Scheme::B : Scheme::None;
    case 1: return cutEdges == 2 ? Scheme::X : Scheme::Touch;
    case 2: return cutEdges == 1 ? Scheme::Y : Scheme::Touch;
    default: return Scheme::Z;
    }
}

/// Position of the crossed edge (a, b) in crossed.edges, or -1.
int crossedIndex(const IntersectedEdges& crossed, int a, int b) {
    const auto it = crossed.index.find(edgeKey(a, b));
    return it == crossed.index.end() ? -1 : it->second;
}

/// Per-node flags of one selection.
enum NodeFlag : std::uint8_t {
    kOnSweep = 1,    ///< lies exactly on the sweep
    kIneligible = 2, ///< a node of a partially cut tet: never a cut node (markPartialTets)
    kCut = 4,        ///< chosen as a cut node (chooseCutNodes)
    kNominated = 8,  ///< nominated by a crossed edge (chooseCutNodes)
    kNear = 16,      ///< within SelectOptions::nearFraction of d of the sweep (nearNodes)
};

/// The tets the sweep touches: on a crossed edge or at a node on the sweep.
struct TouchedTets {
    std::vector<int> tets;                 ///< sorted, without duplicates
    std::vector<std::uint8_t> crossedMask; ///< per tet: bit e set if local edge e is crossed
    std::vector<char> partial;             ///< per tet: partially cut (markPartialTets)
    const IndexMarks<int>* position = nullptr; ///< per mesh tet: its position in `tets`, or -1

    /// Position of tet t in `tets`, or -1.
    int find(int t) const { return (*position)[t]; }
    /// True if tet t is touched and partially cut.
    bool isPartial(int t) const {
        const int k = find(t);
        return k >= 0 && partial[k];
    }
    /// Crossed edges of tet t (0 if it is not touched).
    std::uint8_t crossedEdges(int t) const {
        const int k = find(t);
        return k >= 0 ? crossedMask[k] : 0;
    }
};

TouchedTets gatherTouchedTets(const TetMesh& mesh, const IntersectedEdges& crossed,
                              IndexMarks<int>& position) {
    TouchedTets touched;
    // Each crossed edge's tets, with the edge's local number in each.
    std::vector<std::pair<int, std::uint8_t>> crossings;
    std::vector<int> scratch;
    for (const EdgeCrossing& e : crossed.edges) {
        mesh.edgeTets(e.a, e.b, scratch);
        for (int t : scratch) {
            const Tet& q = mesh.tet(t);
            for (int le = 0; le < 6; ++le) {
                const int x = q[kTetEdges[le][0]], y = q[kTetEdges[le][1]];
                if ((x == e.a && y == e.b) || (x == e.b && y == e.a))
                    crossings.push_back({t, static_cast<std::uint8_t>(le)});
            }
            touched.tets.push_back(t);
        }
    }
    for (int n : crossed.onSweepNodes)
        touched.tets.insert(touched.tets.end(), mesh.nodeTets(n).begin(), mesh.nodeTets(n).end());
    std::sort(touched.tets.begin(), touched.tets.end());
    touched.tets.erase(std::unique(touched.tets.begin(), touched.tets.end()), touched.tets.end());

    touched.crossedMask.assign(touched.tets.size(), 0);
    touched.partial.assign(touched.tets.size(), 0);
    assert(position.clearValue() == -1);
    touched.position = &position;
    for (std::size_t k = 0; k < touched.tets.size(); ++k)
        position.set(touched.tets[k], static_cast<int>(k));
    for (const auto& [t, le] : crossings)
        touched.crossedMask[touched.find(t)] |= static_cast<std::uint8_t>(1 << le);
    return touched;
}

/// Rule "nodes of partially cut tets are never cut nodes" (section 4.4): marks the partially
/// cut tets in `touched` and, per node, whether it is such a node (kIneligible in `node`,
/// which it also marks kOnSweep for the nodes on the sweep). A node on the sweep counts as a
/// cut node of a tet only while it is eligible, so each newly ineligible node on the sweep may
/// make more tets partial: iterated to a fixed point.
void markPartialTets(const TetMesh& mesh, const IntersectedEdges& crossed, TouchedTets& touched,
                     IndexMarks<std::uint8_t>& node) {
    for (int n : crossed.onSweepNodes)
        node.set(n, static_cast<std::uint8_t>(node[n] | kOnSweep));
    for (bool changed = true; changed;) {
        changed = false;
        for (std::size_t k = 0; k < touched.tets.size(); ++k) {
            if (touched.partial[k])
                continue;
            const Tet& q = mesh.tet(touched.tets[k]);
            // Nodes on the sweep and near nodes that are still eligible count as cut nodes;
            // the crossings at near nodes are not splits (a cut node's edges are not split).
            std::uint8_t onCut = 0, crossedMask = touched.crossedMask[k];
            for (int i = 0; i < 4; ++i) {
                const std::uint8_t f = node[q[i]];
                if (f & kIneligible)
                    continue;
                if (f & kOnSweep)
                    onCut |= static_cast<std::uint8_t>(1 << i);
                else if (f & kNear) {
                    onCut |= static_cast<std::uint8_t>(1 << i);
                    for (int e = 0; e < 6; ++e)
                        if (kTetEdges[e][0] == i || kTetEdges[e][1] == i)
                            crossedMask &= static_cast<std::uint8_t>(~(1 << e));
                }
            }
            if (isComplete(crossedMask, onCut))
                continue;
            touched.partial[k] = 1;
            for (int v : q) {
                if (node[v] & kIneligible)
                    continue;
                node.set(v, static_cast<std::uint8_t>(node[v] | kIneligible));
                if (node[v] & (kOnSweep | kNear))
                    changed = true;
            }
        }
    }
}

/// Near nodes (rule "near nodes", select_cut_nodes.h): the ends of crossed edges closer to the
/// sweep than options.nearFraction * options.d, not on it, with their distances, nearest first
/// (ties by node index).
std::vector<std::pair<double, int>> nearNodes(const TetMesh& mesh, const SweepSurface& sweep, const IntersectedEdges& crossed,
                                              const SelectOptions& options, IndexMarks<std::uint8_t>& seen) {
    std::vector<std::pair<double, int>> near;
    const double bound = options.nearFraction * options.d;
    if (!options.allowCutNodes || !(bound > 0))
        return near;
    for (const EdgeCrossing& e : crossed.edges)
        for (int n : {e.a, e.b}) {
            if (seen[n])
                continue;
            seen.set(n, 1);
            const double dist = sweep.closestPoint(mesh.pos(n)).distance;
            if (dist > 0 && dist < bound)
                near.push_back({dist, n});
        }
    std::sort(near.begin(), near.end());
    return near;
}

/// The chosen cut nodes: per node whether it is one (kCut in the selection's node flags), and
/// (node, distance to the sweep) in the order chosen.
struct CutNodeDistances {
    const IndexMarks<std::uint8_t>* node = nullptr; ///< the selection's node flags
    std::vector<std::pair<int, double>> chosen;

    bool isCut(int n) const { return (*node)[n] & kCut; }
};

/// Makes node n a cut node at `distance` from the sweep, unless one of its tets already has
/// three (rule "no tet gets a fourth cut node"); false if refused.
bool acceptCutNode(const TetMesh& mesh, int n, double distance, IndexMarks<std::uint8_t>& node,
                   IndexMarks<std::uint8_t>& cutNodesOfTet, CutNodeDistances& cut) {
    for (int t : mesh.nodeTets(n))
        if (cutNodesOfTet[t] >= 3)
            return false;
    for (int t : mesh.nodeTets(n))
        cutNodesOfTet.set(t, static_cast<std::uint8_t>(cutNodesOfTet[t] + 1));
    node.set(n, static_cast<std::uint8_t>(node[n] | kCut));
    cut.chosen.push_back({n, distance});
    return true;
}

/// Rules "a node exactly on the sweep is always a cut node" and "the nearer end within d"
/// (section 4.3): eligible nodes on the sweep first (distance 0), then every crossed edge
/// nominates its nearer end if it is closer than d to the sweep; nominees are accepted
/// nearest first (ties by node index) unless a tet would get a fourth cut node.
CutNodeDistances chooseCutNodes(const TetMesh& mesh, const SweepSurface& sweep,
                                const IntersectedEdges& crossed, const SelectOptions& options,
                                const std::vector<std::pair<double, int>>& near,
                                IndexMarks<std::uint8_t>& node,
                                IndexMarks<std::uint8_t>& cutNodesOfTet) {
    CutNodeDistances cut;
    cut.node = &node;
    const auto accept = [&](int n, double distance) { return acceptCutNode(mesh, n, distance, node, cutNodesOfTet, cut); };
    for (int n : crossed.onSweepNodes)
        if (!(node[n] & kIneligible))
            accept(n, 0.0);
    for (const auto& [dist, n] : near)
        if (!(node[n] & (kIneligible | kCut)))
            accept(n, dist);
    if (!options.allowCutNodes || !(options.d > 0))
        return cut;
    std::vector<std::pair<double, int>> order;
    for (const EdgeCrossing& e : crossed.edges) {
        const int n = e.hit.t <= 0.5 ? e.a : e.b;
        if (node[n] & (kIneligible | kCut | kNominated))
            continue;
        node.set(n, static_cast<std::uint8_t>(node[n] | kNominated));
        const double dist = sweep.closestPoint(mesh.pos(n)).distance;
        if (dist < options.d)
            order.push_back({dist, n});
    }
    std::sort(order.begin(), order.end());
    for (const auto& [dist, n] : order)
        accept(n, dist);
    return cut;
}

/// The two walls of an earlier crack have nodes at the same reference positions (twins) and
/// so edges at the same positions. If the sweep crosses both copies of such an edge and one
/// copy has a cut node at an end while the other does not (the rules above decide per node:
/// one copy may be in a partially cut tet, or its tet may already have three cut nodes), one
/// wall's edge is split and the other's is not, and the split point hangs on the other wall's
/// face (box, twenty partial strokes, seed 7, pass 16; issue 16). Where that happens, the
/// copy that is not a cut node becomes one if it can; otherwise the copies that are cut nodes
/// stop being cut nodes. Only the crossed edges are looked at.
void matchTwinCutNodes(const TetMesh& mesh, const SweepSurface& sweep, const IntersectedEdges& crossed,
                       double minEdgeFraction, IndexMarks<std::uint8_t>& node, IndexMarks<std::uint8_t>& cutNodesOfTet,
                       CutNodeDistances& cut) {
    std::vector<std::pair<std::array<double, 6>, int>> edges;
    edges.reserve(crossed.edges.size());
    for (int i = 0; i < static_cast<int>(crossed.edges.size()); ++i)
        edges.emplace_back(edgePositionKey(mesh, crossed.edges[i].a, crossed.edges[i].b), i);
    std::sort(edges.begin(), edges.end());
    const auto isCut = [&](int n) { return (node[n] & kCut) != 0; };
    // Whether the split point of a copy that is a cut edge (no cut node at either end) hangs
    // on a boundary face at a copy that is not one, as listCutEdges and decomposeTets would
    // place it. Only then is the mismatch corrected: elsewhere the split point lies a rounding
    // off the other wall's face (curved walls), and correcting those changed the overlap of
    // later cuts on the myoma and the liver lobe (0.098 and 0.047 mean edges, over the
    // 0.04 the stroke rows allow).
    const auto splitHangs = [&](std::size_t i, std::size_t j) {
        const auto isCutEdge = [&](const EdgeCrossing& e) { return !isCut(e.a) && !isCut(e.b); };
        for (std::size_t k = i; k < j; ++k) {
            const EdgeCrossing& e = crossed.edges[edges[k].second];
            if (!isCutEdge(e))
                continue;
            const double t = std::clamp(e.hit.t, minEdgeFraction, 1.0 - minEdgeFraction);
            const Vec3 p = mesh.ref(e.a) + t * (mesh.ref(e.b) - mesh.ref(e.a));
            for (std::size_t l = i; l < j; ++l) {
                const EdgeCrossing& f = crossed.edges[edges[l].second];
                if (!isCutEdge(f) && hangsOnBoundaryFaceAt(mesh, p, f.a, f.b))
                    return true;
            }
        }
        return false;
    };
    for (std::size_t i = 0; i < edges.size();) {
        std::size_t j = i + 1;
        while (j < edges.size() && edges[j].first == edges[i].first)
            ++j;
        if (j - i < 2) {
            i = j;
            continue;
        }
        // Per end position: the copies, and whether some copy is a cut node and some is not.
        for (int end = 0; end < 2; ++end) {
            const Vec3 at = end == 0 ? Vec3(edges[i].first[0], edges[i].first[1], edges[i].first[2])
                                     : Vec3(edges[i].first[3], edges[i].first[4], edges[i].first[5]);
            std::vector<int> copies;
            for (std::size_t k = i; k < j; ++k) {
                const EdgeCrossing& e = crossed.edges[edges[k].second];
                copies.push_back(mesh.ref(e.a) == at ? e.a : e.b);
            }
            const bool someCut = std::any_of(copies.begin(), copies.end(), isCut);
            const bool allCut = std::all_of(copies.begin(), copies.end(), isCut);
            if (!someCut || allCut || !splitHangs(i, j))
                continue;
            bool matched = true;
            for (int n : copies) {
                if (isCut(n))
                    continue;
                if ((node[n] & kIneligible) ||
                    !acceptCutNode(mesh, n, sweep.closestPoint(mesh.pos(n)).distance, node, cutNodesOfTet, cut)) {
                    matched = false;
                    break;
                }
            }
            // (A node exactly on the sweep stays a cut node: its crossings are at it.)
            if (matched || std::any_of(copies.begin(), copies.end(), [&](int n) { return isCut(n) && (node[n] & kOnSweep); }))
                continue;
            for (int n : copies) {
                if (!isCut(n))
                    continue;
                for (int t : mesh.nodeTets(n))
                    cutNodesOfTet.set(t, static_cast<std::uint8_t>(cutNodesOfTet[t] - 1));
                node.set(n, static_cast<std::uint8_t>((node[n] & ~kCut) | kIneligible));
                cut.chosen.erase(std::find_if(cut.chosen.begin(), cut.chosen.end(),
                                              [n](const auto& c) { return c.first == n; }));
            }
        }
        i = j;
    }
}

/// The cut nodes sorted, with their distances and the largest distance.
void listCutNodes(const CutNodeDistances& cut, CutSelection& sel) {
    std::vector<std::pair<int, double>> byNode = cut.chosen;
    std::sort(byNode.begin(), byNode.end());
    for (const auto& [n, dist] : byNode) {
        sel.cutNodes.push_back(n);
        sel.cutNodeDistance.push_back(dist);
        sel.maxCutNodeDistance = std::max(sel.maxCutNodeDistance, dist);
    }
}

/// Cut edges: the crossed edges with no cut node at either end (section 4.3). Rule
/// "minEdgeFraction": a crossing closer than that fraction of the edge to an end node is
/// moved to that fraction, so that no split creates a zero-volume tet.
void listCutEdges(const TetMesh& mesh, const IntersectedEdges& crossed, const CutNodeDistances& cut,
                  double minEdgeFraction, CutSelection& sel) {
    const double lo = minEdgeFraction, hi = 1.0 - minEdgeFraction;
    for (const EdgeCrossing& e : crossed.edges) {
        if (cut.isCut(e.a) || cut.isCut(e.b))
            continue;
        EdgeCrossing c = e;
        if (c.hit.t < lo || c.hit.t > hi) {
            c.hit.t = std::clamp(c.hit.t, lo, hi);
            c.hit.point = mesh.pos(c.a) + c.hit.t * (mesh.pos(c.b) - mesh.pos(c.a));
        }
        sel.cutEdgeIndex.emplace(edgeKey(c.a, c.b), static_cast<int>(sel.cutEdges.size()));
        sel.cutEdges.push_back(c);
    }
}

/// The tets to classify: every touched tet and every tet at a cut node, sorted.
std::vector<int> affectedTets(const TetMesh& mesh, const TouchedTets& touched,
                              const std::vector<int>& cutNodes) {
    std::vector<int> affected = touched.tets;
    for (int n : cutNodes)
        affected.insert(affected.end(), mesh.nodeTets(n).begin(), mesh.nodeTets(n).end());
    std::sort(affected.begin(), affected.end());
    affected.erase(std::unique(affected.begin(), affected.end()), affected.end());
    return affected;
}

/// Side of node n of tet q: from a crossing on one of its edges in q, else from the
/// nearest sweep triangle (+1 in its plane).
int nodeSide(const TetMesh& mesh, const SweepSurface& sweep, const IntersectedEdges& crossed, int n,
             const Tet& q) {
    for (int m : q) {
        if (m == n)
            continue;
        const int ci = crossedIndex(crossed, n, m);
        if (ci >= 0) {
            const EdgeCrossing& e = crossed.edges[ci];
            return e.a == n ? e.hit.sideP : -e.hit.sideP;
        }
    }
    const int s = sweep.sideOf(mesh.pos(n));
    return s == 0 ? 1 : s;
}

/// Sides of the nodes of tet tc.tet: 0 for cut nodes; in a partially cut tet each node's own
/// side; in a complete one the groups of non-cut nodes get opposite sides, taken from a cut
/// edge's crossing where there is one.
void tetSides(const TetMesh& mesh, const SweepSurface& sweep, const IntersectedEdges& crossed,
              const CutSelection& sel, TetCut& tc) {
    const Tet& q = mesh.tet(tc.tet);
    const std::uint8_t rest = static_cast<std::uint8_t>(~tc.nodeCode & 0xF);
    std::array<int, 4> group;
    groupNodes(rest, tc.edgeCode, group);
    int side0 = 0; // side of group 0
    for (int e = 0; e < 6 && side0 == 0; ++e) {
        if (!(tc.edgeCode >> e & 1))
            continue;
        const int i = kTetEdges[e][0];
        const EdgeCrossing& c =
            sel.cutEdges[sel.cutEdgeIndex.at(edgeKey(q[i], q[kTetEdges[e][1]]))];
        const int si = c.a == q[i] ? c.hit.sideP : -c.hit.sideP;
        side0 = group[i] == 0 ? si : -si;
    }
    for (int i = 0; i < 4; ++i) {
        if (tc.nodeCode >> i & 1) {
            tc.side[i] = 0;
        } else if (tc.partial) {
            tc.side[i] = static_cast<std::int8_t>(nodeSide(mesh, sweep, crossed, q[i], q));
        } else {
            if (side0 == 0)
                side0 = group[i] == 0 ? nodeSide(mesh, sweep, crossed, q[i], q)
                                      : -nodeSide(mesh, sweep, crossed, q[i], q);
            tc.side[i] = static_cast<std::int8_t>(group[i] == 0 ? side0 : -side0);
        }
    }
}

/// Codes, scheme (Figure 4) and node sides of tet t; false if the tet is touched only at a
/// node that could not be a cut node (nothing to do).
bool classifyTet(const TetMesh& mesh, const SweepSurface& sweep, const IntersectedEdges& crossed,
                 const TouchedTets& touched, const CutNodeDistances& cut, const CutSelection& sel,
                 int t, TetCut& tc) {
    const Tet& q = mesh.tet(t);
    tc = TetCut{};
    tc.tet = t;
    for (int i = 0; i < 4; ++i)
        if (cut.isCut(q[i]))
            tc.nodeCode |= static_cast<std::uint8_t>(1 << i);
    // Cut edges are the crossed edges without a cut node at either end (listCutEdges).
    const std::uint8_t crossedEdges = touched.crossedEdges(t);
    for (int e = 0; e < 6; ++e)
        if ((crossedEdges >> e & 1) && !(tc.nodeCode >> kTetEdges[e][0] & 1) &&
            !(tc.nodeCode >> kTetEdges[e][1] & 1))
            tc.edgeCode |= static_cast<std::uint8_t>(1 << e);
    tc.partial = touched.isPartial(t);
    const int cutNodes = __builtin_popcount(tc.nodeCode);
    const int cutEdges = __builtin_popcount(tc.edgeCode);
    if (!tc.partial && cutEdges == 0 && cutNodes == 0)
        return false;
    tc.scheme = classify(cutNodes, cutEdges, tc.partial);
    tetSides(mesh, sweep, crossed, sel, tc);
    return true;
}

} // namespace

const char* schemeName(Scheme s) {
    switch (s) {
    case Scheme::None: return "none";
    case Scheme::A: return "A";
    case Scheme::B: return "B";
    case Scheme::C: return "C";
    case Scheme::D: return "D";
    case Scheme::E: return "E";
    case Scheme::X: return "X";
    case Scheme::Y: return "Y";
    case Scheme::Z: return "Z";
    case Scheme::Touch: return "touch";
    }
    return "?";
}

Scheme CutChanges::schemeOf(int t) const {
    const auto it = std::lower_bound(tetScheme.begin(), tetScheme.end(), std::pair<int, Scheme>{t, Scheme::None});
    return it != tetScheme.end() && it->first == t ? it->second : Scheme::None;
}

CutSelection selectCutNodes(const TetMesh& mesh, const SweepSurface& sweep,
                            const IntersectedEdges& crossed, const SelectOptions& options) {
    // Marks per node and per tet, kept between cuts on this thread and cleared when the scopes
    // end, in proportion to what this selection set (see "Marks" at HybridCutter::cut).
    thread_local IndexMarks<std::uint8_t> nodeFlags;
    thread_local IndexMarks<int> tetPosition(-1);
    thread_local IndexMarks<std::uint8_t> cutNodesOfTet;
    const auto nodeScope = nodeFlags.use(mesh.nodeCount());
    const auto positionScope = tetPosition.use(mesh.tetCount());
    const auto countScope = cutNodesOfTet.use(mesh.tetCount());
    // The rules of select_cut_nodes.h, in order: partial tets first (their nodes are never cut
    // nodes), then cut nodes, then cut edges, then the codes and sides of every affected tet.
    std::vector<std::pair<double, int>> near = nearNodes(mesh, sweep, crossed, options, nodeFlags);
    nodeFlags.reset();
    // A near node counts as a cut node when tets are classified (its crossings are not splits),
    // so it must become one: where one does not (a tet would get a fourth cut node, or its
    // twin on the other wall of a crack cannot be one), the selection is made again without it.
    TouchedTets touched;
    CutNodeDistances cut;
    for (;;) {
        for (const auto& [dist, n] : near)
            nodeFlags.set(n, kNear);
        touched = gatherTouchedTets(mesh, crossed, tetPosition);
        markPartialTets(mesh, crossed, touched, nodeFlags);
        std::vector<int> eligibleNear;
        for (const auto& [dist, n] : near)
            if (!(nodeFlags[n] & kIneligible))
                eligibleNear.push_back(n);
        cut = chooseCutNodes(mesh, sweep, crossed, options, near, nodeFlags, cutNodesOfTet);
        matchTwinCutNodes(mesh, sweep, crossed, options.minEdgeFraction, nodeFlags, cutNodesOfTet, cut);
        std::vector<int> dropped;
        for (int n : eligibleNear)
            if (!cut.isCut(n))
                dropped.push_back(n);
        if (dropped.empty())
            break;
        std::sort(dropped.begin(), dropped.end());
        std::erase_if(near, [&](const auto& c) { return std::binary_search(dropped.begin(), dropped.end(), c.second); });
        nodeFlags.reset();
        tetPosition.reset();
        cutNodesOfTet.reset();
    }
    CutSelection sel;
    listCutNodes(cut, sel);
    listCutEdges(mesh, crossed, cut, options.minEdgeFraction, sel);
    for (int t : affectedTets(mesh, touched, sel.cutNodes)) {
        TetCut tc;
        if (classifyTet(mesh, sweep, crossed, touched, cut, sel, t, tc))
            sel.tets.push_back(tc);
    }
    return sel;
}

} // namespace resect
