#include "core/embed/cut_surface.h"

#include "core/embed/flat_marks.h"
#include "core/embed/surface_index.h"
#include "core/embed/triangulate_cut.h"
#include "core/mesh/predicates.h"
#include "core/mesh/union_find.h"
#include "core/sweep/intersect_segment.h"

#include <algorithm>
#include <initializer_list>
#include <limits>
#include <map>
#include <numeric>
#include <span>
#include <string>
#include <unordered_map>
#include <unordered_set>

namespace resect {
namespace {

std::uint64_t undirected(int a, int b) {
    if (a > b)
        std::swap(a, b);
    return (static_cast<std::uint64_t>(static_cast<std::uint32_t>(a)) << 32) | static_cast<std::uint32_t>(b);
}
std::uint64_t directed(int a, int b) {
    return (static_cast<std::uint64_t>(static_cast<std::uint32_t>(a)) << 32) | static_cast<std::uint32_t>(b);
}

/// Canonical order of two surface vertices: by position (lexicographic), then by index. Every
/// computation on an edge or a triangle runs in this order, so coincident edges and triangles
/// of different pieces (the two faces of an earlier cut) give bit-identical crossings.
bool precedes(const Vec3& p, int i, const Vec3& q, int j) {
    if (p.x() != q.x())
        return p.x() < q.x();
    if (p.y() != q.y())
        return p.y() < q.y();
    if (p.z() != q.z())
        return p.z() < q.z();
    return i < j;
}

/// A crossing of a surface edge with the sweep: the edge is split there. Every crossing
/// splits (not only odd numbers of them, as for the tets): an edge crossed twice by a curved
/// sweep leaves the cut and comes back, and the surface follows that exactly.
struct EdgeSplit {
    int low = -1, high = -1;  ///< the edge's ends, low < high
    double t = 0;             ///< crossing parameter from low to high
    Vec3 point = Vec3::Zero();
    Vec2 uv = Vec2::Zero();
    int sideLow = 0;          ///< side of `low` relative to the crossed sweep triangle
    int sweepTriangle = -1;
    std::int64_t feature = 0; ///< the sweep feature crossed (intersect_segment.h)
    int vertex = -1;          ///< the split point (a new vertex)
    int sideOf(int v) const { return v == low ? sideLow : -sideLow; }
};

/// A point the cut passes through on a surface triangle's boundary: a split point, or a
/// surface vertex that lies exactly on the sweep.
struct BoundaryPoint {
    int vertex = -1;
    std::vector<int> sweepTriangles;  ///< the sweep triangles whose closed triangle holds it
};

/// The edges of a surface triangle that each point on its boundary lies on (bit e: edge
/// q[e] -> q[e + 1]): a short list, searched linearly.
struct EdgeBits {
    std::vector<std::pair<int, int>> bits;  ///< (vertex, bits)
    int& of(int v) {
        for (auto& [u, b] : bits)
            if (u == v)
                return b;
        return bits.emplace_back(v, 0).second;
    }
    const int* find(int v) const {
        for (const auto& [u, b] : bits)
            if (u == v)
                return &b;
        return nullptr;
    }
};

/// A point where a sweep edge pierces a surface triangle's interior, found while tracing.
struct Pierce {
    Vec3 point = Vec3::Zero();
    Vec2 uv = Vec2::Zero();
};

/// Points of a cut closer than this fraction of their surface triangle's longest edge count as
/// one (dimensionless; 1e-9 is far above rounding and far below any feature of a mesh).
constexpr double kCoincidentFraction = 1e-9;

/// A crossing closer than this fraction of its edge's length to an end of the edge puts the cut
/// through that end (dimensionless; far above rounding, far below any feature of a mesh).
constexpr double kSnapFraction = 1e-7;

/// A piece's side is probed this fraction of the cut segment's length inside it: far above the
/// rounding of the segment's points, far below the size of a piece.
constexpr double kProbeFraction = 1e-6;

/// A surface triangle whose area is below this fraction of its longest edge squared counts as
/// flat (its plane is not defined to within rounding of a probe's offset).
constexpr double kFlatRatio = 1e-8;

/// Triangle (vertex ids) with a quality for choosing ears: area over the sum of squared edges.
double earQuality(const Vec3& a, const Vec3& b, const Vec3& c) {
    const double edges = (b - a).squaredNorm() + (c - b).squaredNorm() + (a - c).squaredNorm();
    return edges > 0 ? (b - a).cross(c - a).norm() / edges : 0.0;
}

/// Ear clipping of a simple polygon (vertex ids, oriented as `sign` says in the projection
/// that drops axis `drop`) with exact orientation tests. Among the valid ears the best shaped
/// is cut first, so the split points on an edge never make a needle. Unless
/// `allowCutDiagonals`, no diagonal may join two points of the cut (`onCut`): such an edge
/// could also be made by the cap on the other side of the cut, and the surface would pinch
/// there; when only such ears are left, the rest of the polygon is returned in `stuck` (empty
/// when done). No diagonal may join two points on one edge of the surface triangle
/// (`onOneEdge`) unless nothing else is left: it would run along that edge, and with the
/// triangle across the edge the surface would have two triangles on the same points there
/// (a pocket), or three on one edge. False if no ear exists at all (a polygon that is not
/// simple).
template <class OnCut, class OnOneEdge>
bool earClip(std::vector<int> poly, const std::vector<Vec3>& P, int drop, int sign, const OnCut& onCut,
             const OnOneEdge& onOneEdge, bool allowCutDiagonals, std::vector<Tri>& out, std::vector<int>& stuck) {
    stuck.clear();
    while (poly.size() > 3) {
        const int n = static_cast<int>(poly.size());
        int best = -1;
        double bestQuality = -std::numeric_limits<double>::infinity();
        // Passes: convex empty ears, flat empty ears, and (when diagonals between cut points
        // are allowed) the best-shaped ear of any kind, so that clipping always finishes: any
        // sequence of ears triangulates the polygon as a disc.
        const int passes = allowCutDiagonals ? 3 : 2;
        for (int pass = 0; pass < passes && best < 0; ++pass) {
            for (int i = 0; i < n; ++i) {
                const int a = poly[(i + n - 1) % n], b = poly[i], c = poly[(i + 1) % n];
                if (a == c)
                    continue;
                const int o = orient2dProjected(P[a], P[b], P[c], drop) * sign;
                if ((pass == 0 && o <= 0) || (pass == 1 && o < 0))
                    continue;
                if ((!allowCutDiagonals && onCut(a) && onCut(c)) || (pass < 2 && onOneEdge(a, c)))
                    continue;
                bool ok = true;
                for (int j = 0; j < n && ok && pass < 2; ++j) {
                    const int x = poly[j];
                    if (x == a || x == b || x == c || P[x] == P[a] || P[x] == P[b] || P[x] == P[c])
                        continue;
                    const int s1 = orient2dProjected(P[a], P[b], P[x], drop) * sign;
                    const int s2 = orient2dProjected(P[b], P[c], P[x], drop) * sign;
                    const int s3 = orient2dProjected(P[c], P[a], P[x], drop) * sign;
                    ok = !(s1 >= 0 && s2 >= 0 && s3 >= 0);
                }
                if (!ok)
                    continue;
                const double q = earQuality(P[a], P[b], P[c]) * (o >= 0 ? 1 : -1);
                if (q > bestQuality) {
                    bestQuality = q;
                    best = i;
                }
            }
        }
        if (best < 0) {
            if (allowCutDiagonals)
                return false;
            stuck = poly;
            return true;
        }
        out.push_back({poly[(best + n - 1) % n], poly[best], poly[(best + 1) % n]});
        poly.erase(poly.begin() + best);
    }
    if (poly.size() == 3) {
        if (!allowCutDiagonals && onCut(poly[0]) && onCut(poly[1]) && onCut(poly[2])) {
            stuck = poly;  // a triangle of cut points only: its edges would pinch too
            return true;
        }
        out.push_back({poly[0], poly[1], poly[2]});
    }
    return true;
}

/// True if every triangle (s, poly[i], poly[i+1]) is strictly positively oriented: s sees the
/// whole polygon (it lies in its kernel) and a fan from it triangulates it.
bool fansFrom(const Vec3& s, const std::vector<int>& poly, const std::vector<Vec3>& P, int drop, int sign) {
    for (std::size_t i = 0; i < poly.size(); ++i)
        if (orient2dProjected(s, P[poly[i]], P[poly[(i + 1) % poly.size()]], drop) * sign <= 0)
            return false;
    return true;
}

/// Undo log of an in-place surface edit: appended data is truncated, replaced triangles and
/// changed cut (u, v)s are restored. Keeps the promise that a failed cut leaves the surface
/// untouched.
struct SurfaceEdit {
    TriangleSurface& surface;
    std::vector<Vec3>* rest;
    int vertices, triangles;
    std::size_t cutUvs, cutFaces;  ///< sizes before (the arrays may have been empty)
    std::vector<std::pair<int, Tri>> replaced;
    std::vector<std::pair<int, Vec2>> uvChanged;
    bool committed = false;
    SurfaceEdit(TriangleSurface& s, std::vector<Vec3>* r)
        : surface(s), rest(r), vertices(s.vertexCount()), triangles(s.triangleCount()), cutUvs(s.cutUvs.size()),
          cutFaces(s.cutFaces.size()) {}
    SurfaceEdit(const SurfaceEdit&) = delete;
    SurfaceEdit& operator=(const SurfaceEdit&) = delete;
    void replace(int t, const Tri& q) {
        replaced.emplace_back(t, surface.triangles[t]);
        surface.triangles[t] = q;
    }
    void setCutUv(int v, const Vec2& uv) {
        uvChanged.emplace_back(v, surface.cutUvs[v]);
        surface.cutUvs[v] = uv;
    }
    ~SurfaceEdit() {
        if (committed)
            return;
        for (auto it = replaced.rbegin(); it != replaced.rend(); ++it)
            surface.triangles[it->first] = it->second;
        for (auto it = uvChanged.rbegin(); it != uvChanged.rend(); ++it)
            surface.cutUvs[it->first] = it->second;
        surface.positions.resize(vertices);
        if (!surface.uvs.empty())
            surface.uvs.resize(vertices);
        surface.cutUvs.resize(cutUvs);
        surface.triangles.resize(triangles);
        surface.cutFaces.resize(cutFaces);
        if (rest)
            rest->resize(vertices);
    }
};

} // namespace

/// The cut's scratch tables (flat_marks.h), cleared at the start of every cut.
struct SurfaceCutWorkspace::Tables {
    StampedMarks onSweep, cutVertices, shared, mate, mateOf, side, colour, incident, next, visited;
    EdgeTable tested, splits, cutEdges, segmentTriangle, edgeSide, halfEdges, surfaceEdges, byEdge, capEdges;
    EdgeTable checkNow, checkBefore, checkSeen;  ///< checkClosedAlongCut
    std::vector<std::uint64_t> checkKeys;
    void clear(int vertices, int triangles) {
        for (StampedMarks* m : {&onSweep, &cutVertices, &shared, &mate, &mateOf, &incident, &next, &visited}) {
            m->clear();
            m->grow(vertices);
        }
        for (StampedMarks* m : {&side, &colour}) {
            m->clear();
            m->grow(triangles);
        }
        for (EdgeTable* t : {&tested, &splits, &cutEdges, &segmentTriangle, &edgeSide, &halfEdges, &surfaceEdges, &byEdge,
                             &capEdges, &checkNow, &checkBefore, &checkSeen})
            t->clear();
    }
    /// Room for a cut near `candidates` triangles (one allocation each on a cold workspace).
    void reserve(int candidates) {
        for (EdgeTable* t : {&tested, &cutEdges, &segmentTriangle, &edgeSide, &halfEdges, &surfaceEdges, &byEdge})
            t->reserve(2 * candidates);
    }
};

SurfaceCutWorkspace::SurfaceCutWorkspace() : m_tables(std::make_unique<Tables>()) {}
SurfaceCutWorkspace::~SurfaceCutWorkspace() = default;
SurfaceCutWorkspace::SurfaceCutWorkspace(const SurfaceCutWorkspace&) : m_tables(std::make_unique<Tables>()) {}
SurfaceCutWorkspace& SurfaceCutWorkspace::operator=(const SurfaceCutWorkspace&) { return *this; }

namespace {

/// The surface cut of section 5, one step per member function: candidates, edge splits,
/// triangle splits (with the exact course of the cut inside each triangle), separation of the
/// sides, boundary tracing, caps.
class SurfaceCutter {
public:
    SurfaceCutter(TriangleSurface& surface, std::vector<Vec3>* rest, const SweepSurface& sweep, SurfaceCut& out,
                  SurfaceIndex* index, SurfaceCutWorkspace::Tables& tables)
        : m_s(surface), m_rest(rest), m_sweep(sweep), m_out(out), m_edit(surface, rest),
          m_first(surface.vertexCount()), m_index(index), m_t(tables) {
        m_t.clear(surface.vertexCount(), surface.triangleCount());
    }

