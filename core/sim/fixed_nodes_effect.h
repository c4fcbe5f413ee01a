#pragma once
// The `fixed` effect: anchored nodes that do not move. Chosen either as a list of nodes or as
// the nodes whose reference position lies in an axis-aligned box (bounds included). Their
// forces (and the implicit solver's vectors) are zeroed, and after every step their positions
// are reset to the anchors and their velocities to zero, so that no other effect (a tool
// pushing them, say) moves them either: this effect runs last (phase kConstraints).
// After a cut, copies of anchored nodes are anchored too, and in box mode every new node whose
// reference position is in the box.

#include "core/sim/effect.h"

#include <optional>
#include <vector>

namespace resect {

struct FixedSelection {
    std::vector<int> nodes;                 ///< anchored nodes (used when box is not set)
    std::optional<std::array<Vec3, 2>> box; ///< (lo, hi), in reference coordinates
};

class FixedNodesEffect : public Effect {
public:
    /// Anchors at the nodes' current positions. Node indices must be valid.
    FixedNodesEffect(const TetMesh& mesh, FixedSelection selection);

    std::string name() const override { return "fixed"; }
    int phase() const override { return kConstraints; }
    void constrain(std::span<Vec3> perNode) const override;
    bool afterStep(const SimState& s) override;
    void applyCut(const TetMesh& mesh, const CutChanges& changes) override;

    /// Sorted anchored nodes.
    const std::vector<int>& nodes() const { return m_nodes; }

private:
    bool inBox(const Vec3& p) const;
    void anchor(const TetMesh& mesh, int node);

    FixedSelection m_selection;
    std::vector<int> m_nodes;    ///< sorted
    std::vector<Vec3> m_anchors; ///< per entry of m_nodes
};

} // namespace resect
