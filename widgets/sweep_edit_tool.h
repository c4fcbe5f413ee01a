#pragma once
// SweepEditTool: draws an explicit sweep surface (the paper's case, section 4.2: a start
// and an end curve of the tool with the same number of points) in a VtkViewport.
//
// How the author works with it (set it with VtkViewport::setTool):
//  1. Start curve (the active curve at first): each left press away from a handle adds a
//     point at the end of the active curve and grabs it, so holding the button and dragging
//     puts it in place. A new point lands on the pick surface under the cursor when one is
//     set (setPickSurface: the tissue), otherwise on the view plane through the active
//     curve's last point (for a curve's first point: through the other curve's first point,
//     or the camera's focal point when both are empty).
//  2. End curve: beginEndCurve() (the "End curve" button) makes the end curve active, and
//     its points are clicked in one by one, as for the start curve: point k is where the
//     tool's point k ends its path. (An automatic copy of the start curve, shifted down the
//     view, used to appear here: on a tissue its handles ended up hidden inside it and the
//     author had to find and drag every one. copyStartToEnd() still makes such a copy for
//     callers that want it.)
//  3. Any handle (drawn as a sphere of HandleActor::kSizePixels: start curve green, end
//     curve orange, the selected one white) can be dragged: a left press within
//     kHandlePickPixels of it grabs it and it moves in the view plane through its position,
//     keeping the offset between cursor and handle. removeSelectedPoint() and
//     removeLastPoint() delete points.
// Shift/Ctrl + left, the middle and the right button, and Alt + left (orbit) are left to the
// viewport's camera navigation.
//
// Undo: sweepChanged() is emitted once per completed edit (a point added and dragged, a
// handle moved, a point removed, curves replaced or cleared), after the edit. curves() and
// setCurves() save and restore the whole state for undo commands. previewChanged() is also
// emitted for every intermediate drag step (for live redraws, not for undo).
//
// The editor accepts any state (too few points, unequal counts, coincident points);
// isValid() and problem() say whether sweepSpec() is usable and, if not, why. Points are
// never NaN: a cursor position whose ray misses the view plane is ignored.

#include "core/mesh/triangle_surface.h"
#include "scenario/scenario_document.h"
#include "widgets/handle_actor.h"
#include "widgets/sweep_actor.h"
#include "widgets/viewport_tool.h"

#include <QObject>
#include <QPointF>
#include <QPointer>
#include <QString>

#include <array>
#include <optional>
#include <string>
#include <vector>

namespace resect {

class VtkViewport;

class SweepEditTool : public QObject, public ViewportTool {
    Q_OBJECT

public:
    enum class Curve { Start = 0, End = 1 };
    Q_ENUM(Curve)

    /// A handle: point `index` of curve `curve`.
    struct Handle {
        Curve curve = Curve::Start;
        int index = -1;
        bool operator==(const Handle&) const = default;
    };

    /// The tool draws into `viewport` (its props are added there now and removed when the
    /// tool is destroyed); it still has to be made the viewport's tool with setTool().
    explicit SweepEditTool(VtkViewport* viewport, QObject* parent = nullptr);
    ~SweepEditTool() override;

    // --- state ---
    const std::vector<Vec3>& curve(Curve c) const;
    /// Both curves, {start, end}.
    std::vector<std::vector<Vec3>> curves() const;
    /// Replaces both curves (for undo/redo or loading a sweep to edit); non-finite points
    /// are dropped. Keeps the active curve; clears the selection. Emits sweepChanged().
    void setCurves(const std::vector<Vec3>& start, const std::vector<Vec3>& end);
    /// Removes every point, makes the start curve active. Emits sweepChanged().
    void clear();

    Curve activeCurve() const { return m_active; }
    void setActiveCurve(Curve c);
    /// Makes the end curve active (its points are then clicked in, see above).
    void beginEndCurve();
    /// What the next left click on empty space does, for a status line: which point of
    /// which curve it places (with the modifier that turns the view instead).
    QString nextClickHint() const;
    /// Replaces the end curve by the start curve moved by `offset` (mm). Emits sweepChanged().
    void copyStartToEnd(const Vec3& offset);
    /// A fifth of the view's height downwards in the view, at the depth of the start curve's
    /// centroid (or the focal point when the start curve is empty); zero without a viewport.
    Vec3 defaultEndOffset() const;