    Status run() {
        findCandidates();
        findEdgeSplits();
        if (m_splitRanges.empty())
            return Status::success();  // nothing crosses: the surface is unchanged
        buildSweepAdjacency();
        prepareArrays();
        addSplitVertices();
        if (Status s = splitTriangles(); !s.ok())
            return s;
        collectTouched();
        groupFans();
        assignSides();
        separateSides();
        std::vector<std::vector<int>> loops;
        if (Status s = traceBoundary(loops); !s.ok())
            return s;
        if (Status s = closeCaps(loops); !s.ok())
            return s;
        if (Status s = checkClosedAlongCut(); !s.ok())
            return s;
        finishCounts();
        m_edit.committed = true;
        if (m_index) {
            std::vector<int> replaced;
            for (const auto& [t, old] : m_edit.replaced)
                replaced.push_back(t);
            m_index->followCut(m_s, m_first, m_edit.triangles, replaced);
        }
        return Status::success();
    }

    /// The surface is still closed and 2-manifold along what the cut changed: every directed edge
    /// of a changed or added triangle is in no other of them, and its opposite is in one of them
    /// or in a triangle the cut left alone (which had it before: then the edge is one the changed
    /// triangles had before too, and its opposite none of them had). In proportion to the cut. A
    /// cut that fails it is refused (and undone) instead of leaving holes in the surface.
    Status checkClosedAlongCut() {
        EdgeTable &now = m_t.checkNow, &before = m_t.checkBefore, &seen = m_t.checkSeen;
        std::vector<std::uint64_t>& keys = m_t.checkKeys;
        now.clear();
        before.clear();
        seen.clear();
        keys.clear();
        const int added = m_s.triangleCount() - m_edit.triangles, replaced = static_cast<int>(m_edit.replaced.size());
        now.reserve(3 * (added + replaced));
        before.reserve(3 * replaced);
        seen.reserve(replaced);
        keys.reserve(3 * (added + replaced));
        const auto count = [&](int t) {
            const Tri& q = m_s.triangles[t];
            for (int e = 0; e < 3; ++e) {
                const std::uint64_t key = directed(q[e], q[(e + 1) % 3]);
                const auto [value, first] = now.insert(key, 0);
                ++*value;
                if (first)
                    keys.push_back(key);
            }
        };
        // Triangles the surface had before (their first entry holds their corners then), then
        // the added ones (replaced or not).
        for (const auto& [t, old] : m_edit.replaced)
            if (t < m_edit.triangles && seen.insert(static_cast<std::uint64_t>(t) + 1, 1).second) {
                count(t);
                for (int e = 0; e < 3; ++e)
                    before.insert(directed(old[e], old[(e + 1) % 3]), 1);
            }
        for (int t = m_edit.triangles; t < m_s.triangleCount(); ++t)
            count(t);
        for (std::uint64_t key : keys) {
            const int a = static_cast<int>(key >> 32), b = static_cast<int>(key & 0xffffffffu);
            const std::uint64_t reverse = directed(b, a);
            const int times = now.get(key);
            if (times == 1 && (now.contains(reverse) || (before.contains(key) && !before.contains(reverse))))
                continue;
            return Status::error("the cut would leave the surface " + std::string(times == 1 ? "open" : "non-manifold") +
                                 " at its edge (" + std::to_string(a) + ", " + std::to_string(b) + "); refused");
        }
        return Status::success();
    }

    // --- step 1: triangles near the sweep ---

    /// Triangles that can touch the sweep: not all three corners strictly beyond one face of
    /// the sweep's bounding box (exact comparisons, so no crossing is missed). Through the
    /// SurfaceIndex when there is one (the blocks near the sweep), else one pass over the index
    /// array, a few nanoseconds a triangle; everything after it costs in proportion to the
    /// triangles the sweep touches.
    void findCandidates() {
        if (m_index) {
            m_index->candidates(m_s, m_sweep.bounds(), m_candidates);
            m_out.candidateTriangles = static_cast<int>(m_candidates.size());
            return;
        }
        const Vec3 lo = m_sweep.bounds().min(), hi = m_sweep.bounds().max();
        std::vector<std::uint8_t> code(m_s.positions.size());
        for (std::size_t v = 0; v < code.size(); ++v) {
            const Vec3& p = m_s.positions[v];
            code[v] = static_cast<std::uint8_t>((p.x() < lo.x() ? 1 : 0) | (p.x() > hi.x() ? 2 : 0) |
                                                (p.y() < lo.y() ? 4 : 0) | (p.y() > hi.y() ? 8 : 0) |
                                                (p.z() < lo.z() ? 16 : 0) | (p.z() > hi.z() ? 32 : 0));
        }
        for (int t = 0; t < m_s.triangleCount(); ++t) {
            const Tri& q = m_s.triangles[t];
            if ((code[q[0]] & code[q[1]] & code[q[2]]) == 0)
                m_candidates.push_back(t);
        }
        m_out.candidateTriangles = static_cast<int>(m_candidates.size());
    }

    // --- step 2: crossed edges and vertices on the sweep ---

    /// Every crossing of every candidate edge, in two passes. A crossing within kSnapFraction of
    /// an edge's length from one of its ends puts the cut through that end instead (the vertex
    /// counts as on the sweep, as do vertices exactly on it); then every edge at such a vertex
    /// drops its crossings near it. Without this a sweep passing within rounding of a vertex
    /// (a cut through an earlier cut vertex) would leave pieces too small to tell apart.
    void findEdgeSplits() {
        struct EdgeHits {
            int a, b;           ///< the edge, from -> to in canonical order
            int first, count;   ///< its hits in `hits`
        };
        std::vector<EdgeHits> edges;
        std::vector<SegmentHit> hits;
        m_t.reserve(static_cast<int>(m_candidates.size()));
        SegmentQuery query;
        std::vector<int> scratch;
        const auto& P = m_s.positions;
        for (int t : m_candidates) {
            const Tri& q = m_s.triangles[t];
            for (int e = 0; e < 3; ++e) {
                const int a = q[e], b = q[(e + 1) % 3];
                if (!m_t.tested.insert(undirected(a, b), 1).second)
                    continue;
                const bool forward = precedes(P[a], a, P[b], b);
                const int from = forward ? a : b, to = forward ? b : a;
                intersectSegment(m_sweep, P[from], P[to], query, scratch);
                if (query.pOnSweep)
                    m_t.onSweep.insert(from);
                if (query.qOnSweep)
                    m_t.onSweep.insert(to);
                if (query.hits.empty())
                    continue;
                for (const SegmentHit& h : query.hits) {
                    // A crossing all but at an end: that end is on the cut.
                    const int end = h.t < kSnapFraction ? from : h.t > 1 - kSnapFraction ? to : -1;
                    if (end >= 0 && m_t.onSweep.insert(end))
                        m_holding[end] = trianglesOfFeature(h.triangle, h.feature);
                }
                edges.push_back({from, to, static_cast<int>(hits.size()), static_cast<int>(query.hits.size())});
                hits.insert(hits.end(), query.hits.begin(), query.hits.end());
            }
        }
        std::vector<EdgeSplit> splits;
        for (const EdgeHits& edge : edges) {
            const int from = edge.a, to = edge.b;
            const bool fromOn = m_t.onSweep.has(from), toOn = m_t.onSweep.has(to);
            splits.clear();
            for (int k = edge.first; k < edge.first + edge.count; ++k) {
                const SegmentHit& h = hits[k];
                if ((fromOn && h.t < kSnapFraction) || (toOn && h.t > 1 - kSnapFraction))
                    continue;
                EdgeSplit s;
                s.low = std::min(from, to);
                s.high = std::max(from, to);
                const bool fromLow = from == s.low;
                s.t = fromLow ? h.t : 1.0 - h.t;
                s.point = h.point;
                s.uv = h.uv;
                s.sideLow = fromLow ? h.sideP : -h.sideP;
                s.sweepTriangle = h.triangle;
                s.feature = h.feature;
                // Two crossings within rounding of each other are a tangency: neither splits.
                if (!splits.empty() && std::abs(s.t - splits.back().t) <= kSnapFraction) {
                    splits.pop_back();
                    continue;
                }
                splits.push_back(s);
            }
            std::sort(splits.begin(), splits.end(), [](const EdgeSplit& x, const EdgeSplit& y) { return x.t < y.t; });
            if (!splits.empty() && m_t.splits.insert(undirected(from, to), static_cast<int>(m_splitRanges.size())).second) {
                m_splitRanges.push_back({static_cast<int>(m_splitStore.size()), static_cast<int>(splits.size())});
                m_splitStore.insert(m_splitStore.end(), splits.begin(), splits.end());
            }
        }
    }

    /// The crossings of edge (a, b), ordered from low to high (empty if none).
    std::span<EdgeSplit> splitsOf(int a, int b) {
        const int* range = m_t.splits.find(undirected(a, b));
        if (!range)
            return {};
        const auto [first, count] = m_splitRanges[*range];
        return std::span<EdgeSplit>(m_splitStore.data() + first, count);
    }

    // --- sweep topology, for tracing the cut inside a triangle ---

    void buildSweepAdjacency() {
        const auto& T = m_sweep.triangles();
        std::unordered_map<std::uint64_t, std::array<int, 2>> edgeTriangles;
        for (int t = 0; t < static_cast<int>(T.size()); ++t)
            for (int e = 0; e < 3; ++e) {
                auto [it, added] = edgeTriangles.emplace(undirected(T[t][e], T[t][(e + 1) % 3]), std::array<int, 2>{t, -1});
                if (!added)
                    it->second[1] = t;
            }
        m_neighbour.assign(T.size(), {-1, -1, -1});
        for (int t = 0; t < static_cast<int>(T.size()); ++t)
            for (int e = 0; e < 3; ++e) {
                const auto& pair = edgeTriangles.at(undirected(T[t][e], T[t][(e + 1) % 3]));
                m_neighbour[t][e] = pair[0] == t ? pair[1] : pair[0];
            }
        m_vertexTriangles.assign(m_sweep.vertices().size(), {});
        for (int t = 0; t < static_cast<int>(T.size()); ++t)
            for (int v : T[t])
                m_vertexTriangles[v].push_back(t);
    }

