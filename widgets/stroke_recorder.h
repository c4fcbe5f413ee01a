#pragma once
// StrokeRecorder: records a tool stroke (scenario_document.h, Stroke) with the mouse in a
// VtkViewport, in one of two motions (setMotion).
//
// Drag (the default): a left-button drag moves the loop across the view.
//  - Depth: at the press, the depth reference is the point where the press ray meets the
//    pick surface (setPickSurface: the tissue) if it does, else the camera's focal point.
//  - Position: every mouse move (and the release) samples the point under the cursor on the
//    view plane through that reference (pixelOnViewPlane), the press giving the first pose.
//    A sample closer than minSpacingPixels() (viewport pixels) to the last sampled cursor
//    position is skipped, as is one whose time stamp does not increase.
//  - Orientation: one fixed orientation for the whole stroke, chosen at the first sampled
//    movement (strokeOrientation): the loop's plane perpendicular to the drag direction d
//    (the loop cuts like a resectoscope's electrode pulled through tissue), the loop's
//    chord across the drag in the view plane, and its bulge pointing away from the viewer.
//  - Forward only (issue 15): after the first movement a sample is taken only if it
//    advances along d by at least kMinAdvanceFraction of the loop's width (loopWidth) past
//    the last pose. The loop is a fixed planar curve perpendicular to d, so the strip swept
//    between two poses lies in its own slab of d and the sweep can never intersect itself:
//    the stroke is always valid, however the mouse wiggles or turns back. While the cursor
//    is not ahead of the last pose, hintChanged() says so ("move forward ...") and the tool
//    and the sweep stay where the valid stroke ends; moving ahead again continues it.
//
// Pull (the paper's loop motion, section 2 and Figure 10): the loop electrode is placed
// behind the tissue and pulled towards the camera, cutting off what lies inside the loop.
// The press picks where the loop cuts deepest: the loop faces the camera with the tip of its
// bulge on the ray through the cursor, its opening towards the top of the view; dragging
// turns the opening towards the cursor. The stroke (pullPoses) runs along that ray from
// behind every point of the pick surface (the tissue, required) to in front of it, each end
// kPullMarginFraction of the loop's width clear of it, at kPullSpeed. The loop's plane is
// perpendicular to the pull, so this sweep is valid too. The release records it.
//
// Time: t = seconds since the press, from the clock (setClock; by default a QElapsedTimer),
// so the first pose has t = 0 (a pull's time stamps come from kPullSpeed instead).
// The tool is shown at the current pose (ToolActor) and the sweep so far (SweepActor)
// during the drag. The release finishes: with >= 2 poses whose sweep the tool can make
// (strokeSweep succeeds; not checked without a tool curve) it emits strokeRecorded() and
// disarms (recordingChanged(false)); otherwise it emits recordingFailed() with the reason
// (a stroke too short to cut), clears the preview and stays armed.
// While armed, Shift/Ctrl/Alt + left, the middle and the right button stay camera
// navigation; disarmed, the tool leaves every event to the viewport.

#include "core/mesh/triangle_surface.h"
#include "scenario/scenario_document.h"
#include "widgets/camera_ray.h"
#include "widgets/sweep_actor.h"
#include "widgets/tool_actor.h"
#include "widgets/viewport_tool.h"

#include <QElapsedTimer>
#include <QObject>
#include <QPointF>
#include <QPointer>
#include <QString>

#include <functional>
#include <optional>
#include <span>
#include <string>
#include <vector>

namespace resect {

class VtkViewport;

/// The orientation (quaternion w, x, y, z, unit length) that puts the tool's loop plane
/// perpendicular to `dragDirection`, for a camera looking along `viewDirection` (world,
/// any lengths).
/// Tool frame: the principal axes of the tool curve's points (covariance eigenvectors):
/// a1 the largest spread, signed from the first towards the last point (the chord), a3 the
/// second, signed from the chord's midpoint towards the centroid (the bulge), and the loop
/// normal a2 = a3 x a1; a curve of fewer than two distinct points uses a1, a2, a3 = x, y, z.
/// World: d the drag direction made perpendicular to v, v the view direction, e = d x v.
/// The rotation maps a1 -> e, a2 -> d, a3 -> v: the chord lies across the drag in the view
/// plane, the loop's bulge points away from the viewer. Returns the identity (1, 0, 0, 0)
/// when d or v is zero, non-finite, or d is parallel to v.
Eigen::Vector4d strokeOrientation(const ToolSpec& tool, const Vec3& dragDirection,
                                  const Vec3& viewDirection);

/// The orientation (quaternion w, x, y, z) of a loop pulled along `pullDirection` (world,
/// any length) with its opening towards `opening` (any length; its part along the pull is
/// ignored): the loop's plane perpendicular to the pull (a2 -> the pull), its bulge away
/// from the opening (a3 -> -opening), its chord across (a1 = a2 x a3); tool axes as in
/// strokeOrientation. The identity when the directions are zero, non-finite or parallel.
Eigen::Vector4d pullOrientation(const ToolSpec& tool, const Vec3& pullDirection,
                                const Vec3& opening);

/// The width of the tool's loop in mm: size times the largest distance between two of its
/// curve points (0 without a curve).
double loopWidth(const ToolSpec& tool);

/// The point of the tool curve (tool frame, unscaled) deepest in its bulge: farthest from
/// the chord's midpoint along the bulge axis a3. The origin without a curve.
Vec3 loopTip(const ToolSpec& tool);

/// The two poses of a loop pulled towards the camera along `ray` (its direction points away
/// from the camera) through the points `tissue`: the loop's tip (loopTip) on the ray, its
/// opening towards `opening`, from `margin` (mm) behind the farthest point of `tissue` along
/// the ray to `margin` in front of the nearest, at `speed` mm/s (t = 0 at the start). Empty
/// if there is no tissue point, the directions are unusable, or speed or margin are not
/// positive.
std::vector<ToolPose> pullPoses(const ToolSpec& tool, const Ray& ray, const Vec3& opening,
                                std::span<const Vec3> tissue, double margin, double speed);

class StrokeRecorder : public QObject, public ViewportTool {
    Q_OBJECT

public:
    /// How the mouse moves the loop (see the file comment).
    enum class Motion { Drag, Pull };

