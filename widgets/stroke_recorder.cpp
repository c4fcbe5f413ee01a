#include "widgets/stroke_recorder.h"

#include "core/sweep/sweep_surface.h"
#include "scenario/scenario_sweeps.h"
#include "widgets/camera_ray.h"
#include "widgets/surface_pick.h"
#include "widgets/vtk_viewport.h"

#include <QMouseEvent>

#include <Eigen/Eigenvalues>
#include <Eigen/Geometry>

#include <vtkCamera.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace resect {

namespace {

/// Tool-frame axes {a1 chord, a2 loop normal, a3 bulge} as the columns of a rotation.
Eigen::Matrix3d toolAxes(const std::vector<Vec3>& curve) {
    Eigen::Matrix3d axes = Eigen::Matrix3d::Identity();
    std::vector<Vec3> pts;
    for (const Vec3& p : curve)
        if (p.allFinite())
            pts.push_back(p);
    if (pts.size() < 2)
        return axes;
    Vec3 centroid = Vec3::Zero();
    for (const Vec3& p : pts)
        centroid += p;
    centroid /= double(pts.size());
    Eigen::Matrix3d covariance = Eigen::Matrix3d::Zero();
    for (const Vec3& p : pts)
        covariance += (p - centroid) * (p - centroid).transpose();
    if (!(covariance.trace() > 0))
        return axes; // every point the same
    const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> solver(covariance);
    if (solver.info() != Eigen::Success)
        return axes;
    // Eigenvalues ascending: column 2 has the largest spread, column 1 the second.
    Vec3 a1 = solver.eigenvectors().col(2).normalized();
    Vec3 a3 = solver.eigenvectors().col(1).normalized();
    if ((pts.back() - pts.front()).dot(a1) < 0)
        a1 = -a1;
    if ((centroid - 0.5 * (pts.front() + pts.back())).dot(a3) < 0)
        a3 = -a3;
    const Vec3 a2 = a3.cross(a1);
    axes.col(0) = a1;
    axes.col(1) = a2;
    axes.col(2) = a3;
    if (!axes.allFinite())
        return Eigen::Matrix3d::Identity();
    return axes;
}

bool isRecordButton(const QMouseEvent* event) {
    return event->button() == Qt::LeftButton &&
           (event->modifiers() & (Qt::ShiftModifier | Qt::ControlModifier | Qt::AltModifier)) ==
               Qt::NoModifier;
}

Vec3 viewUp(vtkCamera* camera) {
    double up[3];
    camera->GetViewUp(up);
    return {up[0], up[1], up[2]};
}

/// A rotation as a unit quaternion (w, x, y, z), or the identity if it is not finite.
Eigen::Vector4d toQuaternion(const Eigen::Matrix3d& rotation) {
    Eigen::Quaterniond q(rotation);
    q.normalize();
    const Eigen::Vector4d out(q.w(), q.x(), q.y(), q.z());
    return out.allFinite() ? out : Eigen::Vector4d(1, 0, 0, 0);
}

/// Index of loopTip's point in tool.curve, or -1 without a finite curve.
int tipIndex(const ToolSpec& tool) {
    const Eigen::Matrix3d axes = toolAxes(tool.curve);
    const Vec3 bulge = axes.col(2);
    int first = -1, last = -1;
    for (int i = 0; i < static_cast<int>(tool.curve.size()); ++i)
        if (tool.curve[i].allFinite()) {
            if (first < 0)
                first = i;
            last = i;
        }
    if (first < 0)
        return -1;
    const Vec3 mid = 0.5 * (tool.curve[first] + tool.curve[last]);
    int best = first;
    for (int i = first; i <= last; ++i)
        if (tool.curve[i].allFinite() &&
            (tool.curve[i] - mid).dot(bulge) > (tool.curve[best] - mid).dot(bulge))
            best = i;
    return best;
}

} // namespace

double loopWidth(const ToolSpec& tool) {
    double width = 0;
    for (std::size_t i = 0; i < tool.curve.size(); ++i)
        for (std::size_t j = i + 1; j < tool.curve.size(); ++j)
            if (tool.curve[i].allFinite() && tool.curve[j].allFinite())
                width = std::max(width, (tool.curve[i] - tool.curve[j]).norm());
    return std::isfinite(tool.size) ? tool.size * width : 0.0;
}

Vec3 loopTip(const ToolSpec& tool) {
    const int tip = tipIndex(tool);
    return tip < 0 ? Vec3::Zero() : tool.curve[tip];
}

