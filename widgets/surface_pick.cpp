#include "widgets/surface_pick.h"

#include "core/mesh/topology.h"

#include <cmath>
#include <limits>

namespace resect {

std::optional<Vec3> raySurfaceHit(const Ray& ray, const TriangleSurface& surface) {
    // Moeller-Trumbore: solve origin + s * dir = a + b1 * (b - a) + b2 * (c - a).
    double best = std::numeric_limits<double>::infinity();
    const int vertexCount = surface.vertexCount();
    for (const Tri& t : surface.triangles) {
        if (t[0] < 0 || t[1] < 0 || t[2] < 0 || t[0] >= vertexCount || t[1] >= vertexCount ||
            t[2] >= vertexCount)
            continue;
        const Vec3& a = surface.positions[t[0]];
        const Vec3 e1 = surface.positions[t[1]] - a;
        const Vec3 e2 = surface.positions[t[2]] - a;
        const Vec3 p = ray.direction.cross(e2);
        const double det = e1.dot(p);
        // det = dir . (e1 x e2): zero for a ray parallel to the triangle or a triangle of
        // zero area; either way there is no single crossing point.
        if (!(det != 0.0) || !std::isfinite(det))
            continue;
        const Vec3 toOrigin = ray.origin - a;
        const double b1 = toOrigin.dot(p) / det;
        if (b1 < 0.0 || b1 > 1.0)
            continue;
        const Vec3 q = toOrigin.cross(e1);
        const double b2 = ray.direction.dot(q) / det;
        if (b2 < 0.0 || b1 + b2 > 1.0)
            continue;
        const double s = e2.dot(q) / det;
        if (s >= 0.0 && s < best)
            best = s;
    }
    if (!std::isfinite(best))
        return std::nullopt;
    return ray.at(best);
}

TriangleSurface pickSurfaceOf(const TetMesh& mesh) {
    TriangleSurface surface;
    surface.positions.assign(mesh.positions().begin(), mesh.positions().end());
    for (const BoundaryFace& face : boundaryFaces(mesh))
        surface.triangles.push_back(face.nodes);
    return surface;
}

} // namespace resect
