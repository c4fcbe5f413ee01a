#pragma once
// The `fixed` effect: anchored nodes that do not move (anchors.h: a list of nodes and/or the
// nodes whose reference position lies in a box, followed through cuts). Their forces (and the
// implicit solver's vectors) are zeroed, and after every step their positions are reset to the
// anchors and their velocities to zero, so that no other effect (a tool pushing them, say)
// moves them either: this effect runs last (phase kConstraints).

#include "core/sim/anchors.h"
#include "core/sim/effect.h"

#include <vector>

namespace resect {

class FixedNodesEffect : public Effect {
public:
    /// Anchors at the nodes' current positions.
    explicit FixedNodesEffect(const TetMesh& mesh, Anchors anchors);

    std::string name() const override { return "fixed"; }
    int phase() const override { return kConstraints; }
    void constrain(std::span<Vec3> perNode) const override;
    bool afterStep(const SimState& s) override;
    void applyCut(const TetMesh& mesh, const CutChanges& changes) override;

    /// Sorted anchored nodes.
    const std::vector<int>& nodes() const { return m_anchors.nodes(); }
    const Anchors& anchors() const { return m_anchors; }

private:
    Anchors m_anchors;
    std::vector<Vec3> m_positions; ///< per entry of m_anchors.nodes()
};

} // namespace resect
