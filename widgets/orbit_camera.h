#pragma once
// OrbitCamera: the viewport's camera model, pure maths on a vtkCamera (no OpenGL needed).
//
// Mouse gestures in pixels map to camera motions around the focal point: orbit (azimuth
// and elevation, trackball style), pan (focal point and position move together in the view
// plane) and zoom (dolly towards the focal point). The same camera is handed to the VTK
// renderer when there is one, so picking and stroke recording can use it under the
// `offscreen` platform too.

#include <vtkSmartPointer.h>

#include <array>

class vtkCamera;

namespace resect {

/// xmin, xmax, ymin, ymax, zmin, zmax, as VTK reports bounds.
using Bounds = std::array<double, 6>;

class OrbitCamera {
public:
    OrbitCamera();

    vtkCamera* camera() const;

    /// Frames the box: focal point at its centre, the current view direction kept, the
    /// distance chosen so that the bounding sphere fits the view angle in the narrower
    /// viewport direction (`aspect` = width / height), clipping range around the sphere.
    /// Empty or invalid bounds (min > max) leave the camera unchanged.
    void reset(const Bounds& bounds, double aspect);

    /// Sets the view direction (from camera to focal point) and up vector, keeping the
    /// focal point and distance; call reset() afterwards to frame a box.
    void setViewDirection(const std::array<double, 3>& direction, const std::array<double, 3>& up);

    /// Rotates around the focal point: a drag across the whole viewport height turns by
    /// kDegreesPerViewportHeight; dx > 0 turns the scene to the right, dy > 0 (downward
    /// in Qt coordinates) tilts it towards the viewer.
    void orbit(double dxPixels, double dyPixels, double viewportHeightPixels);

    /// Moves focal point and position together so that the point under the cursor follows
    /// it (exact at the focal plane, perspective projection).
    void pan(double dxPixels, double dyPixels, double viewportHeightPixels);

    /// Moves towards the focal point by `factor` (> 1 closer, < 1 farther); non-positive
    /// or non-finite factors are ignored.
    void zoom(double factor);

    /// Sets the clipping range to enclose the box from the current position (a renderer
    /// refines it before each frame; this keeps the camera valid without one).
    void fitClippingRange(const Bounds& bounds);

    static constexpr double kDegreesPerViewportHeight = 180.0;

private:
    vtkSmartPointer<vtkCamera> m_camera;
};

/// True if the bounds describe a non-empty box (min <= max on every axis, all finite).
bool validBounds(const Bounds& bounds);

} // namespace resect
