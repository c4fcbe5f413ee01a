#pragma once
// SweepActor: rendering adapter for a sweep surface (section 4.2) while it is drawn,
// recorded or previewed: the ruled surface between consecutive tool curves, translucent
// (kOpacity) in a colour no tissue has, with the curves drawn as lines on top (the first
// curve in kStartColor, the last in kEndColor, any between in kCurveColor).
//
// Add props() to a VtkViewport (VtkViewport::addProp); the adapter only owns VTK data.

#include "core/sweep/sweep_surface.h"

#include <vtkSmartPointer.h>

#include <array>
#include <vector>

class vtkActor;
class vtkPolyData;
class vtkPolyDataMapper;
class vtkProp;

namespace resect {

class SweepActor {
public:
    SweepActor();

    /// Shows a finished sweep surface (its curves and triangles).
    void setSweep(const SweepSurface& sweep);
    /// Shows curves as authored, which need not make a valid sweep yet: the surface is
    /// drawn between consecutive curves of the same length (>= 2 points, triangulated as in
    /// SweepSurface), other curves as lines only. Non-finite points are left out, with their
    /// segments and triangles. No curves: shows nothing.
    void setCurves(const std::vector<std::vector<Vec3>>& curves);
    void clear();

    /// The surface actor and the curve actor, to add to a viewport.
    std::vector<vtkProp*> props() const;
    vtkActor* surfaceActor() const;
    vtkActor* curveActor() const;
    /// Triangles of the displayed surface (may be empty).
    vtkPolyData* surface() const;
    /// The displayed curves as line cells (cell data "colors").
    vtkPolyData* curves() const;
    /// True when nothing is shown.
    bool empty() const;

    static constexpr double kOpacity = 0.35;
    static constexpr std::array<double, 3> kSurfaceColor{0.30, 0.72, 1.00}; ///< sky blue
    static constexpr std::array<double, 3> kStartColor{0.35, 0.95, 0.45};   ///< green
    static constexpr std::array<double, 3> kEndColor{1.00, 0.60, 0.15};     ///< orange
    static constexpr std::array<double, 3> kCurveColor{0.85, 0.90, 1.00};   ///< pale blue

private:
    vtkSmartPointer<vtkPolyData> m_surface;
    vtkSmartPointer<vtkPolyDataMapper> m_surfaceMapper;
    vtkSmartPointer<vtkActor> m_surfaceActor;
    vtkSmartPointer<vtkPolyData> m_curves;
    vtkSmartPointer<vtkPolyDataMapper> m_curveMapper;
    vtkSmartPointer<vtkActor> m_curveActor;
};

} // namespace resect