    /// The sweep triangles a crossing lies in: its triangle, and every triangle sharing the
    /// crossed edge or vertex.
    std::vector<int> trianglesOfFeature(int triangle, std::int64_t feature) const {
        std::vector<int> out{triangle};
        const int kind = static_cast<int>(feature & 3);
        const std::int64_t body = feature >> 2;
        if (kind == 1) {
            const int a = static_cast<int>(body >> 31), b = static_cast<int>(body & 0x7fffffff);
            for (int t : m_vertexTriangles[a]) {
                const Tri& q = m_sweep.triangles()[t];
                if (t != triangle && std::find(q.begin(), q.end(), b) != q.end())
                    out.push_back(t);
            }
        } else if (kind == 2) {
            for (int t : m_vertexTriangles[static_cast<int>(body)])
                if (t != triangle)
                    out.push_back(t);
        }
        return out;
    }

    /// The sweep triangles whose closed triangle holds the point (exactly).
    std::vector<int> trianglesHolding(const Vec3& p) const {
        std::vector<int> near, out;
        m_sweep.trianglesOverlapping(Box3(p, p), near);
        const auto& V = m_sweep.vertices();
        for (int t : near) {
            if (m_sweep.isDegenerate(t))
                continue;
            const Tri& q = m_sweep.triangles()[t];
            if (orient3d(V[q[0]], V[q[1]], V[q[2]], p) == 0 && inClosedTriangle(p, V[q[0]], V[q[1]], V[q[2]]))
                out.push_back(t);
        }
        return out;
    }

    // --- step 3: new vertices ---

    void prepareArrays() {
        m_s.cutUvs.resize(m_s.vertexCount(), Vec2::Constant(std::numeric_limits<double>::quiet_NaN()));
        m_s.cutFaces.resize(m_s.triangleCount(), 0);
    }

    /// Appends a vertex (position, texture coordinate and rest position interpolated with the
    /// weights of `from`); returns its index.
    using Weights = std::span<const std::pair<int, double>>;
    int addVertex(const Vec3& p, const Vec2& cutUv, std::initializer_list<std::pair<int, double>> from,
                  const std::array<int, 2>& source) {
        return addVertex(p, cutUv, Weights(from.begin(), from.size()), source);
    }
    int addVertex(const Vec3& p, const Vec2& cutUv, Weights from, const std::array<int, 2>& source) {
        m_s.positions.push_back(p);
        if (!m_s.uvs.empty()) {
            Vec2 uv = Vec2::Zero();
            for (const auto& [v, w] : from)
                uv += w * m_s.uvs[v];
            m_s.uvs.push_back(uv);
        }
        if (m_rest) {
            Vec3 r = Vec3::Zero();
            for (const auto& [v, w] : from)
                r += w * (*m_rest)[v];
            m_rest->push_back(r);
        }
        m_s.cutUvs.push_back(cutUv);
        m_sourceEdge.push_back(source);
        m_origin.push_back(m_s.vertexCount() - 1);
        noteNewVertex();
        return m_s.vertexCount() - 1;
    }

    /// Per-vertex scratch for a vertex just appended.
    void noteNewVertex() {
        m_innerSide.push_back(kNotInner);
        m_copySide.push_back(0);
    }
    static constexpr int kNotInner = 2;
    bool isInner(int v) const { return v >= m_first && m_innerSide[v - m_first] != kNotInner; }

    /// One split point per crossed edge, numbered in the order of the triangles (reproducible).
    void addSplitVertices() {
        for (int t : m_candidates) {
            const Tri q = m_s.triangles[t];
            for (int e = 0; e < 3; ++e)
                for (EdgeSplit& s : splitsOf(q[e], q[(e + 1) % 3]))
                        if (s.vertex < 0)
                            s.vertex = addVertex(s.point, s.uv, {{s.low, 1 - s.t}, {s.high, s.t}}, {s.low, s.high});
        }
    }

    // --- step 4: split the crossed triangles along the cut ---

    /// The boundary points of the cut on triangle q: split points of its crossed edges and its
    /// corners on the sweep, in the triangle's boundary order, with that order (the cycle).
    void boundaryOf(const Tri& q, std::vector<int>& cycle, std::vector<BoundaryPoint>& points) {
        cycle.clear();
        points.clear();
        for (int e = 0; e < 3; ++e) {
            const int a = q[e];
            cycle.push_back(a);
            if (m_t.onSweep.has(a)) {
                auto it = m_holding.find(a);
                if (it == m_holding.end())
                    it = m_holding.emplace(a, trianglesHolding(m_s.positions[a])).first;
                if (!it->second.empty())
                    points.push_back({a, it->second});
            }
            if (const std::span<EdgeSplit> list = splitsOf(a, q[(e + 1) % 3]); !list.empty()) {
                // Along the edge from a: increasing t if a is its low end.
                const bool fromLow = a == list.front().low;
                for (std::size_t k = 0; k < list.size(); ++k) {
                    const EdgeSplit& s = list[fromLow ? k : list.size() - 1 - k];
                    cycle.push_back(s.vertex);
                    points.push_back({s.vertex, trianglesOfFeature(s.sweepTriangle, s.feature)});
                }
            }
        }
    }

    /// Where sweep edge (p, q) (indices, canonical p < q) pierces the interior of the surface
    /// triangle T (canonical corner order), exactly; false if it does not.
    bool pierce(const std::array<Vec3, 3>& T, int p, int q, Pierce& out) const {
        const auto& V = m_sweep.vertices();
        const int sp = orient3d(T[0], T[1], T[2], V[p]), sq = orient3d(T[0], T[1], T[2], V[q]);
        if (sp == 0 || sq == 0 || sp == sq)
            return false;
        const int e0 = orient3d(V[p], V[q], T[0], T[1]), e1 = orient3d(V[p], V[q], T[1], T[2]),
                  e2 = orient3d(V[p], V[q], T[2], T[0]);
        if (e0 == 0 || e0 != e1 || e1 != e2)
            return false;
        const double vp = signedVolume(T[0], T[1], T[2], V[p]), vq = signedVolume(T[0], T[1], T[2], V[q]);
        const double t = std::clamp(vp / (vp - vq), 0.0, 1.0);
        out.point = V[p] + t * (V[q] - V[p]);
        out.uv = (1 - t) * m_sweep.vertexUv(p) + t * m_sweep.vertexUv(q);
        return true;
    }

    enum class TraceEnd { Reached, Border, Failed };

    /// Follows the cut T ∩ sweep from boundary point `from` across sweep triangles (through
    /// the points where sweep edges pierce T) until it reaches another of T's boundary points
    /// (`to` is set to its position in `points`), leaves the sweep inside T (a partial cut), or
    /// cannot be followed (a degenerate configuration).
    TraceEnd trace(const std::array<Vec3, 3>& T, const std::vector<BoundaryPoint>& points, std::size_t from,
                   const std::vector<bool>& used, std::size_t& to, std::vector<Pierce>& path,
                   std::vector<int>& segmentTriangles) const {
        const auto& S = m_sweep.triangles();
        const auto holds = [&](std::size_t k, int triangle) {
            const auto& list = points[k].sweepTriangles;
            return std::find(list.begin(), list.end(), triangle) != list.end();
        };
        bool border = false;
        for (int start : points[from].sweepTriangles) {
            path.clear();
            segmentTriangles.clear();
            int current = start, entry = -1;
            for (std::size_t step = 0; step <= S.size(); ++step) {
                segmentTriangles.push_back(current);
                // One sweep triangle meets T in one segment: a boundary point in it ends the cut.
                for (std::size_t k = 0; k < points.size(); ++k)
                    if (k != from && !used[k] && holds(k, current)) {
                        to = k;
                        return TraceEnd::Reached;
                    }
                int exit = -1, exits = 0;
                Pierce found, at;
                for (int e = 0; e < 3; ++e) {
                    if (e == entry)
                        continue;
                    const int a = S[current][e], b = S[current][(e + 1) % 3];
                    if (pierce(T, std::min(a, b), std::max(a, b), at)) {
                        ++exits;
                        exit = e;
                        found = at;
                    }
                }
                if (exits != 1)
                    break;  // the cut leaves T through its boundary here, or is degenerate
                path.push_back(found);
                const int next = m_neighbour[current][exit];
                if (next < 0) {
                    border = true;
                    break;
                }
                const Tri& n = S[next];
                const int a = S[current][exit], b = S[current][(exit + 1) % 3];
                entry = -1;
                for (int e = 0; e < 3; ++e)
                    if (undirected(n[e], n[(e + 1) % 3]) == undirected(a, b))
                        entry = e;
                current = next;
            }
        }
        path.clear();
        segmentTriangles.clear();
        return border ? TraceEnd::Border : TraceEnd::Failed;
    }

    /// The side of sweep triangle s on which the piece left of the cut segment a -> b lies (the
    /// piece runs counter-clockwise about `normal`, its surface triangle's): tested at a point
    /// just inside the piece next to the segment's middle.
    int pieceSide(int s, const Vec3& a, const Vec3& b, const Vec3& normal) const {
        const Vec3 along = b - a;
        const Vec3 inward = normal.cross(along);
        const double length = inward.norm();
        if (!(length > 0))
            return 0;
        const Vec3 probe = 0.5 * (a + b) + (kProbeFraction * along.norm() / length) * inward;
        const auto& V = m_sweep.vertices();
        const Tri& t = m_sweep.triangles()[s];
        return orient3d(V[t[0]], V[t[1]], V[t[2]], probe);
    }

    /// The side of original corner x of triangle q: from the crossing on one of its edges, or
    /// (a corner next to on-sweep corners only) the side of the sweep's nearest triangle.
    int cornerSide(const Tri& q, int x) {
        for (int e = 0; e < 3; ++e)
            if (q[e] == x || q[(e + 1) % 3] == x)
                if (const std::span<EdgeSplit> list = splitsOf(q[e], q[(e + 1) % 3]); !list.empty())
                    return (x == list.front().low ? list.front() : list.back()).sideOf(x);  // the nearest crossing
        return m_sweep.sideOf(m_s.positions[x]);
    }

    Status splitTriangles() {
        std::vector<int> cycle;
        std::vector<BoundaryPoint> points;
        for (int t : m_candidates) {
            const Tri q = m_s.triangles[t];
            boundaryOf(q, cycle, points);
            if (points.empty())
                continue;
            bool split = false;
            for (const BoundaryPoint& p : points)
                split = split || p.vertex >= m_first;
            if (!split && points.size() < 2)
                continue;  // one corner on the sweep: the cut only touches the triangle there
            if (Status s = splitTriangle(t, q, cycle, points); !s.ok())
                return s;
        }
        return Status::success();
    }

