#pragma once
// Camera maths for picking and stroke recording: pixels of a viewport to world-space rays
// and back, from the vtkCamera's projection alone (no renderer, no OpenGL), so they work
// under the `offscreen` platform.
//
// Pixels are Qt widget coordinates: origin at the top-left corner, y downwards, in logical
// pixels of a viewport of `size`.

#include "core/mesh/tet_mesh.h"

#include <QPointF>
#include <QSize>

#include <optional>

class vtkCamera;

namespace resect {

/// A ray origin + s * direction, s >= 0; `direction` has unit length.
struct Ray {
    Vec3 origin = Vec3::Zero();
    Vec3 direction = Vec3::UnitZ();
    Vec3 at(double s) const { return origin + s * direction; }
};

/// The ray from the eye through `pixel` (perspective: from the camera position; parallel
/// projection: from the near plane along the view direction).
Ray pixelRay(vtkCamera* camera, const QSize& size, const QPointF& pixel);

/// Where `world` appears in the viewport; empty when it is behind the camera.
std::optional<QPointF> worldToPixel(vtkCamera* camera, const QSize& size, const Vec3& world);

/// The point under `pixel` on the plane through `planePoint` perpendicular to the view
/// direction (the plane a drag moves things in); empty if the ray is parallel to it.
std::optional<Vec3> pixelOnViewPlane(vtkCamera* camera, const QSize& size, const QPointF& pixel,
                                     const Vec3& planePoint);

/// The camera's focal point and view-plane normal (from the camera towards the focal point,
/// unit length).
Vec3 focalPoint(vtkCamera* camera);
Vec3 viewDirection(vtkCamera* camera);

} // namespace resect
