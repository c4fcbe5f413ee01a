#include "core/mesh/predicates.h"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>

namespace resect {
namespace {
using K = CGAL::Exact_predicates_inexact_constructions_kernel;
K::Point_3 toCgal(const Vec3& p) { return {p.x(), p.y(), p.z()}; }
} // namespace

int orient3dExact(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d) {
    // CGAL::orientation(p, q, r, s) is POSITIVE when s lies on the positive side of the
    // oriented plane (p, q, r), i.e. det[q-p, r-p, s-p] > 0.
    return static_cast<int>(CGAL::orientation(toCgal(a), toCgal(b), toCgal(c), toCgal(d)));
}

bool collinear(const Vec3& a, const Vec3& b, const Vec3& c) {
    return CGAL::collinear(toCgal(a), toCgal(b), toCgal(c));
}

bool trianglesIntersect(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d, const Vec3& e,
                        const Vec3& f) {
    const K::Triangle_3 t1(toCgal(a), toCgal(b), toCgal(c)), t2(toCgal(d), toCgal(e), toCgal(f));
    return CGAL::do_intersect(t1, t2);
}

bool inClosedTriangle(const Vec3& p, const Vec3& a, const Vec3& b, const Vec3& c) {
    const Vec3 n = ((b - a).cross(c - a)).cwiseAbs();
    const int drop = n.x() >= n.y() ? (n.x() >= n.z() ? 0 : 2) : (n.y() >= n.z() ? 1 : 2);
    const int s = orient2dProjected(a, b, c, drop);
    if (s == 0)
        return false;
    return orient2dProjected(a, b, p, drop) != -s && orient2dProjected(b, c, p, drop) != -s &&
           orient2dProjected(c, a, p, drop) != -s;
}

int orient2dProjected(const Vec3& a, const Vec3& b, const Vec3& c, int drop) {
    const int i = drop == 0 ? 1 : 0;
    const int j = drop == 2 ? 1 : 2;
    const K::Point_2 pa(a[i], a[j]), pb(b[i], b[j]), pc(c[i], c[j]);
    return static_cast<int>(CGAL::orientation(pa, pb, pc));
}

} // namespace resect
