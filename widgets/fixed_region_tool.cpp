#include "widgets/fixed_region_tool.h"

#include "widgets/camera_ray.h"
#include "widgets/scenario_document.h"
#include "widgets/vtk_viewport.h"

#include <QMouseEvent>

#include <vtkActor.h>
#include <vtkCellArray.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkPolyDataMapper.h>
#include <vtkProperty.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace resect {

namespace {

constexpr HandleActor::Color kAxisColors[3] = {{0.9, 0.2, 0.2}, {0.2, 0.8, 0.2}, {0.25, 0.45, 1.0}};
constexpr HandleActor::Color kDraggedColor = {1, 1, 1};
constexpr double kOutlineColor[3] = {1.0, 0.6, 0.1};
constexpr double kOutlineWidth = 2.0;

bool isToolButton(const QMouseEvent* event) {
    return event->button() == Qt::LeftButton &&
           (event->modifiers() & (Qt::ShiftModifier | Qt::ControlModifier | Qt::AltModifier)) ==
               Qt::NoModifier;
}

/// The corner of `r` with bit k of `corner` choosing max (1) or min (0) along axis k.
Vec3 cornerOf(const FixedRegion& r, int corner) {
    return {(corner & 1) ? r.max.x() : r.min.x(), (corner & 2) ? r.max.y() : r.min.y(),
            (corner & 4) ? r.max.z() : r.min.z()};
}

} // namespace

FixedRegionTool::FixedRegionTool(ScenarioDocument& document, VtkViewport* viewport, QObject* parent)
    : QObject(parent), m_document(document), m_viewport(viewport),
      m_outline(vtkSmartPointer<vtkPolyData>::New()),
      m_outlineActor(vtkSmartPointer<vtkActor>::New()) {
    auto mapper = vtkSmartPointer<vtkPolyDataMapper>::New();
    mapper->SetInputData(m_outline);
    // Drawn in front of the tissue, like the handles: a box around the base is mostly inside.
    mapper->SetRelativeCoincidentTopologyLineOffsetParameters(0, HandleActor::kDepthOffsetUnits);
    m_outlineActor->SetMapper(mapper);
    m_outlineActor->GetProperty()->SetColor(kOutlineColor[0], kOutlineColor[1], kOutlineColor[2]);
    m_outlineActor->GetProperty()->SetLineWidth(kOutlineWidth);
    m_outlineActor->GetProperty()->LightingOff();
    m_outlineActor->SetVisibility(false);
    connect(&m_document, &ScenarioDocument::fixedRegionsChanged, this,
            &FixedRegionTool::syncFromDocument);
    connect(&m_document, &ScenarioDocument::documentReset, this,
            &FixedRegionTool::syncFromDocument);
    syncFromDocument();
}

FixedRegionTool::~FixedRegionTool() {
    if (m_viewport) {
        if (m_viewport->tool() == this)
            m_viewport->setTool(nullptr);
        m_viewport->removeProp(m_outlineActor);
        m_viewport->removeProp(m_handles.actor());
    }
}

void FixedRegionTool::setActive(bool active) {
    if (active == m_active || !m_viewport)
        return;
    m_active = active;
    if (active) {
        m_viewport->addProp(m_outlineActor);
        m_viewport->addProp(m_handles.actor());
        m_viewport->setTool(this);
    } else {
        if (m_dragged)
            finishDrag();
        if (m_viewport->tool() == this)
            m_viewport->setTool(nullptr);
        m_viewport->removeProp(m_outlineActor);
        m_viewport->removeProp(m_handles.actor());
    }
    updateDisplay();
    emit activeChanged(m_active);
}

void FixedRegionTool::deactivated(VtkViewport& /*viewport*/) {
    // Another tool took the viewport: hide the boxes (setActive(false) would hand the
    // viewport back to the camera, taking it from that tool).
    if (!m_active)
        return;
    if (m_dragged)
        finishDrag();
    m_active = false;
    m_viewport->removeProp(m_outlineActor);
    m_viewport->removeProp(m_handles.actor());
    updateDisplay();
    emit activeChanged(false);
}

Vec3 FixedRegionTool::faceCentre(const Face& face) const {
    const FixedRegion& r = m_regions.at(static_cast<std::size_t>(face.region));
    Vec3 c = 0.5 * (r.min + r.max);
    c[face.axis] = face.max ? r.max[face.axis] : r.min[face.axis];
    return c;
}

std::optional<FixedRegionTool::Face> FixedRegionTool::faceAt(const QPointF& pixel) const {
    if (!m_viewport || !m_active)
        return std::nullopt;
    std::optional<Face> best;
    double bestDistance = kHandlePickPixels;
    for (int i = 0; i < static_cast<int>(m_regions.size()); ++i)
        for (int axis = 0; axis < 3; ++axis)
            for (bool max : {false, true}) {
                const Face face{i, axis, max};
                const auto at =
                    worldToPixel(m_viewport->camera(), m_viewport->size(), faceCentre(face));
                if (!at)
                    continue;
                const double distance = std::hypot(at->x() - pixel.x(), at->y() - pixel.y());
                if (distance <= bestDistance) {
                    bestDistance = distance;
                    best = face;
                }
            }
    return best;
}

