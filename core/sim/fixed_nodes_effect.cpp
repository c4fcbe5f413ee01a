#include "core/sim/fixed_nodes_effect.h"

#include <algorithm>

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
    // Anchored nodes the change moved (the improvement moves them within the anchored box,
    // ImproveOptions::moveAnchored) are held where they are now, not pulled back.
    const std::vector<int>& nodes = m_anchors.nodes();
    for (int n : changes.touchedNodes)
        if (const auto it = std::lower_bound(nodes.begin(), nodes.end(), n); it != nodes.end() && *it == n)
            m_positions[static_cast<std::size_t>(it - nodes.begin())] = mesh.pos(n);
}

} // namespace resect
