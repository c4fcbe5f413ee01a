#pragma once
// The sweep surface of a cut (section 4.2): the ruled surface between consecutive tool
// curves. The paper's case is m = 2 curves (start and end of the tool stroke, 2n
// triangles); recorded strokes give any number m >= 2 of tool poses.
//
// Vertex (i, j) is point j of curve i (0 <= i < m, 0 <= j <= n); its index is i * (n + 1) + j.
// Quad (i, j) between curves i, i+1 and points j, j+1 is split into the triangles
//   (P(i,j), P(i,j+1), P(i+1,j+1)) and (P(i,j), P(i+1,j+1), P(i+1,j)).
// Parameterisation: u = j / n along a curve, v = i / (m - 1) across curves, linear on each
// triangle; so every point of the surface has (u, v) in [0, 1]^2 and back.

#include "core/mesh/tet_mesh.h"
#include "core/status.h"

#include <Eigen/Geometry>

#include <memory>
#include <vector>

namespace resect {

using Vec2 = Eigen::Vector2d;
using Box3 = Eigen::AlignedBox3d;

class SweepSurface {
public:
    SweepSurface();
    ~SweepSurface();
    SweepSurface(const SweepSurface&);
    SweepSurface& operator=(const SweepSurface&);
    SweepSurface(SweepSurface&&) noexcept;
    SweepSurface& operator=(SweepSurface&&) noexcept;

    /// Builds the surface from m >= 2 curves of equal length n + 1 >= 2. Rejects (with a
    /// message naming the curve or point) fewer than two curves, curves of different lengths,
    /// non-finite points, a surface of zero area, and self-intersection (two triangles that
    /// share no vertex intersect; exact test).
    static Status fromCurves(const std::vector<std::vector<Vec3>>& curves, SweepSurface& out);

    /// The paper's case: a start and an end curve.
    static Status fromStartEnd(const std::vector<Vec3>& start, const std::vector<Vec3>& end,
                               SweepSurface& out) {
        return fromCurves({start, end}, out);
    }

    int curveCount() const { return m_m; }
    int pointsPerCurve() const { return m_n + 1; }
    const std::vector<Vec3>& vertices() const { return m_vertices; }
    const std::vector<Tri>& triangles() const { return m_triangles; }
    std::vector<std::vector<Vec3>> curves() const;
    const Box3& bounds() const { return m_bounds; }
    /// True if the triangle has exactly zero area (skipped by intersection tests).
    bool isDegenerate(int triangle) const { return m_degenerate[triangle] != 0; }
    double area() const;

    // --- parameterisation ---
    Vec2 vertexUv(int vertex) const;
    /// (u, v) of the point with barycentric coordinates `bary` in `triangle`.
    Vec2 uvAt(int triangle, const Vec3& bary) const;
    /// The surface point at (u, v), clamped to [0, 1]^2.
    Vec3 pointAt(const Vec2& uv) const;

    // --- queries (bounding-volume hierarchy over the triangles) ---
    struct Closest {
        Vec3 point = Vec3::Zero();
        Vec3 bary = Vec3::Zero();  ///< barycentric coordinates in `triangle`
        int triangle = -1;
        double distance = 0;
        Vec2 uv = Vec2::Zero();
    };
    /// Closest point of the surface to p (orthogonal projection where it exists).
    Closest closestPoint(const Vec3& p) const;
    /// Indices of triangles whose bounding box overlaps `box` (appended to out, cleared first).
    void trianglesOverlapping(const Box3& box, std::vector<int>& out) const;
    /// Sign of the side of p relative to the nearest triangle: +1 on the side its normal
    /// points to, -1 behind, 0 exactly in its plane (exact predicate given the triangle).
    int sideOf(const Vec3& p) const;
    /// Border edges of the surface (vertex index pairs): the first and last curve, and the
    /// first and last points' polylines.
    std::vector<std::array<int, 2>> borderEdges() const;

private:
    struct Bvh;
    void build();

    int m_m = 0;  ///< curves
    int m_n = 0;  ///< segments per curve
    std::vector<Vec3> m_vertices;
    std::vector<Tri> m_triangles;
    std::vector<char> m_degenerate;
    Box3 m_bounds;
    std::unique_ptr<Bvh> m_bvh;
};

/// Closest point to p on triangle (a, b, c); returns barycentric coordinates (sum 1).
Vec3 closestPointBarycentric(const Vec3& p, const Vec3& a, const Vec3& b, const Vec3& c);

} // namespace resect
