#pragma once
// A renumbering that changes few indices. Removing a tet or node from a TetMesh moves the last
// one into the freed slot (TetMesh::removeTet / removeNode), so a local remeshing that removes
// k elements changes at most 2k indices: followers (the spatial index, the surface binding,
// per-tet and per-node marks) update those and leave the rest alone, in proportion to k and
// not to the mesh.

#include <algorithm>
#include <utility>
#include <vector>

namespace resect {

struct SparseRenumbering {
    /// Only the indices that changed: (old, new), new = -1 for a removed element (for a node
    /// merged into another by an edge collapse: that node's new index); sorted by old index,
    /// each old index once.
    std::vector<std::pair<int, int>> changed;
    int oldCount = 0; ///< elements before
    int newCount = 0; ///< elements after (the survivors are numbered 0 .. newCount - 1)

    bool empty() const { return changed.empty(); }
    /// The new index of `old` (-1 if it was removed; itself if it did not change).
    /// O(log changed).
    int operator()(int old) const {
        const auto it = std::lower_bound(changed.begin(), changed.end(), std::make_pair(old, -2));
        return it != changed.end() && it->first == old ? it->second : old;
    }
};

/// Tets and nodes renumbered by one local remeshing.
struct MeshRenumbering {
    SparseRenumbering tets, nodes;
    bool empty() const { return tets.empty() && nodes.empty(); }
};

} // namespace resect
