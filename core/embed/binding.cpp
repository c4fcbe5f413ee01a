#include "core/embed/binding.h"

#include "core/cut/snap_nodes.h"
#include "core/sim/parallel.h"

#include <Eigen/LU>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>
#include <unordered_map>

namespace resect {

std::array<double, 4> barycentricInTet(const TetMesh& mesh, int tet, const Vec3& p) {
    const Tet& q = mesh.tet(tet);
    return barycentric(mesh.pos(q[0]), mesh.pos(q[1]), mesh.pos(q[2]), mesh.pos(q[3]), p);
}

namespace {
double smallest(const std::array<double, 4>& w) { return std::min({w[0], w[1], w[2], w[3]}); }
} // namespace

void SurfaceBinding::bindVertex(const TetMesh& mesh, int v, const Vec3& p, std::span<const int> candidates) {
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
            setWeights(v, w);
        }
    }
}

namespace {

/// barycentric() of p in the tet of frame f (the expressions of core/mesh/tet_mesh.cpp, so the
/// same bits: test_binding checks every new vertex's weights against barycentric()), or false
/// where a weight is certainly below `below`: the tet cannot contain p better than that. With
/// below > 0 that is decided from the signs of the weights' numerators alone (a quotient whose
/// numerator and denominator do not have the same strict sign rounds to <= 0), before dividing.
bool barycentricAtLeast(const SurfaceBinding::TetFrame& f, const Vec3& p, double below, std::array<double, 4>& w) {
    const Vec3 ap = p - f.a;
    const double v = f.volume6;
    const double n1 = ap.dot(f.acCrossAd), n2 = f.ab.dot(ap.cross(f.ad)), n3 = f.ab.dot(f.ac.cross(ap));
    if (below > 0) {
        const auto positive = [&](double n) { return v > 0 ? n > 0 : (v < 0 && n < 0); };
        if (!(positive(n1) & positive(n2) & positive(n3)))
            return false;
    }
    const double w1 = n1 / v, w2 = n2 / v, w3 = n3 / v;
    if (w1 < below || w2 < below || w3 < below)
        return false;
    w = {1.0 - w1 - w2 - w3, w1, w2, w3};
    return true;
}

} // namespace

void SurfaceBinding::bindVertexInSet(const TetMesh& mesh, int v, const Vec3& p, std::span<const int> candidates,
                                     std::span<const int> likely) {
    double best = -std::numeric_limits<double>::infinity();
    int bestTet = -1;
    std::array<double, 4> w;
    // The likely ones first (members of the set: evaluating one twice changes nothing), so that
    // the others are ruled out early.
    for (std::span<const int> list : {likely, candidates})
    for (int t : list) {
        if (t >= mesh.tetCount())
            continue;
        // A weight below the best so far rules the tet out (its smallest weight is lower).
        if (!barycentricAtLeast(frameOf(mesh, t), p, best, w))
            continue;
        const double s = smallest(w);
        if (std::isfinite(s) && (s > best || (s == best && t < bestTet))) {
            best = s;
            bestTet = t;
            m_tet[v] = t;
            setWeights(v, w);
        }
    }
}

const SurfaceBinding::TetFrame& SurfaceBinding::frameOf(const TetMesh& mesh, int t) {
    if (m_frameSlot.has(t))
        return m_frames[m_frameSlot.get(t)];
    m_frameSlot.set(t, static_cast<int>(m_frames.size()));
    TetFrame& f = m_frames.emplace_back();
    const Tet& q = mesh.tet(t);
    f.a = mesh.pos(q[0]);
    f.ab = mesh.pos(q[1]) - f.a;
    f.ac = mesh.pos(q[2]) - f.a;
    f.ad = mesh.pos(q[3]) - f.a;
    f.acCrossAd = f.ac.cross(f.ad);
    f.volume6 = f.ab.dot(f.acCrossAd);
    return f;
}

void SurfaceBinding::forgetFrames() {
    m_frameSlot.clear();
    m_frames.clear();
}

bool SurfaceBinding::isOutside(int v) const { return smallest(weightsOf(v)) < -m_tolerances.inside; }

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
    m_weights.assign(n, {0, 0, 0});  // (w0 = 1)
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
            if (m_tet[v] >= 0 && smallest(weightsOf(v)) >= -tol.inside)
                break;
            // Slightly outside the coarse mesh (its boundary lies inside the curved surface):
            // the tet found in the vertex's own cell is near enough.
            if (m_tet[v] >= 0 && smallest(weightsOf(v)) >= -tol.nearOutside)
                break;
            if (m_tet[v] >= 0 && r >= 2 * cell)
                break;  // outside the mesh: the nearest tet found is kept
        }
        if (m_tet[v] < 0) {
            std::vector<int> all(mesh.tetCount());
            std::iota(all.begin(), all.end(), 0);
            bindVertex(mesh, v, p, all);
        }
        if (smallest(weightsOf(v)) < -tol.inside)
            ++m_outside;
    }
    m_verticesOfTet.assign(mesh.tetCount(), {});
    for (int v = 0; v < n; ++v)
        m_verticesOfTet[m_tet[v]].push_back(v);
    return Status::success();
}