    /// Splits triangle t (corners q, boundary `cycle` with its cut `points`) into the pieces
    /// the cut polylines bound, and records the cut edges and each piece's side.
    Status splitTriangle(int t, const Tri& q, const std::vector<int>& cycle, const std::vector<BoundaryPoint>& points) {
        const std::vector<std::vector<int>> polylines = cutPolylines(q, points);
        std::vector<std::vector<int>> polygons;
        if (Status s = cutPolygons(cycle, polylines, polygons); !s.ok())
            return s;
        for (const auto& line : polylines)
            for (std::size_t k = 0; k < line.size(); ++k) {
                m_t.cutVertices.insert(line[k]);
                if (k + 1 < line.size())
                    m_t.cutEdges.insert(undirected(line[k], line[k + 1]), 1);
            }
        // The edges of q each boundary point lies on (bit e: edge q[e] -> q[e + 1]).
        EdgeBits edgesOf;
        for (std::size_t k = 0, e = 2; k < cycle.size(); ++k) {
            const int v = cycle[k];
            if (v == q[(e + 1) % 3]) {
                e = (e + 1) % 3;
                edgesOf.of(v) = (1 << e) | (1 << (e + 2) % 3);
            } else {
                edgesOf.of(v) |= 1 << e;
            }
        }
        return emitPieces(t, q, polygons, pieceSides(q, polygons), edgesOf);
    }

    /// The cut's polylines through triangle q, from boundary point to boundary point, traced on
    /// the sweep (each segment's sweep triangle is recorded for the side probes).
    std::vector<std::vector<int>> cutPolylines(const Tri& q, const std::vector<BoundaryPoint>& points) {
        const auto& P = m_s.positions;
        std::array<int, 3> order{q[0], q[1], q[2]};
        std::sort(order.begin(), order.end(), [&](int a, int b) { return precedes(P[a], a, P[b], b); });
        const std::array<Vec3, 3> T{P[order[0]], P[order[1]], P[order[2]]};
        std::vector<std::vector<int>> polylines;
        std::vector<bool> used(points.size(), false);
        std::vector<Pierce> path;
        std::vector<int> visited;
        // Pierce points all but on top of a point before them or of the end (the sweep's edge
        // passes within rounding of the triangle's edge) are dropped: they would only make
        // needles, and their (u, v) could not be told apart from their neighbours'.
        const double tiny = kCoincidentFraction * std::max({(P[q[1]] - P[q[0]]).norm(), (P[q[2]] - P[q[1]]).norm(),
                                                             (P[q[0]] - P[q[2]]).norm()});
        for (std::size_t a = 0; a < points.size(); ++a) {
            std::size_t b = 0;
            if (used[a] || trace(T, points, a, used, b, path, visited) != TraceEnd::Reached)
                continue;
            used[a] = used[b] = true;
            std::vector<int> line{points[a].vertex}, lineTriangles{visited.front()};
            Vec3 last = P[points[a].vertex];
            const Vec3 end = P[points[b].vertex];
            for (std::size_t k = 0; k < path.size(); ++k)
                if ((path[k].point - last).norm() > tiny && (path[k].point - end).norm() > tiny) {
                    line.push_back(addPierceVertex(q, path[k]));
                    lineTriangles.push_back(visited[k + 1]);
                    last = path[k].point;
                }
            line.push_back(points[b].vertex);
            for (std::size_t k = 0; k + 1 < line.size(); ++k)
                m_t.segmentTriangle.set(undirected(line[k], line[k + 1]), lineTriangles[k]);
            polylines.push_back(std::move(line));
        }
        // Two boundary points that could not be traced to each other (a degenerate meeting of
        // the sweep with the triangle): the chord between them, unless one ends a partial cut.
        if (polylines.empty() && points.size() == 2) {
            std::size_t b = 0;
            const std::vector<bool> none(points.size(), false);
            const bool partial = trace(T, points, 0, none, b, path, visited) == TraceEnd::Border ||
                                 trace(T, points, 1, none, b, path, visited) == TraceEnd::Border;
            if (!partial) {
                polylines.push_back({points[0].vertex, points[1].vertex});
                m_t.segmentTriangle.set(undirected(points[0].vertex, points[1].vertex), points[0].sweepTriangles.front());
            }
        }
        return polylines;
    }

    /// The pieces of a triangle: its boundary `cycle` cut by each polyline in turn (every
    /// polyline joins two points on the boundary of one piece so far).
    static Status cutPolygons(const std::vector<int>& cycle, const std::vector<std::vector<int>>& polylines,
                              std::vector<std::vector<int>>& polygons) {
        polygons = {cycle};
        for (const auto& line : polylines) {
            int owner = -1;
            for (std::size_t k = 0; k < polygons.size() && owner < 0; ++k) {
                const auto& poly = polygons[k];
                if (std::count(poly.begin(), poly.end(), line.front()) && std::count(poly.begin(), poly.end(), line.back()))
                    owner = static_cast<int>(k);
            }
            if (owner < 0)
                return Status::error("two cuts cross inside one surface triangle");
            const std::vector<int> poly = polygons[owner];
            const int n = static_cast<int>(poly.size());
            const int ia = static_cast<int>(std::find(poly.begin(), poly.end(), line.front()) - poly.begin());
            const int ib = static_cast<int>(std::find(poly.begin(), poly.end(), line.back()) - poly.begin());
            std::vector<int> first, second;
            for (int i = ia;; i = (i + 1) % n) {
                first.push_back(poly[i]);
                if (i == ib)
                    break;
            }
            for (std::size_t k = line.size() - 2; k >= 1; --k)
                first.push_back(line[k]);
            for (int i = ib;; i = (i + 1) % n) {
                second.push_back(poly[i]);
                if (i == ia)
                    break;
            }
            for (std::size_t k = 1; k + 1 < line.size(); ++k)
                second.push_back(line[k]);
            polygons[owner] = std::move(first);
            polygons.push_back(std::move(second));
        }
        return Status::success();
    }

    /// Each piece's side of the sweep: from a segment of the cut on its boundary (the side of
    /// that segment's sweep triangle a point just inside the piece lies on: the two pieces
    /// beside a segment always get opposite sides), else from an original corner off the cut;
    /// 0 where neither tells (assignSides fills those in from neighbours). A (nearly) flat
    /// triangle, a sliver an earlier degenerate cut left, has no plane to probe in.
    std::vector<int> pieceSides(const Tri& q, const std::vector<std::vector<int>>& polygons) {
        const auto& P = m_s.positions;
        std::vector<int> side(polygons.size(), 0);
        const Vec3 normal = (P[q[1]] - P[q[0]]).cross(P[q[2]] - P[q[0]]);
        const double longest = std::max({(P[q[1]] - P[q[0]]).squaredNorm(), (P[q[2]] - P[q[1]]).squaredNorm(),
                                         (P[q[0]] - P[q[2]]).squaredNorm()});
        if (!(normal.norm() > kFlatRatio * longest))
            return side;
        for (std::size_t k = 0; k < polygons.size(); ++k) {
            const auto& poly = polygons[k];
            for (std::size_t i = 0; i < poly.size() && side[k] == 0; ++i) {
                const int a = poly[i], b = poly[(i + 1) % poly.size()];
                const int* segment = m_t.segmentTriangle.find(undirected(a, b));
                if (a != b && segment)
                    side[k] = pieceSide(*segment, P[a], P[b], normal);
            }
            for (int v : poly)
                if (v < m_first && !m_t.cutVertices.has(v) && side[k] == 0)
                    side[k] = cornerSide(q, v);
        }
        return side;
    }

    /// Triangulates every piece in triangle t's plane; the first triangle takes t's slot, the
    /// others are appended (inheriting t's cut-face flag).
    Status emitPieces(int t, const Tri& q, const std::vector<std::vector<int>>& polygons, const std::vector<int>& side,
                      const EdgeBits& edgesOf) {
        const auto& P = m_s.positions;
        const Vec3 n = (P[q[1]] - P[q[0]]).cross(P[q[2]] - P[q[0]]).cwiseAbs();
        const int drop = n.x() >= n.y() ? (n.x() >= n.z() ? 0 : 2) : (n.y() >= n.z() ? 1 : 2);
        // A flat triangle (its corners collinear; a sliver an earlier degenerate cut left) has
        // no orientation: its pieces are then only combinatorial, which is all they need.
        const int sign = orient2dProjected(P[q[0]], P[q[1]], P[q[2]], drop) >= 0 ? 1 : -1;
        bool first = true;
        const std::uint8_t flag = m_s.cutFaces[t];
        for (std::size_t k = 0; k < polygons.size(); ++k) {
            std::vector<int> poly;
            for (int v : polygons[k])
                if (poly.empty() || v != poly.back())
                    poly.push_back(v);
            while (poly.size() > 1 && poly.back() == poly.front())
                poly.pop_back();
            if (poly.size() < 3)
                continue;
            std::vector<Tri> pieces;
            if (Status s = triangulatePiece(t, q, poly, drop, sign, side[k], edgesOf, pieces); !s.ok())
                return s;
            for (const Tri& piece : pieces) {
                int index;
                if (first) {
                    m_edit.replace(t, piece);
                    index = t;
                    first = false;
                } else {
                    m_s.triangles.push_back(piece);
                    m_s.cutFaces.push_back(flag);
                    index = m_s.triangleCount() - 1;
                }
                m_pieces.push_back(index);
                setSide(index, side[k]);
            }
        }
        return Status::success();
    }

    /// Triangulates one piece of triangle q (polygon `poly` in its plane) without an edge
    /// between two points of the cut: by ear clipping, and where the cut bulges so that only
    /// such ears are left, by a fan from a new vertex inside the rest (its centroid, if it sees
    /// the whole rest), else by ear clipping the rest with such edges and then splitting each
    /// of them at its middle (splitInnerCutEdges).
    /// Why no such edge: the two points are also consecutive or nearly so on the cap's
    /// boundary, and the cap is triangulated in (u, v), where the cut may bend the other way
    /// than in q's plane; the cap would then close the same few points with its own triangles
    /// and the surface would pinch into a pocket (an edge of four triangles).
    Status triangulatePiece(int t, const Tri& q, const std::vector<int>& poly, int drop, int sign, int side,
                            const EdgeBits& edgesOf, std::vector<Tri>& out) {
        const auto onCut = [&](int v) { return (v >= m_first && !isInner(v)) || m_t.cutVertices.has(v); };
        const auto onOneEdge = [&](int a, int b) {
            const int* ia = edgesOf.find(a);
            const int* ib = edgesOf.find(b);
            return ia && ib && (*ia & *ib) != 0;
        };
        std::vector<int> rest;
        if (!earClip(poly, m_s.positions, drop, sign, onCut, onOneEdge, false, out, rest))
            return Status::error("a piece of a cut surface triangle is not a simple polygon");
        if (rest.empty())
            return Status::success();
        Vec3 centre = Vec3::Zero();
        std::vector<std::pair<int, double>> average;
        for (int v : rest) {
            centre += m_s.positions[v] / static_cast<double>(rest.size());
            average.emplace_back(v, 1.0 / static_cast<double>(rest.size()));
        }
        if (fansFrom(centre, rest, m_s.positions, drop, sign)) {
            const int c = addInnerVertex(t, q, average, side);
            for (std::size_t i = 0; i < rest.size(); ++i)
                out.push_back({c, rest[i], rest[(i + 1) % rest.size()]});
            return Status::success();
        }
        std::vector<Tri> clipped;
        std::vector<int> none;
        if (!earClip(rest, m_s.positions, drop, sign, onCut, onOneEdge, true, clipped, none))
            return Status::error("a piece of a cut surface triangle is not a simple polygon");
        splitInnerCutEdges(t, q, side, onCut, clipped, out);
        return Status::success();
    }