Eigen::Vector4d pullOrientation(const ToolSpec& tool, const Vec3& pullDirection,
                                const Vec3& opening) {
    const Eigen::Vector4d identity(1, 0, 0, 0);
    if (!pullDirection.allFinite() || !opening.allFinite())
        return identity;
    const double pullLength = pullDirection.norm();
    if (!(pullLength > 0))
        return identity;
    const Vec3 n = pullDirection / pullLength;
    Vec3 o = opening - opening.dot(n) * n;
    const double openingLength = o.norm();
    // Parallel within rounding: no direction across the pull is left.
    if (!(openingLength > 1e-12 * opening.norm()))
        return identity;
    o /= openingLength;
    Eigen::Matrix3d world;
    world.col(1) = n;           // a2, the loop's normal: along the pull
    world.col(2) = -o;          // a3, the bulge: away from the opening
    world.col(0) = n.cross(-o); // a1 = a2 x a3, the chord
    return toQuaternion(world * toolAxes(tool.curve).transpose());
}

std::vector<ToolPose> pullPoses(const ToolSpec& tool, const Ray& ray, const Vec3& opening,
                                std::span<const Vec3> tissue, double margin, double speed) {
    const int tip = tipIndex(tool);
    if (tip < 0 || tissue.empty() || !(margin > 0) || !(speed > 0) || !std::isfinite(margin) ||
        !std::isfinite(speed) || !ray.origin.allFinite() || !ray.direction.allFinite() ||
        !(ray.direction.norm() > 0))
        return {};
    const Vec3 dir = ray.direction.normalized();
    const Vec3 towardsCamera = -dir;
    Vec3 o = opening - opening.dot(dir) * dir;
    if (!o.allFinite() || !(o.norm() > 1e-12 * opening.norm()))
        return {};
    // The depth range of the tissue along the ray.
    double nearest = std::numeric_limits<double>::infinity(), farthest = -nearest;
    for (const Vec3& p : tissue) {
        if (!p.allFinite())
            continue;
        const double s = (p - ray.origin).dot(dir);
        nearest = std::min(nearest, s);
        farthest = std::max(farthest, s);
    }
    if (!(farthest >= nearest))
        return {};
    const double start = farthest + margin, end = nearest - margin;
    ToolPose pose;
    pose.orientation = pullOrientation(tool, towardsCamera, o);
    pose.position = Vec3::Zero();
    // Where the tip is relative to the pose's position, exactly as the sweep places it.
    const Vec3 tipOffset = toolCurveAt(tool, pose)[static_cast<std::size_t>(tip)];
    std::vector<ToolPose> poses(2, pose);
    poses[0].t = 0;
    poses[0].position = ray.origin + start * dir - tipOffset;
    poses[1].t = (start - end) / speed;
    poses[1].position = ray.origin + end * dir - tipOffset;
    if (!poses[0].position.allFinite() || !poses[1].position.allFinite() || !(poses[1].t > 0))
        return {};
    return poses;
}

Eigen::Vector4d strokeOrientation(const ToolSpec& tool, const Vec3& dragDirection,
                                  const Vec3& viewDirection) {
    const Eigen::Vector4d identity(1, 0, 0, 0);
    if (!dragDirection.allFinite() || !viewDirection.allFinite())
        return identity;
    const double viewLength = viewDirection.norm();
    if (!(viewLength > 0))
        return identity;
    const Vec3 v = viewDirection / viewLength;
    Vec3 d = dragDirection - dragDirection.dot(v) * v;
    const double dragLength = d.norm();
    // Parallel within rounding: the drag's component across the view is lost in the noise.
    if (!(dragLength > 1e-12 * dragDirection.norm()))
        return identity;
    d /= dragLength;
    const Vec3 e = d.cross(v);
    Eigen::Matrix3d world;
    world.col(0) = e;
    world.col(1) = d;
    world.col(2) = v;
    return toQuaternion(world * toolAxes(tool.curve).transpose());
}

StrokeRecorder::StrokeRecorder(VtkViewport* viewport, QObject* parent)
    : QObject(parent), m_viewport(viewport) {
    m_timer.start();
    if (m_viewport != nullptr) {
        for (vtkProp* prop : m_sweepActor.props())
            m_viewport->addProp(prop);
        for (vtkProp* prop : m_toolActor.props())
            m_viewport->addProp(prop);
    }
}

