#pragma once
// Element quality measures as in the paper's Table 1 (section 6), all computed in the
// reference configuration.

#include "core/mesh/tet_mesh.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <vector>

namespace resect {

/// Quality of one tet given its four corners.
struct TetQuality {
    double volume = 0;          ///< signed volume
    double radiusRatio = 0;     ///< 3 r_in / R_circ: 1 for a regular tet, 0 when degenerate,
                                ///< negative for inverted tets. The paper's tet_minAR is this
                                ///< value divided by 3 (r_in / R_circ).
    double minDihedral = 0;     ///< radians
    double maxDihedral = 0;     ///< radians
    double minEdge = 0;
    double maxEdge = 0;
};

/// Computes the measures of one tet. Scale invariant: coordinates are translated to the
/// first corner and divided by the longest edge before the ratios are taken, so tets of
/// size 1e-6 and 1e6 give the same ratios as at size 1.
TetQuality tetQuality(const Vec3& p0, const Vec3& p1, const Vec3& p2, const Vec3& p3);

/// Only the radius ratio 3 r_in / R_circ (signed; same value as tetQuality's), without the
/// dihedral angles: for inner loops that compare shapes (inline for them: relaxation and
/// decomposition evaluate it tens of thousands of times per cut).
inline double radiusRatio(const Vec3& p0, const Vec3& p1, const Vec3& p2, const Vec3& p3) {
    double lmax2 = 0;
    const Vec3 p[4] = {p0, p1, p2, p3};
    for (const auto& e : kTetEdges)
        lmax2 = std::max(lmax2, (p[e[1]] - p[e[0]]).squaredNorm());
    if (!(lmax2 > 0) || !std::isfinite(lmax2))
        return 0;
    const double s = 1.0 / std::sqrt(lmax2);
    const Vec3 a = (p1 - p0) * s, b = (p2 - p0) * s, c = (p3 - p0) * s;
    const double sixV = a.dot(b.cross(c));
    const double areaSum = 0.5 * (a.cross(b).norm() + b.cross(c).norm() + c.cross(a).norm() +
                                  (b - a).cross(c - a).norm());
    const Vec3 num =
        a.squaredNorm() * b.cross(c) + b.squaredNorm() * c.cross(a) + c.squaredNorm() * a.cross(b);
    const double absSixV = std::abs(sixV);
    if (!(absSixV > 0) || !(areaSum > 0))
        return 0;
    const double rIn = (absSixV / 2.0) / areaSum;
    const double rCirc = num.norm() / (2.0 * absSixV);
    return std::copysign(3.0 * rIn / rCirc, sixV);
}

/// radiusRatio of two tets at once, s and t (corners in order), bit for bit the same values:
/// each SIMD lane performs radiusRatio's operations in its order, and lanes round as scalars
/// do. About twice as fast; for loops that need many ratios (relaxation's trial moves).
std::array<double, 2> radiusRatioPair(const std::array<Vec3, 4>& s, const std::array<Vec3, 4>& t);

/// Measures of every tet of the mesh (reference configuration).
std::vector<TetQuality> tetQualities(const TetMesh& mesh);

/// Mesh summary, the rows of Table 1 (without the time step, see stable_time_step.h).
struct QualitySummary {
    int nodes = 0;
    int edges = 0;
    int tets = 0;
    double volume = 0;            ///< total signed reference volume
    double minRadiusRatio = 0;
    double meanRadiusRatio = 0;
    double minAspectRatioPaper = 0;  ///< minRadiusRatio / 3, the paper's tet_minAR
    double volumeRatio = 0;       ///< Vmax / Vmin over all tets (|V|; inf if Vmin is 0)
    double edgeRatio = 0;         ///< lmax / lmin over all edges
    double minEdge = 0;
    double maxEdge = 0;
    double meanEdge = 0;          ///< average edge length (unique edges); the unit of `d`
    double minDihedralDeg = 0;
    double maxDihedralDeg = 0;
};
QualitySummary summarizeQuality(const TetMesh& mesh);

/// Mean length of the unique edges in the reference configuration.
double meanEdgeLength(const TetMesh& mesh);

} // namespace resect
