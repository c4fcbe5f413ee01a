#pragma once
// Anchors: the nodes of a tissue held in place (the scene's fixed regions), followed through
// cuts. A node is anchored if it is listed, or if its reference position lies in the box
// (bounds included); after a cut, the copies of anchored nodes and every new node whose
// reference position is in the box are anchored too. One implementation of that rule, used by
// the tissue (to tell anchored pieces from resected ones) and by the `fixed` effect (to hold
// the nodes during simulation).

#include "core/cut/cut_types.h"
#include "core/mesh/renumbering.h"
#include "core/status.h"

#include <array>
#include <optional>
#include <vector>

namespace resect {

struct FixedSelection {
    std::vector<int> nodes;                 ///< anchored nodes
    std::optional<std::array<Vec3, 2>> box; ///< (lo, hi), reference coordinates (mm)
    bool empty() const { return nodes.empty() && !box; }
};

class Anchors {
public:
    Anchors() = default;
    /// The listed nodes and the nodes in the box. Errors: a node index outside the mesh, a
    /// box that is not finite or has lo > hi.
    static Status create(const TetMesh& mesh, const FixedSelection& selection, Anchors& out);

    /// Sorted, without duplicates.
    const std::vector<int>& nodes() const { return m_nodes; }
    bool contains(int node) const;
    bool empty() const { return m_nodes.empty(); }
    /// The box new nodes are tested against (if any).
    const std::optional<std::array<Vec3, 2>>& box() const { return m_box; }
    /// The selection that re-creates these anchors on the same mesh (the node list and box).
    FixedSelection selection() const { return {m_nodes, m_box}; }

    /// After a cut: anchors the copies of anchored nodes and the new nodes in the box. Returns
    /// the nodes added (increasing; all >= changes.firstNewNode, so the list stays sorted by
    /// appending). O(new nodes).
    std::vector<int> applyCut(const TetMesh& mesh, const CutChanges& changes);

    /// After a local remeshing (core/mesh/renumbering.h): anchored nodes that changed index
    /// follow it (a node merged into another anchors that one), removed ones leave, and the
    /// `moved` nodes (new indices) now in the box are anchored. O(anchors + changes), not
    /// O(mesh).
    void renumber(const TetMesh& mesh, const SparseRenumbering& nodes, const std::vector<int>& moved);

private:
    bool inBox(const Vec3& p) const;

    std::vector<int> m_nodes;
    std::optional<std::array<Vec3, 2>> m_box;
};

} // namespace resect
