#include "core/embed/cut_surface.h"

#include "core/embed/triangulate_cut.h"
#include "core/sweep/intersect_segment.h"

#include <algorithm>
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

Status cutSurface(TriangleSurface& surface, std::vector<Vec3>* rest, const SweepSurface& sweep, SurfaceCut& out) {
    out = {};
    out.firstNewVertex = surface.vertexCount();
    if (rest && static_cast<int>(rest->size()) != surface.vertexCount())
        return Status::error("rest positions do not match the surface's vertices");
    // 1. Crossed edges (an odd number of crossings: split at the middle one).
    std::unordered_map<std::uint64_t, Crossing> crossings;
    SegmentQuery query;
    std::vector<int> scratch;
    // Each edge of a closed surface is in two triangles, once in each direction: test it
    // from the direction low -> high only, and keep only the crossed ones.
    for (const Tri& t : surface.triangles)
        for (int e = 0; e < 3; ++e) {
            const int a = t[e], b = t[(e + 1) % 3];
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
    const auto crossingOf = [&](int a, int b) -> Crossing* {
        auto it = crossings.find(key(a, b));
        return it == crossings.end() ? nullptr : &it->second;
    };
    // 2. Triangles with one crossed edge make their crossing a shared face vertex.
    std::vector<int> crossedCount(surface.triangleCount(), 0);
    for (int t = 0; t < surface.triangleCount(); ++t) {
        const Tri& q = surface.triangles[t];
        for (int e = 0; e < 3; ++e)
            crossedCount[t] += crossingOf(q[e], q[(e + 1) % 3]) ? 1 : 0;
        if (crossedCount[t] == 3)
            return Status::error("a surface triangle is crossed on all three edges (the sweep folds inside it)");
    }
    bool any = false;
    for (int t = 0; t < surface.triangleCount(); ++t) {
        const Tri& q = surface.triangles[t];
        for (int e = 0; e < 3; ++e)
            if (Crossing* c = crossingOf(q[e], q[(e + 1) % 3])) {
                any = true;
                if (crossedCount[t] == 1)
                    c->shared = true;
            }
    }
    if (!any)
        return Status::success();

    // 3. Split points (work on copies so that an error leaves the input untouched).
    TriangleSurface result = surface;
    std::vector<Vec3> restResult = rest ? *rest : std::vector<Vec3>{};
    const bool hasUv = surface.uvs.size() == surface.positions.size();
    const auto addVertex = [&](const Crossing& c, int side) {
        const double t = c.hit.t;
        out.sourceEdge.push_back({c.low, c.high});
        out.side.push_back(side);
        result.positions.push_back(c.hit.point);
        if (hasUv)
            result.uvs.push_back((1 - t) * surface.uvs[c.low] + t * surface.uvs[c.high]);
        if (rest)
            restResult.push_back((1 - t) * (*rest)[c.low] + t * (*rest)[c.high]);
        out.sweepUv.push_back(c.hit.uv);
        return result.vertexCount() - 1;
    };
    // Iterate in a fixed order (the triangles') so that vertex numbering is reproducible.
    for (const Tri& q : surface.triangles)
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
    // Side of an original vertex relative to the crossing on one of its edges.
    const auto sideAt = [](const Crossing& c, int v) { return v == c.low ? c.hit.sideP : -c.hit.sideP; };

    // 4. Split the crossed triangles, keeping their orientation.
    std::vector<Tri> triangles;
    triangles.reserve(result.triangles.size() + 2 * out.splitEdges);
    for (int t = 0; t < surface.triangleCount(); ++t) {
        const Tri& q = surface.triangles[t];
        if (crossedCount[t] == 0) {
            triangles.push_back(q);
            continue;
        }
        if (crossedCount[t] == 1) {
            int e = 0;
            while (!crossingOf(q[e], q[(e + 1) % 3]))
                ++e;
            const int x = q[e], y = q[(e + 1) % 3], z = q[(e + 2) % 3];
            const int f = crossingOf(x, y)->plus;  // shared
            triangles.push_back({x, f, z});
            triangles.push_back({f, y, z});
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
        triangles.push_back({x, p.copyFor(sx), w.copyFor(sx)});
        triangles.push_back({p.copyFor(-sx), y, z});
        triangles.push_back({p.copyFor(-sx), z, w.copyFor(-sx)});
    }

    // 5. Boundary half-edges (the surface was closed, so all are on the cut) and their loops.
    std::unordered_set<std::uint64_t> halfEdges;
    for (const Tri& q : triangles)
        for (int e = 0; e < 3; ++e)
            halfEdges.insert(directed(q[e], q[(e + 1) % 3]));
    std::unordered_map<int, int> next;
    for (const Tri& q : triangles)
        for (int e = 0; e < 3; ++e) {
            const int a = q[e], b = q[(e + 1) % 3];
            if (!halfEdges.count(directed(b, a))) {
                if (next.count(a))
                    return Status::error("the cut boundary is not a set of simple loops (non-manifold cut)");
                next[a] = b;
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
    std::unordered_map<int, int> plusOf, minusOf;  // new vertex -> its + / - copy
    std::unordered_set<int> sharedVertex, plusVertex;
    for (const auto& [k, c] : crossings) {
        plusOf[c.plus] = c.plus;
        plusOf[c.minus] = c.plus;
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

    std::vector<Vec2> uv(result.vertexCount(), Vec2::Zero());
    for (int v = out.firstNewVertex; v < result.vertexCount(); ++v)
        uv[v] = out.sweepUv[v - out.firstNewVertex];
    // Each piece is closed on its own: pieces can touch on earlier cut faces, where their
    // boundary points coincide in (u, v).
    std::vector<int> parent(result.vertexCount());
    std::iota(parent.begin(), parent.end(), 0);
    const auto find = [&](int x) {
        while (parent[x] != x)
            x = parent[x] = parent[parent[x]];
        return x;
    };
    for (const Tri& q : triangles) {
        parent[find(q[1])] = find(q[0]);
        parent[find(q[2])] = find(q[0]);
    }
    std::map<int, std::vector<std::vector<int>>> polygonsOfPiece;
    for (const auto& polygon : plusPolygons)
        polygonsOfPiece[find(polygon[0])].push_back(polygon);
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
            triangles.push_back({t[0], t[1], t[2]});
            // The - side: the same triangle on the - copies, reversed.
            triangles.push_back({minusOf[t[0]], minusOf[t[2]], minusOf[t[1]]});
        }
        capCount += static_cast<int>(cap.size());
    }
    out.capTriangles = 2 * capCount;
    result.triangles = std::move(triangles);
    surface = std::move(result);
    if (rest)
        *rest = std::move(restResult);
    return Status::success();
}

} // namespace resect
