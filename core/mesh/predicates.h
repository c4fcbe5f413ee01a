#pragma once
// Exact geometric predicates (CGAL's filtered exact kernel behind a plain interface, so
// that CGAL stays private to a few translation units).

#include "core/mesh/tet_mesh.h"

namespace resect {

/// Sign of det[b-a, c-a, d-a]: +1 if d lies on the positive side of the plane (a, b, c)
/// (the tet a,b,c,d is positively oriented), -1 on the negative side, 0 if coplanar.
/// Exact for any finite double input.
int orient3d(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d);

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
