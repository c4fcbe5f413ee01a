#include "widgets/sweep_edit_tool.h"

#include "core/sweep/sweep_surface.h"
#include "widgets/camera_ray.h"
#include "widgets/surface_pick.h"
#include "widgets/vtk_viewport.h"

#include <QMouseEvent>

#include <vtkActor.h>

#include <Eigen/Geometry>

#include <cmath>

#include <limits>

namespace resect {

namespace {

/// Plain left button: the tool's; with Shift, Ctrl or Alt it is camera navigation.
bool isToolButton(const QMouseEvent* event) {
    return event->button() == Qt::LeftButton &&
           (event->modifiers() & (Qt::ShiftModifier | Qt::ControlModifier | Qt::AltModifier)) ==
               Qt::NoModifier;
}

std::vector<Vec3> finitePoints(const std::vector<Vec3>& points) {
    std::vector<Vec3> out;
    out.reserve(points.size());
    for (const Vec3& p : points)
        if (p.allFinite())
            out.push_back(p);
    return out;
}

} // namespace

SweepEditTool::SweepEditTool(VtkViewport* viewport, QObject* parent)
    : QObject(parent), m_viewport(viewport) {
    if (m_viewport != nullptr) {
        for (vtkProp* prop : m_sweepActor.props())
            m_viewport->addProp(prop);
        m_viewport->addProp(m_handleActor.actor());
    }
}

SweepEditTool::~SweepEditTool() {
    if (m_viewport == nullptr)
        return;
    if (m_viewport->tool() == this)
        m_viewport->setTool(nullptr);
    for (vtkProp* prop : m_sweepActor.props())
        m_viewport->removeProp(prop);
    m_viewport->removeProp(m_handleActor.actor());
}

const std::vector<Vec3>& SweepEditTool::curve(Curve c) const {
    return m_curves[static_cast<int>(c)];
}

std::vector<std::vector<Vec3>> SweepEditTool::curves() const {
    return {m_curves[0], m_curves[1]};
}

void SweepEditTool::setCurves(const std::vector<Vec3>& start, const std::vector<Vec3>& end) {
    m_dragging = false;
    m_curves[0] = finitePoints(start);
    m_curves[1] = finitePoints(end);
    m_selected.reset();
    updateDisplay();
    emit sweepChanged();
}

void SweepEditTool::clear() {
    m_dragging = false;
    m_curves[0].clear();
    m_curves[1].clear();
    m_selected.reset();
    setActiveCurve(Curve::Start);
    updateDisplay();
    emit sweepChanged();
}

void SweepEditTool::setActiveCurve(Curve c) {
    if (c == m_active)
        return;
    m_active = c;
    emit activeCurveChanged(c);
}

void SweepEditTool::beginEndCurve() {
    setActiveCurve(Curve::End);
}

QString SweepEditTool::nextClickHint() const {
    const int starts = static_cast<int>(curve(Curve::Start).size());
    const int ends = static_cast<int>(curve(Curve::End).size());
    const QString turn = tr("Alt+drag turns the view, Shift+drag pans, the wheel zooms.");
    if (m_active == Curve::Start) {
        if (starts == 0)
            return tr("Click on the tissue to place the first point of the start curve. %1").arg(turn);
        if (starts == 1)
            return tr("Start curve: click to place point 2; drag a point to move it. %1").arg(turn);
        return tr("Start curve: %1 points. Click to add point %2, or press End curve to draw where "
                  "the tool ends. %3")
            .arg(starts)
            .arg(starts + 1)
            .arg(turn);
    }
    if (ends < starts)
        return tr("End curve: click where point %1 of %2 ends its path. %3").arg(ends + 1).arg(starts).arg(turn);
    return {};
}

void SweepEditTool::copyStartToEnd(const Vec3& offset) {
    if (!offset.allFinite())
        return;
    std::vector<Vec3> end = curve(Curve::Start);
    for (Vec3& p : end)
        p += offset;
    m_dragging = false;
    points(Curve::End) = std::move(end);
    m_selected.reset();
    updateDisplay();
    emit sweepChanged();
}

Vec3 SweepEditTool::defaultEndOffset() const {
    if (m_viewport == nullptr)
        return Vec3::Zero();
    vtkCamera* camera = m_viewport->camera();
    Vec3 depth = focalPoint(camera);
    const auto& start = curve(Curve::Start);
    if (!start.empty()) {
        Vec3 sum = Vec3::Zero();
        for (const Vec3& p : start)
            sum += p;
        depth = sum / double(start.size());
    }
    const QSize size = m_viewport->size();
    const QPointF centre(0.5 * size.width(), 0.5 * size.height());
    const auto a = pixelOnViewPlane(camera, size, centre, depth);
    const auto b = pixelOnViewPlane(camera, size, centre + QPointF(0, 0.2 * size.height()), depth);
    if (!a || !b)
        return Vec3::Zero();
    const Vec3 offset = *b - *a;
    return offset.allFinite() ? offset : Vec3(Vec3::Zero());
}

bool SweepEditTool::validHandle(const Handle& h) const {
    return h.index >= 0 && h.index < static_cast<int>(curve(h.curve).size());
}

void SweepEditTool::movePoint(const Handle& handle, const Vec3& position) {
    if (!validHandle(handle) || !position.allFinite())
        return;
    points(handle.curve)[handle.index] = position;
    updateDisplay();
    emit sweepChanged();
}

bool SweepEditTool::removePoint(const Handle& handle) {
    if (!validHandle(handle))
        return false;
    m_dragging = false;
    auto& pts = points(handle.curve);
    pts.erase(pts.begin() + handle.index);
    m_selected.reset();
    updateDisplay();
    emit sweepChanged();
    return true;
}

bool SweepEditTool::removeLastPoint() {
    const int n = static_cast<int>(curve(m_active).size());
    return n > 0 && removePoint({m_active, n - 1});
}

bool SweepEditTool::removeSelectedPoint() {
    return m_selected && removePoint(*m_selected);
}

void SweepEditTool::setPickSurface(const TriangleSurface& surface) {
    m_pickSurface = surface;
}

void SweepEditTool::clearPickSurface() {
    m_pickSurface.reset();
}

QString SweepEditTool::problem() const {
    const auto& start = curve(Curve::Start);
    const auto& end = curve(Curve::End);
    if (start.size() < 2)
        return tr("The start curve needs at least two points; it has %1.").arg(start.size());
    if (end.size() < 2)
        return tr("The end curve needs at least two points; it has %1.").arg(end.size());
    if (start.size() != end.size())
        return tr("The start curve has %1 points and the end curve %2; both need the same "
                  "number of points.")
            .arg(start.size())
            .arg(end.size());
    Eigen::AlignedBox3d box;
    for (const auto* c : {&start, &end})
        for (const Vec3& p : *c)
            box.extend(p);
    const double tolerance = kCoincidentTolerance * box.diagonal().norm();
    for (std::size_t j = 0; j + 1 < start.size(); ++j) {
        if ((start[j + 1] - start[j]).norm() <= tolerance)
            return tr("Points %1 and %2 of the start curve coincide.").arg(j + 1).arg(j + 2);
        if ((end[j + 1] - end[j]).norm() <= tolerance)
            return tr("Points %1 and %2 of the end curve coincide.").arg(j + 1).arg(j + 2);
    }
    SweepSurface sweep;
    const Status status = SweepSurface::fromStartEnd(start, end, sweep);
    if (!status.ok())
        return tr("These curves do not make a usable sweep surface: %1")
            .arg(QString::fromStdString(status.message()));
    return {};
}

std::optional<SweepSpec> SweepEditTool::sweepSpec() const {
    if (!isValid())
        return std::nullopt;
    SweepSpec spec;
    spec.name = m_name;
    spec.curves = curves();
    return spec;
}

std::optional<SweepEditTool::Handle> SweepEditTool::handleAt(const QPointF& pixel) const {
    if (m_viewport == nullptr)
        return std::nullopt;
    vtkCamera* camera = m_viewport->camera();
    const QSize size = m_viewport->size();
    std::optional<Handle> best;
    double bestDistance = std::numeric_limits<double>::infinity();
    // The active curve first, so it wins a tie.
    const Curve order[2] = {m_active, m_active == Curve::Start ? Curve::End : Curve::Start};
    for (Curve c : order) {
        const auto& pts = curve(c);
        for (int i = 0; i < static_cast<int>(pts.size()); ++i) {
            const auto at = worldToPixel(camera, size, pts[i]);
            if (!at)
                continue;
            const QPointF d = *at - pixel;
            const double distance = std::hypot(d.x(), d.y());
            if (distance <= kHandlePickPixels && distance < bestDistance) {
                bestDistance = distance;
                best = Handle{c, i};
            }
        }
    }
    return best;
}

std::optional<Vec3> SweepEditTool::placePoint(VtkViewport& viewport, const QPointF& pixel) const {
    vtkCamera* camera = viewport.camera();
    const QSize size = viewport.size();
    if (m_pickSurface) {
        if (const auto hit = raySurfaceHit(pixelRay(camera, size, pixel), *m_pickSurface))
            return hit;
    }
    const auto& active = curve(m_active);
    const auto& other = curve(m_active == Curve::Start ? Curve::End : Curve::Start);
    const Vec3 depth = !active.empty() ? active.back()
                       : !other.empty() ? other.front()
                                        : focalPoint(camera);
    const auto p = pixelOnViewPlane(camera, size, pixel, depth);
    if (!p || !p->allFinite())
        return std::nullopt;
    return p;
}

bool SweepEditTool::mousePress(VtkViewport& viewport, QMouseEvent* event) {
    if (!isToolButton(event))
        return false;
    vtkCamera* camera = viewport.camera();
    const QSize size = viewport.size();
    const QPointF pixel = event->position();
    if (const auto handle = handleAt(pixel)) {
        m_selected = handle;
        m_dragAnchor = curve(handle->curve)[handle->index];
        const auto cursor = pixelOnViewPlane(camera, size, pixel, m_dragAnchor);
        m_dragOffset = Vec3::Zero();
        if (cursor && cursor->allFinite())
            m_dragOffset = m_dragAnchor - *cursor;
        m_dragging = true;
        m_dragChanged = false;
    } else {
        const auto p = placePoint(viewport, pixel);
        if (!p)
            return true; // consumed: a press meant for the tool must not orbit the camera
        points(m_active).push_back(*p);
        m_selected = Handle{m_active, static_cast<int>(curve(m_active).size()) - 1};
        m_dragAnchor = *p;
        m_dragOffset = Vec3::Zero();
        m_dragging = true;
        m_dragChanged = true;
    }
    updateDisplay();
    return true;
}

bool SweepEditTool::mouseMove(VtkViewport& viewport, QMouseEvent* event) {
    if (!m_dragging)
        return false; // hover: nothing to do
    if (!m_selected || !validHandle(*m_selected))
        return true;
    const auto cursor =
        pixelOnViewPlane(viewport.camera(), viewport.size(), event->position(), m_dragAnchor);
    if (!cursor)
        return true;
    const Vec3 p = *cursor + m_dragOffset;
    if (!p.allFinite())
        return true;
    Vec3& point = points(m_selected->curve)[m_selected->index];
    if (p == point)
        return true;
    point = p;
    m_dragChanged = true;
    updateDisplay();
    return true;
}

bool SweepEditTool::mouseRelease(VtkViewport& viewport, QMouseEvent* event) {
    if (!m_dragging)
        return false;
    mouseMove(viewport, event); // the release position counts
    finishDrag();
    return true;
}

void SweepEditTool::deactivated(VtkViewport& /*viewport*/) {
    if (m_dragging)
        finishDrag();
}

void SweepEditTool::finishDrag() {
    m_dragging = false;
    if (m_dragChanged) {
        m_dragChanged = false;
        emit sweepChanged();
    }
}

void SweepEditTool::updateDisplay() {
    m_sweepActor.setCurves(curves());
    std::vector<Vec3> handles;
    std::vector<HandleActor::Color> colors;
    for (Curve c : {Curve::Start, Curve::End}) {
        const auto& pts = curve(c);
        for (int i = 0; i < static_cast<int>(pts.size()); ++i) {
            handles.push_back(pts[i]);
            const bool selected = m_selected && *m_selected == Handle{c, i};
            colors.push_back(selected              ? kSelectedHandleColor
                             : c == Curve::Start ? kStartHandleColor
                                                 : kEndHandleColor);
        }
    }
    m_handleActor.setHandles(handles, colors);
    if (m_viewport != nullptr)
        m_viewport->requestRender();
    emit previewChanged();
}

} // namespace resect