    /// Triangles `clipped` (a triangulation of one piece of triangle q) with every inner edge
    /// between two points of the cut split at its middle (a new inner vertex, shared by the two
    /// triangles beside the edge: the triangulation stays a disc with the same boundary). A
    /// triangle with k split edges becomes k + 1 triangles, fanned from one of its new
    /// vertices; a triangle of three cut points with no inner edge (the whole rest) is fanned
    /// from its centroid. Appends to `out`.
    template <class OnCut>
    void splitInnerCutEdges(int t, const Tri& q, int side, const OnCut& onCut, const std::vector<Tri>& clipped,
                            std::vector<Tri>& out) {
        std::unordered_map<std::uint64_t, int> uses;
        for (const Tri& c : clipped)
            for (int e = 0; e < 3; ++e)
                ++uses[undirected(c[e], c[(e + 1) % 3])];
        std::unordered_map<std::uint64_t, int> middle;  // inner cut-to-cut edge -> its middle vertex
        for (const Tri& c : clipped)
            for (int e = 0; e < 3; ++e) {
                const int a = c[e], b = c[(e + 1) % 3];
                const std::uint64_t key = undirected(a, b);
                if (uses[key] == 2 && onCut(a) && onCut(b) && !middle.count(key))
                    middle[key] = addInnerVertex(t, q, {{a, 0.5}, {b, 0.5}}, side);
            }
        for (const Tri& c : clipped) {
            std::vector<int> ring;
            int hub = -1;
            for (int e = 0; e < 3; ++e) {
                ring.push_back(c[e]);
                if (auto it = middle.find(undirected(c[e], c[(e + 1) % 3])); it != middle.end()) {
                    if (hub < 0)
                        hub = static_cast<int>(ring.size());
                    ring.push_back(it->second);
                }
            }
            if (hub < 0 && onCut(c[0]) && onCut(c[1]) && onCut(c[2])) {
                const int g = addInnerVertex(t, q, {{c[0], 1.0 / 3}, {c[1], 1.0 / 3}, {c[2], 1.0 / 3}}, side);
                for (int e = 0; e < 3; ++e)
                    out.push_back({g, c[e], c[(e + 1) % 3]});
                continue;
            }
            if (hub < 0) {
                out.push_back(c);
                continue;
            }
            // A fan from a new vertex on the triangle's boundary keeps the triangle's
            // orientation; no fan triangle has two corners on one edge with it.
            std::rotate(ring.begin(), ring.begin() + hub, ring.end());
            for (std::size_t i = 1; i + 1 < ring.size(); ++i)
                out.push_back({ring[0], ring[i], ring[i + 1]});
        }
    }

    /// A new vertex inside a piece of triangle t (corners q), on side `side` of the sweep, at
    /// the weighted mean `from` of some of the piece's vertices: it is on no cut. Its texture
    /// coordinates and rest position are interpolated in q (from the mean, where q is too flat
    /// to have barycentric coordinates); inside a piece of an earlier cut face it takes that
    /// face's (u, v) the same way.
    int addInnerVertex(int t, const Tri& q, const std::vector<std::pair<int, double>>& from, int side) {
        const auto& P = m_s.positions;
        Vec3 p = Vec3::Zero();
        for (const auto& [v, w] : from)
            p += w * P[v];
        const Vec3 w = closestPointBarycentric(p, P[q[0]], P[q[1]], P[q[2]]);
        std::vector<std::pair<int, double>> weights = from;
        if (w.allFinite())
            weights = {{q[0], w[0]}, {q[1], w[1]}, {q[2], w[2]}};
        Vec2 uv = Vec2::Constant(std::numeric_limits<double>::quiet_NaN());
        if (m_s.cutFaces[t]) {
            uv = Vec2::Zero();
            for (const auto& [v, wv] : weights)
                uv += wv * m_s.cutUvs[v];
        }
        const int c = addVertex(p, uv, weights, {q[0], q[1]});
        m_innerSide[c - m_first] = side;
        return c;
    }

    /// A new vertex where a sweep edge pierces triangle q.
    int addPierceVertex(const Tri& q, const Pierce& p) {
        const auto& P = m_s.positions;
        const Vec3 w = closestPointBarycentric(p.point, P[q[0]], P[q[1]], P[q[2]]);
        return addVertex(p.point, p.uv, {{q[0], w[0]}, {q[1], w[1]}, {q[2], w[2]}}, {q[0], q[1]});
    }

    // --- step 5: separate the sides ---

    /// Every vertex on the cut gets one copy per group of its triangles that stay connected
    /// through edges not on the cut (as the tets' separate step does, section 4.4): a split
    /// point between two sides gets two, the end of a partial cut (a face vertex of the paper)
    /// stays one, shared by both sides.
    /// The triangles the cut touches: the pieces of split triangles and every triangle around
    /// a surface vertex on the cut.
    void collectTouched() {
        std::vector<int> scan = m_pieces;
        for (int t : m_candidates)
            for (int v : m_s.triangles[t])
                if (v < m_first && m_t.cutVertices.has(v)) {
                    scan.push_back(t);
                    break;
                }
        std::sort(scan.begin(), scan.end());
        scan.erase(std::unique(scan.begin(), scan.end()), scan.end());
        m_touched = std::move(scan);
    }

    /// Sides (+1 / -1 of the sweep) of the touched triangles. The pieces of split triangles
    /// have theirs from splitTriangle (probed next to a cut segment, so the two pieces beside a
    /// segment always get opposite sides). Other touched triangles (around a surface vertex on
    /// the cut) are probed the same way next to a cut edge they have, or else take the side of
    /// a neighbour across an edge not on the cut, preferably one away from the ends of partial
    /// cuts (groupFans). (No global 2-colouring: around the end of a partial cut the two sides
    /// are one region.)
    void assignSides() {
        const auto& P = m_s.positions;
        // The touched triangles of every edge, in the order of m_touched (linked lists).
        m_edgeLists.clear();
        m_edgeEntries.clear();
        m_t.byEdge.clear();
        for (int t : m_touched) {
            const Tri& q = m_s.triangles[t];
            for (int e = 0; e < 3; ++e) {
                const auto [list, added] = m_t.byEdge.insert(undirected(q[e], q[(e + 1) % 3]),
                                                             static_cast<int>(m_edgeLists.size()));
                const int entry = static_cast<int>(m_edgeEntries.size());
                m_edgeEntries.push_back({t, -1});
                if (added) {
                    m_edgeLists.push_back({entry, entry, 1});
                } else {
                    auto& l = m_edgeLists[*list];
                    m_edgeEntries[l[1]][1] = entry;
                    l[1] = entry;
                    ++l[2];
                }
            }
            if (sideOf(t) != 0)
                continue;
            const Vec3 normal = (P[q[1]] - P[q[0]]).cross(P[q[2]] - P[q[0]]);
            const double longest = std::max({(P[q[1]] - P[q[0]]).squaredNorm(), (P[q[2]] - P[q[1]]).squaredNorm(),
                                             (P[q[0]] - P[q[2]]).squaredNorm()});
            if (!(normal.norm() > kFlatRatio * longest))
                continue;
            for (int e = 0; e < 3 && sideOf(t) == 0; ++e) {
                if (const int* s = m_t.segmentTriangle.find(undirected(q[e], q[(e + 1) % 3])))
                    setSide(t, pieceSide(*s, P[q[e]], P[q[(e + 1) % 3]], normal));
            }
        }
        const auto trianglesOf = [&](std::uint64_t key, int* out) {  // up to two; returns the count
            const auto& l = m_edgeLists[*m_t.byEdge.find(key)];
            if (l[2] <= 2) {
                out[0] = m_edgeEntries[l[0]][0];
                out[1] = m_edgeEntries[l[1]][0];
            }
            return l[2];
        };
        // Where the cut separates cleanly, the sides follow from the topology alone: 2-colour
        // the touched triangles (an edge on the cut joins different colours, any other edge the
        // same) and give each coloured group the sign most of its probes vote for. A group with
        // a contradiction (around the end of a partial cut both sides are one region) keeps its
        // probed sides.
        StampedMarks& colour = m_t.colour;
        std::vector<int> group;
        for (int seed : m_touched) {
            if (colour.has(seed))
                continue;
            group.assign(1, seed);
            colour.set(seed, 1);
            bool consistent = true;
            for (std::size_t i = 0; i < group.size(); ++i) {
                const int t = group[i];
                const Tri& q = m_s.triangles[t];
                for (int e = 0; e < 3; ++e) {
                    const std::uint64_t key = undirected(q[e], q[(e + 1) % 3]);
                    int list[2];
                    if (trianglesOf(key, list) != 2)
                        continue;
                    const int other = list[0] == t ? list[1] : list[0];
                    const int wanted = m_t.cutEdges.contains(key) ? -colour.get(t) : colour.get(t);
                    if (colour.has(other)) {
                        consistent = consistent && colour.get(other) == wanted;
                        continue;
                    }
                    colour.set(other, wanted);
                    group.push_back(other);
                }
            }
            if (!consistent)
                continue;
            int vote = 0;
            for (int t : group)
                vote += sideOf(t) * colour.get(t);
            const int sign = vote >= 0 ? 1 : -1;
            for (int t : group)
                setSide(t, sign * colour.get(t));
        }
        // The rest take the side of a neighbour across an edge not on the cut: first only
        // across edges away from the ends of partial cuts, where the sides meet (a side read
        // across such an edge can be the wrong one: on a flat sliver next to the end, both
        // pieces beside the cut's last segment would get the side of the triangle beyond the
        // end, and the cut edge would have no - triangle); then across any.
        propagateSides(false);
        propagateSides(true);
    }

    /// Gives every side-0 touched triangle the side of a neighbour across an edge not on the cut
    /// (breadth first from the triangles with a side); `atEnds`: also across edges with an end of
    /// a partial cut (m_t.shared, from groupFans) for a corner.
    void propagateSides(bool atEnds) {
        std::vector<int> queue;
        for (int t : m_touched)
            if (sideOf(t) != 0)
                queue.push_back(t);
        for (std::size_t i = 0; i < queue.size(); ++i) {
            const int t = queue[i];
            const Tri& q = m_s.triangles[t];
            for (int e = 0; e < 3; ++e) {
                const int a = q[e], b = q[(e + 1) % 3];
                const std::uint64_t key = undirected(a, b);
                if (m_t.cutEdges.contains(key) || (!atEnds && (m_t.shared.has(a) || m_t.shared.has(b))))
                    continue;
                for (int k = m_edgeLists[*m_t.byEdge.find(key)][0]; k >= 0; k = m_edgeEntries[k][1]) {
                    const int other = m_edgeEntries[k][0];
                    if (sideOf(other) == 0) {
                        setSide(other, sideOf(t));
                        queue.push_back(other);
                    }
                }
            }
        }
    }

    /// Side of the sweep of triangle t (0: not known).
    int sideOf(int t) const { return m_t.side.get(t); }
    void setSide(int t, int side) { m_t.side.set(t, side); }