StrokeRecorder::~StrokeRecorder() {
    if (m_viewport == nullptr)
        return;
    if (m_viewport->tool() == this)
        m_viewport->setTool(nullptr);
    for (vtkProp* prop : m_sweepActor.props())
        m_viewport->removeProp(prop);
    for (vtkProp* prop : m_toolActor.props())
        m_viewport->removeProp(prop);
}

void StrokeRecorder::setToolSpec(const ToolSpec& tool) {
    m_tool = tool;
    updateDisplay();
}

void StrokeRecorder::setPickSurface(const TriangleSurface& surface) {
    m_pickSurface = surface;
}

void StrokeRecorder::clearPickSurface() {
    m_pickSurface.reset();
}

void StrokeRecorder::setClock(std::function<double()> clock) {
    m_clock = std::move(clock);
}

void StrokeRecorder::setMotion(Motion motion) {
    if (motion == m_motion)
        return;
    if (m_dragging)
        clear();
    m_motion = motion;
}

void StrokeRecorder::setMinSpacingPixels(double pixels) {
    m_minSpacing = std::isfinite(pixels) && pixels > 0 ? pixels : 0.0;
}

double StrokeRecorder::now() const {
    return m_clock ? m_clock() : double(m_timer.nsecsElapsed()) * 1e-9;
}

void StrokeRecorder::setRecording(bool armed) {
    if (armed == m_armed)
        return;
    m_armed = armed;
    if (!armed && m_dragging)
        clear();
    emit recordingChanged(armed);
}

void StrokeRecorder::clear() {
    m_dragging = false;
    m_poses.clear();
    setHint(QString());
    m_toolActor.hide();
    m_sweepActor.clear();
    if (m_viewport != nullptr)
        m_viewport->requestRender();
}

bool StrokeRecorder::mousePress(VtkViewport& viewport, QMouseEvent* event) {
    if (!m_armed || !isRecordButton(event))
        return false;
    if (m_motion == Motion::Pull)
        return pressPull(viewport, event->position());
    vtkCamera* camera = viewport.camera();
    const QSize size = viewport.size();
    const QPointF pixel = event->position();
    m_depth = focalPoint(camera);
    if (m_pickSurface) {
        if (const auto hit = raySurfaceHit(pixelRay(camera, size, pixel), *m_pickSurface))
            m_depth = *hit;
    }
    m_view = viewDirection(camera);
    const auto start = pixelOnViewPlane(camera, size, pixel, m_depth);
    if (!start || !start->allFinite())
        return true; // consumed (no camera motion), but nothing to record from here
    clear();
    m_dragging = true;
    m_orientationFixed = false;
    m_drag = Vec3::Zero();
    m_t0 = now();
    m_lastPixel = pixel;
    ToolPose first;
    first.t = 0;
    first.position = *start;
    // Until the first movement the tool is shown as if dragged towards the top of the view.
    first.orientation = strokeOrientation(m_tool, viewUp(camera), m_view);
    m_poses.push_back(first);
    updateDisplay();
    return true;
}

bool StrokeRecorder::sample(VtkViewport& viewport, const QPointF& pixel) {
    const QPointF moved = pixel - m_lastPixel;
    if (std::hypot(moved.x(), moved.y()) < m_minSpacing)
        return false;
    const auto p = pixelOnViewPlane(viewport.camera(), viewport.size(), pixel, m_depth);
    if (!p || !p->allFinite() || *p == m_poses.back().position)
        return false;
    const double t = now() - m_t0;
    if (!std::isfinite(t) || !(t > m_poses.back().t))
        return false;
    // Forward only: every pose past the last along d (the first movement defines d).
    const double minAdvance = kMinAdvanceFraction * loopWidth(m_tool);
    if (!m_orientationFixed) {
        const Vec3 move = *p - m_poses.front().position;
        const Vec3 across = move - move.dot(m_view) * m_view;
        if (!(across.norm() > 0) || across.norm() < minAdvance)
            return false;
        m_drag = across.normalized();
        m_poses.front().orientation = strokeOrientation(m_tool, move, m_view);
        m_orientationFixed = true;
    } else {
        const double advance = (*p - m_poses.back().position).dot(m_drag);
        if (!(advance > 0) || advance < minAdvance) {
            setHint(tr("Move forward along the pull to continue the stroke: no pose is taken "
                       "behind its end (the stroke would cut through itself)."));
            return false;
        }
    }
    setHint(QString());
    ToolPose pose;
    pose.t = t;
    pose.position = *p;
    pose.orientation = m_poses.front().orientation;
    m_poses.push_back(pose);
    m_lastPixel = pixel;
    updateDisplay();
    emit poseSampled(static_cast<int>(m_poses.size()));
    return true;
}

