#include "core/cut/intersect_edges.h"

#include <algorithm>
#include <numeric>
#include <unordered_set>

namespace resect {

IntersectedEdges intersectEdges(const TetMesh& mesh, const TetGrid& grid,
                                const SweepSurface& sweep) {
    IntersectedEdges result;
    // Candidate tets: those in grid cells the sweep triangles pass through.
    std::vector<int> candidates, scratch;
    if (grid.empty()) {
        candidates.resize(mesh.tetCount());
        std::iota(candidates.begin(), candidates.end(), 0);
    } else {
        std::unordered_set<int> seen;
        const auto& V = sweep.vertices();
        for (int t = 0; t < static_cast<int>(sweep.triangles().size()); ++t) {
            if (sweep.isDegenerate(t))
                continue;
            const Tri& q = sweep.triangles()[t];
            grid.queryTriangle(V[q[0]], V[q[1]], V[q[2]], scratch);
            for (int tet : scratch)
                if (tet < mesh.tetCount() && seen.insert(tet).second)
                    candidates.push_back(tet);
        }
        std::sort(candidates.begin(), candidates.end());
    }
    result.candidateTets = candidates;

    std::unordered_set<std::uint64_t> tested;
    std::unordered_set<int> onSweep;
    SegmentQuery query;
    for (int tet : candidates) {
        const Tet& q = mesh.tet(tet);
        for (const auto& le : kTetEdges) {
            int a = q[le[0]], b = q[le[1]];
            if (a > b)
                std::swap(a, b);
            if (!tested.insert(edgeKey(a, b)).second)
                continue;
            intersectSegment(sweep, mesh.pos(a), mesh.pos(b), query, scratch);
            if (query.pOnSweep)
                onSweep.insert(a);
            if (query.qOnSweep)
                onSweep.insert(b);
            // Crossed twice (or any even number of times): both ends are on the same side,
            // and the crossings are discarded (section 4.3). Crossed an odd number of times
            // (a nearly tangent edge and a folded sweep): the ends are on opposite sides, so
            // the edge is split once, at the middle crossing.
            const std::size_t hits = query.hits.size();
            if (hits % 2 == 1) {
                result.index.emplace(edgeKey(a, b), static_cast<int>(result.edges.size()));
                result.edges.push_back({a, b, query.hits[hits / 2]});
                if (hits > 1)
                    ++result.multiplyCrossedEdges;
            } else if (hits > 0) {
                ++result.discardedEdges;
            }
        }
    }
    result.onSweepNodes.assign(onSweep.begin(), onSweep.end());
    std::sort(result.onSweepNodes.begin(), result.onSweepNodes.end());
    return result;
}

} // namespace resect