    /// The touched triangles around every vertex on the cut (every new vertex, split and pierce
    /// points, and every surface vertex on a polyline; m_fanVertices, sorted, and
    /// m_incidentLists), grouped by the edges not on the cut that join them (m_fanLabels,
    /// m_fanCounts). A vertex with one group is an end of a partial cut (the paper's face
    /// vertex): it goes to m_t.shared. Topology only, so that assignSides can use the ends.
    void groupFans() {
        m_fanVertices.clear();
        const auto trianglesAt = [&](int v) -> std::vector<int>& {
            if (m_t.incident.insert(v, static_cast<int>(m_fanVertices.size()))) {
                if (m_incidentLists.size() <= m_fanVertices.size())
                    m_incidentLists.emplace_back();
                m_incidentLists[m_fanVertices.size()].clear();
                m_fanVertices.push_back(v);
            }
            return m_incidentLists[m_t.incident.get(v)];
        };
        for (int t : m_touched)
            for (int v : m_s.triangles[t])
                if ((v >= m_first && !isInner(v)) || m_t.cutVertices.has(v))
                    trianglesAt(v).push_back(t);
        std::sort(m_fanVertices.begin(), m_fanVertices.end());
        m_fanLabels.resize(m_incidentLists.size());
        m_fanCounts.resize(m_incidentLists.size());
        std::vector<std::pair<int, int>> byNeighbour;  // neighbour vertex -> a triangle with edge (c, it)
        for (int c : m_fanVertices) {
            const int fan = m_t.incident.get(c);
            const std::vector<int>& tris = m_incidentLists[fan];
            UnionFind groups(static_cast<int>(tris.size()));
            byNeighbour.clear();
            for (int i = 0; i < static_cast<int>(tris.size()); ++i) {
                const Tri& q = m_s.triangles[tris[i]];
                const int at = static_cast<int>(std::find(q.begin(), q.end(), c) - q.begin());
                for (int x : {q[(at + 1) % 3], q[(at + 2) % 3]}) {
                    if (m_t.cutEdges.contains(undirected(c, x)))
                        continue;
                    const auto it = std::find_if(byNeighbour.begin(), byNeighbour.end(),
                                                 [&](const auto& entry) { return entry.first == x; });
                    if (it == byNeighbour.end())
                        byNeighbour.emplace_back(x, i);
                    else
                        groups.unite(i, it->second);
                }
            }
            m_fanCounts[fan] = groups.compact(m_fanLabels[fan]);
            if (m_fanCounts[fan] == 1 && m_t.shared.insert(c))
                m_sharedList.push_back(c);
        }
    }

    /// Every vertex on the cut gets one copy per group of its triangles (groupFans); the
    /// triangles with no side yet take their group's.
    void separateSides() {
        // Surface vertices on the cut get their (u, v) on the sweep (for the caps).
        for (int v : m_fanVertices)
            if (v < m_first)
                m_edit.setCutUv(v, m_sweep.closestPoint(m_s.positions[v]).uv);
        for (int c : m_fanVertices) {
            const int fan = m_t.incident.get(c);
            const std::vector<int>& tris = m_incidentLists[fan];
            const std::vector<int>& label = m_fanLabels[fan];
            const int count = m_fanCounts[fan];
            std::vector<int> groupSide(count, 0);
            for (int i = 0; i < static_cast<int>(tris.size()); ++i)
                if (groupSide[label[i]] == 0)
                    groupSide[label[i]] = sideOf(tris[i]);
            for (int i = 0; i < static_cast<int>(tris.size()); ++i)
                if (sideOf(tris[i]) == 0)
                    setSide(tris[i], groupSide[label[i]]);
            if (count == 1)
                continue;  // an end of a partial cut (m_t.shared)
            if (c >= m_first)
                m_copySide[c - m_first] = groupSide[0];
            for (int g = 1; g < count; ++g) {
                const int copy = copyVertex(c);
                m_copySide[copy - m_first] = groupSide[g];
                for (int i = 0; i < static_cast<int>(tris.size()); ++i) {
                    if (label[i] != g)
                        continue;
                    Tri r = m_s.triangles[tris[i]];
                    std::replace(r.begin(), r.end(), c, copy);
                    m_edit.replace(tris[i], r);
                }
            }
        }
    }

    int copyVertex(int c) {
        m_s.positions.push_back(m_s.positions[c]);
        if (!m_s.uvs.empty())
            m_s.uvs.push_back(m_s.uvs[c]);
        if (m_rest)
            m_rest->push_back((*m_rest)[c]);
        const Vec2 uv = m_s.cutUvs[c];
        m_s.cutUvs.push_back(uv);
        const std::array<int, 2> source = c < m_first ? std::array<int, 2>{c, c} : m_sourceEdge[c - m_first];
        const int origin = c < m_first ? c : m_origin[c - m_first];
        m_sourceEdge.push_back(source);
        m_origin.push_back(origin);
        noteNewVertex();
        return m_s.vertexCount() - 1;
    }

    int originOf(int v) const { return v >= m_first ? m_origin[v - m_first] : v; }

    // --- step 6: the cut's boundary loops ---

    Status traceBoundary(std::vector<std::vector<int>>& loops) {
        // Boundary edges join two cut vertices; every triangle holding such an edge holds a
        // cut vertex, so the opposite half-edge, if any, is among the touched triangles.
        const auto onCut = [&](int v) { return m_t.cutVertices.has(originOf(v)); };
        const std::vector<int>& tris = m_touched;
        for (int t : tris) {
            const Tri& q = m_s.triangles[t];
            for (int e = 0; e < 3; ++e)
                m_t.halfEdges.insert(directed(q[e], q[(e + 1) % 3]), 1);
        }
        StampedMarks& next = m_t.next;  // a -> b for boundary edge a -> b
        std::vector<int> starts;
        for (int t : tris) {
            const Tri& q = m_s.triangles[t];
            for (int e = 0; e < 3; ++e) {
                const int a = q[e], b = q[(e + 1) % 3];
                if (!onCut(a) || !onCut(b) || m_t.halfEdges.contains(directed(b, a)))
                    continue;
                if (!next.insert(a, b))
                    return Status::error("the cut boundary is not a set of simple loops (non-manifold cut)");
                starts.push_back(a);
                m_t.edgeSide.set(directed(a, b), sideOf(t));
            }
        }
        std::sort(starts.begin(), starts.end());
        StampedMarks& visited = m_t.visited;
        for (int start : starts) {
            if (visited.has(start))
                continue;
            std::vector<int> loop;
            for (int v = start; !visited.has(v);) {
                visited.set(v, 1);
                loop.push_back(v);
                if (!next.has(v))
                    return Status::error("the cut boundary is open (the surface was not closed)");
                v = next.get(v);
            }
            loops.push_back(std::move(loop));
        }
        m_out.loops = static_cast<int>(loops.size());
        return Status::success();
    }

    // --- step 7: caps (section 5.2) ---

    /// Position of a (u, v) on the border of the sweep's parameter square, counter-clockwise
    /// from (0, 0): the bottom (v = 0) gives u, the right 1 + v, the top 3 - u, the left 4 - v;
    /// a point inside goes to the nearest side.
    static double perimeterAt(const Vec2& uv) {
        const double u = std::clamp(uv.x(), 0.0, 1.0), v = std::clamp(uv.y(), 0.0, 1.0);
        const double d[4] = {v, 1 - u, 1 - v, u};
        const int side = static_cast<int>(std::min_element(d, d + 4) - d);
        switch (side) {
        case 0: return u;
        case 1: return 1 + v;
        case 2: return 3 - u;
        default: return 4 - v;
        }
    }

    /// The + side's cap polygons of one piece. The + boundary runs counter-clockwise around the
    /// cap in (u, v) (the parameterisation is counter-clockwise seen from the + side the
    /// sweep's normal points to, and a piece's boundary runs against its cap's). Whole loops of
    /// + edges are polygons as they are. A loop through shared vertices (the ends of a partial
    /// cut, where the sweep's border lies inside the tissue: the paper's face vertices) is cut
    /// there into lips; the + lips are joined in the order their ends meet the sweep's border,
    /// going counter-clockwise along it, by chords (the paper's jump from one face vertex to the
    /// next): the cap then covers the sweep up to its border, even when the border crosses the
    /// surface several times.
    Status plusPolygons(const std::vector<std::vector<int>>& loops, std::vector<std::vector<int>>& out) {
        return sidePolygons(loops, 1, out);
    }

    /// The same for either side: the - boundary runs clockwise around its cap, so its lips
    /// are joined going clockwise along the border.
    Status sidePolygons(const std::vector<std::vector<int>>& loops, int sign, std::vector<std::vector<int>>& out) {
        std::vector<std::vector<int>> arcs;
        for (const auto& loop : loops) {
            const int n = static_cast<int>(loop.size());
            std::vector<int> cuts;
            for (int i = 0; i < n; ++i)
                if (m_t.shared.has(loop[i]))
                    cuts.push_back(i);
            const auto sideAt = [&](int i) { return m_t.edgeSide.get(directed(loop[i], loop[(i + 1) % n])); };
            if (cuts.empty()) {
                if (sideAt(0) == 0)
                    return Status::error("a cut-boundary loop lies on no side of the sweep");
                if (sideAt(0) == sign)
                    out.push_back(loop);
                continue;
            }
            for (std::size_t k = 0; k < cuts.size(); ++k) {
                const int a = cuts[k], b = cuts[(k + 1) % cuts.size()];
                if (sideAt(a) != sign)
                    continue;
                std::vector<int> arc;
                for (int i = a;; i = (i + 1) % n) {
                    arc.push_back(loop[i]);
                    if (i == b && arc.size() > 1)
                        break;
                }
                arcs.push_back(std::move(arc));
            }
        }
        if (arcs.empty())
            return Status::success();
        // Ends and starts of the lips along the border; they must alternate (end, start, ...).
        struct Stop {
            double at;
            int arc;
            bool start;
        };
        std::vector<Stop> stops;
        for (int a = 0; a < static_cast<int>(arcs.size()); ++a) {
            // Clockwise for the - side: the perimeter read backwards.
            const double front = perimeterAt(m_s.cutUvs[arcs[a].front()]);
            const double back = perimeterAt(m_s.cutUvs[arcs[a].back()]);
            stops.push_back({sign > 0 ? front : 4 - front, a, true});
            stops.push_back({sign > 0 ? back : 4 - back, a, false});
        }
        std::sort(stops.begin(), stops.end(), [](const Stop& x, const Stop& y) {
            return x.at != y.at ? x.at < y.at : (x.start ? 1 : 0) < (y.start ? 1 : 0);
        });
        const int m = static_cast<int>(stops.size());
        std::vector<int> next(arcs.size(), -1);
        for (int i = 0; i < m; ++i)
            if (!stops[i].start) {
                const Stop& following = stops[(i + 1) % m];
                if (!following.start) {
                    next.assign(arcs.size(), -1);  // not alternating: each lip closes itself
                    break;
                }
                next[stops[i].arc] = following.arc;
            }
        std::vector<bool> used(arcs.size(), false);
        for (int a = 0; a < static_cast<int>(arcs.size()); ++a) {
            if (used[a])
                continue;
            std::vector<int> polygon;
            for (int b = a; b >= 0 && !used[b]; b = next[b]) {
                used[b] = true;
                for (int v : arcs[b])
                    if (polygon.empty() || polygon.back() != v)
                        polygon.push_back(v);
                if (next[b] < 0)
                    break;
            }
            while (polygon.size() > 1 && polygon.back() == polygon.front())
                polygon.pop_back();
            if (polygon.size() >= 3)
                out.push_back(std::move(polygon));
        }
        return Status::success();
    }

