#include "core/embed/embedded_surface.h"

#include "core/mesh/union_find.h"

#include <algorithm>
#include <chrono>
#include <limits>
#include <map>

namespace resect {

Status EmbeddedSurface::bind(const TetMesh& mesh, TriangleSurface surface) {
    m_surface = {};
    m_binding = {};
    m_index = {};
    if (Status s = m_binding.bind(mesh, surface); !s.ok())
        return s;
    m_surface = std::move(surface);
    m_index.build(m_surface);
    // Cut-face data from the start, and headroom, so that cuts append without moving the
    // whole surface (a cut then costs in proportion to what it touches; see cutSurface).
    m_surface.cutUvs.resize(m_surface.positions.size(), Vec2::Constant(std::numeric_limits<double>::quiet_NaN()));
    m_surface.cutFaces.resize(m_surface.triangles.size(), 0);
    const auto headroom = [](auto& v) { v.reserve(v.size() + v.size() / 4 + 1024); };
    headroom(m_surface.positions);
    headroom(m_surface.uvs);
    headroom(m_surface.cutUvs);
    headroom(m_surface.triangles);
    headroom(m_surface.cutFaces);
    return Status::success();
}

void EmbeddedSurface::update(const TetMesh& mesh, int threads) {
    if (empty())
        return;
    m_binding.apply(mesh, m_surface.positions, m_keepRender ? &m_render : nullptr, threads);
    m_index.positionsChanged();
}

void EmbeddedSurface::keepRenderPositions(bool keep) {
    m_keepRender = keep;
    if (!keep) {
        m_render.clear();
        m_render.shrink_to_fit();
        return;
    }
    m_render.resize(3 * m_surface.positions.size());
    for (std::size_t v = 0; v < m_surface.positions.size(); ++v)
        for (int k = 0; k < 3; ++k)
            m_render[3 * v + k] = static_cast<float>(m_surface.positions[v][k]);
}

Status EmbeddedSurface::cut(const TetMesh& mesh, const CutChanges& changes, const SweepSurface& sweep,
                            EmbeddedCut* stats) {
    if (empty())
        return Status::success();
    using Clock = std::chrono::steady_clock;
    const auto ms = [](Clock::time_point t0) {
        return std::chrono::duration<double, std::milli>(Clock::now() - t0).count();
    };
    EmbeddedCut c;
    // The surface cut first: it is the one step that may fail, and it changes nothing then.
    // Re-binding only reads the positions of the vertices it re-binds (never moved by the
    // surface cut) and the new vertices are bound after it.
    auto t0 = Clock::now();
    if (Status s = cutSurface(m_surface, nullptr, sweep, c.surface, &m_index, &m_workspace); !s.ok())
        return s;
    c.cutMs = ms(t0);
    t0 = Clock::now();
    c.reboundVertices = m_binding.rebind(mesh, changes, m_surface.positions, sweep);
    c.rebindMs = ms(t0);
    t0 = Clock::now();
    const SurfaceCut& sc = c.surface;
    m_binding.bindNewVertices(mesh, m_surface.positions, sc.firstNewVertex, sc.sourceEdge, sc.side, changes, sweep,
                              true);
    c.bindNewMs = ms(t0);
    if (stats)
        *stats = std::move(c);
    return Status::success();
}

std::vector<TriangleSurface> EmbeddedSurface::splitOff(const std::vector<int>& pieceOfTet, int pieces,
                                                       const std::vector<int>& newTetOf, const TetMesh& mesh) {
    std::vector<TriangleSurface> out(pieces);
    if (empty())
        return out;
    const TriangleSurface& s = m_surface;
    // Connected parts of the surface, and the piece most of each part's vertices are bound to.
    UnionFind parts(s.vertexCount());
    for (const Tri& t : s.triangles) {
        parts.unite(t[1], t[0]);
        parts.unite(t[2], t[0]);
    }
    std::map<int, std::map<int, int>> votes;  // part root -> piece -> count
    for (int v = 0; v < s.vertexCount(); ++v)
        ++votes[parts.find(v)][pieceOfTet[m_binding.tetOf(v)]];
    std::vector<int> destination(s.vertexCount(), -1);
    for (int v = 0; v < s.vertexCount(); ++v) {
        const auto& tally = votes[parts.find(v)];
        destination[v] = std::max_element(tally.begin(), tally.end(), [](const auto& a, const auto& b) {
                             return a.second < b.second;
                         })->first;
    }
    // A kept vertex bound to a removed tet (on a part that went to the tissue by majority)
    // is bound to the nearest kept tet (by centre; a linear scan, for these rare vertices).
    std::vector<int> kept, newIndex(s.vertexCount(), -1);
    std::vector<int> indexInChip(s.vertexCount(), -1);
    std::unordered_map<int, std::pair<int, std::array<double, 4>>> rebound;
    for (int v = 0; v < s.vertexCount(); ++v) {
        if (destination[v] < 0) {
            if (newTetOf[m_binding.tetOf(v)] < 0) {
                int best = 0;
                double bestDistance = std::numeric_limits<double>::infinity();
                for (int t = 0; t < mesh.tetCount(); ++t) {
                    Vec3 c = Vec3::Zero();
                    for (int n : mesh.tet(t))
                        c += mesh.pos(n) / 4;
                    if ((c - s.positions[v]).squaredNorm() < bestDistance) {
                        bestDistance = (c - s.positions[v]).squaredNorm();
                        best = t;
                    }
                }
                rebound[v] = {best, barycentricInTet(mesh, best, s.positions[v])};
            }
            newIndex[v] = static_cast<int>(kept.size());
            kept.push_back(v);
        } else {
            TriangleSurface& chip = out[destination[v]];
            indexInChip[v] = chip.vertexCount();
            chip.positions.push_back(s.positions[v]);
            if (!s.uvs.empty())
                chip.uvs.push_back(s.uvs[v]);
            if (!s.cutUvs.empty())
                chip.cutUvs.push_back(s.cutUvs[v]);
        }
    }
    TriangleSurface remaining;
    for (int v : kept) {
        remaining.positions.push_back(s.positions[v]);
        if (!s.uvs.empty())
            remaining.uvs.push_back(s.uvs[v]);
        if (!s.cutUvs.empty())
            remaining.cutUvs.push_back(s.cutUvs[v]);
    }
    for (int f = 0; f < s.triangleCount(); ++f) {
        const Tri& t = s.triangles[f];
        const int d = destination[t[0]];
        const std::uint8_t flag = s.isCutFace(f) ? 1 : 0;
        if (d < 0) {
            if (newIndex[t[0]] < 0 || newIndex[t[1]] < 0 || newIndex[t[2]] < 0)
                continue;
            remaining.triangles.push_back({newIndex[t[0]], newIndex[t[1]], newIndex[t[2]]});
            remaining.cutFaces.push_back(flag);
        } else {
            out[d].triangles.push_back({indexInChip[t[0]], indexInChip[t[1]], indexInChip[t[2]]});
            out[d].cutFaces.push_back(flag);
        }
    }
    m_binding.compact(kept, newTetOf, mesh.tetCount(), rebound);
    m_surface = std::move(remaining);
    m_index.build(m_surface);
    return out;
}

EmbeddedSurface::RemeshRecord EmbeddedSurface::recordAround(const TetMesh& mesh, const std::vector<int>& tets) const {
    RemeshRecord record;
    if (empty())
        return record;
    for (int t : tets)
        for (int v : m_binding.verticesOf(t)) {
            const Tet& q = mesh.tet(t);
            const auto& w = m_binding.weightsOf(v);
            record.vertices.push_back(v);
            record.positions.push_back(w[0] * mesh.pos(q[0]) + w[1] * mesh.pos(q[1]) + w[2] * mesh.pos(q[2]) +
                                       w[3] * mesh.pos(q[3]));
            record.nodes.push_back(q);
        }
    return record;
}

namespace {

/// The tets each recorded vertex may be bound to after a remeshing: those of its recorded tet's
/// nodes, mapped through `newNode` (old -> new, -1: none), sorted.
template <class NewNode>
std::vector<std::vector<int>> candidatesAfterRemesh(const TetMesh& mesh, const EmbeddedSurface::RemeshRecord& record,
                                                    const NewNode& newNode) {
    std::vector<std::vector<int>> candidates(record.vertices.size());
    for (std::size_t i = 0; i < record.vertices.size(); ++i) {
        std::vector<int>& c = candidates[i];
        for (int n : record.nodes[i]) {
            const int node = newNode(n);
            if (node >= 0)
                c.insert(c.end(), mesh.nodeTets(node).begin(), mesh.nodeTets(node).end());
        }
        std::sort(c.begin(), c.end());
        c.erase(std::unique(c.begin(), c.end()), c.end());
    }
    return candidates;
}

} // namespace

void EmbeddedSurface::followRemesh(const TetMesh& mesh, const RemeshRecord& record,
                                   const MeshRenumbering& renumbering) {
    if (empty())
        return;
    const auto candidates = candidatesAfterRemesh(mesh, record, [&](int n) { return renumbering.nodes(n); });
    m_binding.rebindAfterRemesh(mesh, record.vertices, record.positions, candidates, renumbering.tets);
}

void EmbeddedSurface::followRemesh(const TetMesh& mesh, const RemeshRecord& record, const std::vector<int>& newTet,
                                   const std::vector<int>& newNode) {
    if (empty())
        return;
    const auto candidates =
        candidatesAfterRemesh(mesh, record, [&](int n) { return newNode.empty() ? n : newNode[n]; });
    m_binding.rebindAfterRemesh(mesh, record.vertices, record.positions, candidates, newTet);
}

} // namespace resect