void SurfaceBinding::compact(const std::vector<int>& kept, const std::vector<int>& newTetOf, int tetCount,
                             const std::unordered_map<int, std::pair<int, std::array<double, 4>>>& rebound) {
    std::vector<int> tet(kept.size());
    std::vector<std::array<double, 3>> weights(kept.size());
    for (std::size_t i = 0; i < kept.size(); ++i) {
        if (auto it = rebound.find(kept[i]); it != rebound.end()) {
            tet[i] = it->second.first;
            const auto& w = it->second.second;
            weights[i] = {w[1], w[2], w[3]};
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
        if (isOutside(v))
            ++m_outside;
    }
}

const std::vector<int>& SurfaceBinding::verticesOf(int t) const {
    static const std::vector<int> none;
    return t >= 0 && t < static_cast<int>(m_verticesOfTet.size()) ? m_verticesOfTet[t] : none;
}

void SurfaceBinding::rebindAfterRemesh(const TetMesh& mesh, const std::vector<int>& vertices,
                                       const std::vector<Vec3>& positions,
                                       const std::vector<std::vector<int>>& candidates,
                                       const std::vector<int>& newTet) {
    SparseRenumbering tets;
    tets.oldCount = static_cast<int>(newTet.empty() ? m_verticesOfTet.size() : newTet.size());
    tets.newCount = mesh.tetCount();
    for (int t = 0; t < static_cast<int>(newTet.size()); ++t)
        if (newTet[t] != t)
            tets.changed.emplace_back(t, newTet[t]);
    rebindAfterRemesh(mesh, vertices, positions, candidates, tets);
}

void SurfaceBinding::rebindAfterRemesh(const TetMesh& mesh, const std::vector<int>& vertices,
                                       const std::vector<Vec3>& positions,
                                       const std::vector<std::vector<int>>& candidates,
                                       const SparseRenumbering& tets) {
    // 1. The recorded vertices leave their tets' lists (old indices), and the outside count.
    for (int v : vertices) {
        auto& list = m_verticesOfTet[m_tet[v]];
        list.erase(std::remove(list.begin(), list.end(), v), list.end());
        if (isOutside(v))
            --m_outside;
    }
    // 2. The lists of renumbered tets move to their new index, with their vertices; removed
    // tets' lists are empty now (only recorded vertices may be bound to them).
    if (!tets.empty()) {
        std::vector<std::vector<int>> moved(tets.changed.size());
        for (std::size_t k = 0; k < tets.changed.size(); ++k) {
            const int from = tets.changed[k].first;
            if (from < static_cast<int>(m_verticesOfTet.size())) {
                moved[k] = std::move(m_verticesOfTet[from]);
                m_verticesOfTet[from].clear();
            }
        }
        if (static_cast<int>(m_verticesOfTet.size()) < mesh.tetCount())
            m_verticesOfTet.resize(mesh.tetCount());
        for (std::size_t k = 0; k < tets.changed.size(); ++k) {
            const int to = tets.changed[k].second;
            if (to < 0)
                continue;
            for (int v : moved[k])
                m_tet[v] = to;
            m_verticesOfTet[to] = std::move(moved[k]);
        }
        for (int v : vertices)
            m_tet[v] = tets(m_tet[v]);
    }
    m_verticesOfTet.resize(mesh.tetCount());
    // 3. The recorded vertices are bound again among their candidates.
    for (std::size_t i = 0; i < vertices.size(); ++i) {
        const int v = vertices[i];
        const int old = m_tet[v];
        m_tet[v] = -1;
        bindVertex(mesh, v, positions[i], candidates[i]);
        if (m_tet[v] < 0) {  // no candidate left (cannot happen for a node that still has tets)
            m_tet[v] = old >= 0 ? old : 0;
            setWeights(v, barycentricInTet(mesh, m_tet[v], positions[i]));
        }
        m_verticesOfTet[m_tet[v]].push_back(v);
        if (isOutside(v))
            ++m_outside;
    }
}

namespace {

/// Vertices per thread below which apply() stays on fewer threads (a fork-join costs
/// microseconds; this many vertices take about as long).
constexpr std::int64_t kApplyGrain = 16384;

/// apply() on vertices [begin, end). The nodes of consecutive vertices' tets are mostly the same
/// and stay in cache; reading them again for every vertex was faster than testing whether the
/// tet changed (a branch taken every four vertices or so, mispredicted).
void applyRange(const TetMesh& mesh, const int* tets, const std::array<double, 3>* weights, int begin, int end,
                Vec3* out, float* render) {
    const Vec3* P = mesh.positions().data();
    const Tet* T = mesh.tets().data();
    for (int v = begin; v < end; ++v) {
        const Tet& q = T[tets[v]];
        const double w1 = weights[v][0], w2 = weights[v][1], w3 = weights[v][2];
        const double w0 = 1.0 - w1 - w2 - w3;
        const Vec3 &p0 = P[q[0]], &p1 = P[q[1]], &p2 = P[q[2]], &p3 = P[q[3]];
        Vec3& x = out[v];
        x.x() = w0 * p0.x() + w1 * p1.x() + w2 * p2.x() + w3 * p3.x();
        x.y() = w0 * p0.y() + w1 * p1.y() + w2 * p2.y() + w3 * p3.y();
        x.z() = w0 * p0.z() + w1 * p1.z() + w2 * p2.z() + w3 * p3.z();
        if (render) {
            render[3 * v] = static_cast<float>(x.x());
            render[3 * v + 1] = static_cast<float>(x.y());
            render[3 * v + 2] = static_cast<float>(x.z());
        }
    }
}

} // namespace

void SurfaceBinding::apply(const TetMesh& mesh, std::vector<Vec3>& out, std::vector<float>* render,
                           int threads) const {
    const int n = vertexCount();
    out.resize(n);
    if (render)
        render->resize(3 * static_cast<std::size_t>(n));
    const int used = threadsFor(resolveThreadCount(threads), n, kApplyGrain);
    Vec3* o = out.data();
    float* r = render ? render->data() : nullptr;
    parallelRun(used, [&](int t) {
        applyRange(mesh, m_tet.data(), m_weights.data(), static_cast<int>(chunkBegin(n, used, t)),
                   static_cast<int>(chunkBegin(n, used, t + 1)), o, r);
    });
}

void SurfaceBinding::collectPieces(const CutChanges& changes) {
    m_pieceSlot.clear();
    m_pieceKeys.clear();
    const auto listOf = [&](int t) -> std::vector<int>& {
        if (m_pieceSlot.insert(t, static_cast<int>(m_pieceKeys.size()))) {
            if (m_pieces.size() <= m_pieceKeys.size())
                m_pieces.emplace_back();
            m_pieces[m_pieceKeys.size()].clear();
            m_pieceKeys.push_back(t);
        }
        return m_pieces[m_pieceSlot.get(t)];
    };
    for (int t : changes.modifiedTets)
        listOf(t).push_back(t);
    for (std::size_t k = 0; k < changes.parentOfNewTet.size(); ++k)
        listOf(changes.parentOfNewTet[k]).push_back(changes.firstNewTet + static_cast<int>(k));
}

std::span<const int> SurfaceBinding::piecesOf(int t) const {
    if (t >= 0 && m_pieceSlot.has(t))
        return m_pieces[m_pieceSlot.get(t)];
    return {};
}

void SurfaceBinding::bindNewVertices(const TetMesh& mesh, const std::vector<Vec3>& positions, int first,
                                     const std::vector<std::array<int, 2>>& sourceEdges, const std::vector<int>& sides,
                                     const CutChanges& changes, const SweepSurface& sweep, bool afterRebind) {
    if (!afterRebind)
        m_sides.begin(mesh, changes, sweep);
    forgetFrames();
    const int total = static_cast<int>(positions.size());
    m_tet.resize(total, -1);
    m_weights.resize(total, {0, 0, 0});
    if (static_cast<int>(m_verticesOfTet.size()) < mesh.tetCount())
        m_verticesOfTet.resize(mesh.tetCount());
    std::array<int, 2> ringOf{-1, -1};  // the tets m_ring is the ring of
    for (int v = first; v < total; ++v) {
        const auto& edge = sourceEdges[v - first];
        // Tets near the ones the source edge's ends are bound to (the same for the copies and
        // the other points split from one edge: computed once for consecutive ones).
        const std::array<int, 2> ends{m_tet[edge[0]], m_tet[edge[1]]};
        if (ends != ringOf) {
            m_sides.ring(ends, m_ring);
            ringOf = ends;
            m_ringSides.clear();
            for (int t : m_ring)
                m_ringSides.push_back(static_cast<std::int8_t>(m_sides.tetSide(t)));
        }
        const int side = sides[v - first];
        m_kept.clear();
        for (std::size_t k = 0; k < m_ring.size(); ++k)
            if (side == 0 || m_ringSides[k] == side)
                m_kept.push_back(m_ring[k]);
        // The tets of the edge's ends and their pieces are likely to contain the vertex.
        m_likely.clear();
        for (int end : ends) {
            m_likely.push_back(end);
            const std::span<const int> pieces = piecesOf(end);
            m_likely.insert(m_likely.end(), pieces.begin(), pieces.end());
        }
        std::erase_if(m_likely, [&](int t) {
            return !m_sides.inRing(t) || (!m_kept.empty() && side != 0 && m_sides.tetSide(t) != side);
        });
        bindVertexInSet(mesh, v, positions[v], m_kept.empty() ? m_ring : m_kept, m_likely);
        m_verticesOfTet[m_tet[v]].push_back(v);
        if (isOutside(v))
            ++m_outside;
    }
}

void SurfaceBinding::markRecomputeTets(const TetMesh& mesh, const CutChanges& changes, int oldTets) {
    m_recompute.clear();
    m_recomputeMark.clear();
    m_nodeMark.clear();
    const auto markNode = [&](int n) {
        if (!m_nodeMark.insert(n))
            return;
        for (int t : mesh.nodeTets(n))
            if (t < oldTets && m_recomputeMark.insert(t))
                m_recompute.push_back(t);
    };
    for (int n : changes.touchedNodes)
        markNode(n);
    // (The neighbours of a node, and the node, are the nodes of its tets.)
    for (int n : changes.cutSurfaceNodes)
        for (int t : mesh.nodeTets(n))
            for (int u : mesh.tet(t))
                markNode(u);
}

void SurfaceBinding::rebindVertex(const TetMesh& mesh, int v, const Vec3& p, const SweepSurface& sweep) {
    const int old = m_tet[v];
    if (isOutside(v))
        --m_outside;
    const std::span<const int> pieces = piecesOf(old);
    const std::span<const int> candidates = pieces.empty() ? std::span<const int>(&old, 1) : pieces;
    // Keep the tets on the vertex's side of the sweep; if none (a vertex just outside the
    // coarse mesh, nearest to a tet across the cut), look one ring further.
    int side = 2;  // not computed yet: only needed where a candidate lies on one side
    const auto keepSameSide = [&](std::span<const int> tets) {
        m_kept.clear();
        for (int t : tets) {
            const int s = m_sides.tetSide(t);
            if (s != 0 && side == 2)
                side = sweep.sideOf(p);
            if (side == 0 || s == 0 || s == side)
                m_kept.push_back(t);
        }
    };
    keepSameSide(candidates);
    m_tet[v] = -1;
    if (!m_kept.empty()) {
        bindVertex(mesh, v, p, m_kept);
    } else {
        m_sides.ring(candidates, m_ring);
        keepSameSide(m_ring);
        if (!m_kept.empty())
            bindVertexInSet(mesh, v, p, m_kept, {});
        else
            bindVertex(mesh, v, p, candidates);
    }
    if (m_tet[v] < 0) {
        m_tet[v] = old;
        setWeights(v, barycentricInTet(mesh, old, p));
    }
    if (isOutside(v))
        ++m_outside;
}

int SurfaceBinding::rebind(const TetMesh& mesh, const CutChanges& changes, const std::vector<Vec3>& positions,
                           const SweepSurface& sweep) {
    m_sides.begin(mesh, changes, sweep);
    forgetFrames();
    const int oldTets = static_cast<int>(m_verticesOfTet.size());
    // Pieces of every changed tet: itself (its slot now holds a piece) and its appended pieces.
    collectPieces(changes);
    // Tets around moved nodes need new coordinates, and tets around the cut surface may now
    // lie on the other side of the sweep from vertices bound to them.
    // (Two rings: where cut nodes stay off the sweep, the mesh's cut deviates from the sweep
    // by up to d, and a vertex next to the sweep may sit in a tet a ring away, across it.)
    markRecomputeTets(mesh, changes, oldTets);
    if (static_cast<int>(m_verticesOfTet.size()) < mesh.tetCount())
        m_verticesOfTet.resize(mesh.tetCount());

    // The vertices bound to any of them (each once: a vertex is in one tet's list). Each is
    // re-bound on its own, so their order only orders the rebuilt lists.
    m_affected.clear();
    for (int t : m_pieceKeys)
        m_affected.insert(m_affected.end(), m_verticesOfTet[t].begin(), m_verticesOfTet[t].end());
    for (int t : m_recompute)
        if (piecesOf(t).empty())
            m_affected.insert(m_affected.end(), m_verticesOfTet[t].begin(), m_verticesOfTet[t].end());
    for (int v : m_affected)
        rebindVertex(mesh, v, positions[v], sweep);

    // Rebuild the per-tet lists for what changed.
    for (std::size_t k = 0; k < m_pieceKeys.size(); ++k)
        for (int piece : m_pieces[k])
            m_verticesOfTet[piece].clear();
    for (int t : m_recompute)
        m_verticesOfTet[t].clear();
    for (int v : m_affected)
        m_verticesOfTet[m_tet[v]].push_back(v);
    return static_cast<int>(m_affected.size());
}

} // namespace resect
