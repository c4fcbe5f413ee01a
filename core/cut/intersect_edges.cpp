#include "core/cut/intersect_edges.h"

#include "core/mesh/edge_key_table.h"
#include "core/mesh/index_marks.h"

#include <algorithm>
#include <numeric>

namespace resect {

IntersectedEdges intersectEdges(const TetMesh& mesh, const TetGrid& grid,
                                const SweepSurface& sweep) {
    IntersectedEdges result;
    // Candidate tets: those in grid cells the sweep triangles pass through (sorted, once each).
    std::vector<int>& candidates = result.candidateTets;
    std::vector<int> scratch;
    if (grid.empty()) {
        candidates.resize(mesh.tetCount());
        std::iota(candidates.begin(), candidates.end(), 0);
    } else {
        // Neighbouring sweep triangles meet mostly the same tets: a mark per tet keeps each once
        // (kept between cuts on this thread: see "Marks" at HybridCutter::cut).
        thread_local IndexMarks<char> seen;
        const auto scope = seen.use(mesh.tetCount());
        const auto& V = sweep.vertices();
        for (int t = 0; t < static_cast<int>(sweep.triangles().size()); ++t) {
            if (sweep.isDegenerate(t))
                continue;
            const Tri& q = sweep.triangles()[t];
            grid.queryTriangle(V[q[0]], V[q[1]], V[q[2]], scratch);
            for (int tet : scratch)
                if (tet < mesh.tetCount() && !seen[tet]) {
                    seen.set(tet, 1);
                    candidates.push_back(tet);
                }
        }
        std::sort(candidates.begin(), candidates.end());
    }

    // A patch of tets has two or three edges per tet (inner edges are shared by about five).
    EdgeKeyTable tested(3 * candidates.size());
    std::vector<int>& onSweep = result.onSweepNodes;
    SegmentQuery query;
    for (int tet : candidates) {
        const Tet& q = mesh.tet(tet);
        for (const auto& le : kTetEdges) {
            int a = q[le[0]], b = q[le[1]];
            if (a > b)
                std::swap(a, b);
            if (!tested.tryInsert(edgeKey(a, b), 0).second)
                continue;
            intersectSegment(sweep, mesh.pos(a), mesh.pos(b), query, scratch);
            if (query.pOnSweep)
                onSweep.push_back(a);
            if (query.qOnSweep)
                onSweep.push_back(b);
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
    std::sort(onSweep.begin(), onSweep.end());
    onSweep.erase(std::unique(onSweep.begin(), onSweep.end()), onSweep.end());
    return result;
}

} // namespace resect
