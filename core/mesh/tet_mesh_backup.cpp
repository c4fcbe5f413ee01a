#include "core/mesh/tet_mesh_backup.h"

#include <algorithm>
#include <cassert>

namespace resect {

TetMeshBackup::TetMeshBackup(TetMesh& mesh)
    : m_mesh(&mesh), m_nodes(mesh.nodeCount()), m_tets(mesh.tetCount()) {
    mesh.m_backups.open.push_back(this);
}

TetMeshBackup::~TetMeshBackup() {
    if (isOpen())
        restore();
}

void TetMeshBackup::saveTet(int t) {
    if (t < m_tets && m_seenTets.insert(t).second)
        m_savedTets.emplace_back(t, m_mesh->m_tets[t]);
}

void TetMeshBackup::saveNode(int n) {
    if (n >= m_nodes || !m_seenNodes.insert(n).second)
        return;
    const TetMesh& m = *m_mesh;
    m_savedNodes.push_back({n, m.m_ref[n], m.m_pos[n], m.m_vel[n], m.m_mass[n], m.m_nodeTets[n]});
}

void TetMeshBackup::close() {
    auto& open = m_mesh->m_backups.open;
    const auto it = std::find(open.begin(), open.end(), this);
    assert(it != open.end());
    open.erase(it);
    m_mesh = nullptr;
    m_savedTets.clear();
    m_savedNodes.clear();
    m_seenTets.clear();
    m_seenNodes.clear();
}

void TetMeshBackup::restore() {
    if (!isOpen())
        return;
    TetMesh& m = *m_mesh;
    // Backups opened inside this one are undone first (they hold later states).
    while (m.m_backups.open.back() != this)
        m.m_backups.open.back()->restore();
    // Recorded state is written back directly (no attach/detach): each node's adjacency list
    // is restored verbatim, which also drops the entries of appended tets.
    // (Sized first: tets removed from the end since are written back to where they were.)
    m.m_tets.resize(m_tets);
    for (const auto& [t, nodes] : m_savedTets)
        if (t < m_tets)
            m.m_tets[t] = nodes;
    m.m_ref.resize(m_nodes);
    m.m_pos.resize(m_nodes);
    m.m_vel.resize(m_nodes);
    m.m_mass.resize(m_nodes);
    m.m_nodeTets.resize(m_nodes);
    for (NodeRecord& r : m_savedNodes) {
        m.m_ref[r.node] = r.ref;
        m.m_pos[r.node] = r.pos;
        m.m_vel[r.node] = r.vel;
        m.m_mass[r.node] = r.mass;
        m.m_nodeTets[r.node] = std::move(r.tets);
    }
    close();
}

void TetMeshBackup::commit() {
    if (isOpen())
        close();
}

} // namespace resect
