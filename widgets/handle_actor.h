#pragma once
// HandleActor: rendering adapter for editing handles: points drawn as shaded spheres of a
// fixed size in pixels (kSizePixels, so they stay grabbable at any zoom), each in its own
// colour (point data "colors").
//
// Add actor() to a VtkViewport (VtkViewport::addProp); the adapter only owns VTK data.

#include "core/mesh/tet_mesh.h"

#include <vtkSmartPointer.h>

#include <array>
#include <vector>

class vtkActor;
class vtkPolyData;
class vtkPolyDataMapper;

namespace resect {

class HandleActor {
public:
    using Color = std::array<double, 3>; ///< RGB in [0, 1]

    HandleActor();

    /// One handle per point, coloured by colors[i] (colors.size() == points.size(), else
    /// every handle gets the first colour, or white). Non-finite points are left out.
    void setHandles(const std::vector<Vec3>& points, const std::vector<Color>& colors);
    void clear();

    vtkActor* actor() const;
    vtkPolyData* polyData() const;
    /// Number of handles shown.
    int count() const;

    static constexpr double kSizePixels = 12.0;
    /// Depth offset of the handles towards the camera, in depth-buffer units (VTK's
    /// coincident-topology offset): enough to draw them over the surface they lie on.
    static constexpr double kDepthOffsetUnits = -66000.0;

private:
    vtkSmartPointer<vtkPolyData> m_polyData;
    vtkSmartPointer<vtkPolyDataMapper> m_mapper;
    vtkSmartPointer<vtkActor> m_actor;
};

} // namespace resect
