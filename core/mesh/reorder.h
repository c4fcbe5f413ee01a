#pragma once
// Node and tet order for memory locality. An explicit step reads, for every tet and edge, the
// positions of its nodes and scatters forces back to them: when neighbouring tets have nodes
// that are near in memory, those reads hit the cache. The mesher's output is ordered by
// insertion during Delaunay refinement, close to random in space: on a 1M-tet box numbered at
// random, a step costs 2-3 times what it costs in the box's own order (resect bench sim --shuffle).
//
// reorderForLocality() numbers the nodes along a Z-order (Morton) curve through the reference
// positions and the tets by their centroids along the same curve. The mesh stays the same mesh
// (same tets as node sets, same orientation, same positions); only indices change.

#include "core/mesh/tet_mesh.h"

#include <vector>

namespace resect {

/// What reorderForLocality did: newNode[old] and newTet[old].
struct Reordering {
    std::vector<int> newNode, newTet;
};

/// Renumbers nodes and tets along a Z-order curve (reference positions). Node arrays
/// (positions, velocities, masses) move with their nodes. O(n log n).
Reordering reorderForLocality(TetMesh& mesh);

/// Mean over tets of the largest difference between two of its node indices, over the node
/// count: small when tets use nodes near each other in memory (about 1/3 for a random order).
double nodeIndexSpread(const TetMesh& mesh);

} // namespace resect