    /// + copy -> - copy of every vertex on the + side's boundary, from the cut edges (each has
    /// a + and a - triangle); shared vertices are their own mates.
    void findMates() {
        std::unordered_map<std::uint64_t, std::array<int, 2>> sides;  // origin edge -> (+ tri, - tri)
        for (int t : m_touched) {
            const Tri& q = m_s.triangles[t];
            const int s = sideOf(t);
            if (s == 0)
                continue;
            for (int e = 0; e < 3; ++e) {
                const std::uint64_t key = undirected(originOf(q[e]), originOf(q[(e + 1) % 3]));
                if (!m_t.cutEdges.contains(key))
                    continue;
                auto& entry = sides.try_emplace(key, std::array<int, 2>{-1, -1}).first->second;
                entry[s > 0 ? 0 : 1] = t;
            }
        }
        for (const auto& [key, pair] : sides) {
            if (pair[0] < 0 || pair[1] < 0)
                continue;
            const int ends[2] = {static_cast<int>(key >> 32), static_cast<int>(key & 0xffffffffu)};
            for (int u : m_s.triangles[pair[0]]) {
                const int o = originOf(u);
                if (o != ends[0] && o != ends[1])
                    continue;
                for (int w : m_s.triangles[pair[1]])
                    if (originOf(w) == o) {
                        const bool added = addMate(u, w);
                        m_mirrorable = m_mirrorable && (added || m_t.mate.get(u) == w);
                    }
            }
        }
        for (int v : m_sharedList)
            setMate(v, v);
        // Two + copies with one - copy mate (a vertex the cut passes through twice): the caps
        // cannot mirror each other vertex for vertex.
        for (int u : m_mateKeys) {
            const int w = m_t.mate.get(u);
            if (u != w && !m_t.mateOf.insert(w, u))
                m_mirrorable = false;
        }
    }

    /// + copy -> - copy (m_t.mate, keys in m_mateKeys): adds u's mate unless it has one.
    bool addMate(int u, int w) {
        if (!m_t.mate.insert(u, w))
            return false;
        m_mateKeys.push_back(u);
        return true;
    }
    void setMate(int u, int w) {
        if (!addMate(u, w))
            m_t.mate.at(u) = w;
    }
    /// The mate of v, or -1.
    int mateOf(int v) const { return m_t.mate.get(v, -1); }

    /// True if the surface (outside the caps) has the edge (a, b). Only edges between two cut
    /// vertices matter here; they are all in touched triangles.
    bool surfaceHasEdge(int a, int b) {
        if (m_t.surfaceEdges.empty())
            for (int t : m_touched) {
                const Tri& q = m_s.triangles[t];
                for (int e = 0; e < 3; ++e)
                    m_t.surfaceEdges.set(undirected(q[e], q[(e + 1) % 3]), 1);
            }
        return m_t.surfaceEdges.get(undirected(a, b)) != 0;
    }

    /// A cap edge between two boundary vertices that the surface beside it also has (on
    /// either side: the - cap mirrors the + cap), or between two shared vertices (the - cap has
    /// it too), would make that edge belong to four triangles.
    /// Such interior cap edges are flipped away where the two triangles beside them form a
    /// strictly convex quadrilateral in (u, v) (the cap is any triangulation of its loops, so
    /// this only changes which diagonal it uses); any left are split at their middle by a new
    /// cap vertex (splitCapEdge), which always removes them. `uv` and `vertexOf` (the cap's
    /// points) grow by the new vertices. With `mirrored`, the cap is the + cap, mirrored on the
    /// mates (the new vertices get mates too); else it is one side's (`side`) own.
    void avoidSurfaceEdges(std::vector<std::array<int, 3>>& cap, std::vector<Vec2>& uv, std::vector<int>& vertexOf,
                           bool mirrored, int side) {
        const auto forbidden = [&](int a, int b) {
            const int u = vertexOf[a], w = vertexOf[b];
            // Between two shared vertices an interior edge of the + cap is one of the - cap too.
            if (surfaceHasEdge(u, w) || (m_t.shared.has(u) && m_t.shared.has(w)))
                return true;
            const int mu = mateOf(u), mw = mateOf(w);
            return mu >= 0 && mw >= 0 && surfaceHasEdge(mu, mw);
        };
        const auto ccw = [&](int a, int b, int c) {
            return orient2dProjected(Vec3(uv[a].x(), uv[a].y(), 0), Vec3(uv[b].x(), uv[b].y(), 0),
                                     Vec3(uv[c].x(), uv[c].y(), 0), 2) > 0;
        };
        // edge -> (triangle, corner opposite)
        using EdgeMap = std::unordered_map<std::uint64_t, std::vector<std::pair<int, int>>>;
        const auto edgesOf = [&]() {
            EdgeMap edges;
            for (int t = 0; t < static_cast<int>(cap.size()); ++t)
                for (int e = 0; e < 3; ++e)
                    edges[undirected(cap[t][e], cap[t][(e + 1) % 3])].push_back({t, (e + 2) % 3});
            return edges;
        };
        // Most caps have no forbidden interior edge: then there is nothing to flip or split.
        m_t.capEdges.clear();
        m_t.capEdges.reserve(3 * static_cast<int>(cap.size()));
        for (const auto& c : cap)
            for (int e = 0; e < 3; ++e)
                ++*m_t.capEdges.insert(undirected(c[e], c[(e + 1) % 3]), 0).first;
        bool any = false;
        for (const auto& c : cap)
            for (int e = 0; e < 3 && !any; ++e)
                any = m_t.capEdges.get(undirected(c[e], c[(e + 1) % 3])) == 2 && forbidden(c[e], c[(e + 1) % 3]);
        if (!any)
            return;
        for (int round = 0; round < 4; ++round) {
            const EdgeMap edges = edgesOf();
            bool flipped = false;
            std::unordered_set<int> changed;
            for (const auto& [key, list] : edges) {
                if (list.size() != 2 || changed.count(list[0].first) || changed.count(list[1].first))
                    continue;
                const int a = static_cast<int>(key >> 32), b = static_cast<int>(key & 0xffffffffu);
                if (!forbidden(a, b))
                    continue;
                const auto [t1, o1] = list[0];
                const auto [t2, o2] = list[1];
                const int c = cap[t1][o1], d = cap[t2][o2];
                if (c == d || edges.count(undirected(c, d)) || forbidden(c, d))
                    continue;
                // t1 = (x, y, c) with edge x -> y, t2 = (y, x, d): the flip gives (c, x, d), (d, y, c).
                const int x = cap[t1][(o1 + 1) % 3], y = cap[t1][(o1 + 2) % 3];
                if (!ccw(c, x, d) || !ccw(d, y, c))
                    continue;
                cap[t1] = {c, x, d};
                cap[t2] = {d, y, c};
                changed.insert(t1);
                changed.insert(t2);
                flipped = true;
            }
            if (!flipped)
                break;
        }
        // Each split removes one forbidden edge and adds only edges at its new vertex.
        for (bool again = true; again;) {
            again = false;
            const EdgeMap edges = edgesOf();
            for (const auto& [key, list] : edges) {
                const int a = static_cast<int>(key >> 32), b = static_cast<int>(key & 0xffffffffu);
                if (list.size() == 2 && forbidden(a, b)) {
                    splitCapEdge(cap, uv, vertexOf, list[0], list[1], mirrored, side);
                    again = true;
                    break;
                }
            }
        }
    }

    /// Splits the cap edge between triangles `first` and `second` (each: triangle, corner
    /// opposite the edge) at its middle: a new vertex there, in space and in (u, v) (the cap's
    /// shape is unchanged), with a mate for the - cap if `mirrored`.
    void splitCapEdge(std::vector<std::array<int, 3>>& cap, std::vector<Vec2>& uv, std::vector<int>& vertexOf,
                      std::pair<int, int> first, std::pair<int, int> second, bool mirrored, int side) {
        const auto [t1, o1] = first;
        const auto [t2, o2] = second;
        // t1 = (x, y, c) with edge x -> y, t2 = (y, x, d).
        const int x = cap[t1][(o1 + 1) % 3], y = cap[t1][(o1 + 2) % 3], c = cap[t1][o1], d = cap[t2][o2];
        const Vec2 middle = 0.5 * (uv[x] + uv[y]);
        const auto addCapVertex = [&](int u, int w, int vertexSide) {
            const std::array<int, 2> source = u >= m_first ? m_sourceEdge[u - m_first] : std::array<int, 2>{u, w};
            const int v = addVertex(0.5 * (m_s.positions[u] + m_s.positions[w]), middle, {{u, 0.5}, {w, 0.5}}, source);
            m_copySide[v - m_first] = vertexSide;
            return v;
        };
        const int m = static_cast<int>(uv.size());
        uv.push_back(middle);
        vertexOf.push_back(addCapVertex(vertexOf[x], vertexOf[y], side));
        const int mx = mateOf(vertexOf[x]), my = mateOf(vertexOf[y]);
        if (mirrored && mx >= 0 && my >= 0)  // (else closeCaps reports the missing mate)
            setMate(vertexOf[m], addCapVertex(mx, my, -side));
        cap[t1] = {x, m, c};
        cap.push_back({m, y, c});
        cap[t2] = {y, m, d};
        cap.push_back({m, x, d});
    }

    /// A chord joining two lips of a partial cut (sidePolygons) runs between two shared
    /// vertices; where they are neighbours on the surface (the lips end on one surface edge,
    /// next to each other), the chord is that surface edge, and with the + and the - cap on it
    /// besides its two surface triangles it would have four. Such a surface edge is split at its
    /// middle (a new vertex off the cut; the surface keeps its shape), so the chord is an edge
    /// of the caps only.
    Status splitSurfaceEdgesUnderChords(const std::map<int, std::vector<std::vector<int>>>& loopsOfPiece) {
        std::vector<std::array<int, 2>> chords;
        for (const auto& [piece, pieceLoops] : loopsOfPiece)
            for (int sign : {1, -1}) {
                std::vector<std::vector<int>> polygons;
                if (Status s = sidePolygons(pieceLoops, sign, polygons); !s.ok())
                    return s;
                for (const auto& polygon : polygons)
                    for (std::size_t i = 0; i < polygon.size(); ++i) {
                        const int u = polygon[i], w = polygon[(i + 1) % polygon.size()];
                        const bool onLoop = m_t.edgeSide.contains(directed(u, w)) || m_t.edgeSide.contains(directed(w, u));
                        if (!onLoop && surfaceHasEdge(u, w))
                            chords.push_back({u, w});
                    }
            }
        for (const auto& [u, w] : chords)
            if (surfaceHasEdge(u, w))
                splitSurfaceEdge(u, w);
        return Status::success();
    }

    /// Splits the surface edge (u, w) at its middle: each of its two (touched) triangles
    /// becomes two. The new vertex is off the cut, on the side of the triangles beside it (0 if
    /// they differ: next to the end of a partial cut both sides are one region).
    void splitSurfaceEdge(int u, int w) {
        std::vector<int> beside;
        for (int t : m_touched) {
            const Tri& q = m_s.triangles[t];
            if (std::count(q.begin(), q.end(), u) && std::count(q.begin(), q.end(), w))
                beside.push_back(t);
        }
        const auto sourceOf = [&](int v) {
            return v < m_first ? std::array<int, 2>{v, v} : m_sourceEdge[v - m_first];
        };
        const std::array<int, 2> source = u >= m_first ? sourceOf(u) : sourceOf(w);
        const int m = addVertex(0.5 * (m_s.positions[u] + m_s.positions[w]), 0.5 * (m_s.cutUvs[u] + m_s.cutUvs[w]),
                                {{u, 0.5}, {w, 0.5}}, source);

        int side = 0;
        for (std::size_t k = 0; k < beside.size(); ++k) {
            const int s = sideOf(beside[k]);
            side = k == 0 ? s : s == side ? side : 0;
        }
        m_innerSide[m - m_first] = side;
        if (int* present = m_t.surfaceEdges.find(undirected(u, w)))
            *present = 0;
        for (int t : beside) {
            const Tri q = m_s.triangles[t];
            int e = 0;
            while (!((q[e] == u && q[(e + 1) % 3] == w) || (q[e] == w && q[(e + 1) % 3] == u)))
                ++e;
            const int a = q[e], b = q[(e + 1) % 3], x = q[(e + 2) % 3];
            m_edit.replace(t, {a, m, x});
            m_s.triangles.push_back({m, b, x});
            m_s.cutFaces.push_back(m_s.cutFaces[t]);
            const int added = m_s.triangleCount() - 1;
            if (m_t.side.has(t))
                setSide(added, sideOf(t));
            m_touched.push_back(added);
            for (int v : {a, b, x})
                m_t.surfaceEdges.set(undirected(m, v), 1);
        }
    }

