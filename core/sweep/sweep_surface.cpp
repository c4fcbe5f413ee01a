#include "core/sweep/sweep_surface.h"

#include "core/mesh/predicates.h"

#include <algorithm>
#include <cassert>
#include <cmath>
#include <limits>
#include <numeric>
#include <string>

namespace resect {

/// Static median-split bounding-volume hierarchy over the sweep triangles.
struct SweepSurface::Bvh {
    struct Node {
        Box3 box;
        int left = -1, right = -1;  ///< children, or -1 for a leaf
        int first = 0, count = 0;   ///< range in `order` for leaves
    };
    std::vector<Node> nodes;
    std::vector<int> order;
    std::vector<Box3> triangleBox;  ///< by triangle: the box of its three vertices
    /// Traversal stacks live on the call stack (queries run per mesh edge and per relaxed
    /// node): a depth-first walk holds at most one pending node per level plus one, and
    /// median splits of fewer than 2^31 triangles make fewer than 32 levels.
    static constexpr int kMaxStack = 64;
};

SweepSurface::SweepSurface() = default;
SweepSurface::~SweepSurface() = default;
SweepSurface::SweepSurface(SweepSurface&&) noexcept = default;
SweepSurface& SweepSurface::operator=(SweepSurface&&) noexcept = default;
SweepSurface::SweepSurface(const SweepSurface& o)
    : m_m(o.m_m), m_n(o.m_n), m_vertices(o.m_vertices), m_triangles(o.m_triangles),
      m_degenerate(o.m_degenerate), m_bounds(o.m_bounds),
      m_bvh(o.m_bvh ? std::make_unique<Bvh>(*o.m_bvh) : nullptr) {}
SweepSurface& SweepSurface::operator=(const SweepSurface& o) {
    if (this != &o) {
        SweepSurface copy(o);
        *this = std::move(copy);
    }
    return *this;
}

Status SweepSurface::fromCurves(const std::vector<std::vector<Vec3>>& curves, SweepSurface& out) {
    if (curves.size() < 2)
        return Status::error("sweep needs at least two curves, got " + std::to_string(curves.size()));
    const std::size_t len = curves[0].size();
    if (len < 2)
        return Status::error("sweep curve 0 has " + std::to_string(len) +
                             " points; each curve needs at least two");
    for (std::size_t i = 0; i < curves.size(); ++i) {
        if (curves[i].size() != len)
            return Status::error("sweep curve " + std::to_string(i) + " has " +
                                 std::to_string(curves[i].size()) + " points, curve 0 has " +
                                 std::to_string(len) + "; all curves need the same number");
        for (std::size_t j = 0; j < len; ++j)
            if (!curves[i][j].allFinite())
                return Status::error("sweep curve " + std::to_string(i) + " point " +
                                     std::to_string(j) + " is not finite");
    }
    SweepSurface s;
    s.m_m = static_cast<int>(curves.size());
    s.m_n = static_cast<int>(len) - 1;
    for (const auto& c : curves)
        s.m_vertices.insert(s.m_vertices.end(), c.begin(), c.end());
    const auto idx = [&](int i, int j) { return i * (s.m_n + 1) + j; };
    for (int i = 0; i + 1 < s.m_m; ++i)
        for (int j = 0; j < s.m_n; ++j) {
            s.m_triangles.push_back({idx(i, j), idx(i, j + 1), idx(i + 1, j + 1)});
            s.m_triangles.push_back({idx(i, j), idx(i + 1, j + 1), idx(i + 1, j)});
        }
    s.m_degenerate.resize(s.m_triangles.size());
    for (std::size_t t = 0; t < s.m_triangles.size(); ++t) {
        const Tri& q = s.m_triangles[t];
        s.m_degenerate[t] = collinear(s.m_vertices[q[0]], s.m_vertices[q[1]], s.m_vertices[q[2]]);
    }
    if (std::all_of(s.m_degenerate.begin(), s.m_degenerate.end(), [](char d) { return d != 0; }))
        return Status::error("sweep surface has zero area (all curves collinear or identical)");
    s.build();

    // Self-intersection: triangles sharing no vertex must not meet (exact test).
    std::vector<int> candidates;
    for (int t = 0; t < static_cast<int>(s.m_triangles.size()); ++t) {
        if (s.m_degenerate[t])
            continue;
        const Tri& a = s.m_triangles[t];
        Box3 box;
        for (int v : a)
            box.extend(s.m_vertices[v]);
        s.trianglesOverlapping(box, candidates);
        for (int u : candidates) {
            if (u <= t || s.m_degenerate[u])
                continue;
            const Tri& b = s.m_triangles[u];
            bool shared = false;
            for (int x : a)
                for (int y : b)
                    shared = shared || x == y;
            if (shared)
                continue;
            if (trianglesIntersect(s.m_vertices[a[0]], s.m_vertices[a[1]], s.m_vertices[a[2]],
                                   s.m_vertices[b[0]], s.m_vertices[b[1]], s.m_vertices[b[2]]))
                return Status::error("sweep surface intersects itself (triangles " +
                                     std::to_string(t) + " and " + std::to_string(u) + ")");
        }
    }
    out = std::move(s);
    return Status::success();
}

std::vector<std::vector<Vec3>> SweepSurface::curves() const {
    std::vector<std::vector<Vec3>> result(m_m);
    for (int i = 0; i < m_m; ++i)
        result[i].assign(m_vertices.begin() + i * (m_n + 1), m_vertices.begin() + (i + 1) * (m_n + 1));
    return result;
}

double SweepSurface::area() const {
    double a = 0;
    for (const Tri& t : m_triangles)
        a += 0.5 * (m_vertices[t[1]] - m_vertices[t[0]]).cross(m_vertices[t[2]] - m_vertices[t[0]]).norm();
    return a;
}

void SweepSurface::build() {
    m_bounds.setEmpty();
    for (const Vec3& v : m_vertices)
        m_bounds.extend(v);
    m_bvh = std::make_unique<Bvh>();
    Bvh& bvh = *m_bvh;
    const int count = static_cast<int>(m_triangles.size());
    bvh.order.resize(count);
    std::iota(bvh.order.begin(), bvh.order.end(), 0);
    std::vector<Vec3> centroid(count);
    std::vector<Box3> box(count);
    for (int t = 0; t < count; ++t) {
        box[t].setEmpty();
        for (int v : m_triangles[t])
            box[t].extend(m_vertices[v]);
        centroid[t] = box[t].center();
    }
    bvh.triangleBox = box;
    constexpr int kLeafSize = 4;
    struct Item {
        int node, first, count;
    };
    bvh.nodes.push_back({});
    std::vector<Item> stack{{0, 0, count}};
    while (!stack.empty()) {
        const Item item = stack.back();
        stack.pop_back();
        Bvh::Node& node = bvh.nodes[item.node];
        node.box.setEmpty();
        for (int k = item.first; k < item.first + item.count; ++k)
            node.box.extend(box[bvh.order[k]]);
        if (item.count <= kLeafSize) {
            node.first = item.first;
            node.count = item.count;
            continue;
        }
        int axis = 0;
        node.box.sizes().maxCoeff(&axis);
        const int mid = item.first + item.count / 2;
        std::nth_element(bvh.order.begin() + item.first, bvh.order.begin() + mid,
                         bvh.order.begin() + item.first + item.count,
                         [&](int a, int b) { return centroid[a][axis] < centroid[b][axis]; });
        const int left = static_cast<int>(bvh.nodes.size());
        bvh.nodes.push_back({});
        bvh.nodes.push_back({});
        bvh.nodes[item.node].left = left;
        bvh.nodes[item.node].right = left + 1;
        stack.push_back({left, item.first, mid - item.first});
        stack.push_back({left + 1, mid, item.first + item.count - mid});
    }
}

void SweepSurface::trianglesOverlapping(const Box3& box, std::vector<int>& out) const {
    out.clear();
    if (!m_bvh || m_bvh->nodes.empty())
        return;
    int stack[Bvh::kMaxStack];
    int depth = 0;
    stack[depth++] = 0;
    while (depth > 0) {
        const Bvh::Node& node = m_bvh->nodes[stack[--depth]];
        if (!node.box.intersects(box))
            continue;
        if (node.left < 0) {
            for (int k = node.first; k < node.first + node.count; ++k) {
                const int t = m_bvh->order[k];
                if (m_bvh->triangleBox[t].intersects(box))
                    out.push_back(t);
            }
        } else {
            assert(depth + 2 <= Bvh::kMaxStack);
            stack[depth++] = node.left;
            stack[depth++] = node.right;
        }
    }
}

Vec3 closestPointBarycentric(const Vec3& p, const Vec3& a, const Vec3& b, const Vec3& c) {
    // Region tests on the triangle's Voronoi regions (vertex, edge, face).
    const Vec3 ab = b - a, ac = c - a, ap = p - a;
    const double d1 = ab.dot(ap), d2 = ac.dot(ap);
    if (d1 <= 0 && d2 <= 0)
        return {1, 0, 0};
    const Vec3 bp = p - b;
    const double d3 = ab.dot(bp), d4 = ac.dot(bp);
    if (d3 >= 0 && d4 <= d3)
        return {0, 1, 0};
    const double vc = d1 * d4 - d3 * d2;
    if (vc <= 0 && d1 >= 0 && d3 <= 0) {
        const double v = d1 / (d1 - d3);
        return {1 - v, v, 0};
    }
    const Vec3 cp = p - c;
    const double d5 = ab.dot(cp), d6 = ac.dot(cp);
    if (d6 >= 0 && d5 <= d6)
        return {0, 0, 1};
    const double vb = d5 * d2 - d1 * d6;
    if (vb <= 0 && d2 >= 0 && d6 <= 0) {
        const double w = d2 / (d2 - d6);
        return {1 - w, 0, w};
    }
    const double va = d3 * d6 - d5 * d4;
    if (va <= 0 && (d4 - d3) >= 0 && (d5 - d6) >= 0) {
        const double w = (d4 - d3) / ((d4 - d3) + (d5 - d6));
        return {0, 1 - w, w};
    }
    const double denom = va + vb + vc;
    if (!(std::abs(denom) > 0))
        return {1, 0, 0};  // degenerate triangle: fall back to a vertex
    const double v = vb / denom, w = vc / denom;
    return {1 - v - w, v, w};
}

SweepSurface::Closest SweepSurface::closestPoint(const Vec3& p) const {
    Closest best;
    best.distance = std::numeric_limits<double>::infinity();
    if (!m_bvh || m_bvh->nodes.empty())
        return best;
    double best2 = std::numeric_limits<double>::infinity();
    int stack[Bvh::kMaxStack];
    int depth = 0;
    stack[depth++] = 0;
    while (depth > 0) {
        const Bvh::Node& node = m_bvh->nodes[stack[--depth]];
        if (node.box.squaredExteriorDistance(p) >= best2)
            continue;
        if (node.left < 0) {
            for (int k = node.first; k < node.first + node.count; ++k) {
                const int t = m_bvh->order[k];
                const Tri& q = m_triangles[t];
                const Vec3& a = m_vertices[q[0]];
                const Vec3& b = m_vertices[q[1]];
                const Vec3& c = m_vertices[q[2]];
                const Vec3 bary = closestPointBarycentric(p, a, b, c);
                const Vec3 x = bary[0] * a + bary[1] * b + bary[2] * c;
                const double d2 = (x - p).squaredNorm();
                if (d2 < best2) {
                    best2 = d2;
                    best.point = x;
                    best.bary = bary;
                    best.triangle = t;
                }
            }
        } else {
            // Visit the nearer child last so that it is popped first.
            const double dl = m_bvh->nodes[node.left].box.squaredExteriorDistance(p);
            const double dr = m_bvh->nodes[node.right].box.squaredExteriorDistance(p);
            assert(depth + 2 <= Bvh::kMaxStack);
            if (dl < dr) {
                stack[depth++] = node.right;
                stack[depth++] = node.left;
            } else {
                stack[depth++] = node.left;
                stack[depth++] = node.right;
            }
        }
    }
    best.distance = std::sqrt(best2);
    best.uv = uvAt(best.triangle, best.bary);
    return best;
}

int SweepSurface::sideOf(const Vec3& p) const {
    const Closest c = closestPoint(p);
    if (c.triangle < 0)
        return 0;
    int t = c.triangle;
    if (m_degenerate[t]) {
        // Use the partner triangle of the quad if this one is flat.
        const int partner = (t % 2 == 0) ? t + 1 : t - 1;
        if (partner >= 0 && partner < static_cast<int>(m_triangles.size()) && !m_degenerate[partner])
            t = partner;
        else
            return 0;
    }
    const Tri& q = m_triangles[t];
    return orient3d(m_vertices[q[0]], m_vertices[q[1]], m_vertices[q[2]], p);
}

Vec2 SweepSurface::vertexUv(int vertex) const {
    const int i = vertex / (m_n + 1), j = vertex % (m_n + 1);
    return {static_cast<double>(j) / m_n, static_cast<double>(i) / (m_m - 1)};
}

Vec2 SweepSurface::uvAt(int triangle, const Vec3& bary) const {
    if (triangle < 0)
        return Vec2::Zero();
    const Tri& q = m_triangles[triangle];
    return bary[0] * vertexUv(q[0]) + bary[1] * vertexUv(q[1]) + bary[2] * vertexUv(q[2]);
}

Vec3 SweepSurface::pointAt(const Vec2& uvIn) const {
    const double u = std::clamp(uvIn.x(), 0.0, 1.0) * m_n;
    const double v = std::clamp(uvIn.y(), 0.0, 1.0) * (m_m - 1);
    const int j = std::min(static_cast<int>(u), m_n - 1);
    const int i = std::min(static_cast<int>(v), m_m - 2);
    const double s = u - j, t = v - i;  // local coordinates in quad (i, j)
    const auto P = [&](int ii, int jj) -> const Vec3& { return m_vertices[ii * (m_n + 1) + jj]; };
    // Triangle (P(i,j), P(i,j+1), P(i+1,j+1)) covers s >= t; the other covers s < t.
    if (s >= t)
        return (1 - s) * P(i, j) + (s - t) * P(i, j + 1) + t * P(i + 1, j + 1);
    return (1 - t) * P(i, j) + s * P(i + 1, j + 1) + (t - s) * P(i + 1, j);
}

std::vector<std::array<int, 2>> SweepSurface::borderEdges() const {
    std::vector<std::array<int, 2>> edges;
    const auto idx = [&](int i, int j) { return i * (m_n + 1) + j; };
    for (int j = 0; j < m_n; ++j) {
        edges.push_back({idx(0, j), idx(0, j + 1)});
        edges.push_back({idx(m_m - 1, j), idx(m_m - 1, j + 1)});
    }
    for (int i = 0; i + 1 < m_m; ++i) {
        edges.push_back({idx(i, 0), idx(i + 1, 0)});
        edges.push_back({idx(i, m_n), idx(i + 1, m_n)});
    }
    return edges;
}

} // namespace resect
