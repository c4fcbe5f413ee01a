#include "core/embed/triangulate_cut.h"

#include "core/embed/flat_marks.h"
#include "core/mesh/union_find.h"

#include <CGAL/Constrained_Delaunay_triangulation_2.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Triangulation_face_base_with_info_2.h>
#include <CGAL/Triangulation_vertex_base_with_info_2.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <cstdio>
#include <cstdlib>
#include <deque>
#include <numeric>
#include <string>
#include <unordered_map>

namespace resect {
namespace {

using K = CGAL::Exact_predicates_inexact_constructions_kernel;
using Vb = CGAL::Triangulation_vertex_base_with_info_2<int, K>;  ///< the distinct point's index
struct FaceInfo {
    bool known = false;
    int winding = 0;
};
using Fbb = CGAL::Triangulation_face_base_with_info_2<FaceInfo, K>;
using Fb = CGAL::Constrained_triangulation_face_base_2<K, Fbb>;
using Tds = CGAL::Triangulation_data_structure_2<Vb, Fb>;
using Cdt = CGAL::Constrained_Delaunay_triangulation_2<K, Tds, CGAL::Exact_predicates_tag>;

std::uint64_t directedKey(int a, int b) {
    return (static_cast<std::uint64_t>(static_cast<std::uint32_t>(a)) << 32) | static_cast<std::uint32_t>(b);
}

/// Points of the loops closer than this in u and in v are one point. Coincident points of the
/// cut (the two walls of an earlier cut, where the surface's vertices were placed through
/// different tets after a simulation step) differ by rounding, a few 1e-15; the constrained
/// triangulation would treat them as two points with a sliver between them, inside or outside
/// the region by rounding (a blobby scan, pull 4 of 20: a slit of an earlier cut crossed,
/// 3e-15 apart, left the surface open). (u, v) is in [0, 1]^2: 1e-11 is far above rounding
/// and far below any feature of a cut.
constexpr double kSamePointUv = 1e-11;

/// The loops with their points merged where (u, v) are equal to within kSamePointUv: distinct
/// points, and every loop edge between distinct points by their indices (loop vertex of its
/// start and end).
struct MergedLoops {
    std::vector<Vec2> points;       ///< distinct (u, v)
    std::vector<int> distinctOf;    ///< per input point used by a loop: its distinct point
    /// directed (distinct a, distinct b) -> the loop edges (input a, input b) between them
    std::unordered_map<std::uint64_t, std::vector<std::array<int, 2>>> edges;
};

MergedLoops merge(const std::vector<Vec2>& points, const std::vector<std::vector<int>>& loops) {
    MergedLoops m;
    m.distinctOf.assign(points.size(), -1);
    // The loops' points in order of first use, then sorted by u; points within kSamePointUv of
    // each other (in u and v, transitively) are one distinct point, at the (u, v) of the first
    // used, numbered in order of first use.
    std::vector<int> used;
    for (const auto& loop : loops)
        for (int i : loop)
            if (m.distinctOf[i] == -1) {
                m.distinctOf[i] = -2;
                used.push_back(i);
            }
    std::vector<int> order(used.size());
    std::iota(order.begin(), order.end(), 0);
    std::sort(order.begin(), order.end(), [&](int a, int b) {
        const Vec2 &p = points[used[a]], &q = points[used[b]];
        return p.x() != q.x() ? p.x() < q.x() : p.y() != q.y() ? p.y() < q.y() : a < b;
    });
    UnionFind same;
    same.reset(static_cast<int>(used.size()));
    for (std::size_t k = 0; k < order.size(); ++k) {
        const Vec2& p = points[used[order[k]]];
        for (std::size_t j = k; j-- > 0;) {
            const Vec2& q = points[used[order[j]]];
            if (p.x() - q.x() > kSamePointUv)
                break;
            if (std::abs(p.y() - q.y()) <= kSamePointUv)
                same.unite(order[k], order[j]);
        }
    }
    std::vector<int> leader(used.size(), -1);  // per cluster root: its first-used point
    for (std::size_t j = 0; j < used.size(); ++j) {
        int& first = leader[same.find(static_cast<int>(j))];
        if (first < 0) {
            first = static_cast<int>(j);
            m.distinctOf[used[j]] = static_cast<int>(m.points.size());
            m.points.push_back(points[used[j]]);
        } else {
            m.distinctOf[used[j]] = m.distinctOf[used[first]];
        }
    }
    for (const auto& loop : loops)
        for (std::size_t k = 0; k < loop.size(); ++k) {
            const int a = loop[k], b = loop[(k + 1) % loop.size()];
            const int da = m.distinctOf[a], db = m.distinctOf[b];
            if (da != db)
                m.edges[directedKey(da, db)].push_back({a, b});
        }
    return m;
}

/// Winding number of every face: 0 outside, and crossing a loop edge a -> b from its right to
/// its left adds one (loops running along the same segment in opposite directions cancel).
void markWindings(Cdt& cdt, const MergedLoops& m) {
    std::deque<Cdt::Face_handle> queue{cdt.infinite_face()};
    cdt.infinite_face()->info() = {true, 0};
    while (!queue.empty()) {
        const Cdt::Face_handle f = queue.front();
        queue.pop_front();
        for (int i = 0; i < 3; ++i) {
            const Cdt::Face_handle n = f->neighbor(i);
            if (n->info().known)
                continue;
            int winding = f->info().winding;
            if (cdt.is_constrained(Cdt::Edge(f, i))) {
                // The edge (a, b) with f on its left when a = vertex(ccw(i)), b = vertex(cw(i)).
                const int a = f->vertex(Cdt::ccw(i))->info(), b = f->vertex(Cdt::cw(i))->info();
                const auto count = [&](int x, int y) {
                    const auto it = m.edges.find(directedKey(x, y));
                    return it == m.edges.end() ? 0 : static_cast<int>(it->second.size());
                };
                // Crossing from f (left of a -> b) to n: leaving the left of a -> b edges and
                // entering the left of b -> a edges.
                winding += count(b, a) - count(a, b);
            }
            n->info() = {true, winding};
            queue.push_back(n);
        }
    }
}

/// The loop vertex for the corner at vertex index i of the inside face f: turning
/// counter-clockwise around that point from f to the first loop edge (v, w), the face before
/// it lies right of v -> w, so the loop edge with the region on its side is w -> v (side +1)
/// or v -> w (side -1).
int cornerVertex(const Cdt& cdt, const MergedLoops& m, Cdt::Face_handle f, int i, int side) {
    const Cdt::Vertex_handle v = f->vertex(i);
    Cdt::Face_handle g = f;
    for (int guard = 0; guard < 10000; ++guard) {
        const int iv = g->index(v);
        const int across = Cdt::ccw(iv);  // the edge (v, g->vertex(cw(iv)))
        if (cdt.is_constrained(Cdt::Edge(g, across))) {
            const int dv = v->info(), dw = g->vertex(Cdt::cw(iv))->info();
            const auto it = side > 0 ? m.edges.find(directedKey(dw, dv)) : m.edges.find(directedKey(dv, dw));
            if (it != m.edges.end() && !it->second.empty())
                return side > 0 ? it->second.front()[1] : it->second.front()[0];
            break;
        }
        g = g->neighbor(across);
        if (g == f)
            break;
    }
    // Not reached for points of a valid loop set: any loop vertex at this point.
    for (std::size_t k = 0; k < m.distinctOf.size(); ++k)
        if (m.distinctOf[k] == v->info())
            return static_cast<int>(k);
    return -1;
}

double cross(const Vec2& a, const Vec2& b, const Vec2& c) {
    return (b - a).x() * (c - a).y() - (b - a).y() * (c - a).x();
}

double signedArea(const std::vector<Vec2>& P, const std::vector<int>& loop) {
    double a = 0;
    for (std::size_t k = 0; k < loop.size(); ++k) {
        const Vec2& p = P[loop[k]];
        const Vec2& q = P[loop[(k + 1) % loop.size()]];
        a += p.x() * q.y() - p.y() * q.x();
    }
    return 0.5 * a;
}

double triangleQuality(const Vec2& a, const Vec2& b, const Vec2& c) {
    const double edges = (b - a).squaredNorm() + (c - b).squaredNorm() + (a - c).squaredNorm();
    return edges > 0 ? cross(a, b, c) / edges : 0.0;
}

/// Ear clipping of one polygon (left of its edges is inside) that never gives up: strictly
/// convex empty ears first, then flat ones, then the best of whatever is left. Any sequence of
/// ears triangulates the polygon as a disc, so the cap stays closed and manifold even where its
/// (u, v) image is degenerate (a spike, a loop touching itself); only its shape suffers there.
void clipEars(const std::vector<Vec2>& P, std::vector<int> poly, std::vector<std::array<int, 3>>& out) {
    while (poly.size() > 3) {
        const int n = static_cast<int>(poly.size());
        int best = -1;
        double bestQuality = -std::numeric_limits<double>::infinity();
        for (int pass = 0; pass < 3 && best < 0; ++pass)
            for (int i = 0; i < n; ++i) {
                const int a = poly[(i + n - 1) % n], b = poly[i], c = poly[(i + 1) % n];
                if (a == c || a == b || b == c)
                    continue;
                const double turn = cross(P[a], P[b], P[c]);
                if ((pass == 0 && !(turn > 0)) || (pass == 1 && turn < 0))
                    continue;
                bool empty = true;
                for (int j = 0; j < n && empty && pass < 2; ++j) {
                    const int x = poly[j];
                    if (x == a || x == b || x == c || P[x] == P[a] || P[x] == P[b] || P[x] == P[c])
                        continue;
                    empty = !(cross(P[a], P[b], P[x]) >= 0 && cross(P[b], P[c], P[x]) >= 0 && cross(P[c], P[a], P[x]) >= 0);
                }
                if (!empty)
                    continue;
                const double q = triangleQuality(P[a], P[b], P[c]);
                if (q > bestQuality) {
                    bestQuality = q;
                    best = i;
                }
            }
        if (best < 0)
            best = 0;  // every corner repeats a vertex: cut the first
        const int a = poly[(best + n - 1) % n], b = poly[best], c = poly[(best + 1) % n];
        if (a != b && b != c && a != c)
            out.push_back({a, b, c});
        poly.erase(poly.begin() + best);
    }
    if (poly.size() == 3 && poly[0] != poly[1] && poly[1] != poly[2] && poly[0] != poly[2])
        out.push_back({poly[0], poly[1], poly[2]});
}

/// The fallback of triangulateCap, for a (u, v) image too degenerate for the constrained
/// triangulation (a spike, a loop touching itself, loops crossing by rounding): every loop is
/// closed on its own by ear clipping. Each loop becomes a disc, so the cap is closed and
/// manifold whatever the geometry; a hole is then covered twice with opposite orientations,
/// which adds no volume.
void triangulateByEars(const std::vector<Vec2>& P, std::vector<std::vector<int>> loops, int side,
                       std::vector<std::array<int, 3>>& out) {
    for (auto& loop : loops) {
        if (side < 0)
            std::reverse(loop.begin(), loop.end());
        // A hole runs clockwise: clip it as its own (counter-clockwise) disc, then turn its
        // triangles back so that they bound the hole's edges from the correct side.
        const bool hole = signedArea(P, loop) < 0;
        if (hole)
            std::reverse(loop.begin(), loop.end());
        std::vector<std::array<int, 3>> disc;
        clipEars(P, loop, disc);
        for (auto& t : disc) {
            if (hole)
                std::swap(t[1], t[2]);
            out.push_back(t);
        }
    }
}

/// True if every loop edge a -> b is an edge of exactly one triangle, as a -> b (side +1: the
/// counter-clockwise triangle on its left) or b -> a (side -1), and of none on its other side
/// (unless that is a loop edge too). Where two walls of an earlier cut cross each other in the
/// (u, v) image (the simulation moved them apart, one bulging across the other), the windings
/// count some of the region twice and a loop edge between them lies inside it.
bool coversLoops(const std::vector<std::array<int, 3>>& triangles, const std::vector<std::vector<int>>& loops,
                 int side) {
    EdgeTable count;
    count.reserve(3 * static_cast<int>(triangles.size()));
    for (const auto& t : triangles)
        for (int e = 0; e < 3; ++e)
            if (++*count.insert(directedKey(t[e], t[(e + 1) % 3]), 0).first > 1)
                return false;  // two triangles on one side of an edge: not a disc
    EdgeTable boundary;  // the loop edges, as the region's triangles have them
    for (const auto& loop : loops)
        for (std::size_t k = 0; k < loop.size(); ++k) {
            const int a = loop[k], b = loop[(k + 1) % loop.size()];
            boundary.insert(side > 0 ? directedKey(a, b) : directedKey(b, a), 1);
        }
    for (const auto& loop : loops)
        for (std::size_t k = 0; k < loop.size(); ++k) {
            const int a = loop[k], b = loop[(k + 1) % loop.size()];
            const std::uint64_t in = side > 0 ? directedKey(a, b) : directedKey(b, a);
            const std::uint64_t out = side > 0 ? directedKey(b, a) : directedKey(a, b);
            if (count.get(in) != 1 || (count.get(out) != 0 && boundary.get(out) == 0))
                return false;
        }
    return true;
}

} // namespace

Status triangulateCap(const std::vector<Vec2>& points, const std::vector<std::vector<int>>& loops, int side,
                      std::vector<std::array<int, 3>>& triangles) {
    triangles.clear();
    for (const auto& loop : loops)
        for (int i : loop)
            if (i < 0 || i >= static_cast<int>(points.size()) || !points[i].allFinite())
                return Status::error("a cut-boundary point has no finite (u, v)");
    try {
        const MergedLoops m = merge(points, loops);
        Cdt cdt;
        std::vector<Cdt::Vertex_handle> handle(m.points.size());
        for (std::size_t d = 0; d < m.points.size(); ++d) {
            handle[d] = cdt.insert(K::Point_2(m.points[d].x(), m.points[d].y()));
            handle[d]->info() = static_cast<int>(d);
        }
        const std::size_t inserted = cdt.number_of_vertices();
        for (const auto& [key, list] : m.edges)
            cdt.insert_constraint(handle[key >> 32], handle[key & 0xffffffffu]);
        if (cdt.number_of_vertices() != inserted) {
            // Two loop edges cross: the (u, v) image is degenerate here.
            triangulateByEars(points, loops, side, triangles);
            return Status::success();
        }
        // A loop point exactly on another loop's edge splits that constraint; the windings
        // below count whole loop edges, so the fallback takes that too.
        for (const auto& [key, list] : m.edges)
            if (!cdt.is_edge(handle[key >> 32], handle[key & 0xffffffffu])) {
                triangulateByEars(points, loops, side, triangles);
                return Status::success();
            }
        // All points on one line (or fewer than three): no faces to mark.
        if (cdt.dimension() < 2) {
            triangulateByEars(points, loops, side, triangles);
            return Status::success();
        }
        for (auto f = cdt.all_faces_begin(); f != cdt.all_faces_end(); ++f)
            f->info() = {};
        markWindings(cdt, m);
        for (auto f = cdt.finite_faces_begin(); f != cdt.finite_faces_end(); ++f) {
            if (f->info().winding * side <= 0)
                continue;
            std::array<int, 3> t{};
            for (int i = 0; i < 3; ++i)
                t[i] = cornerVertex(cdt, m, f, i, side);
            triangles.push_back(t);
        }
        // Every loop edge must border exactly one triangle, on the region's side; where the
        // (u, v) image is degenerate (collinear or coincident loop points) it may not.
        if (!coversLoops(triangles, loops, side)) {
            triangles.clear();
            triangulateByEars(points, loops, side, triangles);
        }
    } catch (const std::exception& e) {
        return Status::error(std::string("triangulating the cut face failed: ") + e.what());
    }
    return Status::success();
}

} // namespace resect
