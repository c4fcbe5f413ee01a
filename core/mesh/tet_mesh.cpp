#include "core/mesh/tet_mesh.h"

#include "core/mesh/tet_mesh_backup.h"

#include <Eigen/Geometry>

#include <algorithm>
#include <cassert>
#include <string>

namespace resect {

TetMesh TetMesh::fromArrays(std::vector<Vec3> referencePositions, std::vector<Tet> tets) {
    TetMesh mesh;
    const std::size_t n = referencePositions.size();
    mesh.m_pos = referencePositions;
    mesh.m_ref = std::move(referencePositions);
    mesh.m_vel.assign(n, Vec3::Zero());
    mesh.m_mass.assign(n, 0.0);
    mesh.m_nodeTets.resize(n);
    mesh.m_tets = std::move(tets);
    // Count first so every adjacency list is allocated once.
    std::vector<int> valence(n, 0);
    for (const Tet& t : mesh.m_tets)
        for (int v : t)
            ++valence[v];
    for (std::size_t i = 0; i < n; ++i)
        mesh.m_nodeTets[i].reserve(valence[i]);
    for (int t = 0; t < mesh.tetCount(); ++t)
        mesh.attach(t);
    return mesh;
}

int TetMesh::addNode(const Vec3& referencePosition, const Vec3& currentPosition) {
    m_ref.push_back(referencePosition);
    m_pos.push_back(currentPosition);
    m_vel.push_back(Vec3::Zero());
    m_mass.push_back(0.0);
    m_nodeTets.emplace_back();
    return nodeCount() - 1;
}

int TetMesh::addTet(const Tet& t) {
    willChangeNodesOf(t);
    m_tets.push_back(t);
    attach(tetCount() - 1);
    return tetCount() - 1;
}

void TetMesh::replaceTet(int t, const Tet& nodes) {
    willChangeTet(t);
    willChangeNodesOf(m_tets[t]);
    willChangeNodesOf(nodes);
    detach(t);
    m_tets[t] = nodes;
    attach(t);
}

void TetMesh::removeTet(int t) {
    const int last = tetCount() - 1;
    willChangeTet(t);
    willChangeTet(last);
    willChangeNodesOf(m_tets[t]);
    willChangeNodesOf(m_tets[last]);
    detach(t);
    if (t != last) {
        detach(last);
        m_tets[t] = m_tets[last];
        attach(t);
    }
    m_tets.pop_back();
}

void TetMesh::removeNode(int n) {
    assert(m_nodeTets[n].empty());
    const int last = nodeCount() - 1;
    willChangeNode(n);
    willChangeNode(last);
    if (n != last) {
        for (int t : m_nodeTets[last]) {
            willChangeTet(t);
            willChangeNodesOf(m_tets[t]);
            for (int& v : m_tets[t])
                if (v == last)
                    v = n;
        }
        m_ref[n] = m_ref[last];
        m_pos[n] = m_pos[last];
        m_vel[n] = m_vel[last];
        m_mass[n] = m_mass[last];
        m_nodeTets[n] = std::move(m_nodeTets[last]);
    }
    m_ref.pop_back();
    m_pos.pop_back();
    m_vel.pop_back();
    m_mass.pop_back();
    m_nodeTets.pop_back();
}

void TetMesh::reserve(int nodes, int tets) {
    m_ref.reserve(nodes);
    m_pos.reserve(nodes);
    m_vel.reserve(nodes);
    m_mass.reserve(nodes);
    m_nodeTets.reserve(nodes);
    m_tets.reserve(tets);
}

void TetMesh::truncate(int nodes, int tets) {
    for (int t = tetCount() - 1; t >= tets; --t) {
        willChangeNodesOf(m_tets[t]);
        detach(t);
    }
    m_tets.resize(std::min<std::size_t>(m_tets.size(), tets));
    const std::size_t n = std::min<std::size_t>(m_ref.size(), nodes);
    for (std::size_t i = n; i < m_nodeTets.size(); ++i)
        assert(m_nodeTets[i].empty());
    m_ref.resize(n);
    m_pos.resize(n);
    m_vel.resize(n);
    m_mass.resize(n);
    m_nodeTets.resize(n);
}

void TetMesh::setNodePosition(int n, const Vec3& referencePosition, const Vec3& currentPosition) {
    willChangeNode(n);
    m_ref[n] = referencePosition;
    m_pos[n] = currentPosition;
}

void TetMesh::setMass(int n, double mass) {
    willChangeNode(n);
    m_mass[n] = mass;
}

void TetMesh::willChangeTet(int t) {
    for (TetMeshBackup* b : m_backups.open)
        b->saveTet(t);
}

void TetMesh::willChangeNode(int n) {
    for (TetMeshBackup* b : m_backups.open)
        b->saveNode(n);
}

void TetMesh::willChangeNodesOf(const Tet& t) {
    if (m_backups.open.empty())
        return;
    for (int v : t)
        willChangeNode(v);
}

void TetMesh::attach(int t) {
    for (int v : m_tets[t]) {
        assert(v >= 0 && v < nodeCount());
        m_nodeTets[v].push_back(t);
    }
}

void TetMesh::detach(int t) {
    for (int v : m_tets[t]) {
        auto& list = m_nodeTets[v];
        auto it = std::find(list.begin(), list.end(), t);
        assert(it != list.end());
        *it = list.back();
        list.pop_back();
    }
}

void TetMesh::edgeTets(int a, int b, std::vector<int>& out) const {
    out.clear();
    for (int t : m_nodeTets[a]) {
        const Tet& q = m_tets[t];
        if (std::find(q.begin(), q.end(), b) != q.end())
            out.push_back(t);
    }
}

void TetMesh::faceTets(int a, int b, int c, std::vector<int>& out) const {
    out.clear();
    for (int t : m_nodeTets[a]) {
        const Tet& q = m_tets[t];
        if (std::find(q.begin(), q.end(), b) != q.end() &&
            std::find(q.begin(), q.end(), c) != q.end())
            out.push_back(t);
    }
}

std::vector<int> TetMesh::nodeNeighbours(int n) const {
    std::vector<int> result;
    result.reserve(m_nodeTets[n].size() * 3);
    for (int t : m_nodeTets[n])
        for (int v : m_tets[t])
            if (v != n)
                result.push_back(v);
    std::sort(result.begin(), result.end());
    result.erase(std::unique(result.begin(), result.end()), result.end());
    return result;
}

double signedVolume(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d) {
    return (b - a).dot((c - a).cross(d - a)) / 6.0;
}

std::array<double, 4> barycentric(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d, const Vec3& p) {
    const Vec3 ab = b - a, ac = c - a, ad = d - a, ap = p - a;
    const double v = ab.dot(ac.cross(ad));
    const double w1 = ap.dot(ac.cross(ad)) / v;
    const double w2 = ab.dot(ap.cross(ad)) / v;
    const double w3 = ab.dot(ac.cross(ap)) / v;
    return {1.0 - w1 - w2 - w3, w1, w2, w3};
}

double TetMesh::referenceVolume(int t) const {
    const Tet& q = m_tets[t];
    return signedVolume(m_ref[q[0]], m_ref[q[1]], m_ref[q[2]], m_ref[q[3]]);
}

double TetMesh::currentVolume(int t) const {
    const Tet& q = m_tets[t];
    return signedVolume(m_pos[q[0]], m_pos[q[1]], m_pos[q[2]], m_pos[q[3]]);
}

double TetMesh::totalReferenceVolume() const {
    double sum = 0.0;
    for (int t = 0; t < tetCount(); ++t)
        sum += referenceVolume(t);
    return sum;
}

std::string checkTetIndices(int nodeCount, std::span<const Tet> tets) {
    for (std::size_t t = 0; t < tets.size(); ++t) {
        const Tet& q = tets[t];
        for (int i = 0; i < 4; ++i) {
            if (q[i] < 0 || q[i] >= nodeCount)
                return "tet " + std::to_string(t) + " refers to node " + std::to_string(q[i]) +
                       ", but there are only " + std::to_string(nodeCount) + " nodes";
            for (int j = 0; j < i; ++j)
                if (q[i] == q[j])
                    return "tet " + std::to_string(t) + " uses node " + std::to_string(q[i]) +
                           " twice";
        }
    }
    return {};
}

} // namespace resect
