#include "core/sim/deformation_model.h"

#include "core/mesh/topology.h"

#include <algorithm>
#include <numeric>

namespace resect {
namespace {

Tri sortedTri(Tri t) {
    std::sort(t.begin(), t.end());
    return t;
}

bool tetHas(const Tet& q, int v) {
    return q[0] == v || q[1] == v || q[2] == v || q[3] == v;
}

/// CSR offsets of slots sorted by owner: begin[o] .. begin[o+1] are the slots of owner o.
std::vector<int> csrBegin(const std::vector<int>& sortedOwners, int nodeCount) {
    std::vector<int> begin(static_cast<std::size_t>(nodeCount) + 1, 0);
    for (int o : sortedOwners)
        ++begin[static_cast<std::size_t>(o) + 1];
    std::partial_sum(begin.begin(), begin.end(), begin.begin());
    return begin;
}

} // namespace

// --- slot index -------------------------------------------------------------------------

template <class F> void DeformationModel::SlotIndex::forEach(int owner, F&& f) const {
    if (owner + 1 < static_cast<int>(begin.size()))
        for (int s = begin[owner]; s < begin[owner + 1]; ++s)
            f(s);
    if (auto it = extra.find(owner); it != extra.end())
        for (int s : it->second)
            f(s);
}

bool DeformationModel::SlotIndex::inInitialRange(int owner, int slot) const {
    return owner + 1 < static_cast<int>(begin.size()) && slot >= begin[owner] &&
           slot < begin[owner + 1];
}

void DeformationModel::SlotIndex::add(int owner, int slot) {
    if (!inInitialRange(owner, slot))
        extra[owner].push_back(slot);
}

void DeformationModel::SlotIndex::remove(int owner, int slot) {
    if (inInitialRange(owner, slot))
        return;
    auto it = extra.find(owner);
    if (it == extra.end())
        return;
    auto& v = it->second;
    v.erase(std::remove(v.begin(), v.end(), slot), v.end());
    if (v.empty())
        extra.erase(it);
}

// --- building -----------------------------------------------------------------------------

DeformationModel::DeformationModel(const TetMesh& mesh, const Material& material,
                                   const DeformationTerms& terms)
    : m_material(material), m_terms(terms) {
    const int nodes = mesh.nodeCount();
    if (terms.distance) {
        m_edges = uniqueEdges(mesh); // sorted by (a, b): grouped by smallest node
        m_edgeRest.resize(m_edges.size());
        m_edgeK.resize(m_edges.size());
        std::vector<int> owners(m_edges.size());
        for (std::size_t s = 0; s < m_edges.size(); ++s) {
            owners[s] = m_edges[s][0];
            setEdge(mesh, static_cast<int>(s), m_edges[s][0], m_edges[s][1]);
        }
        m_edgeIndex.begin = csrBegin(owners, nodes);
    }
    if (terms.volume) {
        m_tetRest.resize(mesh.tetCount());
        m_tetK.resize(mesh.tetCount());
        for (int t = 0; t < mesh.tetCount(); ++t)
            setTet(mesh, t);
    }
    if (terms.area) {
        std::vector<std::pair<Tri, Tri>> faces; // (sorted key, oriented nodes)
        for (const BoundaryFace& f : boundaryFaces(mesh))
            faces.push_back({sortedTri(f.nodes), f.nodes});
        std::sort(faces.begin(), faces.end());
        m_tris.resize(faces.size());
        m_triRest.resize(faces.size());
        m_triK.resize(faces.size());
        std::vector<int> owners(faces.size());
        for (std::size_t s = 0; s < faces.size(); ++s) {
            owners[s] = faces[s].first[0];
            setTriangle(mesh, static_cast<int>(s), faces[s].second);
        }
        m_triIndex.begin = csrBegin(owners, nodes);
    }
}

void DeformationModel::setTet(const TetMesh& mesh, int t) {
    const Tet& q = mesh.tet(t);
    const auto m = mesh.masses();
    const double v6 =
        restTetVolume6(mesh.ref(q[0]), mesh.ref(q[1]), mesh.ref(q[2]), mesh.ref(q[3]));
    const double v0 = v6 / 6.0;
    m_tetRest[t] = v6;
    // Eq. 4, k_v = k sum m / V0^2, stored as k_v / 36.
    m_tetK[t] =
        v0 != 0 ? m_material.stiffness * (m[q[0]] + m[q[1]] + m[q[2]] + m[q[3]]) / (v0 * v0) / 36.0
                : 0.0;
}

void DeformationModel::setEdge(const TetMesh& mesh, int slot, int a, int b) {
    const auto m = mesh.masses();
    m_edges[slot] = {a, b};
    const double l2 = (mesh.ref(b) - mesh.ref(a)).squaredNorm();
    m_edgeRest[slot] = restEdgeLength(mesh.ref(a), mesh.ref(b));
    m_edgeK[slot] = l2 > 0 ? m_material.stiffness * (m[a] + m[b]) / l2 : 0.0;
}

void DeformationModel::setTriangle(const TetMesh& mesh, int slot, const Tri& nodes) {
    const auto m = mesh.masses();
    m_tris[slot] = nodes;
    const double a0 = restTriangleArea(mesh.ref(nodes[0]), mesh.ref(nodes[1]), mesh.ref(nodes[2]));
    m_triRest[slot] = a0;
    m_triK[slot] =
        a0 > 0 ? m_material.stiffness * (m[nodes[0]] + m[nodes[1]] + m[nodes[2]]) / (a0 * a0) : 0.0;
}

// --- slots --------------------------------------------------------------------------------

int DeformationModel::findEdge(int a, int b) const {
    int found = -1;
    m_edgeIndex.forEach(a, [&](int s) {
        if (m_edges[s][0] == a && m_edges[s][1] == b)
            found = s;
    });
    return found;
}

int DeformationModel::findTriangle(const Tri& key) const {
    int found = -1;
    m_triIndex.forEach(key[0], [&](int s) {
        if (m_tris[s][0] != m_tris[s][1] && sortedTri(m_tris[s]) == key)
            found = s;
    });
    return found;
}

int DeformationModel::allocateEdge(int owner) {
    int s;
    if (!m_freeEdges.empty()) {
        s = m_freeEdges.back();
        m_freeEdges.pop_back();
    } else {
        s = static_cast<int>(m_edges.size());
        m_edges.push_back({0, 0});
        m_edgeRest.push_back(0);
        m_edgeK.push_back(0);
    }
    m_edgeIndex.add(owner, s);
    return s;
}

int DeformationModel::allocateTriangle(int owner) {
    int s;
    if (!m_freeTris.empty()) {
        s = m_freeTris.back();
        m_freeTris.pop_back();
    } else {
        s = static_cast<int>(m_tris.size());
        m_tris.push_back({0, 0, 0});
        m_triRest.push_back(0);
        m_triK.push_back(0);
    }
    m_triIndex.add(owner, s);
    return s;
}

void DeformationModel::killEdge(int s) {
    const int owner = m_edges[s][0];
    m_edgeIndex.remove(owner, s);
    m_edges[s] = {owner, owner}; // inert: zero length, zero stiffness
    m_edgeRest[s] = 0;
    m_edgeK[s] = 0;
    m_freeEdges.push_back(s);
}

void DeformationModel::killTriangle(int s) {
    const int owner = sortedTri(m_tris[s])[0];
    m_triIndex.remove(owner, s);
    m_tris[s] = {owner, owner, owner};
    m_triRest[s] = 0;
    m_triK[s] = 0;
    m_freeTris.push_back(s);
}

// --- after a cut --------------------------------------------------------------------------

DeformationChanges DeformationModel::applyCut(const TetMesh& mesh, const CutChanges& changes) {
    std::vector<int> touched = changes.touchedNodes;
    for (const auto& [orig, copy] : changes.duplicatedNodes) {
        touched.push_back(orig);
        touched.push_back(copy);
    }
    std::sort(touched.begin(), touched.end());
    touched.erase(std::unique(touched.begin(), touched.end()), touched.end());
    DeformationChanges out;

    if (m_terms.volume) {
        // Every tet whose nodes or whose nodes' masses changed has a touched node.
        m_tetRest.resize(mesh.tetCount());
        m_tetK.resize(mesh.tetCount());
        for (int n : touched)
            for (int t : mesh.nodeTets(n))
                out.tets.push_back(t);
        std::sort(out.tets.begin(), out.tets.end());
        out.tets.erase(std::unique(out.tets.begin(), out.tets.end()), out.tets.end());
        for (int t : out.tets)
            setTet(mesh, t);
    }

    if (m_terms.distance) {
        // An edge that disappeared had all its tets changed, so both its nodes are touched:
        // looking at the edges owned by touched nodes finds it.
        std::vector<int> dead;
        for (int n : touched)
            m_edgeIndex.forEach(n, [&](int s) {
                const auto [a, b] = m_edges[s];
                if (a != n || b == n)
                    return; // owned by another node now, or inert
                bool exists = false;
                for (int t : mesh.nodeTets(n))
                    exists = exists || tetHas(mesh.tet(t), b);
                if (!exists)
                    dead.push_back(s);
            });
        for (int s : dead)
            killEdge(s);
        out.edgeSlots = dead;
        // Edges at touched nodes: new ones, or new masses / rest lengths.
        for (int n : touched)
            for (int t : mesh.nodeTets(n))
                for (int v : mesh.tet(t)) {
                    if (v == n)
                        continue;
                    const int a = std::min(n, v), b = std::max(n, v);
                    int s = findEdge(a, b);
                    if (s < 0)
                        s = allocateEdge(a);
                    setEdge(mesh, s, a, b);
                    out.edgeSlots.push_back(s);
                }
    }

    if (m_terms.area) {
        std::vector<int> dead;
        std::vector<int> scratch;
        for (int n : touched)
            m_triIndex.forEach(n, [&](int s) {
                const Tri key = sortedTri(m_tris[s]);
                if (key[0] != n || key[0] == key[1])
                    return;
                mesh.faceTets(key[0], key[1], key[2], scratch);
                if (scratch.size() != 1)
                    dead.push_back(s);
            });
        for (int s : dead)
            killTriangle(s);
        out.triangleSlots = dead;
        for (int n : touched)
            for (int t : mesh.nodeTets(n)) {
                const Tet& q = mesh.tet(t);
                for (const auto& lf : kTetFaces) {
                    const Tri face{q[lf[0]], q[lf[1]], q[lf[2]]};
                    if (face[0] != n && face[1] != n && face[2] != n)
                        continue;
                    mesh.faceTets(face[0], face[1], face[2], scratch);
                    if (scratch.size() != 1)
                        continue;
                    const Tri key = sortedTri(face);
                    int s = findTriangle(key);
                    if (s < 0)
                        s = allocateTriangle(key[0]);
                    setTriangle(mesh, s, face);
                    out.triangleSlots.push_back(s);
                }
            }
    }
    for (auto* v : {&out.edgeSlots, &out.triangleSlots}) {
        std::sort(v->begin(), v->end());
        v->erase(std::unique(v->begin(), v->end()), v->end());
    }
    return out;
}

std::vector<Edge> DeformationModel::liveEdges() const {
    std::vector<Edge> result;
    for (const Edge& e : m_edges)
        if (e[0] != e[1])
            result.push_back(e);
    std::sort(result.begin(), result.end());
    return result;
}

std::vector<Tri> DeformationModel::liveTriangles() const {
    std::vector<Tri> result;
    for (const Tri& t : m_tris)
        if (t[0] != t[1])
            result.push_back(sortedTri(t));
    std::sort(result.begin(), result.end());
    return result;
}

} // namespace resect
