#include "core/sim/fixed_nodes_effect.h"

namespace resect {

FixedNodesEffect::FixedNodesEffect(const TetMesh& mesh, Anchors anchors) : m_anchors(std::move(anchors)) {
    m_positions.reserve(m_anchors.nodes().size());
    for (int n : m_anchors.nodes())
        m_positions.push_back(mesh.pos(n));
}

void FixedNodesEffect::constrain(std::span<Vec3> perNode) const {
    for (int n : m_anchors.nodes())
        perNode[n].setZero();
}

bool FixedNodesEffect::afterStep(const SimState& s) {
    bool moved = false;
    const std::vector<int>& nodes = m_anchors.nodes();
    for (std::size_t i = 0; i < nodes.size(); ++i) {
        const int n = nodes[i];
        moved = moved || s.x[n] != m_positions[i];
        s.x[n] = m_positions[i];
        s.v[n].setZero();
    }
    return moved;
}

void FixedNodesEffect::applyCut(const TetMesh& mesh, const CutChanges& changes) {
    // Added nodes are appended to the sorted list (anchors.h), so their positions are too.
    for (int n : m_anchors.applyCut(mesh, changes))
        m_positions.push_back(mesh.pos(n));
}

} // namespace resect
