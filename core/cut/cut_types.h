#pragma once
// Data passed between the steps of a cut (section 4.1 of the paper), and the change list a
// cut reports so that the embedded surface, the simulation and the renderer update only
// what changed.

#include "core/mesh/tet_mesh.h"
#include "core/sweep/intersect_segment.h"

#include <cstdint>
#include <unordered_map>
#include <utility>
#include <vector>

namespace resect {

/// Key of the undirected edge (a, b).
inline std::uint64_t edgeKey(int a, int b) {
    if (a > b)
        std::swap(a, b);
    return (static_cast<std::uint64_t>(static_cast<std::uint32_t>(a)) << 32) |
           static_cast<std::uint32_t>(b);
}

/// A mesh edge crossed by the sweep. a < b; the hit is relative to the direction a -> b.
struct EdgeCrossing {
    int a = -1;
    int b = -1;
    SegmentHit hit;
};

/// Step 2: the edges the sweep crosses (section 4.3).
struct IntersectedEdges {
    std::vector<EdgeCrossing> edges;             ///< crossed exactly once
    std::unordered_map<std::uint64_t, int> index;  ///< edge key -> position in `edges`
    std::vector<int> onSweepNodes;               ///< nodes lying exactly on the sweep
    std::vector<int> candidateTets;              ///< tets examined
    int discardedEdges = 0;        ///< crossed an even number of times: discarded
    int multiplyCrossedEdges = 0;  ///< crossed 3, 5, ... times: split at the middle crossing
};

/// Decomposition scheme of one tet (Figure 4). A-E have cut edges only: A (3 edges around a
/// node) and B (4 edges, two and two) are complete cuts; C (1 edge), D (2 edges) and E (3 or
/// more edges in no complete pattern) are partial cuts, where the sweep's border lies
/// inside the tet. X (1 cut node, 2 cut edges), Y (2 cut nodes, 1 cut edge) and Z (3 cut
/// nodes, only detached) are the paper's hybrid schemes. Touch: 1 or 2 cut nodes and no cut
/// edge (the cut passes through the tet's corner or edge; the tet is only re-attached).
enum class Scheme : std::uint8_t { None, A, B, C, D, E, X, Y, Z, Touch };
const char* schemeName(Scheme s);

/// Per-tet classification (step 3).
struct TetCut {
    int tet = -1;
    std::uint8_t edgeCode = 0;  ///< bit e set: local edge e (kTetEdges) is a cut edge
    std::uint8_t nodeCode = 0;  ///< bit i set: local node i is a cut node
    Scheme scheme = Scheme::None;
    bool partial = false;
    std::array<std::int8_t, 4> side{};  ///< side of each local node: +1, -1, 0 for cut nodes
};

/// Step 3: cut nodes, cut edges and the affected tets.
struct CutSelection {
    std::vector<int> cutNodes;
    std::vector<double> cutNodeDistance;  ///< distance of each cut node to the sweep
    std::vector<EdgeCrossing> cutEdges;
    std::unordered_map<std::uint64_t, int> cutEdgeIndex;  ///< edge key -> position in cutEdges
    std::vector<TetCut> tets;             ///< affected tets (cut edges or cut nodes)
    double maxCutNodeDistance = 0;
};

/// What a cut changed, for incremental updates downstream.
struct CutChanges {
    int firstNewNode = 0;   ///< nodes >= this were created by the cut
    int firstNewTet = 0;    ///< tets >= this were created by the cut
    std::vector<int> modifiedTets;                ///< existing tets whose nodes changed
    std::vector<int> parentOfNewTet;              ///< for tet firstNewTet + i: its original tet
    std::vector<std::array<int, 2>> duplicatedNodes;  ///< (original, copy) from separation
    std::vector<int> cutNodes;                    ///< original cut nodes (before duplication)
    /// Every node on the sweep: cut nodes and split points (both copies), and the interior
    /// points placed on the sweep in partially cut tets.
    std::vector<int> cutSurfaceNodes;
    /// Side of the cut of every tet the cut decomposed or re-attached (+1 / -1; 0 for pieces
    /// of partially cut tets, which lie on both sides), for re-binding the embedded surface.
    std::unordered_map<int, std::int8_t> tetSide;
    /// All nodes whose incident tets changed (masses and stiffnesses need updating).
    std::vector<int> touchedNodes;
    /// Scheme (Figure 4) of every original tet the cut classified, as (tet, scheme) sorted by
    /// tet. A tet created by the cut was produced by the scheme of its parent
    /// (parentOfNewTet); for inspection and overlays.
    std::vector<std::pair<int, Scheme>> tetScheme;
    /// The scheme of original tet t, or Scheme::None if the cut did not classify it.
    Scheme schemeOf(int t) const;
};

} // namespace resect
