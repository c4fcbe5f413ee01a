#include "core/mesh/body_surface.h"

#include "core/mesh/topology.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>

namespace resect {

Vec3 closestPointOnTriangle(const Vec3& p, const Vec3& a, const Vec3& b, const Vec3& c, int* featureOut) {
    int dummy = 0;
    int& feature = featureOut ? *featureOut : dummy;
    const Vec3 ab = b - a, ac = c - a, ap = p - a;
    const double d1 = ab.dot(ap), d2 = ac.dot(ap);
    if (d1 <= 0 && d2 <= 0) {
        feature = 0;
        return a;
    }
    const Vec3 bp = p - b;
    const double d3 = ab.dot(bp), d4 = ac.dot(bp);
    if (d3 >= 0 && d4 <= d3) {
        feature = 1;
        return b;
    }
    const double vc = d1 * d4 - d3 * d2;
    if (vc <= 0 && d1 >= 0 && d3 <= 0) {
        feature = 3;  // edge (a, b)
        return a + ab * (d1 / (d1 - d3));
    }
    const Vec3 cp = p - c;
    const double d5 = ab.dot(cp), d6 = ac.dot(cp);
    if (d6 >= 0 && d5 <= d6) {
        feature = 2;
        return c;
    }
    const double vb = d5 * d2 - d1 * d6;
    if (vb <= 0 && d2 >= 0 && d6 <= 0) {
        feature = 5;  // edge (c, a)
        return a + ac * (d2 / (d2 - d6));
    }
    const double va = d3 * d6 - d5 * d4;
    if (va <= 0 && (d4 - d3) >= 0 && (d5 - d6) >= 0) {
        feature = 4;  // edge (b, c)
        return b + (c - b) * ((d4 - d3) / ((d4 - d3) + (d5 - d6)));
    }
    const double denom = 1.0 / (va + vb + vc);
    if (!std::isfinite(denom)) {  // degenerate triangle: its nearest corner
        const double da = ap.squaredNorm(), db = bp.squaredNorm(), dc = cp.squaredNorm();
        feature = da <= db && da <= dc ? 0 : (db <= dc ? 1 : 2);
        return feature == 0 ? a : (feature == 1 ? b : c);
    }
    feature = 6;
    return a + ab * (vb * denom) + ac * (vc * denom);
}

std::shared_ptr<const BodySurface> BodySurface::fromBoundary(const TetMesh& mesh) {
    auto s = std::make_shared<BodySurface>();
    const std::vector<BoundaryFace> faces = boundaryFaces(mesh);
    if (faces.empty())
        return s;
    // Compact the boundary nodes.
    std::vector<int> index(mesh.nodeCount(), -1);
    for (const BoundaryFace& f : faces) {
        Tri t;
        for (int i = 0; i < 3; ++i) {
            int& k = index[f.nodes[i]];
            if (k < 0) {
                k = static_cast<int>(s->m_points.size());
                s->m_points.push_back(mesh.ref(f.nodes[i]));
            }
            t[i] = k;
        }
        s->m_tris.push_back(t);
    }
    // Normals: faces (unit), vertices (angle-weighted), edges (sum of their faces').
    const int nt = static_cast<int>(s->m_tris.size());
    s->m_faceNormals.resize(nt);
    s->m_vertexNormals.assign(s->m_points.size(), Vec3::Zero());
    std::map<std::pair<int, int>, std::pair<Vec3, int>> edgeSum;  // edge -> sum of its faces' normals, count
    double edgeLength = 0;
    for (int t = 0; t < nt; ++t) {
        const Tri& tri = s->m_tris[t];
        const Vec3 n = (s->m_points[tri[1]] - s->m_points[tri[0]]).cross(s->m_points[tri[2]] - s->m_points[tri[0]]);
        const double len = n.norm();
        s->m_faceNormals[t] = len > 0 ? Vec3(n / len) : Vec3::Zero();
        for (int i = 0; i < 3; ++i) {
            const Vec3& a = s->m_points[tri[i]];
            const Vec3 u = s->m_points[tri[(i + 1) % 3]] - a, v = s->m_points[tri[(i + 2) % 3]] - a;
            const double angle = std::atan2(u.cross(v).norm(), u.dot(v));
            s->m_vertexNormals[tri[i]] += angle * s->m_faceNormals[t];
            auto& e = edgeSum.try_emplace(std::minmax(tri[i], tri[(i + 1) % 3]), Vec3::Zero(), 0).first->second;
            e.first += s->m_faceNormals[t];
            ++e.second;
            edgeLength += u.norm();
        }
    }
    s->m_edgeNormals.resize(nt);
    for (int t = 0; t < nt; ++t)
        for (int i = 0; i < 3; ++i)
            s->m_edgeNormals[t][i] = edgeSum.at(std::minmax(s->m_tris[t][i], s->m_tris[t][(i + 1) % 3])).first;
    edgeLength /= 3.0 * nt;
    // Slack: a smooth edge of length L whose faces turn by phi is a chord of a surface of
    // radius about L / phi; a point sliding along the faces' tangent planes there leaves them by
    // up to about L phi / 4. Corners take the largest of their smooth edges', triangles of their
    // corners'. Sharp edges (and edges of more or fewer than two faces) allow nothing.
    std::vector<double> cornerSlack(s->m_points.size(), 0);
    for (const auto& [edge, sum] : edgeSum) {
        if (sum.second != 2)
            continue;
        const double bend = 2 * std::acos(std::clamp(sum.first.norm() / 2, 0.0, 1.0));
        if (!(bend < kSharpBend))
            continue;
        const double slack = (s->m_points[edge.first] - s->m_points[edge.second]).norm() * bend / 4;
        cornerSlack[edge.first] = std::max(cornerSlack[edge.first], slack);
        cornerSlack[edge.second] = std::max(cornerSlack[edge.second], slack);
    }
    s->m_slack.resize(nt);
    for (int t = 0; t < nt; ++t)
        s->m_slack[t] = std::max({cornerSlack[s->m_tris[t][0]], cornerSlack[s->m_tris[t][1]], cornerSlack[s->m_tris[t][2]]});

    // Grid of about one mean edge per cell, at most about 8 cells per triangle.
    Vec3 lo = s->m_points.front(), hi = lo;
    for (const Vec3& p : s->m_points) {
        lo = lo.cwiseMin(p);
        hi = hi.cwiseMax(p);
    }
    const Vec3 extent = (hi - lo).cwiseMax(Vec3::Constant(1e-300));
    double cell = edgeLength > 0 ? edgeLength : extent.maxCoeff();
    const double maxCells = 8.0 * nt + 64;
    while ((extent.x() / cell + 1) * (extent.y() / cell + 1) * (extent.z() / cell + 1) > maxCells)
        cell *= 1.5;
    s->m_cell = cell;
    s->m_origin = lo;
    for (int k = 0; k < 3; ++k)
        s->m_dims[k] = static_cast<int>(std::floor(extent[k] / cell)) + 1;
    const auto cellRange = [&](const Vec3& a, const Vec3& b, std::array<int, 3>& c0, std::array<int, 3>& c1) {
        for (int k = 0; k < 3; ++k) {
            c0[k] = std::clamp(static_cast<int>(std::floor((a[k] - lo[k]) / cell)), 0, s->m_dims[k] - 1);
            c1[k] = std::clamp(static_cast<int>(std::floor((b[k] - lo[k]) / cell)), 0, s->m_dims[k] - 1);
        }
    };
    const std::size_t cells = static_cast<std::size_t>(s->m_dims[0]) * s->m_dims[1] * s->m_dims[2];
    std::vector<int> count(cells + 1, 0);
    const auto forCells = [&](int t, auto&& f) {
        const Tri& tri = s->m_tris[t];
        const Vec3 a = s->m_points[tri[0]].cwiseMin(s->m_points[tri[1]]).cwiseMin(s->m_points[tri[2]]);
        const Vec3 b = s->m_points[tri[0]].cwiseMax(s->m_points[tri[1]]).cwiseMax(s->m_points[tri[2]]);
        std::array<int, 3> c0, c1;
        cellRange(a, b, c0, c1);
        for (int z = c0[2]; z <= c1[2]; ++z)
            for (int y = c0[1]; y <= c1[1]; ++y)
                for (int x = c0[0]; x <= c1[0]; ++x)
                    f((static_cast<std::size_t>(z) * s->m_dims[1] + y) * s->m_dims[0] + x);
    };
    for (int t = 0; t < nt; ++t)
        forCells(t, [&](std::size_t c) { ++count[c + 1]; });
    for (std::size_t c = 0; c < cells; ++c)
        count[c + 1] += count[c];
    s->m_cellStart = count;
    s->m_cellTris.resize(count.back());
    for (int t = 0; t < nt; ++t)
        forCells(t, [&](std::size_t c) { s->m_cellTris[count[c]++] = t; });
    return s;
}

BodySurface::Nearest BodySurface::nearest(const Vec3& p, double range) const {
    Nearest best{range, -1, -1, Vec3::Zero()};
    if (m_tris.empty() || !p.allFinite() || !(range > 0))
        return best;
    std::array<int, 3> c0, c1;
    for (int k = 0; k < 3; ++k) {
        const double a = std::floor((p[k] - range - m_origin[k]) / m_cell);
        const double b = std::floor((p[k] + range - m_origin[k]) / m_cell);
        if (b < 0 || a > m_dims[k] - 1)
            return best;  // the ball misses the grid, hence every triangle
        c0[k] = static_cast<int>(std::max(a, 0.0));
        c1[k] = static_cast<int>(std::min(b, m_dims[k] - 1.0));
    }
    for (int z = c0[2]; z <= c1[2]; ++z)
        for (int y = c0[1]; y <= c1[1]; ++y)
            for (int x = c0[0]; x <= c1[0]; ++x) {
                const std::size_t c = (static_cast<std::size_t>(z) * m_dims[1] + y) * m_dims[0] + x;
                for (int i = m_cellStart[c]; i < m_cellStart[c + 1]; ++i) {
                    const int t = m_cellTris[i];
                    const Tri& tri = m_tris[t];
                    int feature = 6;
                    const Vec3 q = closestPointOnTriangle(p, m_points[tri[0]], m_points[tri[1]], m_points[tri[2]], &feature);
                    const double d = (p - q).norm();
                    if (d < best.distance || (best.tri < 0 && d <= best.distance)) {
                        best = {d, t, feature, q};
                    }
                }
            }
    return best;
}

Vec3 BodySurface::featureNormal(const Nearest& n) const {
    if (n.feature < 3)
        return m_vertexNormals[m_tris[n.tri][n.feature]];
    if (n.feature < 6)
        return m_edgeNormals[n.tri][n.feature - 3];
    return m_faceNormals[n.tri];
}

BodySurface::Side BodySurface::side(const Vec3& p, double range) const {
    const Nearest n = nearest(p, range);
    if (n.tri < 0)
        return {-range, 0};
    const double side = featureNormal(n).dot(p - n.point);
    return {side > 0 ? n.distance : -n.distance, m_slack[n.tri]};
}

} // namespace resect