    /// A sample must advance along the drag by this fraction of the loop's width (Drag).
    static constexpr double kMinAdvanceFraction = 0.02;
    /// A pulled stroke starts and ends this fraction of the loop's width clear of the tissue.
    static constexpr double kPullMarginFraction = 0.25;
    /// mm/s: the speed of a pulled stroke (its time stamps; a resectoscope loop is pulled
    /// through a polyp in about a second).
    static constexpr double kPullSpeed = 10.0;

    /// The recorder draws into `viewport` (its props are added now, removed when it is
    /// destroyed); it still has to be made the viewport's tool with setTool().
    explicit StrokeRecorder(VtkViewport* viewport, QObject* parent = nullptr);
    ~StrokeRecorder() override;

    /// The tool that is moved (its curve is shown and swept); copied.
    void setToolSpec(const ToolSpec& tool);
    const ToolSpec& toolSpec() const { return m_tool; }
    /// Name given to recorded strokes.
    void setStrokeName(const std::string& name) { m_strokeName = name; }
    const std::string& strokeName() const { return m_strokeName; }

    /// Surface whose hit under the press sets the stroke's depth (the tissue); copied.
    void setPickSurface(const TriangleSurface& surface);
    void clearPickSurface();

    /// Time source in seconds (any origin; only differences are used). Null restores the
    /// default, a QElapsedTimer.
    void setClock(std::function<double()> clock);
    void setMinSpacingPixels(double pixels);
    double minSpacingPixels() const { return m_minSpacing; }

    void setMotion(Motion motion);
    Motion motion() const { return m_motion; }

    /// Arms or disarms the recorder; disarming during a drag abandons it (no signal).
    void setRecording(bool armed);
    bool isRecording() const { return m_armed; }
    /// True between a press and its release while armed.
    bool isDragging() const { return m_dragging; }

    /// The poses of the stroke being recorded, or of the last one recorded.
    const std::vector<ToolPose>& poses() const { return m_poses; }
    /// Hides the tool and the preview sweep and forgets the poses (abandons a drag).
    void clear();

    ToolActor& toolActor() { return m_toolActor; }
    SweepActor& sweepActor() { return m_sweepActor; }

    static constexpr double kDefaultMinSpacingPixels = 4.0;

    // --- ViewportTool ---
    bool mousePress(VtkViewport& viewport, QMouseEvent* event) override;
    bool mouseMove(VtkViewport& viewport, QMouseEvent* event) override;
    bool mouseRelease(VtkViewport& viewport, QMouseEvent* event) override;
    void deactivated(VtkViewport& viewport) override;

signals:
    void recordingChanged(bool armed);
    /// A pose was added to the stroke being recorded (count = poses().size()).
    void poseSampled(int count);
    /// What the author should know while dragging (empty: nothing beyond the usual):
    /// e.g. that the cursor is behind the stroke and samples are not taken.
    void hintChanged(const QString& hint);
    void strokeRecorded(const resect::Stroke& stroke);
    void recordingFailed(const QString& reason);

private:
    double now() const;
    /// Samples the cursor at `pixel`; returns true if a pose was added.
    bool sample(VtkViewport& viewport, const QPointF& pixel);
    bool pressPull(VtkViewport& viewport, const QPointF& pixel);
    /// The pulled stroke with its opening towards the cursor at `pixel` (the press: up).
    void updatePull(VtkViewport& viewport, const QPointF& pixel);
    void setHint(const QString& hint);
    void updateDisplay();
    /// The reason the poses are not a usable stroke (empty when they are).
    QString strokeProblem(const Stroke& stroke) const;

    QPointer<VtkViewport> m_viewport;
    ToolSpec m_tool;
    std::string m_strokeName;
    std::optional<TriangleSurface> m_pickSurface;
    std::function<double()> m_clock;
    QElapsedTimer m_timer;
    double m_minSpacing = kDefaultMinSpacingPixels;
    Motion m_motion = Motion::Drag;

    bool m_armed = false;
    bool m_dragging = false;
    bool m_orientationFixed = false;
    double m_t0 = 0;
    Vec3 m_depth = Vec3::Zero();     ///< the depth reference of the drag
    Vec3 m_view = Vec3::UnitZ();     ///< view direction at the press
    Vec3 m_drag = Vec3::Zero();      ///< the drag direction d, once fixed (unit)
    QPointF m_lastPixel;             ///< cursor position of the last pose
    QPointF m_pressPixel;            ///< where a pull was pressed
    Ray m_pullRay;                   ///< the ray a pull runs along
    QString m_hint;
    std::vector<ToolPose> m_poses;

    ToolActor m_toolActor;
    SweepActor m_sweepActor;
};

} // namespace resect
