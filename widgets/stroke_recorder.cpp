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

#include <cmath>

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

} // namespace

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
    const Eigen::Matrix3d rotation = world * toolAxes(tool.curve).transpose();
    Eigen::Quaterniond q(rotation);
    q.normalize();
    const Eigen::Vector4d out(q.w(), q.x(), q.y(), q.z());
    return out.allFinite() ? out : identity;
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
    m_toolActor.hide();
    m_sweepActor.clear();
    if (m_viewport != nullptr)
        m_viewport->requestRender();
}

bool StrokeRecorder::mousePress(VtkViewport& viewport, QMouseEvent* event) {
    if (!m_armed || !isRecordButton(event))
        return false;
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
    if (!m_orientationFixed) {
        const Eigen::Vector4d q = strokeOrientation(m_tool, *p - m_poses.front().position, m_view);
        m_poses.front().orientation = q;
        m_orientationFixed = true;
    }
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

bool StrokeRecorder::mouseMove(VtkViewport& viewport, QMouseEvent* event) {
    if (!m_dragging)
        return false;
    sample(viewport, event->position());
    return true;
}

bool StrokeRecorder::mouseRelease(VtkViewport& viewport, QMouseEvent* event) {
    if (!m_dragging)
        return false;
    sample(viewport, event->position());
    m_dragging = false;
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
    if (stroke.poses.size() < 2)
        return tr("Nothing was recorded: hold the left button and drag the electrode across "
                  "the view.");
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