    Status closeCaps(const std::vector<std::vector<int>>& loops) {
        m_capStart = m_s.triangleCount();
        if (loops.empty())
            return Status::success();
        findMates();
        // Each piece is closed on its own: loops grouped by the connected component of the
        // surface they bound (pieces may touch along earlier cuts, where their points coincide).
        std::map<int, std::vector<std::vector<int>>> loopsOfPiece;
        if (needsPieces(loops)) {
            UnionFind pieces(m_s.vertexCount());
            for (const Tri& q : m_s.triangles) {
                pieces.unite(q[1], q[0]);
                pieces.unite(q[2], q[0]);
            }
            for (const auto& loop : loops)
                loopsOfPiece[pieces.find(loop[0])].push_back(loop);
        } else {
            loopsOfPiece[0] = loops;
        }
        if (Status s = splitSurfaceEdgesUnderChords(loopsOfPiece); !s.ok())
            return s;
        m_capStart = m_s.triangleCount();  // (the splits appended surface triangles)
        int capCount = 0, closed = 0;
        if (!m_mirrorable)
            return closeEachSide(loopsOfPiece);
        for (const auto& [piece, pieceLoops] : loopsOfPiece) {
            std::vector<std::vector<int>> polygons;
            if (Status s = plusPolygons(pieceLoops, polygons); !s.ok())
                return s;
            if (polygons.empty())
                continue;
            ++closed;
            const int side = 1;  // the + boundary runs counter-clockwise around its cap (plusPolygons)
            std::vector<int> vertexOf;
            std::vector<std::array<int, 3>> cap;
            if (Status s = capInUv(polygons, side, true, vertexOf, cap); !s.ok())
                return s;
            for (const auto& c : cap) {
                // Counter-clockwise in (u, v); the + cap must run against the + boundary.
                Tri plus{vertexOf[c[0]], vertexOf[c[1]], vertexOf[c[2]]};
                if (side > 0)
                    std::swap(plus[1], plus[2]);
                Tri minus;
                for (int k = 0; k < 3; ++k) {
                    const int mate = mateOf(plus[k]);
                    if (mate < 0) {
                        return Status::error("a cut-boundary vertex has no copy on the other side");
                    }
                    minus[k] = mate;
                }
                std::swap(minus[1], minus[2]);
                // A triangle of shared vertices only (between chords of a partial cut) is its own
                // mirror: the two would lie on each other and pinch the surface; neither is needed.
                if (minus[0] == plus[0] && minus[1] == plus[2] && minus[2] == plus[1])
                    continue;
                ++capCount;
                m_s.triangles.push_back(plus);
                m_s.triangles.push_back(minus);
                m_s.cutFaces.push_back(1);
                m_s.cutFaces.push_back(1);
            }
        }
        if (closed == 0)
            return Status::error("the cut boundary has no side to close");
        m_out.capTriangles = 2 * capCount;
        return Status::success();
    }

    /// False where grouping the loops by piece cannot change the caps, so that the pass over the
    /// whole surface that finds the pieces is not needed: a single loop, or mirrored caps of
    /// whole loops (no lips, hence no chords) of which at most one is on the + side (only its
    /// piece gets a cap, whatever the others' pieces; a complete cut through one piece).
    bool needsPieces(const std::vector<std::vector<int>>& loops) const {
        if (loops.size() <= 1)
            return false;
        if (!m_mirrorable)
            return true;
        int plus = 0;
        for (const auto& loop : loops) {
            for (int v : loop)
                if (m_t.shared.has(v))
                    return true;
            if (m_t.edgeSide.get(directed(loop[0], loop[1 % loop.size()])) == 1)
                ++plus;
        }
        return plus > 1;
    }

    /// Triangulates the region bounded by `polygons` (surface vertices) in the sweep's (u, v)
    /// plane, then flips or splits cap edges the surface already has (`mirrored`: both sides'
    /// caps follow). `cap` indexes `vertexOf`, the surface vertex of each point.
    Status capInUv(const std::vector<std::vector<int>>& polygons, int side, bool mirrored, std::vector<int>& vertexOf,
                   std::vector<std::array<int, 3>>& cap) {
        std::vector<Vec2> uv;
        std::vector<std::vector<int>> local;
        for (const auto& polygon : polygons) {
            std::vector<int> loop;
            for (int v : polygon) {
                loop.push_back(static_cast<int>(uv.size()));
                uv.push_back(m_s.cutUvs[v]);
                vertexOf.push_back(v);
            }
            local.push_back(std::move(loop));
        }
        if (Status s = triangulateCap(uv, local, side, cap); !s.ok())
            return s;
        avoidSurfaceEdges(cap, uv, vertexOf, mirrored, side);
        return Status::success();
    }

    /// Where the caps cannot mirror each other (the cut passes through a surface vertex twice,
    /// and one side has two copies of it where the other has one), each side's loops are closed
    /// by their own triangulation in (u, v). The two caps are then only as coincident as the
    /// sweep is flat between their points (exactly, for a flat sweep).
    Status closeEachSide(const std::map<int, std::vector<std::vector<int>>>& loopsOfPiece) {
        int capCount = 0, closed = 0;
        for (const auto& [piece, pieceLoops] : loopsOfPiece)
            for (int sign : {1, -1}) {
                std::vector<std::vector<int>> polygons;
                if (Status s = sidePolygons(pieceLoops, sign, polygons); !s.ok())
                    return s;
                if (polygons.empty())
                    continue;
                ++closed;
                std::vector<int> vertexOf;
                std::vector<std::array<int, 3>> cap;
                if (Status s = capInUv(polygons, sign, false, vertexOf, cap); !s.ok())
                    return s;
                for (const auto& c : cap) {
                    // Counter-clockwise in (u, v): the + cap runs against its boundary, the -
                    // cap (whose region lies right of its boundary) with it.
                    Tri t{vertexOf[c[0]], vertexOf[c[1]], vertexOf[c[2]]};
                    if (sign > 0)
                        std::swap(t[1], t[2]);
                    if (t[0] == t[1] || t[1] == t[2] || t[0] == t[2])
                        continue;
                    m_s.triangles.push_back(t);
                    m_s.cutFaces.push_back(1);
                    ++capCount;
                }
            }
        if (closed == 0)
            return Status::error("the cut boundary has no side to close");
        m_out.capTriangles = capCount;
        return Status::success();
    }

    void finishCounts() {
        m_out.splitEdges = static_cast<int>(m_splitRanges.size());
        for (const EdgeSplit& s : m_splitStore)
            if (m_t.shared.has(s.vertex))
                ++m_out.faceVertices;
        const int added = m_s.vertexCount() - m_first;
        m_out.sourceEdge = m_sourceEdge;
        m_out.sweepUv.assign(m_s.cutUvs.begin() + m_first, m_s.cutUvs.end());
        m_out.side.assign(added, 0);
        for (int v = m_first; v < m_s.vertexCount(); ++v) {
            if (isInner(v)) {
                m_out.side[v - m_first] = m_innerSide[v - m_first];
                continue;
            }
            if (m_t.shared.has(v))
                continue;
            m_out.side[v - m_first] = m_copySide[v - m_first];
        }
    }

    TriangleSurface& m_s;
    std::vector<Vec3>* m_rest;
    const SweepSurface& m_sweep;
    SurfaceCut& m_out;
    SurfaceEdit m_edit;
    const int m_first;

    std::vector<int> m_candidates;
    SurfaceIndex* m_index;
    SurfaceCutWorkspace::Tables& m_t;
    std::vector<EdgeSplit> m_splitStore;                  ///< the crossings, grouped by edge
    std::vector<std::array<int, 2>> m_splitRanges;        ///< per crossed edge (m_t.splits): first, count
    std::unordered_map<int, std::vector<int>> m_holding;  ///< on-sweep vertex -> sweep triangles
    std::vector<std::array<int, 3>> m_neighbour;          ///< sweep triangle -> across each edge
    std::vector<std::vector<int>> m_vertexTriangles;      ///< sweep vertex -> triangles
    std::vector<std::array<int, 2>> m_sourceEdge;         ///< per new vertex
    std::vector<int> m_origin;                            ///< per new vertex: the cut vertex it copies
    std::vector<int> m_pieces;                            ///< triangles made by step 4
    std::vector<int> m_touched;                           ///< triangles at cut vertices
    std::vector<int> m_fanVertices;                       ///< groupFans: the vertices on the cut, sorted
    std::vector<std::vector<int>> m_incidentLists;        ///< groupFans: per vertex on the cut, its triangles
    std::vector<std::vector<int>> m_fanLabels;            ///< groupFans: per vertex on the cut, group of each
    std::vector<int> m_fanCounts;                         ///< groupFans: per vertex on the cut, its groups
    std::vector<std::array<int, 3>> m_edgeLists;          ///< assignSides: per edge head, tail, count
    std::vector<std::array<int, 2>> m_edgeEntries;        ///< assignSides: triangle, next entry
    std::vector<int> m_sharedList;                        ///< cut vertices kept as one (face vertices; m_t.shared)
    std::vector<int> m_copySide;                          ///< per new vertex: its side if a cut vertex copy (else 0)
    std::vector<int> m_mateKeys;                          ///< vertices with a mate (m_t.mate: + copy -> - copy)
    int m_capStart = 0;                                   ///< first cap triangle
    bool m_mirrorable = true;                             ///< every + boundary vertex has one - mate
    /// Per new vertex: its side if it lies inside a piece (fan centres, split surface edges;
    /// off the cut), else kNotInner.
    std::vector<int> m_innerSide;
};

} // namespace

Status cutSurface(TriangleSurface& surface, std::vector<Vec3>* rest, const SweepSurface& sweep, SurfaceCut& out,
                  SurfaceIndex* index, SurfaceCutWorkspace* workspace) {
    out = {};
    out.firstNewVertex = surface.vertexCount();
    if (rest && static_cast<int>(rest->size()) != surface.vertexCount())
        return Status::error("rest positions do not match the surface's vertices");
    if (!surface.uvs.empty() && surface.uvs.size() != surface.positions.size())
        return Status::error("the surface's texture coordinates do not match its vertices");
    std::unique_ptr<SurfaceCutWorkspace> local;
    if (!workspace) {
        local = std::make_unique<SurfaceCutWorkspace>();
        workspace = local.get();
    }
    SurfaceCutter cutter(surface, rest, sweep, out, index, workspace->tables());
    if (Status s = cutter.run(); !s.ok()) {
        const int first = out.firstNewVertex;
        out = {};
        out.firstNewVertex = first;
        return s;
    }
    return Status::success();
}

} // namespace resect
