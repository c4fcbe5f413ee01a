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
    CutSelection sel;
    const auto crossedIndex = [&](int a, int b) {
        auto it = crossed.index.find(edgeKey(a, b));
        return it == crossed.index.end() ? -1 : it->second;
    };

    // Tets touched by the sweep: on a crossed edge or at a node on the sweep.
    std::vector<int> touched, scratch;
    for (const EdgeCrossing& e : crossed.edges) {
        mesh.edgeTets(e.a, e.b, scratch);
        touched.insert(touched.end(), scratch.begin(), scratch.end());
    }
    for (int n : crossed.onSweepNodes)
        touched.insert(touched.end(), mesh.nodeTets(n).begin(), mesh.nodeTets(n).end());
    std::sort(touched.begin(), touched.end());
    touched.erase(std::unique(touched.begin(), touched.end()), touched.end());

    std::vector<std::uint8_t> crossedMask(touched.size(), 0);
    for (std::size_t k = 0; k < touched.size(); ++k) {
        const Tet& q = mesh.tet(touched[k]);
        for (int e = 0; e < 6; ++e)
            if (crossedIndex(q[kTetEdges[e][0]], q[kTetEdges[e][1]]) >= 0)
                crossedMask[k] |= static_cast<std::uint8_t>(1 << e);
    }

    // Eligibility fixed point: nodes of partial tets can never be cut nodes.
    std::unordered_set<int> onSweep(crossed.onSweepNodes.begin(), crossed.onSweepNodes.end());
    std::unordered_set<int> ineligible;
    std::vector<char> partial(touched.size(), 0);
    for (bool changed = true; changed;) {
        changed = false;
        for (std::size_t k = 0; k < touched.size(); ++k) {
            if (partial[k])
                continue;
            const Tet& q = mesh.tet(touched[k]);
            std::uint8_t onCut = 0;
            for (int i = 0; i < 4; ++i)
                if (onSweep.count(q[i]) && !ineligible.count(q[i]))
                    onCut |= static_cast<std::uint8_t>(1 << i);
            if (isComplete(crossedMask[k], onCut))
                continue;
            partial[k] = 1;
            for (int v : q)
                if (ineligible.insert(v).second && onSweep.count(v))
                    changed = true;
        }
    }

    // Cut nodes: eligible nodes on the sweep, then nominees by distance (nearest first).
    std::unordered_map<int, double> cutDistance;
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
    if (options.allowCutNodes && options.d > 0) {
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
    }
    for (const auto& [n, dist] : cutDistance) {
        sel.cutNodes.push_back(n);
    }
    std::sort(sel.cutNodes.begin(), sel.cutNodes.end());
    for (int n : sel.cutNodes) {
        sel.cutNodeDistance.push_back(cutDistance[n]);
        sel.maxCutNodeDistance = std::max(sel.maxCutNodeDistance, cutDistance[n]);
    }

    // Cut edges: crossed edges away from cut nodes; crossings moved off the end nodes.
    const double lo = options.minEdgeFraction, hi = 1.0 - options.minEdgeFraction;
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

    // Affected tets: touched ones with cut edges or partial, and every tet at a cut node.
    std::unordered_map<int, int> touchedPos;
    for (std::size_t k = 0; k < touched.size(); ++k)
        touchedPos.emplace(touched[k], static_cast<int>(k));
    std::vector<int> affected;
    for (std::size_t k = 0; k < touched.size(); ++k)
        affected.push_back(touched[k]);
    for (int n : sel.cutNodes)
        affected.insert(affected.end(), mesh.nodeTets(n).begin(), mesh.nodeTets(n).end());
    std::sort(affected.begin(), affected.end());
    affected.erase(std::unique(affected.begin(), affected.end()), affected.end());

    // Side of a node: from a crossing on one of its edges, else from the nearest triangle.
    const auto nodeSide = [&](int n, const Tet& q) -> int {
        for (int m : q) {
            if (m == n)
                continue;
            const int ci = crossedIndex(n, m);
            if (ci >= 0) {
                const EdgeCrossing& e = crossed.edges[ci];
                return e.a == n ? e.hit.sideP : -e.hit.sideP;
            }
        }
        const int s = sweep.sideOf(mesh.pos(n));
        return s == 0 ? 1 : s;
    };

    for (int t : affected) {
        const Tet& q = mesh.tet(t);
        TetCut tc;
        tc.tet = t;
        for (int i = 0; i < 4; ++i)
            if (cutDistance.count(q[i]))
                tc.nodeCode |= static_cast<std::uint8_t>(1 << i);
        for (int e = 0; e < 6; ++e)
            if (sel.cutEdgeIndex.count(edgeKey(q[kTetEdges[e][0]], q[kTetEdges[e][1]])))
                tc.edgeCode |= static_cast<std::uint8_t>(1 << e);
        auto tp = touchedPos.find(t);
        tc.partial = tp != touchedPos.end() && partial[tp->second];
        const int cutNodes = __builtin_popcount(tc.nodeCode);
        const int cutEdges = __builtin_popcount(tc.edgeCode);
        if (!tc.partial && cutEdges == 0 && cutNodes == 0)
            continue;  // touched only at a node that could not be a cut node
        tc.scheme = classify(cutNodes, cutEdges, tc.partial);

        // Sides. Complete tets: the groups of non-cut nodes get opposite sides, taken from a
        // cut edge's crossing where there is one.
        const std::uint8_t rest = static_cast<std::uint8_t>(~tc.nodeCode & 0xF);
        std::array<int, 4> group;
        groupNodes(rest, tc.edgeCode, group);
        int side0 = 0;  // side of group 0
        for (int e = 0; e < 6 && side0 == 0; ++e) {
            if (!(tc.edgeCode >> e & 1))
                continue;
            const int i = kTetEdges[e][0];
            const EdgeCrossing& c = sel.cutEdges[sel.cutEdgeIndex.at(edgeKey(q[i], q[kTetEdges[e][1]]))];
            const int si = c.a == q[i] ? c.hit.sideP : -c.hit.sideP;
            side0 = group[i] == 0 ? si : -si;
        }
        for (int i = 0; i < 4; ++i) {
            if (tc.nodeCode >> i & 1) {
                tc.side[i] = 0;
            } else if (tc.partial) {
                tc.side[i] = static_cast<std::int8_t>(nodeSide(q[i], q));
            } else {
                if (side0 == 0)
                    side0 = group[i] == 0 ? nodeSide(q[i], q) : -nodeSide(q[i], q);
                tc.side[i] = static_cast<std::int8_t>(group[i] == 0 ? side0 : -side0);
            }
        }
        sel.tets.push_back(tc);
    }
    return sel;
}

} // namespace resect
