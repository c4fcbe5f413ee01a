#pragma once
// ViewportTool: a mode of interaction with a VtkViewport (picking a tet, placing sweep
// handles, recording a stroke). The viewport hands every mouse event to its active tool
// first; a tool that returns true has consumed the event, otherwise the viewport's camera
// navigation gets it. Tools work with the camera maths (camera_ray.h), never the GPU, so
// they work under the `offscreen` platform too.

class QMouseEvent;

namespace resect {

class VtkViewport;

class ViewportTool {
public:
    virtual ~ViewportTool() = default;
    virtual bool mousePress(VtkViewport& viewport, QMouseEvent* event) = 0;
    virtual bool mouseMove(VtkViewport& viewport, QMouseEvent* event) = 0;
    virtual bool mouseRelease(VtkViewport& viewport, QMouseEvent* event) = 0;
    /// The viewport stopped using this tool (another tool, or none, was set).
    virtual void deactivated(VtkViewport& /*viewport*/) {}
};

} // namespace resect