std::optional<double> FixedRegionTool::dragCoordinate(const QPointF& pixel) const {
    // The point of the face's axis line nearest to the ray under the cursor.
    const Vec3 p = faceCentre(*m_dragged);
    Vec3 e = Vec3::Zero();
    e[m_dragged->axis] = 1;
    const Ray ray = pixelRay(m_viewport->camera(), m_viewport->size(), pixel);
    const Vec3 w = p - ray.origin;
    const double b = e.dot(ray.direction);
    const double denominator = 1 - b * b; // |e| = |d| = 1
    if (denominator < 1e-9)
        return std::nullopt; // looking along the axis: the cursor says nothing about it
    const double t = (b * ray.direction.dot(w) - e.dot(w)) / denominator;
    const double coordinate = p[m_dragged->axis] + t;
    if (!std::isfinite(coordinate))
        return std::nullopt;
    return coordinate;
}

bool FixedRegionTool::mousePress(VtkViewport& /*viewport*/, QMouseEvent* event) {
    if (!isToolButton(event))
        return false;
    const auto face = faceAt(event->position());
    if (!face)
        return false; // not on a handle: the camera turns
    m_dragged = face;
    m_dragChanged = false;
    const auto cursor = dragCoordinate(event->position());
    const FixedRegion& r = m_regions[static_cast<std::size_t>(face->region)];
    m_grabOffset = cursor ? (face->max ? r.max : r.min)[face->axis] - *cursor : 0.0;
    updateDisplay();
    return true;
}

bool FixedRegionTool::mouseMove(VtkViewport& /*viewport*/, QMouseEvent* event) {
    if (!m_dragged)
        return false;
    const auto cursor = dragCoordinate(event->position());
    if (!cursor)
        return true;
    FixedRegion& r = m_regions[static_cast<std::size_t>(m_dragged->region)];
    const int k = m_dragged->axis;
    // A face never passes the opposite one (min <= max, as the file requires).
    const double value = m_dragged->max ? std::max(*cursor + m_grabOffset, r.min[k])
                                        : std::min(*cursor + m_grabOffset, r.max[k]);
    double& face = m_dragged->max ? r.max[k] : r.min[k];
    if (value == face)
        return true;
    face = value;
    m_dragChanged = true;
    updateDisplay();
    return true;
}

bool FixedRegionTool::mouseRelease(VtkViewport& viewport, QMouseEvent* event) {
    if (!m_dragged)
        return false;
    mouseMove(viewport, event); // the release position counts
    finishDrag();
    return true;
}

void FixedRegionTool::finishDrag() {
    const Face face = *m_dragged;
    m_dragged.reset();
    if (m_dragChanged) {
        m_dragChanged = false;
        // One undo step; the document's signal redraws (and a refused edit comes back).
        m_document.setFixedRegion(face.region, m_regions[static_cast<std::size_t>(face.region)]);
    }
    syncFromDocument();
}

void FixedRegionTool::syncFromDocument() {
    if (m_dragged)
        return; // the drag's box is on show until the release
    m_regions = m_document.fixedRegions();
    updateDisplay();
}

void FixedRegionTool::updateDisplay() {
    // Outlines: the twelve edges of every box (corners joined where they differ in one bit).
    auto points = vtkSmartPointer<vtkPoints>::New();
    points->SetDataTypeToDouble();
    auto lines = vtkSmartPointer<vtkCellArray>::New();
    std::vector<Vec3> handles;
    std::vector<HandleActor::Color> colors;
    for (int i = 0; i < static_cast<int>(m_regions.size()); ++i) {
        const FixedRegion& r = m_regions[static_cast<std::size_t>(i)];
        const vtkIdType first = points->GetNumberOfPoints();
        for (int corner = 0; corner < 8; ++corner) {
            const Vec3 c = cornerOf(r, corner);
            points->InsertNextPoint(c.x(), c.y(), c.z());
        }
        for (int corner = 0; corner < 8; ++corner)
            for (int bit : {1, 2, 4})
                if (!(corner & bit)) {
                    const vtkIdType edge[2] = {first + corner, first + (corner | bit)};
                    lines->InsertNextCell(2, edge);
                }
        for (int axis = 0; axis < 3; ++axis)
            for (bool max : {false, true}) {
                const Face face{i, axis, max};
                handles.push_back(faceCentre(face));
                colors.push_back(m_dragged && *m_dragged == face ? kDraggedColor
                                                                 : kAxisColors[axis]);
            }
    }
    m_outline->Initialize();
    m_outline->SetPoints(points);
    m_outline->SetLines(lines);
    m_outline->Modified();
    m_outlineActor->SetVisibility(m_active && !m_regions.empty());
    if (m_active)
        m_handles.setHandles(handles, colors);
    else
        m_handles.clear();
    if (m_viewport)
        m_viewport->requestRender();
}

} // namespace resect
