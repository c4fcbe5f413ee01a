#include "core/embed/cut_surface.h"

#include "core/embed/triangulate_cut.h"
#include "core/mesh/union_find.h"
#include "core/sweep/intersect_segment.h"

#include <algorithm>
#include <limits>
#include <map>
#include <numeric>
#include <unordered_map>
#include <unordered_set>

namespace resect {
namespace {

std::uint64_t key(int a, int b) {
    if (a > b)
        std::swap(a, b);
    return (static_cast<std::uint64_t>(static_cast<std::uint32_t>(a)) << 32) | static_cast<std::uint32_t>(b);
}
std::uint64_t directed(int a, int b) {
    return (static_cast<std::uint64_t>(static_cast<std::uint32_t>(a)) << 32) | static_cast<std::uint32_t>(b);
}

struct Crossing {
    SegmentHit hit;  ///< relative to the direction low -> high vertex index
    int low = -1, high = -1;
    bool shared = false;
    int plus = -1, minus = -1;  ///< the copies on the + and - side (equal if shared)
    int copyFor(int side) const { return side > 0 ? plus : minus; }
};

} // namespace

namespace {

/// Triangles that can touch the sweep: not all three corners strictly beyond one face of the
/// sweep's bounding box (exact comparisons, so no crossing is missed). One pass over the
/// index array, a few nanoseconds a triangle; everything after it costs in proportion to the
/// triangles the sweep touches.
std::vector<int> candidateTriangles(const TriangleSurface& surface, const SweepSurface& sweep) {
    const Vec3 lo = sweep.bounds().min(), hi = sweep.bounds().max();
    // Outcodes of the vertices first (a streaming pass; the byte array stays in cache for
    // the triangle pass that follows).
    std::vector<std::uint8_t> code(surface.positions.size());
    for (std::size_t v = 0; v < code.size(); ++v) {
        const Vec3& p = surface.positions[v];
        code[v] = static_cast<std::uint8_t>((p.x() < lo.x() ? 1 : 0) | (p.x() > hi.x() ? 2 : 0) | (p.y() < lo.y() ? 4 : 0) |
                                            (p.y() > hi.y() ? 8 : 0) | (p.z() < lo.z() ? 16 : 0) | (p.z() > hi.z() ? 32 : 0));
    }
    std::vector<int> out;
    const int n = surface.triangleCount();
    for (int t = 0; t < n; ++t) {
        const Tri& q = surface.triangles[t];
        if ((code[q[0]] & code[q[1]] & code[q[2]]) == 0)
            out.push_back(t);
    }
    return out;
}

/// Undo log of an in-place surface edit: appended data is truncated, replaced triangles are
/// restored. Keeps the promise that a failed cut leaves the surface untouched.
struct SurfaceEdit {
    TriangleSurface& surface;
    std::vector<Vec3>* rest;
    int vertices, triangles;
    std::size_t cutUvs, cutFaces;  ///< sizes before (the arrays may have been empty)
    std::vector<std::pair<int, Tri>> replaced;
    bool committed = false;
    SurfaceEdit(TriangleSurface& s, std::vector<Vec3>* r)
        : surface(s), rest(r), vertices(s.vertexCount()), triangles(s.triangleCount()), cutUvs(s.cutUvs.size()),
          cutFaces(s.cutFaces.size()) {}
    ~SurfaceEdit() {
        if (committed)
            return;
        for (auto it = replaced.rbegin(); it != replaced.rend(); ++it)
            surface.triangles[it->first] = it->second;
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

Status cutSurface(TriangleSurface& surface, std::vector<Vec3>* rest, const SweepSurface& sweep, SurfaceCut& out) {
    out = {};
    out.firstNewVertex = surface.vertexCount();
    if (rest && static_cast<int>(rest->size()) != surface.vertexCount())
        return Status::error("rest positions do not match the surface's vertices");
    if (!surface.uvs.empty() && surface.uvs.size() != surface.positions.size())
        return Status::error("the surface's texture coordinates do not match its vertices");
    // 1. Crossed edges among the candidate triangles (an odd number of crossings: split at
    // the middle one). Both triangles of a crossed edge are candidates.
    const std::vector<int> candidates = candidateTriangles(surface, sweep);
    out.candidateTriangles = static_cast<int>(candidates.size());
    std::unordered_map<std::uint64_t, Crossing> crossings;
    SegmentQuery query;
    std::vector<int> scratch;
    // Each edge of a closed surface is in two triangles, once in each direction: test it
    // from the direction low -> high only.
    for (int t : candidates) {
        const Tri& q = surface.triangles[t];
        for (int e = 0; e < 3; ++e) {
            const int a = q[e], b = q[(e + 1) % 3];
            if (a > b)
                continue;
            intersectSegment(sweep, surface.positions[a], surface.positions[b], query, scratch);
            if (query.hits.size() % 2 == 1) {
                Crossing c;
                c.hit = query.hits[query.hits.size() / 2];
                c.low = a;
                c.high = b;
                crossings.emplace(key(a, b), c);
            }
        }
    }
    if (crossings.empty())
        return Status::success();
    const auto crossingOf = [&](int a, int b) -> Crossing* {
        auto it = crossings.find(key(a, b));
        return it == crossings.end() ? nullptr : &it->second;
    };
    // 2. Crossed triangles; those with one crossed edge make their crossing a shared face
    // vertex.
    std::vector<std::pair<int, int>> crossed;  // (triangle, crossed edges)
    for (int t : candidates) {
        const Tri& q = surface.triangles[t];
        int count = 0;
        for (int e = 0; e < 3; ++e)
            count += crossingOf(q[e], q[(e + 1) % 3]) ? 1 : 0;
        if (count == 3)
            return Status::error("a surface triangle is crossed on all three edges (the sweep folds inside it)");
        if (count > 0)
            crossed.emplace_back(t, count);
    }
    for (const auto& [t, count] : crossed)
        if (count == 1) {
            const Tri& q = surface.triangles[t];
            for (int e = 0; e < 3; ++e)
                if (Crossing* c = crossingOf(q[e], q[(e + 1) % 3]))
                    c->shared = true;
        }

    // 3. Split points, appended in place; the edit log undoes everything on error.
    SurfaceEdit edit(surface, rest);
    const bool hasUv = !surface.uvs.empty();
    surface.cutUvs.resize(surface.vertexCount(), Vec2::Constant(std::numeric_limits<double>::quiet_NaN()));
    surface.cutFaces.resize(surface.triangleCount(), 0);
    const auto addVertex = [&](const Crossing& c, int side) {
        const double t = c.hit.t;
        out.sourceEdge.push_back({c.low, c.high});
        out.side.push_back(side);
        surface.positions.push_back(c.hit.point);
        if (hasUv)
            surface.uvs.push_back((1 - t) * surface.uvs[c.low] + t * surface.uvs[c.high]);
        if (rest)
            rest->push_back((1 - t) * (*rest)[c.low] + t * (*rest)[c.high]);
        surface.cutUvs.push_back(c.hit.uv);
        out.sweepUv.push_back(c.hit.uv);
        return surface.vertexCount() - 1;
    };
    // Number in a fixed order (the triangles') so that vertex numbering is reproducible.
    for (const auto& [t, count] : crossed) {
        const Tri q = surface.triangles[t];
        for (int e = 0; e < 3; ++e) {
            Crossing* c = crossingOf(q[e], q[(e + 1) % 3]);
            if (!c || c->plus >= 0)
                continue;
            ++out.splitEdges;
            c->plus = addVertex(*c, c->shared ? 0 : 1);
            if (c->shared) {
                c->minus = c->plus;
                ++out.faceVertices;
            } else {
                c->minus = addVertex(*c, -1);
            }
        }
    }
    // Side of an original vertex relative to the crossing on one of its edges.
    const auto sideAt = [](const Crossing& c, int v) { return v == c.low ? c.hit.sideP : -c.hit.sideP; };

    // 4. Split the crossed triangles in place, keeping their orientation; the pieces inherit
    // the cut-face flag (a later cut through an earlier cut face).
    std::vector<int> splitTriangles;  // every triangle made in this step
    const auto emit = [&](int original, bool first, const Tri& q) {
        if (first) {
            edit.replaced.emplace_back(original, surface.triangles[original]);
            surface.triangles[original] = q;
            splitTriangles.push_back(original);
        } else {
            const std::uint8_t flag = surface.cutFaces[original];
            surface.triangles.push_back(q);
            surface.cutFaces.push_back(flag);
            splitTriangles.push_back(surface.triangleCount() - 1);
        }
    };
    for (const auto& [t, count] : crossed) {
        const Tri q = surface.triangles[t];
        if (count == 1) {
            int e = 0;
            while (!crossingOf(q[e], q[(e + 1) % 3]))
                ++e;
            const int x = q[e], y = q[(e + 1) % 3], z = q[(e + 2) % 3];
            const int f = crossingOf(x, y)->plus;  // shared
            emit(t, true, {x, f, z});
            emit(t, false, {f, y, z});
            continue;
        }
        // Two crossed edges: the lone vertex x is the one both crossed edges share.
        int r = 0;
        while (!(crossingOf(q[r], q[(r + 1) % 3]) && crossingOf(q[(r + 2) % 3], q[r])))
            ++r;
        const int x = q[r], y = q[(r + 1) % 3], z = q[(r + 2) % 3];
        const Crossing& p = *crossingOf(x, y);
        const Crossing& w = *crossingOf(z, x);
        const int sx = sideAt(p, x);
        emit(t, true, {x, p.copyFor(sx), w.copyFor(sx)});
        emit(t, false, {p.copyFor(-sx), y, z});
        emit(t, false, {p.copyFor(-sx), z, w.copyFor(-sx)});
    }

    // 5. The cut boundary: half-edges of the split triangles through a new vertex without an
    // opposite (an opposite of such an edge can only be in another split triangle).
    std::unordered_set<std::uint64_t> halfEdges;
    for (int t : splitTriangles) {
        const Tri& q = surface.triangles[t];
        for (int e = 0; e < 3; ++e)
            halfEdges.insert(directed(q[e], q[(e + 1) % 3]));
    }
    std::unordered_map<int, int> next;
    for (int t : splitTriangles) {
        const Tri& q = surface.triangles[t];
        for (int e = 0; e < 3; ++e) {
            const int a = q[e], b = q[(e + 1) % 3];
            if (a < out.firstNewVertex && b < out.firstNewVertex)
                continue;
            if (!halfEdges.count(directed(b, a))) {
                if (next.count(a))
                    return Status::error("the cut boundary is not a set of simple loops (non-manifold cut)");
                next[a] = b;
            }
        }
    }
    std::vector<std::vector<int>> loops;
    std::unordered_set<int> visited;
    std::vector<int> starts;
    for (const auto& [a, b] : next)
        starts.push_back(a);
    std::sort(starts.begin(), starts.end());
    for (int start : starts) {
        if (visited.count(start))
            continue;
        std::vector<int> loop;
        for (int v = start; !visited.count(v);) {
            visited.insert(v);
            loop.push_back(v);
            auto it = next.find(v);
            if (it == next.end())
                return Status::error("the cut boundary is open (the surface was not closed)");
            v = it->second;
        }
        loops.push_back(std::move(loop));
    }
    out.loops = static_cast<int>(loops.size());

    // 6. Cap polygons of the + side, in the sweep's (u, v) plane. A loop through the two face
    // vertices of a partial cut is cut there into its two lips; the + lip is closed by the chord.
    std::unordered_map<int, int> minusOf;  // new vertex -> its - copy
    std::unordered_set<int> sharedVertex, plusVertex;
    for (const auto& [k, c] : crossings) {
        minusOf[c.plus] = c.minus;
        minusOf[c.minus] = c.minus;
        plusVertex.insert(c.plus);
        if (c.shared)
            sharedVertex.insert(c.plus);
    }
    std::vector<std::vector<int>> plusPolygons;  // boundary order of the + side (cap is reversed)
    for (const auto& loop : loops) {
        std::vector<int> cuts;
        for (std::size_t i = 0; i < loop.size(); ++i)
            if (sharedVertex.count(loop[i]))
                cuts.push_back(static_cast<int>(i));
        if (cuts.empty()) {
            // A whole loop lies on one side: keep the + side's loops.
            if (plusVertex.count(loop[0]) && !sharedVertex.count(loop[0]))
                plusPolygons.push_back(loop);
            continue;
        }
        if (cuts.size() != 2)
            return Status::error("a partial cut with " + std::to_string(cuts.size()) +
                                 " face vertices on one boundary loop is not supported");
        for (int k = 0; k < 2; ++k) {
            std::vector<int> arc;
            for (int i = cuts[k];; i = (i + 1) % static_cast<int>(loop.size())) {
                arc.push_back(loop[i]);
                if (i == cuts[1 - k])
                    break;
            }
            // The arc between the face vertices: + copies make the + lip.
            if (arc.size() > 2 ? plusVertex.count(arc[1]) && !sharedVertex.count(arc[1]) : false)
                plusPolygons.push_back(arc);
        }
    }
    if (plusPolygons.empty())
        return Status::error("the cut boundary has no side to close");

    // Points in (u, v), indexed locally (new vertex v -> v - firstNewVertex).
    std::vector<Vec2> uv(out.sweepUv.begin(), out.sweepUv.end());
    const int first = out.firstNewVertex;
    // Each piece is closed on its own. Polygons whose (u, v) boxes are disjoint can neither
    // nest nor touch: each is its own cap. Overlapping ones may be nested loops of one piece
    // (an annulus) or loops of different pieces touching on earlier cut faces, where their
    // points coincide: only these are grouped by connected component (one pass over the
    // surface's triangles).
    std::vector<Eigen::AlignedBox2d> boxes;
    for (const auto& polygon : plusPolygons) {
        Eigen::AlignedBox2d b;
        for (int v : polygon)
            b.extend(uv[v - first]);
        boxes.push_back(b);
    }
    std::vector<int> group(plusPolygons.size());
    std::iota(group.begin(), group.end(), 0);
    bool overlapping = false;
    for (std::size_t i = 0; i < boxes.size() && !overlapping; ++i)
        for (std::size_t j = i + 1; j < boxes.size() && !overlapping; ++j)
            overlapping = boxes[i].intersects(boxes[j]);
    if (overlapping) {
        // A polygon's group is its piece's representative; polygonsOfPiece is ordered by it,
        // so the order of the caps follows UnionFind's documented choice of root.
        UnionFind pieces(surface.vertexCount());
        for (const Tri& q : surface.triangles) {
            pieces.unite(q[1], q[0]);
            pieces.unite(q[2], q[0]);
        }
        for (std::size_t i = 0; i < plusPolygons.size(); ++i)
            group[i] = pieces.find(plusPolygons[i][0]);
    }
    std::map<int, std::vector<std::vector<int>>> polygonsOfPiece;
    for (std::size_t i = 0; i < plusPolygons.size(); ++i) {
        std::vector<int> local;
        for (int v : plusPolygons[i])
            local.push_back(v - first);
        polygonsOfPiece[group[i]].push_back(std::move(local));
    }
    int capCount = 0;
    for (const auto& [piece, polygons] : polygonsOfPiece) {
        std::vector<std::array<int, 3>> cap;
        if (Status s = triangulateInPlane(uv, polygons, cap); !s.ok())
            return s;
        // Orient the caps: the + cap must contain every + boundary edge reversed.
        const int a = polygons[0][0], b = polygons[0][1];
        bool flip = false;
        for (const auto& t : cap)
            for (int e = 0; e < 3; ++e)
                if (t[e] == a && t[(e + 1) % 3] == b)
                    flip = true;
        for (auto t : cap) {
            if (flip)
                std::swap(t[1], t[2]);
            const Tri plus{t[0] + first, t[1] + first, t[2] + first};
            surface.triangles.push_back(plus);
            // The - side: the same triangle on the - copies, reversed.
            surface.triangles.push_back({minusOf[plus[0]], minusOf[plus[2]], minusOf[plus[1]]});
            surface.cutFaces.push_back(1);
            surface.cutFaces.push_back(1);
        }
        capCount += static_cast<int>(cap.size());
    }
    out.capTriangles = 2 * capCount;
    edit.committed = true;
    return Status::success();
}

} // namespace resect
