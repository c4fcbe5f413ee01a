#include "widgets/orbit_camera.h"

#include <vtkCamera.h>
#include <vtkMath.h>

#include <algorithm>
#include <cmath>
#include <numbers>

namespace resect {

namespace {

constexpr double kDegToRad = std::numbers::pi / 180.0;

/// Radius of the sphere through the box corners, and its centre.
double boundingRadius(const Bounds& b, double centre[3]) {
    double r2 = 0;
    for (int i = 0; i < 3; ++i) {
        centre[i] = 0.5 * (b[2 * i] + b[2 * i + 1]);
        const double half = 0.5 * (b[2 * i + 1] - b[2 * i]);
        r2 += half * half;
    }
    return std::sqrt(r2);
}

} // namespace

bool validBounds(const Bounds& bounds) {
    for (int i = 0; i < 3; ++i) {
        if (!std::isfinite(bounds[2 * i]) || !std::isfinite(bounds[2 * i + 1]) ||
            bounds[2 * i] > bounds[2 * i + 1])
            return false;
    }
    return true;
}

OrbitCamera::OrbitCamera() : m_camera(vtkSmartPointer<vtkCamera>::New()) {}

vtkCamera* OrbitCamera::camera() const {
    return m_camera;
}

void OrbitCamera::reset(const Bounds& bounds, double aspect) {
    if (!validBounds(bounds))
        return;
    double centre[3];
    double radius = boundingRadius(bounds, centre);
    if (!(radius > 0))
        radius = 0.5; // a single point: frame a unit sphere around it

    // The sphere must fit the narrower field of view. VTK's view angle is vertical; a
    // viewport narrower than tall has a smaller horizontal angle (vtkRenderer::ResetCamera
    // makes the same choice).
    const double vertical = m_camera->GetViewAngle() * kDegToRad;
    double angle = vertical;
    if (aspect > 0 && aspect < 1)
        angle = 2.0 * std::atan(std::tan(0.5 * vertical) * aspect);
    const double distance = radius / std::sin(0.5 * angle);

    double direction[3];
    m_camera->GetDirectionOfProjection(direction);
    m_camera->SetFocalPoint(centre);
    m_camera->SetPosition(centre[0] - distance * direction[0], centre[1] - distance * direction[1],
                          centre[2] - distance * direction[2]);
    m_camera->OrthogonalizeViewUp();
    fitClippingRange(bounds);
}

void OrbitCamera::setViewDirection(const std::array<double, 3>& direction,
                                   const std::array<double, 3>& up) {
    double d[3] = {direction[0], direction[1], direction[2]};
    if (vtkMath::Normalize(d) == 0.0)
        return;
    double fp[3];
    m_camera->GetFocalPoint(fp);
    const double distance = m_camera->GetDistance();
    m_camera->SetPosition(fp[0] - distance * d[0], fp[1] - distance * d[1],
                          fp[2] - distance * d[2]);
    m_camera->SetViewUp(up[0], up[1], up[2]);
    m_camera->OrthogonalizeViewUp();
}

void OrbitCamera::orbit(double dxPixels, double dyPixels, double viewportHeightPixels) {
    if (!(viewportHeightPixels > 0))
        return;
    const double degreesPerPixel = kDegreesPerViewportHeight / viewportHeightPixels;
    m_camera->Azimuth(-dxPixels * degreesPerPixel);
    m_camera->Elevation(dyPixels * degreesPerPixel);
    m_camera->OrthogonalizeViewUp();
}

void OrbitCamera::pan(double dxPixels, double dyPixels, double viewportHeightPixels) {
    if (!(viewportHeightPixels > 0))
        return;
    // Height of the view at the focal plane, in world units.
    const double worldHeight =
        2.0 * m_camera->GetDistance() * std::tan(0.5 * m_camera->GetViewAngle() * kDegToRad);
    const double scale = worldHeight / viewportHeightPixels;

    double up[3], dop[3], right[3];
    m_camera->GetViewUp(up);
    m_camera->GetDirectionOfProjection(dop);
    vtkMath::Cross(dop, up, right);
    vtkMath::Normalize(right);

    // The scene follows the cursor: the camera moves the other way. Qt's y grows downward.
    double shift[3];
    for (int i = 0; i < 3; ++i)
        shift[i] = scale * (-dxPixels * right[i] + dyPixels * up[i]);

    double fp[3], pos[3];
    m_camera->GetFocalPoint(fp);
    m_camera->GetPosition(pos);
    m_camera->SetFocalPoint(fp[0] + shift[0], fp[1] + shift[1], fp[2] + shift[2]);
    m_camera->SetPosition(pos[0] + shift[0], pos[1] + shift[1], pos[2] + shift[2]);
}

void OrbitCamera::zoom(double factor) {
    if (!(factor > 0) || !std::isfinite(factor))
        return;
    m_camera->Dolly(factor);
}

void OrbitCamera::fitClippingRange(const Bounds& bounds) {
    if (!validBounds(bounds))
        return;
    double centre[3];
    const double radius = std::max(boundingRadius(bounds, centre), 1e-12);
    double pos[3], dop[3];
    m_camera->GetPosition(pos);
    m_camera->GetDirectionOfProjection(dop);
    // Depth of the sphere centre along the view direction.
    const double depth = (centre[0] - pos[0]) * dop[0] + (centre[1] - pos[1]) * dop[1] +
                         (centre[2] - pos[2]) * dop[2];
    const double farPlane = depth + 1.01 * radius;
    // A near plane at or behind the eye is invalid; keep a depth-buffer friendly ratio.
    const double nearPlane = std::max(depth - 1.01 * radius, 1e-3 * farPlane);
    if (farPlane > 0)
        m_camera->SetClippingRange(nearPlane, farPlane);
}

} // namespace resect
