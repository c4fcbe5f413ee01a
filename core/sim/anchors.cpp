#include "core/sim/anchors.h"

#include <algorithm>
#include <cmath>
#include <string>

namespace resect {

Status Anchors::create(const TetMesh& mesh, const FixedSelection& selection, Anchors& out) {
    Anchors a;
    for (int n : selection.nodes)
        if (n < 0 || n >= mesh.nodeCount())
            return Status::error("anchored node " + std::to_string(n) + " is not in the mesh (" +
                                 std::to_string(mesh.nodeCount()) + " nodes)");
    if (selection.box) {
        const auto& [lo, hi] = *selection.box;
        if (!lo.allFinite() || !hi.allFinite() || (lo.array() > hi.array()).any())
            return Status::error("the anchor box must be finite with lo <= hi");
        a.m_box = selection.box;
    }
    a.m_nodes = selection.nodes;
    if (a.m_box)
        for (int n = 0; n < mesh.nodeCount(); ++n)
            if (a.inBox(mesh.ref(n)))
                a.m_nodes.push_back(n);
    std::sort(a.m_nodes.begin(), a.m_nodes.end());
    a.m_nodes.erase(std::unique(a.m_nodes.begin(), a.m_nodes.end()), a.m_nodes.end());
    out = std::move(a);
    return Status::success();
}

bool Anchors::contains(int node) const { return std::binary_search(m_nodes.begin(), m_nodes.end(), node); }

bool Anchors::inBox(const Vec3& p) const {
    const auto& [lo, hi] = *m_box;
    return (p.array() >= lo.array()).all() && (p.array() <= hi.array()).all();
}

std::vector<int> Anchors::applyCut(const TetMesh& mesh, const CutChanges& changes) {
    std::vector<int> added;
    for (const auto& [orig, copy] : changes.duplicatedNodes)
        if (contains(orig))
            added.push_back(copy);
    if (m_box)
        for (int n = changes.firstNewNode; n < mesh.nodeCount(); ++n)
            if (inBox(mesh.ref(n)))
                added.push_back(n);
    std::sort(added.begin(), added.end());
    added.erase(std::unique(added.begin(), added.end()), added.end());
    // New nodes are appended to the mesh, so they sort after every node anchored before;
    // a copy listed twice (or already anchored) is skipped.
    added.erase(std::remove_if(added.begin(), added.end(),
                               [&](int n) { return !m_nodes.empty() && n <= m_nodes.back(); }),
                added.end());
    m_nodes.insert(m_nodes.end(), added.begin(), added.end());
    return added;
}

void Anchors::renumber(const TetMesh& mesh, const SparseRenumbering& nodes, const std::vector<int>& moved) {
    std::vector<int> gone, added;
    for (const auto& [old, now] : nodes.changed)
        if (contains(old)) {
            gone.push_back(old);
            if (now >= 0)
                added.push_back(now);
        }
    if (m_box)
        for (int n : moved)
            if (inBox(mesh.ref(n)))
                added.push_back(n);
    if (gone.empty() && added.empty())
        return;
    std::sort(gone.begin(), gone.end());
    m_nodes.erase(std::remove_if(m_nodes.begin(), m_nodes.end(),
                                 [&](int n) { return std::binary_search(gone.begin(), gone.end(), n); }),
                  m_nodes.end());
    std::sort(added.begin(), added.end());
    const auto middle = static_cast<std::ptrdiff_t>(m_nodes.size());
    m_nodes.insert(m_nodes.end(), added.begin(), added.end());
    std::inplace_merge(m_nodes.begin(), m_nodes.begin() + middle, m_nodes.end());
    m_nodes.erase(std::unique(m_nodes.begin(), m_nodes.end()), m_nodes.end());
}

} // namespace resect
