#pragma once
// FixedRegionTool: the first tissue's fixed regions drawn in a VtkViewport as boxes, each with
// a handle at the centre of each of its six faces (HandleActor), so that the author places a
// box where it should anchor the tissue (issue 19).
//
// While active (setActive(true): the viewport's tool, the boxes shown), a left press within
// kHandlePickPixels of a handle grabs that face, and dragging moves the face along its axis
// (to the point of the axis nearest to the ray under the cursor; it never passes the opposite
// face); the box is redrawn as it moves, and the release is one document edit
// (ScenarioDocument::setFixedRegion: undoable). A press anywhere else, and every other button
// or modifier, is left to the camera. The tool follows the document (undo, redo, the numeric
// editor, a new document). Picking uses the camera maths (camera_ray.h), so the tool works
// under the `offscreen` platform.
//
// Boxes are orange outlines; a face's handle is red, green or blue for x, y or z (the axis it
// moves along), white while dragged.

#include "scenario/scenario_document.h"
#include "widgets/handle_actor.h"
#include "widgets/viewport_tool.h"

#include <QObject>
#include <QPointF>
#include <QPointer>

#include <optional>
#include <vector>

#include <vtkSmartPointer.h>

class vtkActor;
class vtkPolyData;

namespace resect {

class ScenarioDocument;
class VtkViewport;

class FixedRegionTool : public QObject, public ViewportTool {
    Q_OBJECT

public:
    static constexpr double kHandlePickPixels = 10.0;

    /// A face of a box: region `region`, axis 0..2, the max face or the min one.
    struct Face {
        int region = -1;
        int axis = 0;
        bool max = false;
        bool operator==(const Face&) const = default;
    };

    FixedRegionTool(ScenarioDocument& document, VtkViewport* viewport, QObject* parent = nullptr);
    ~FixedRegionTool() override;

    /// Shows the boxes and makes this the viewport's tool (or hides them and gives the
    /// viewport back to the camera).
    void setActive(bool active);
    bool isActive() const { return m_active; }

    /// The centre of a face (world, mm) of the boxes as drawn.
    Vec3 faceCentre(const Face& face) const;
    /// The face whose handle is under `pixel` (within kHandlePickPixels), if any.
    std::optional<Face> faceAt(const QPointF& pixel) const;
    /// The boxes as drawn (the document's, or the one being dragged).
    const std::vector<FixedRegion>& regions() const { return m_regions; }
    /// Handles shown (six per box while active).
    int handleCount() const { return m_handles.count(); }

    bool mousePress(VtkViewport& viewport, QMouseEvent* event) override;
    bool mouseMove(VtkViewport& viewport, QMouseEvent* event) override;
    bool mouseRelease(VtkViewport& viewport, QMouseEvent* event) override;
    void deactivated(VtkViewport& viewport) override;

signals:
    /// Active or not (also when another tool took the viewport).
    void activeChanged(bool active);

private:
    void syncFromDocument();
    void updateDisplay();
    /// The coordinate of the dragged face under `pixel`, if the ray is not parallel to its axis.
    std::optional<double> dragCoordinate(const QPointF& pixel) const;
    void finishDrag();

    ScenarioDocument& m_document;
    QPointer<VtkViewport> m_viewport;
    std::vector<FixedRegion> m_regions;
    HandleActor m_handles;
    vtkSmartPointer<vtkPolyData> m_outline;
    vtkSmartPointer<vtkActor> m_outlineActor;
    bool m_active = false;
    std::optional<Face> m_dragged;
    double m_grabOffset = 0; ///< face coordinate minus the cursor's, at the press
    bool m_dragChanged = false;
};

} // namespace resect
