#include "widgets/camera_ray.h"

#include <vtkCamera.h>
#include <vtkMatrix4x4.h>
#include <vtkNew.h>

#include <algorithm>
#include <cmath>

namespace resect {

namespace {

double aspectOf(const QSize& size) {
    return size.height() > 0 ? double(std::max(1, size.width())) / double(size.height()) : 1.0;
}

/// Normalised device coordinates of a pixel: x, y in [-1, 1], y upwards.
Eigen::Vector2d toNdc(const QSize& size, const QPointF& pixel) {
    const double w = std::max(1, size.width()), h = std::max(1, size.height());
    return {2.0 * pixel.x() / w - 1.0, 1.0 - 2.0 * pixel.y() / h};
}

Eigen::Matrix4d projection(vtkCamera* camera, const QSize& size) {
    // Near and far planes at -1 and 1 in depth, as VTK's renderer uses them.
    vtkMatrix4x4* m = camera->GetCompositeProjectionTransformMatrix(aspectOf(size), -1.0, 1.0);
    Eigen::Matrix4d out;
    for (int r = 0; r < 4; ++r)
        for (int c = 0; c < 4; ++c)
            out(r, c) = m->GetElement(r, c);
    return out;
}

Vec3 unproject(const Eigen::Matrix4d& inverse, double x, double y, double z) {
    const Eigen::Vector4d p = inverse * Eigen::Vector4d(x, y, z, 1.0);
    return p.head<3>() / p.w();
}

} // namespace

Vec3 focalPoint(vtkCamera* camera) {
    double f[3];
    camera->GetFocalPoint(f);
    return {f[0], f[1], f[2]};
}

Vec3 viewDirection(vtkCamera* camera) {
    double p[3], f[3];
    camera->GetPosition(p);
    camera->GetFocalPoint(f);
    const Vec3 d(f[0] - p[0], f[1] - p[1], f[2] - p[2]);
    const double n = d.norm();
    return n > 0 ? Vec3(d / n) : Vec3(0, 0, -1);
}

Ray pixelRay(vtkCamera* camera, const QSize& size, const QPointF& pixel) {
    const Eigen::Matrix4d inverse = projection(camera, size).inverse();
    const Eigen::Vector2d ndc = toNdc(size, pixel);
    const Vec3 nearPoint = unproject(inverse, ndc.x(), ndc.y(), -1.0);
    const Vec3 farPoint = unproject(inverse, ndc.x(), ndc.y(), 1.0);
    Ray ray;
    ray.direction = (farPoint - nearPoint).normalized();
    if (camera->GetParallelProjection()) {
        ray.origin = nearPoint;
    } else {
        double p[3];
        camera->GetPosition(p);
        ray.origin = Vec3(p[0], p[1], p[2]);
    }
    return ray;
}

std::optional<QPointF> worldToPixel(vtkCamera* camera, const QSize& size, const Vec3& world) {
    const Eigen::Vector4d clip = projection(camera, size) * Eigen::Vector4d(world.x(), world.y(), world.z(), 1.0);
    if (!(clip.w() > 0))
        return std::nullopt;
    const double x = clip.x() / clip.w(), y = clip.y() / clip.w();
    if (!std::isfinite(x) || !std::isfinite(y))
        return std::nullopt;
    const double w = std::max(1, size.width()), h = std::max(1, size.height());
    return QPointF((x + 1.0) * 0.5 * w, (1.0 - y) * 0.5 * h);
}

std::optional<Vec3> pixelOnViewPlane(vtkCamera* camera, const QSize& size, const QPointF& pixel,
                                     const Vec3& planePoint) {
    const Ray ray = pixelRay(camera, size, pixel);
    const Vec3 normal = viewDirection(camera);
    const double denom = ray.direction.dot(normal);
    if (std::abs(denom) < 1e-12)
        return std::nullopt;
    const double s = (planePoint - ray.origin).dot(normal) / denom;
    if (!std::isfinite(s))
        return std::nullopt;
    return ray.at(s);
}

} // namespace resect
