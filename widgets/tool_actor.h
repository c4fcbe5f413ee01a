#pragma once
// ToolActor: rendering adapter for the loop electrode: the tool's polyline (ToolSpec::curve)
// at a pose (scenario_sweeps.h, toolCurveAt) drawn as a metallic tube.
//
// Add actor() to a VtkViewport (VtkViewport::addProp); the adapter only owns VTK data.

#include "scenario/scenario_document.h"

#include <vtkSmartPointer.h>

#include <array>
#include <vector>

class vtkActor;
class vtkPolyData;
class vtkPolyDataMapper;
class vtkProp;
class vtkTubeFilter;

namespace resect {

class ToolActor {
public:
    ToolActor();

    /// Shows the tool at the pose: the world polyline toolCurveAt(tool, pose). A tool curve
    /// of fewer than two points hides it.
    void setPose(const ToolSpec& tool, const ToolPose& pose);
    /// Shows a world polyline as the tool. Non-finite points and repeats of the point before
    /// are dropped; fewer than two points left hides it.
    void setCurve(const std::vector<Vec3>& worldCurve);
    void hide();

    bool isVisible() const;
    /// The world polyline shown (after dropping bad points); empty when hidden.
    const std::vector<Vec3>& curve() const { return m_curve; }

    /// Tube radius in mm; 0 (the default) picks kAutoRadiusFraction of the shown curve's
    /// bounding-box diagonal.
    void setRadius(double mm);
    /// The radius in use for the shown curve (mm; 0 when hidden).
    double radius() const;

    vtkActor* actor() const;
    std::vector<vtkProp*> props() const;
    /// The shown polyline (input of the tube filter).
    vtkPolyData* polyline() const;

    static constexpr double kAutoRadiusFraction = 0.03;
    static constexpr std::array<double, 3> kColor{0.82, 0.84, 0.88}; ///< steel

private:
    double effectiveRadius() const;

    std::vector<Vec3> m_curve;
    double m_radius = 0;
    vtkSmartPointer<vtkPolyData> m_polyline;
    vtkSmartPointer<vtkTubeFilter> m_tube;
    vtkSmartPointer<vtkPolyDataMapper> m_mapper;
    vtkSmartPointer<vtkActor> m_actor;
};

} // namespace resect
