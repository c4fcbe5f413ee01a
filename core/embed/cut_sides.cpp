#include "core/embed/cut_sides.h"

#include <algorithm>

namespace resect {

void CutSides::begin(const TetMesh& mesh, const CutChanges& changes, const SweepSurface& sweep) {
    m_mesh = &mesh;
    m_changes = &changes;
    m_sweep = &sweep;
    for (StampedMarks* m : {&m_tetSides, &m_nodeSides, &m_onCut, &m_pairSlot})
        m->clear();
    for (int n : changes.cutSurfaceNodes)
        m_onCut.set(n, 1);

    // Duplicated-node pairs indexed by node (CSR, pair indices ascending per node).
    int slots = 0;
    for (const auto& pair : changes.duplicatedNodes)
        for (int n : pair)
            if (m_pairSlot.insert(n, slots))
                ++slots;
    m_pairStart.assign(slots + 1, 0);
    for (const auto& pair : changes.duplicatedNodes)
        for (int n : pair)
            ++m_pairStart[m_pairSlot.get(n) + 1];
    for (int s = 0; s < slots; ++s)
        m_pairStart[s + 1] += m_pairStart[s];
    m_pairIndex.resize(m_pairStart.back());
    std::vector<int>& fill = m_pending;
    fill.assign(m_pairStart.begin(), m_pairStart.end() - 1);
    for (int i = 0; i < static_cast<int>(changes.duplicatedNodes.size()); ++i)
        for (int n : changes.duplicatedNodes[i])
            m_pairIndex[fill[m_pairSlot.get(n)]++] = i;
}

int CutSides::nodeSide(int n) {
    if (!m_nodeSides.has(n))
        m_nodeSides.set(n, m_sweep->sideOf(m_mesh->pos(n)));
    return m_nodeSides.get(n);
}

int CutSides::tetSide(int t) {
    if (m_tetSides.has(t))
        return m_tetSides.get(t);
    int side = 0;
    if (auto it = m_changes->tetSide.find(t); it != m_changes->tetSide.end()) {
        side = it->second;
    } else {
        Vec3 centre = Vec3::Zero();
        bool found = false;
        for (int node : m_mesh->tet(t)) {
            if (!m_onCut.has(node)) {
                const int s = nodeSide(node);
                if (s != 0) {
                    side = s;
                    found = true;
                    break;
                }
            }
            centre += m_mesh->pos(node) / 4.0;
        }
        if (!found)
            side = m_sweep->sideOf(centre);
    }
    m_tetSides.set(t, side);
    return side;
}

void CutSides::ring(std::span<const int> tets, std::vector<int>& out) {
    out.clear();
    const TetMesh& mesh = *m_mesh;
    m_ringNode.clear();
    m_ringTet.clear();
    m_ringNodes.clear();
    m_pending.clear();
    const auto addNode = [&](int n, int afterPair) {
        if (!m_ringNode.insert(n))
            return;
        m_ringNodes.push_back(n);
        if (m_pairSlot.has(n)) {
            const int slot = m_pairSlot.get(n);
            for (int k = m_pairStart[slot]; k < m_pairStart[slot + 1]; ++k)
                if (m_pairIndex[k] > afterPair)
                    m_pending.push_back(m_pairIndex[k]);
        }
    };
    for (int t : tets)
        for (int n : mesh.tet(t))
            addNode(n, -1);
    // The pairs in list order, one pass: a pair whose node joined at pair i is read only if it
    // comes after i (as a single pass over the list would).
    int last = -1;
    while (!m_pending.empty()) {
        const auto next = std::min_element(m_pending.begin(), m_pending.end());
        const int i = *next;
        *next = m_pending.back();
        m_pending.pop_back();
        if (i <= last)
            continue;
        last = i;
        for (int n : m_changes->duplicatedNodes[i])
            addNode(n, i);
    }
    for (int n : m_ringNodes)
        for (int t : mesh.nodeTets(n))
            if (m_ringTet.insert(t))
                out.push_back(t);
}

} // namespace resect
