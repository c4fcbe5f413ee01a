#include "core/embed/binding.h"

#include "core/cut/snap_nodes.h"

#include <Eigen/LU>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>
#include <unordered_map>
#include <unordered_set>

namespace resect {

std::array<double, 4> barycentricInTet(const TetMesh& mesh, int tet, const Vec3& p) {
    const Tet& q = mesh.tet(tet);
    return barycentric(mesh.pos(q[0]), mesh.pos(q[1]), mesh.pos(q[2]), mesh.pos(q[3]), p);
}

namespace {
double smallest(const std::array<double, 4>& w) { return std::min({w[0], w[1], w[2], w[3]}); }
} // namespace

void SurfaceBinding::bindVertex(const TetMesh& mesh, int v, const Vec3& p, const std::vector<int>& candidates) {
    // The containing tet has all weights >= 0; otherwise the one "least outside".
    double best = -std::numeric_limits<double>::infinity();
    for (int t : candidates) {
        if (t >= mesh.tetCount())
            continue;
        const auto w = barycentricInTet(mesh, t, p);
        const double s = smallest(w);
        if (std::isfinite(s) && s > best) {
            best = s;
            m_tet[v] = t;
            m_weights[v] = w;
        }
    }
}

Status SurfaceBinding::bind(const TetMesh& mesh, const TriangleSurface& surface, const BindingTolerances& tolerances) {
    if (mesh.empty())
        return Status::error("cannot bind a surface to an empty tet mesh");
    const BindingTolerances& tol = tolerances;
    if (!(tol.inside >= 0 && tol.inside <= 1e-3) || !(tol.nearOutside >= tol.inside && tol.nearOutside <= 1) ||
        !(tol.maxSearchCells >= 1 && tol.maxSearchCells <= 1024))
        return Status::error("binding tolerances out of range: inside " + formatNumber(tol.inside) +
                             " (expected [0, 0.001]), nearOutside " + formatNumber(tol.nearOutside) +
                             " (expected [inside, 1]), maxSearchCells " + formatNumber(tol.maxSearchCells) +
                             " (expected [1, 1024])");
    m_tolerances = tol;
    for (const Vec3& p : surface.positions)
        if (!p.allFinite())
            return Status::error("surface has a non-finite vertex");
    const int n = surface.vertexCount();
    m_tet.assign(n, -1);
    m_weights.assign(n, {1, 0, 0, 0});
    // Headroom for vertices that cuts add (bindNewVertices), so that they append in place.
    m_tet.reserve(n + n / 4 + 1024);
    m_weights.reserve(n + n / 4 + 1024);
    m_outside = 0;
    TetGrid grid;
    grid.build(mesh);
    std::vector<int> candidates;
    const double cell = grid.cellSize();
    for (int v = 0; v < n; ++v) {
        const Vec3& p = surface.positions[v];
        // Grow the search box until a containing tet (or, far out, any tet) is found.
        for (double r = 0.0; r <= tol.maxSearchCells * cell; r = r == 0 ? cell : 2 * r) {
            Eigen::AlignedBox3d box(p - Vec3::Constant(r), p + Vec3::Constant(r));
            grid.query(box, candidates);
            bindVertex(mesh, v, p, candidates);
            if (m_tet[v] >= 0 && smallest(m_weights[v]) >= -tol.inside)
                break;
            // Slightly outside the coarse mesh (its boundary lies inside the curved surface):
            // the tet found in the vertex's own cell is near enough.
            if (m_tet[v] >= 0 && smallest(m_weights[v]) >= -tol.nearOutside)
                break;
            if (m_tet[v] >= 0 && r >= 2 * cell)
                break;  // outside the mesh: the nearest tet found is kept
        }
        if (m_tet[v] < 0) {
            std::vector<int> all(mesh.tetCount());
            std::iota(all.begin(), all.end(), 0);
            bindVertex(mesh, v, p, all);
        }
        if (smallest(m_weights[v]) < -tol.inside)
            ++m_outside;
    }
    m_verticesOfTet.assign(mesh.tetCount(), {});
    for (int v = 0; v < n; ++v)
        m_verticesOfTet[m_tet[v]].push_back(v);
    sortByTet();
    return Status::success();
}

void SurfaceBinding::compact(const std::vector<int>& kept, const std::vector<int>& newTetOf, int tetCount,
                             const std::unordered_map<int, std::pair<int, std::array<double, 4>>>& rebound) {
    std::vector<int> tet(kept.size());
    std::vector<std::array<double, 4>> weights(kept.size());
    for (std::size_t i = 0; i < kept.size(); ++i) {
        if (auto it = rebound.find(kept[i]); it != rebound.end()) {
            tet[i] = it->second.first;
            weights[i] = it->second.second;
            continue;
        }
        tet[i] = newTetOf[m_tet[kept[i]]];
        weights[i] = m_weights[kept[i]];
    }
    m_tet = std::move(tet);
    m_weights = std::move(weights);
    m_verticesOfTet.assign(tetCount, {});
    m_outside = 0;
    for (int v = 0; v < static_cast<int>(m_tet.size()); ++v) {
        m_verticesOfTet[m_tet[v]].push_back(v);
        const auto& w = m_weights[v];
        if (std::min({w[0], w[1], w[2], w[3]}) < -m_tolerances.inside)
            ++m_outside;
    }
    sortByTet();
}

const std::vector<int>& SurfaceBinding::verticesOf(int t) const {
    static const std::vector<int> none;
    return t >= 0 && t < static_cast<int>(m_verticesOfTet.size()) ? m_verticesOfTet[t] : none;
}

void SurfaceBinding::rebindAfterRemesh(const TetMesh& mesh, const std::vector<int>& vertices,
                                       const std::vector<Vec3>& positions,
                                       const std::vector<std::vector<int>>& candidates,
                                       const std::vector<int>& newTet) {
    if (!newTet.empty()) {
        for (int v = 0; v < vertexCount(); ++v)
            m_tet[v] = newTet[m_tet[v]];
    } else {
        for (int v : vertices) {
            auto& list = m_verticesOfTet[m_tet[v]];
            list.erase(std::remove(list.begin(), list.end(), v), list.end());
        }
    }
    for (std::size_t i = 0; i < vertices.size(); ++i) {
        const int v = vertices[i];
        const int old = m_tet[v];
        m_tet[v] = -1;
        bindVertex(mesh, v, positions[i], candidates[i]);
        if (m_tet[v] < 0) {  // no candidate left (cannot happen for a node that still has tets)
            m_tet[v] = old >= 0 ? old : 0;
            m_weights[v] = barycentricInTet(mesh, m_tet[v], positions[i]);
        }
    }
    if (!newTet.empty()) {
        m_verticesOfTet.assign(mesh.tetCount(), {});
        for (int v = 0; v < vertexCount(); ++v)
            m_verticesOfTet[m_tet[v]].push_back(v);
        sortByTet();
    } else {
        if (static_cast<int>(m_verticesOfTet.size()) < mesh.tetCount())
            m_verticesOfTet.resize(mesh.tetCount());
        for (int v : vertices)
            m_verticesOfTet[m_tet[v]].push_back(v);
    }
    m_outside = 0;
    for (const auto& w : m_weights)
        if (std::min({w[0], w[1], w[2], w[3]}) < -m_tolerances.inside)
            ++m_outside;
}

void SurfaceBinding::sortByTet() {
    m_order.resize(m_tet.size());
    std::iota(m_order.begin(), m_order.end(), 0);
    std::stable_sort(m_order.begin(), m_order.end(), [&](int a, int b) { return m_tet[a] < m_tet[b]; });
}

void SurfaceBinding::apply(const TetMesh& mesh, std::vector<Vec3>& out) const {
    out.resize(m_tet.size());
    for (int v : m_order) {
        const Tet& q = mesh.tet(m_tet[v]);
        const auto& w = m_weights[v];
        out[v] = w[0] * mesh.pos(q[0]) + w[1] * mesh.pos(q[1]) + w[2] * mesh.pos(q[2]) + w[3] * mesh.pos(q[3]);
    }
}

namespace {

/// Side of a tet relative to the sweep: from the cut where it made the tet; else from its
/// nodes off the cut surface (a tet touching the cut at nodes that stayed off the sweep may
/// have its centre across it); else from its centre.
int tetSideOf(const TetMesh& mesh, const CutChanges& changes, const std::unordered_set<int>& onCut,
              const SweepSurface& sweep, int t) {
    auto it = changes.tetSide.find(t);
    if (it != changes.tetSide.end())
        return it->second;
    Vec3 centre = Vec3::Zero();
    for (int node : mesh.tet(t)) {
        if (!onCut.count(node)) {
            const int s = sweep.sideOf(mesh.pos(node));
            if (s != 0)
                return s;
        }
        centre += mesh.pos(node) / 4.0;
    }
    return sweep.sideOf(centre);
}

/// Tets sharing a node with any of `tets`, including the stars of separated copies.
std::vector<int> ringOf(const TetMesh& mesh, const CutChanges& changes, const std::vector<int>& tets) {
    std::vector<int> ring;
    std::unordered_set<int> nodes;
    for (int t : tets)
        for (int node : mesh.tet(t))
            nodes.insert(node);
    for (const auto& [orig, copy] : changes.duplicatedNodes)
        if (nodes.count(orig) || nodes.count(copy)) {
            nodes.insert(orig);
            nodes.insert(copy);
        }
    for (int node : nodes)
        ring.insert(ring.end(), mesh.nodeTets(node).begin(), mesh.nodeTets(node).end());
    std::sort(ring.begin(), ring.end());
    ring.erase(std::unique(ring.begin(), ring.end()), ring.end());
    return ring;
}

} // namespace

void SurfaceBinding::bindNewVertices(const TetMesh& mesh, const std::vector<Vec3>& positions, int first,
                                     const std::vector<std::array<int, 2>>& sourceEdges, const std::vector<int>& sides,
                                     const CutChanges& changes, const SweepSurface& sweep) {
    const std::unordered_set<int> onCut(changes.cutSurfaceNodes.begin(), changes.cutSurfaceNodes.end());
    const int total = static_cast<int>(positions.size());
    m_tet.resize(total, -1);
    m_weights.resize(total, {1, 0, 0, 0});
    if (static_cast<int>(m_verticesOfTet.size()) < mesh.tetCount())
        m_verticesOfTet.resize(mesh.tetCount());
    for (int v = first; v < total; ++v) {
        const auto& edge = sourceEdges[v - first];
        std::vector<int> near = ringOf(mesh, changes, {m_tet[edge[0]], m_tet[edge[1]]});
        const int side = sides[v - first];
        std::vector<int> kept;
        for (int t : near)
            if (side == 0 || tetSideOf(mesh, changes, onCut, sweep, t) == side)
                kept.push_back(t);
        bindVertex(mesh, v, positions[v], kept.empty() ? near : kept);
        m_verticesOfTet[m_tet[v]].push_back(v);
    }
    m_order.resize(total);
    for (int v = first; v < total; ++v)
        m_order[v] = v;
}

int SurfaceBinding::rebind(const TetMesh& mesh, const CutChanges& changes, const std::vector<Vec3>& positions,
                           const SweepSurface& sweep) {
    // Pieces of every changed tet: itself (its slot now holds a piece) and its appended pieces.
    std::unordered_map<int, std::vector<int>> pieces;
    for (int t : changes.modifiedTets)
        pieces[t].push_back(t);
    for (std::size_t k = 0; k < changes.parentOfNewTet.size(); ++k)
        pieces[changes.parentOfNewTet[k]].push_back(changes.firstNewTet + static_cast<int>(k));
    // Tets around moved nodes only need new coordinates.
    // Tets around moved nodes need new coordinates, and tets around the cut surface may now
    // lie on the other side of the sweep from vertices bound to them.
    // (Two rings: where cut nodes stay off the sweep, the mesh's cut deviates from the sweep
    // by up to d, and a vertex next to the sweep may sit in a tet a ring away, across it.)
    std::unordered_map<int, char> recompute;
    std::vector<int> ring = changes.touchedNodes;
    ring.insert(ring.end(), changes.cutSurfaceNodes.begin(), changes.cutSurfaceNodes.end());
    for (int n : changes.cutSurfaceNodes)
        for (int u : mesh.nodeNeighbours(n))
            ring.push_back(u);
    std::sort(ring.begin(), ring.end());
    ring.erase(std::unique(ring.begin(), ring.end()), ring.end());
    for (int node : ring)
        for (int t : mesh.nodeTets(node))
            if (t < static_cast<int>(m_verticesOfTet.size()))
                recompute.emplace(t, 1);

    if (static_cast<int>(m_verticesOfTet.size()) < mesh.tetCount())
        m_verticesOfTet.resize(mesh.tetCount());
    std::vector<int> affected;
    for (const auto& [t, list] : pieces)
        for (int v : m_verticesOfTet[t])
            affected.push_back(v);
    for (const auto& [t, flag] : recompute)
        if (!pieces.count(t))
            for (int v : m_verticesOfTet[t])
                affected.push_back(v);
    std::sort(affected.begin(), affected.end());
    affected.erase(std::unique(affected.begin(), affected.end()), affected.end());

    const std::unordered_set<int> onCut(changes.cutSurfaceNodes.begin(), changes.cutSurfaceNodes.end());
    const auto sideOfTet = [&](int t) { return tetSideOf(mesh, changes, onCut, sweep, t); };
    for (int v : affected) {
        const int old = m_tet[v];
        auto it = pieces.find(old);
        std::vector<int> candidates = it == pieces.end() ? std::vector<int>{old} : it->second;
        // Keep the tets on the vertex's side of the sweep; if none (a vertex just outside the
        // coarse mesh, nearest to a tet across the cut), look one ring further.
        const int side = sweep.sideOf(positions[v]);
        const auto sameSide = [&](const std::vector<int>& tets) {
            std::vector<int> kept;
            for (int t : tets)
                if (side == 0 || sideOfTet(t) == 0 || sideOfTet(t) == side)
                    kept.push_back(t);
            return kept;
        };
        std::vector<int> kept = sameSide(candidates);
        if (kept.empty())
            kept = sameSide(ringOf(mesh, changes, candidates));
        if (!kept.empty())
            candidates = kept;
        m_tet[v] = -1;
        bindVertex(mesh, v, positions[v], candidates);
        if (m_tet[v] < 0) {
            m_tet[v] = old;
            m_weights[v] = barycentricInTet(mesh, old, positions[v]);
        }
    }
    // Rebuild the per-tet lists for what changed, and the streaming order.
    for (const auto& [t, list] : pieces)
        for (int piece : list)
            m_verticesOfTet[piece].clear();
    for (const auto& [t, flag] : recompute)
        m_verticesOfTet[t].clear();
    for (int v : affected)
        m_verticesOfTet[m_tet[v]].push_back(v);
    return static_cast<int>(affected.size());
}

} // namespace resect
