#include "core/sim/fixed_nodes_effect.h"

#include <algorithm>

namespace resect {

FixedNodesEffect::FixedNodesEffect(const TetMesh& mesh, FixedSelection selection)
    : m_selection(std::move(selection)) {
    if (m_selection.box) {
        for (int n = 0; n < mesh.nodeCount(); ++n)
            if (inBox(mesh.ref(n)))
                m_nodes.push_back(n);
    } else {
        m_nodes = m_selection.nodes;
        std::sort(m_nodes.begin(), m_nodes.end());
        m_nodes.erase(std::unique(m_nodes.begin(), m_nodes.end()), m_nodes.end());
    }
    m_anchors.reserve(m_nodes.size());
    for (int n : m_nodes)
        m_anchors.push_back(mesh.pos(n));
}

bool FixedNodesEffect::inBox(const Vec3& p) const {
    const auto& [lo, hi] = *m_selection.box;
    return (p.array() >= lo.array()).all() && (p.array() <= hi.array()).all();
}

void FixedNodesEffect::constrain(std::span<Vec3> perNode) const {
    for (int n : m_nodes)
        perNode[n].setZero();
}

bool FixedNodesEffect::afterStep(const SimState& s) {
    bool moved = false;
    for (std::size_t i = 0; i < m_nodes.size(); ++i) {
        const int n = m_nodes[i];
        moved = moved || s.x[n] != m_anchors[i];
        s.x[n] = m_anchors[i];
        s.v[n].setZero();
    }
    return moved;
}

void FixedNodesEffect::anchor(const TetMesh& mesh, int node) {
    const auto it = std::lower_bound(m_nodes.begin(), m_nodes.end(), node);
    if (it != m_nodes.end() && *it == node)
        return;
    const auto i = it - m_nodes.begin();
    m_nodes.insert(it, node);
    m_anchors.insert(m_anchors.begin() + i, mesh.pos(node));
}

void FixedNodesEffect::applyCut(const TetMesh& mesh, const CutChanges& changes) {
    // New nodes are appended, so inserting them keeps the list sorted at O(1) each; copies of
    // anchored originals and in-box new nodes are the only candidates.
    for (const auto& [orig, copy] : changes.duplicatedNodes)
        if (std::binary_search(m_nodes.begin(), m_nodes.end(), orig))
            anchor(mesh, copy);
    if (m_selection.box)
        for (int n = changes.firstNewNode; n < mesh.nodeCount(); ++n)
            if (inBox(mesh.ref(n)))
                anchor(mesh, n);
}

} // namespace resect
