#pragma once
// Exact geometric predicates (CGAL's filtered exact kernel behind a plain interface, so
// that CGAL stays private to a few translation units). orient3d, which the cut steps call in
// their inner loops, first tries a floating-point filter inline here and asks CGAL only when
// the filter cannot vouch for the sign.

#include "core/mesh/tet_mesh.h"

#include <cmath>

namespace resect {

/// The floating-point stage of orient3d: the sign of det[b-a, c-a, d-a] (+1 or -1) when the
/// rounded determinant exceeds a bound on its rounding error, so that the sign is certainly
/// the exact one; 0 when it does not (nearly or exactly coplanar points, non-finite input).
///
/// The bound is Shewchuk's for this 3x3 determinant of coordinate differences (J. R.
/// Shewchuk, "Adaptive Precision Floating-Point Arithmetic and Fast Robust Geometric
/// Predicates", Discrete Comput. Geom. 18, 1997, section 4.3; orient3d's errboundA =
/// (7 + 56 eps) eps with eps = 2^-53, times the permanent, the same expression with every
/// product and difference taken by absolute value). It assumes no underflow; the second
/// term covers what underflow can add: each of the nine products may lose up to 2^-1075,
/// and an inner product's loss is multiplied by its outer factor (|u_z|, |v_z|, |w_z|), so
/// together less than 2^-1073 (|u_z| + |v_z| + |w_z| + 1); (.. + 1) 2^-1071 is four times
/// that. Overflow gives an infinite or NaN bound or determinant, which decides nothing.
inline int orient3dFilter(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d) {
    constexpr double kEps = 0x1p-53;
    constexpr double kRelativeBound = (7.0 + 56.0 * kEps) * kEps;
    constexpr double kUnderflowUnit = 0x1p-1071;
    const double ux = b.x() - a.x(), uy = b.y() - a.y(), uz = b.z() - a.z();
    const double vx = c.x() - a.x(), vy = c.y() - a.y(), vz = c.z() - a.z();
    const double wx = d.x() - a.x(), wy = d.y() - a.y(), wz = d.z() - a.z();
    const double vxwy = vx * wy, wxvy = wx * vy;
    const double wxuy = wx * uy, uxwy = ux * wy;
    const double uxvy = ux * vy, vxuy = vx * uy;
    const double det = uz * (vxwy - wxvy) + vz * (wxuy - uxwy) + wz * (uxvy - vxuy);
    const double auz = std::abs(uz), avz = std::abs(vz), awz = std::abs(wz);
    const double permanent = (std::abs(vxwy) + std::abs(wxvy)) * auz +
                             (std::abs(wxuy) + std::abs(uxwy)) * avz +
                             (std::abs(uxvy) + std::abs(vxuy)) * awz;
    const double bound = kRelativeBound * permanent + (auz + avz + awz + 1.0) * kUnderflowUnit;
    if (det > bound)
        return 1;
    if (-det > bound)
        return -1;
    return 0;
}

/// orient3d decided exactly (CGAL), without the filter; for tests and for the filter's
/// undecided cases.
int orient3dExact(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d);

/// Sign of det[b-a, c-a, d-a]: +1 if d lies on the positive side of the plane (a, b, c)
/// (the tet a,b,c,d is positively oriented), -1 on the negative side, 0 if coplanar.
/// Exact for any finite double input.
inline int orient3d(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d) {
    if (const int sign = orient3dFilter(a, b, c, d))
        return sign;
    return orient3dExact(a, b, c, d);
}

/// True if a, b and c are exactly collinear (the triangle has zero area).
bool collinear(const Vec3& a, const Vec3& b, const Vec3& c);

/// True if the closed triangles (a, b, c) and (d, e, f) intersect (exact; both must be
/// non-degenerate).
bool trianglesIntersect(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d, const Vec3& e,
                        const Vec3& f);

/// For p coplanar with the non-degenerate triangle (a, b, c) (orient3d == 0): true if p lies
/// in the closed triangle. Exact (projects along the normal's dominant axis).
bool inClosedTriangle(const Vec3& p, const Vec3& a, const Vec3& b, const Vec3& c);

/// Sign of the 2-D orientation of (a, b, c) after dropping coordinate `drop` (0, 1 or 2).
int orient2dProjected(const Vec3& a, const Vec3& b, const Vec3& c, int drop);

} // namespace resect