    /// Moves a point (ignored for a non-finite position or a bad handle). Emits
    /// sweepChanged().
    void movePoint(const Handle& handle, const Vec3& position);
    /// Removes a point. Returns false for a bad handle. Emits sweepChanged().
    bool removePoint(const Handle& handle);
    /// Removes the last point of the active curve; false if it was empty.
    bool removeLastPoint();
    /// Removes the selected point; false if none is selected.
    bool removeSelectedPoint();
    /// The handle last pressed or added; empty after a removal, clear() or setCurves().
    std::optional<Handle> selectedHandle() const { return m_selected; }

    /// Surface that new points are placed on (the tissue, world coordinates). Copied.
    void setPickSurface(const TriangleSurface& surface);
    void clearPickSurface();

    /// Name given to the SweepSpec.
    void setName(const std::string& name) { m_name = name; }
    const std::string& name() const { return m_name; }

    // --- validity ---
    /// True when both curves have >= 2 points, equally many, no two consecutive points of a
    /// curve coincide (within kCoincidentTolerance of the points' bounding-box diagonal) and
    /// SweepSurface::fromStartEnd accepts them (non-zero area, no self-intersection).
    bool isValid() const { return problem().isEmpty(); }
    /// Why the state is not a usable sweep (translated); empty when it is.
    QString problem() const;
    /// The sweep as a scenario entry {name, curves {start, end}}; empty when not valid.
    std::optional<SweepSpec> sweepSpec() const;

    // --- picking ---
    /// The handle nearest to `pixel` within kHandlePickPixels (viewport pixels), preferring
    /// the active curve on a tie; empty if none (or no viewport).
    std::optional<Handle> handleAt(const QPointF& pixel) const;
    /// True while a handle is being dragged.
    bool isDragging() const { return m_dragging; }

    SweepActor& sweepActor() { return m_sweepActor; }
    HandleActor& handleActor() { return m_handleActor; }

    static constexpr double kHandlePickPixels = 8.0;
    static constexpr double kCoincidentTolerance = 1e-9;
    static constexpr HandleActor::Color kStartHandleColor{0.35, 0.95, 0.45};
    static constexpr HandleActor::Color kEndHandleColor{1.00, 0.60, 0.15};
    static constexpr HandleActor::Color kSelectedHandleColor{1.00, 1.00, 1.00};

    // --- ViewportTool ---
    bool mousePress(VtkViewport& viewport, QMouseEvent* event) override;
    bool mouseMove(VtkViewport& viewport, QMouseEvent* event) override;
    bool mouseRelease(VtkViewport& viewport, QMouseEvent* event) override;
    void deactivated(VtkViewport& viewport) override;

signals:
    /// A completed edit (see the header comment); query curves()/sweepSpec().
    void sweepChanged();
    /// Any change of the shown state, including every step of a drag.
    void previewChanged();
    void activeCurveChanged(resect::SweepEditTool::Curve curve);

private:
    std::vector<Vec3>& points(Curve c) { return m_curves[static_cast<int>(c)]; }
    bool validHandle(const Handle& h) const;
    /// Where a new point under `pixel` goes (see the header comment).
    std::optional<Vec3> placePoint(VtkViewport& viewport, const QPointF& pixel) const;
    void finishDrag();
    void updateDisplay();

    QPointer<VtkViewport> m_viewport;
    std::array<std::vector<Vec3>, 2> m_curves;
    Curve m_active = Curve::Start;
    std::optional<Handle> m_selected;
    std::string m_name;
    std::optional<TriangleSurface> m_pickSurface;

    bool m_dragging = false;
    bool m_dragChanged = false; ///< the drag added or moved a point
    Vec3 m_dragAnchor = Vec3::Zero(); ///< the handle's position at the press
    Vec3 m_dragOffset = Vec3::Zero(); ///< handle minus the cursor's point at the press

    SweepActor m_sweepActor;
    HandleActor m_handleActor;
};

} // namespace resect
