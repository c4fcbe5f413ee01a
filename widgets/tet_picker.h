#pragma once
// TetPicker: a viewport tool that picks the tet under a click (issue 8, tet inspection).
//
// A click is a left press and release, without modifiers, that moved less than
// kClickTolerance pixels; the picker consumes those presses (so a plain left drag does not
// orbit while it is active; Shift/Ctrl+left, middle and right buttons and the wheel still
// navigate). On the release it casts pixelRay (camera_ray.h) through the pixel and finds the
// nearest triangle of the tet mesh actor's displayed geometry (TetMeshActor::boundary():
// exactly what is drawn, so the quality filter, the clipping plane and shrunk tets are
// respected), then emits tetPicked with its owning tet, or -1 for a miss.
//
// Pure camera maths and ray/triangle tests (Moller-Trumbore, with a bounding-box early out
// for the whole geometry): works under the `offscreen` platform.

#include "widgets/camera_ray.h"
#include "widgets/viewport_tool.h"

#include <QObject>
#include <QPointF>

namespace resect {

class TetMeshActor;
class VtkViewport;

class TetPicker : public QObject, public ViewportTool {
    Q_OBJECT

public:
    explicit TetPicker(QObject* parent = nullptr);

    /// The tet whose displayed triangle is hit first by the ray through `pixel` (widget
    /// coordinates of the viewport), or -1.
    static int pickTet(const VtkViewport& viewport, QPointF pixel);
    /// The same for any actor and ray; `distance` (optional) receives the ray parameter of
    /// the hit.
    static int pickTet(const TetMeshActor& actor, const Ray& ray, double* distance = nullptr);

    /// The last tet picked by a click (-1 after a miss or before any click).
    int lastPicked() const { return m_lastPicked; }

    bool mousePress(VtkViewport& viewport, QMouseEvent* event) override;
    bool mouseMove(VtkViewport& viewport, QMouseEvent* event) override;
    bool mouseRelease(VtkViewport& viewport, QMouseEvent* event) override;
    void deactivated(VtkViewport& viewport) override;

    /// Largest motion between press and release, in pixels, that still counts as a click.
    static constexpr double kClickTolerance = 4.0;

signals:
    /// A click picked `tet` (-1: nothing under the cursor).
    void tetPicked(int tet);
    /// The viewport stopped using this tool (another tool, or none, was set).
    void toolDeactivated();

private:
    bool m_pressed = false;
    bool m_moved = false;
    QPointF m_pressPos;
    int m_lastPicked = -1;
};

} // namespace resect
