#include "core/cut/select_cut_nodes.h"

#include "core/mesh/union_find.h"

#include <algorithm>
#include <cmath>
#include <unordered_map>
#include <unordered_set>

namespace resect {
namespace {

/// Groups of the nodes in `nodes` (4-bit mask) joined by the tet edges NOT in `cut` (6-bit).
/// Returns a group id per local node (-1 for nodes outside the mask) and the group count.
/// Groups are numbered in the order of their lowest local node.
int groupNodes(std::uint8_t nodes, std::uint8_t cut, std::array<int, 4>& group) {
    UnionFind joined(4);
    for (int e = 0; e < 6; ++e) {
        const int i = kTetEdges[e][0], j = kTetEdges[e][1];
        if ((nodes >> i & 1) && (nodes >> j & 1) && !(cut >> e & 1))
            joined.unite(i, j);
    }
    std::vector<int> label;
    const int count = joined.compact(label, [&](int i) { return (nodes >> i & 1) != 0; });
    std::copy(label.begin(), label.end(), group.begin());
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

/// The tets the sweep touches: on a crossed edge or at a node on the sweep.
struct TouchedTets {
    std::vector<int> tets;                 ///< sorted, without duplicates
    std::vector<std::uint8_t> crossedMask; ///< per tet: bit e set if local edge e is crossed
    std::vector<char> partial;             ///< per tet: partially cut (markPartialTets)

    /// True if tet t is touched and partially cut.
    bool isPartial(int t) const {
        const auto it = std::lower_bound(tets.begin(), tets.end(), t);
        return it != tets.end() && *it == t && partial[it - tets.begin()];
    }
};

TouchedTets gatherTouchedTets(const TetMesh& mesh, const IntersectedEdges& crossed) {
    TouchedTets touched;
    std::vector<int> scratch;
    for (const EdgeCrossing& e : crossed.edges) {
        mesh.edgeTets(e.a, e.b, scratch);
        touched.tets.insert(touched.tets.end(), scratch.begin(), scratch.end());
    }
    for (int n : crossed.onSweepNodes)
        touched.tets.insert(touched.tets.end(), mesh.nodeTets(n).begin(), mesh.nodeTets(n).end());
    std::sort(touched.tets.begin(), touched.tets.end());
    touched.tets.erase(std::unique(touched.tets.begin(), touched.tets.end()), touched.tets.end());

    touched.crossedMask.assign(touched.tets.size(), 0);
    touched.partial.assign(touched.tets.size(), 0);
    for (std::size_t k = 0; k < touched.tets.size(); ++k) {
        const Tet& q = mesh.tet(touched.tets[k]);
        for (int e = 0; e < 6; ++e)
            if (crossedIndex(crossed, q[kTetEdges[e][0]], q[kTetEdges[e][1]]) >= 0)
                touched.crossedMask[k] |= static_cast<std::uint8_t>(1 << e);
    }
    return touched;
}

/// Rule "nodes of partially cut tets are never cut nodes" (section 4.4): marks the partially
/// cut tets in `touched` and returns their nodes. A node on the sweep counts as a cut node
/// of a tet only while it is eligible, so each newly ineligible node on the sweep may make
/// more tets partial: iterated to a fixed point.
std::unordered_set<int> markPartialTets(const TetMesh& mesh, const IntersectedEdges& crossed,
                                        TouchedTets& touched) {
    const std::unordered_set<int> onSweep(crossed.onSweepNodes.begin(), crossed.onSweepNodes.end());
    std::unordered_set<int> ineligible;
    for (bool changed = true; changed;) {
        changed = false;
        for (std::size_t k = 0; k < touched.tets.size(); ++k) {
            if (touched.partial[k])
                continue;
            const Tet& q = mesh.tet(touched.tets[k]);
            std::uint8_t onCut = 0;
            for (int i = 0; i < 4; ++i)
                if (onSweep.count(q[i]) && !ineligible.count(q[i]))
                    onCut |= static_cast<std::uint8_t>(1 << i);
            if (isComplete(touched.crossedMask[k], onCut))
                continue;
            touched.partial[k] = 1;
            for (int v : q)
                if (ineligible.insert(v).second && onSweep.count(v))
                    changed = true;
        }
    }
    return ineligible;
}

/// Cut node -> its distance to the sweep.
using CutNodeDistances = std::unordered_map<int, double>;

/// Rules "a node exactly on the sweep is always a cut node" and "the nearer end within d"
/// (section 4.3): eligible nodes on the sweep first (distance 0), then every crossed edge
/// nominates its nearer end if it is closer than d to the sweep; nominees are accepted
/// nearest first (ties by node index) unless a tet would get a fourth cut node.
CutNodeDistances chooseCutNodes(const TetMesh& mesh, const SweepSurface& sweep,
                                const IntersectedEdges& crossed,
                                const std::unordered_set<int>& ineligible,
                                const SelectOptions& options) {
    CutNodeDistances cutDistance;
    std::unordered_map<int, int> cutCountOfTet;
    const auto accept = [&](int n, double distance) {
        for (int t : mesh.nodeTets(n))
            if (cutCountOfTet[t] >= 3)
                return false;
        for (int t : mesh.nodeTets(n))
            ++cutCountOfTet[t];
        cutDistance[n] = distance;
        return true;
    };
    for (int n : crossed.onSweepNodes)
        if (!ineligible.count(n))
            accept(n, 0.0);
    if (!options.allowCutNodes || !(options.d > 0))
        return cutDistance;
    std::unordered_map<int, double> nominee;
    for (const EdgeCrossing& e : crossed.edges) {
        const int n = e.hit.t <= 0.5 ? e.a : e.b;
        if (ineligible.count(n) || cutDistance.count(n) || nominee.count(n))
            continue;
        const double dist = sweep.closestPoint(mesh.pos(n)).distance;
        if (dist < options.d)
            nominee[n] = dist;
    }
    std::vector<std::pair<double, int>> order;
    for (const auto& [n, dist] : nominee)
        order.push_back({dist, n});
    std::sort(order.begin(), order.end());
    for (const auto& [dist, n] : order)
        accept(n, dist);
    return cutDistance;
}

/// The cut nodes sorted, with their distances and the largest distance.
void listCutNodes(const CutNodeDistances& cutDistance, CutSelection& sel) {
    for (const auto& [n, dist] : cutDistance)
        sel.cutNodes.push_back(n);
    std::sort(sel.cutNodes.begin(), sel.cutNodes.end());
    for (int n : sel.cutNodes) {
        sel.cutNodeDistance.push_back(cutDistance.at(n));
        sel.maxCutNodeDistance = std::max(sel.maxCutNodeDistance, cutDistance.at(n));
    }
}

/// Cut edges: the crossed edges with no cut node at either end (section 4.3). Rule
/// "minEdgeFraction": a crossing closer than that fraction of the edge to an end node is
/// moved to that fraction, so that no split creates a zero-volume tet.
void listCutEdges(const TetMesh& mesh, const IntersectedEdges& crossed,
                  const CutNodeDistances& cutDistance, double minEdgeFraction, CutSelection& sel) {
    const double lo = minEdgeFraction, hi = 1.0 - minEdgeFraction;
    for (const EdgeCrossing& e : crossed.edges) {
        if (cutDistance.count(e.a) || cutDistance.count(e.b))
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
                 const TouchedTets& touched, const CutNodeDistances& cutDistance,
                 const CutSelection& sel, int t, TetCut& tc) {
    const Tet& q = mesh.tet(t);
    tc = TetCut{};
    tc.tet = t;
    for (int i = 0; i < 4; ++i)
        if (cutDistance.count(q[i]))
            tc.nodeCode |= static_cast<std::uint8_t>(1 << i);
    for (int e = 0; e < 6; ++e)
        if (sel.cutEdgeIndex.count(edgeKey(q[kTetEdges[e][0]], q[kTetEdges[e][1]])))
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
    // The rules of select_cut_nodes.h, in order: partial tets first (their nodes are never cut
    // nodes), then cut nodes, then cut edges, then the codes and sides of every affected tet.
    TouchedTets touched = gatherTouchedTets(mesh, crossed);
    const std::unordered_set<int> ineligible = markPartialTets(mesh, crossed, touched);
    const CutNodeDistances cutDistance = chooseCutNodes(mesh, sweep, crossed, ineligible, options);
    CutSelection sel;
    listCutNodes(cutDistance, sel);
    listCutEdges(mesh, crossed, cutDistance, options.minEdgeFraction, sel);
    for (int t : affectedTets(mesh, touched, sel.cutNodes)) {
        TetCut tc;
        if (classifyTet(mesh, sweep, crossed, touched, cutDistance, sel, t, tc))
            sel.tets.push_back(tc);
    }
    return sel;
}

} // namespace resect
