#include "widgets/tool_actor.h"

#include "scenario/scenario_sweeps.h"

#include <Eigen/Geometry>

#include <vtkActor.h>
#include <vtkCellArray.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkPolyDataMapper.h>
#include <vtkProperty.h>
#include <vtkTubeFilter.h>

#include <cmath>

namespace resect {

ToolActor::ToolActor()
    : m_polyline(vtkSmartPointer<vtkPolyData>::New()),
      m_tube(vtkSmartPointer<vtkTubeFilter>::New()),
      m_mapper(vtkSmartPointer<vtkPolyDataMapper>::New()),
      m_actor(vtkSmartPointer<vtkActor>::New()) {
    m_tube->SetInputData(m_polyline);
    m_tube->SetNumberOfSides(12);
    m_tube->CappingOn();
    m_mapper->SetInputConnection(m_tube->GetOutputPort());
    m_mapper->ScalarVisibilityOff();
    m_actor->SetMapper(m_mapper);
    vtkProperty* property = m_actor->GetProperty();
    property->SetColor(kColor[0], kColor[1], kColor[2]);
    property->SetAmbient(0.2);
    property->SetDiffuse(0.6);
    property->SetSpecular(0.8);
    property->SetSpecularPower(60.0);
    m_actor->SetVisibility(false);
}

void ToolActor::setPose(const ToolSpec& tool, const ToolPose& pose) {
    if (tool.curve.size() < 2) {
        hide();
        return;
    }
    setCurve(toolCurveAt(tool, pose));
}

void ToolActor::setCurve(const std::vector<Vec3>& worldCurve) {
    std::vector<Vec3> curve;
    curve.reserve(worldCurve.size());
    for (const Vec3& p : worldCurve)
        if (p.allFinite() && (curve.empty() || p != curve.back()))
            curve.push_back(p);
    if (curve.size() < 2) {
        hide();
        return;
    }
    m_curve = std::move(curve);
    auto points = vtkSmartPointer<vtkPoints>::New();
    points->SetDataTypeToDouble();
    auto line = vtkSmartPointer<vtkCellArray>::New();
    line->InsertNextCell(static_cast<vtkIdType>(m_curve.size()));
    for (const Vec3& p : m_curve)
        line->InsertCellPoint(points->InsertNextPoint(p.x(), p.y(), p.z()));
    m_polyline->Initialize();
    m_polyline->SetPoints(points);
    m_polyline->SetLines(line);
    m_polyline->Modified();
    m_tube->SetRadius(effectiveRadius());
    m_actor->SetVisibility(true);
}

void ToolActor::hide() {
    m_curve.clear();
    m_polyline->Initialize();
    m_polyline->Modified();
    m_actor->SetVisibility(false);
}

bool ToolActor::isVisible() const {
    return !m_curve.empty();
}

void ToolActor::setRadius(double mm) {
    m_radius = (std::isfinite(mm) && mm > 0) ? mm : 0.0;
    if (isVisible())
        m_tube->SetRadius(effectiveRadius());
}

double ToolActor::radius() const {
    return isVisible() ? effectiveRadius() : 0.0;
}

double ToolActor::effectiveRadius() const {
    if (m_radius > 0)
        return m_radius;
    Eigen::AlignedBox3d box;
    for (const Vec3& p : m_curve)
        box.extend(p);
    const double diagonal = m_curve.empty() ? 0.0 : box.diagonal().norm();
    return kAutoRadiusFraction * diagonal;
}

vtkActor* ToolActor::actor() const {
    return m_actor;
}

std::vector<vtkProp*> ToolActor::props() const {
    return {m_actor};
}

vtkPolyData* ToolActor::polyline() const {
    return m_polyline;
}

} // namespace resect