bool StrokeRecorder::pressPull(VtkViewport& viewport, const QPointF& pixel) {
    clear();
    if (!m_pickSurface || m_pickSurface->positions.empty()) {
        emit recordingFailed(tr("There is no tissue to pull the loop through."));
        return true; // consumed: no camera motion while armed
    }
    m_pullRay = pixelRay(viewport.camera(), viewport.size(), pixel);
    m_view = viewDirection(viewport.camera());
    m_pressPixel = pixel;
    m_dragging = true;
    m_t0 = now();
    updatePull(viewport, pixel);
    return true;
}

void StrokeRecorder::updatePull(VtkViewport& viewport, const QPointF& pixel) {
    if (!m_pickSurface) { // the tissue went away during the drag
        m_poses.clear();
        updateDisplay();
        return;
    }
    vtkCamera* camera = viewport.camera();
    Vec3 opening = viewUp(camera);
    const QPointF moved = pixel - m_pressPixel;
    if (std::hypot(moved.x(), moved.y()) >= std::max(m_minSpacing, 1.0)) {
        // The on-screen direction from the press to the cursor, in the world.
        const Vec3 reference = focalPoint(camera);
        const auto a = pixelOnViewPlane(camera, viewport.size(), m_pressPixel, reference);
        const auto b = pixelOnViewPlane(camera, viewport.size(), pixel, reference);
        if (a && b && (*b - *a).allFinite())
            opening = *b - *a;
    }
    m_poses = pullPoses(m_tool, m_pullRay, opening, m_pickSurface->positions,
                        kPullMarginFraction * loopWidth(m_tool), kPullSpeed);
    updateDisplay();
}

void StrokeRecorder::setHint(const QString& hint) {
    if (hint == m_hint)
        return;
    m_hint = hint;
    emit hintChanged(m_hint);
}

bool StrokeRecorder::mouseMove(VtkViewport& viewport, QMouseEvent* event) {
    if (!m_dragging)
        return false;
    if (m_motion == Motion::Pull)
        updatePull(viewport, event->position());
    else
        sample(viewport, event->position());
    return true;
}

bool StrokeRecorder::mouseRelease(VtkViewport& viewport, QMouseEvent* event) {
    if (!m_dragging)
        return false;
    if (m_motion == Motion::Pull)
        updatePull(viewport, event->position());
    else
        sample(viewport, event->position());
    m_dragging = false;
    setHint(QString());
    Stroke stroke;
    stroke.name = m_strokeName;
    stroke.poses = m_poses;
    const QString problem = strokeProblem(stroke);
    if (!problem.isEmpty()) {
        clear();
        emit recordingFailed(problem);
        return true;
    }
    emit strokeRecorded(stroke);
    setRecording(false);
    return true;
}

void StrokeRecorder::deactivated(VtkViewport& /*viewport*/) {
    if (m_dragging)
        clear();
}

QString StrokeRecorder::strokeProblem(const Stroke& stroke) const {
    if (stroke.poses.size() < 2 && m_motion == Motion::Pull)
        return tr("The loop cannot be pulled here: it needs a tool with a loop curve and a "
                  "tissue behind the cursor.");
    if (stroke.poses.size() < 2)
        return tr("The stroke is too short to cut: hold the left button and drag the "
                  "electrode forward across the view.");
    if (m_tool.curve.size() < 2)
        return {};
    Scenario scenario;
    scenario.tool = m_tool;
    scenario.strokes.push_back(stroke);
    SweepSurface sweep;
    const Status status = strokeSweep(scenario, 0, sweep);
    if (!status.ok())
        return tr("The recorded stroke does not make a usable cut: %1")
            .arg(QString::fromStdString(status.message()));
    return {};
}

void StrokeRecorder::updateDisplay() {
    if (m_poses.empty()) {
        m_toolActor.hide();
        m_sweepActor.clear();
    } else {
        m_toolActor.setPose(m_tool, m_poses.back());
        std::vector<std::vector<Vec3>> curves;
        if (m_tool.curve.size() >= 2 && m_poses.size() >= 2)
            for (const ToolPose& pose : m_poses)
                curves.push_back(toolCurveAt(m_tool, pose));
        m_sweepActor.setCurves(curves);
    }
    if (m_viewport != nullptr)
        m_viewport->requestRender();
}

} // namespace resect
