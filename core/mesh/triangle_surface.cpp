#include "core/mesh/triangle_surface.h"

#include <Eigen/Geometry>

namespace resect {

double surfaceArea(const TriangleSurface& surface) {
    double area = 0.0;
    for (const Tri& t : surface.triangles) {
        const Vec3& a = surface.positions[t[0]];
        area += 0.5 * (surface.positions[t[1]] - a).cross(surface.positions[t[2]] - a).norm();
    }
    return area;
}

double enclosedVolume(const TriangleSurface& surface) {
    // Sum relative to the centroid of the first vertex keeps cancellation small for models
    // far from the origin.
    if (surface.positions.empty())
        return 0.0;
    const Vec3 o = surface.positions.front();
    double sum = 0.0;
    for (const Tri& t : surface.triangles) {
        const Vec3 a = surface.positions[t[0]] - o;
        const Vec3 b = surface.positions[t[1]] - o;
        const Vec3 c = surface.positions[t[2]] - o;
        sum += a.dot(b.cross(c));
    }
    return sum / 6.0;
}

std::array<Vec3, 2> boundingBox(std::span<const Vec3> points) {
    if (points.empty())
        return {Vec3::Zero(), Vec3::Zero()};
    Vec3 lo = points.front(), hi = points.front();
    for (const Vec3& p : points) {
        lo = lo.cwiseMin(p);
        hi = hi.cwiseMax(p);
    }
    return {lo, hi};
}

} // namespace resect
