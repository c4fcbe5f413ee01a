#include "widgets/surface_actor.h"

#include "scenario/vtk_convert.h"

#include <vtkActor.h>
#include <vtkPolyData.h>
#include <vtkPolyDataMapper.h>
#include <vtkProperty.h>

namespace resect {

SurfaceActor::SurfaceActor()
    : m_polyData(vtkSmartPointer<vtkPolyData>::New()),
      m_mapper(vtkSmartPointer<vtkPolyDataMapper>::New()),
      m_actor(vtkSmartPointer<vtkActor>::New()) {
    m_mapper->SetInputData(m_polyData);
    m_mapper->ScalarVisibilityOff();
    m_actor->SetMapper(m_mapper);
    vtkProperty* property = m_actor->GetProperty();
    property->SetColor(0.90, 0.62, 0.60); // pale mucosa pink
    property->SetAmbient(0.15);
    property->SetDiffuse(0.8);
    property->SetSpecular(0.25);
    property->SetSpecularPower(30.0);
    m_actor->SetVisibility(false);
}

void SurfaceActor::setSurface(const TriangleSurface& surface) {
    if (surface.triangles.empty()) {
        clear();
        return;
    }
    vtkSmartPointer<vtkPolyData> polyData = toPolyData(surface);
    if (polyData == nullptr) {
        clear();
        return;
    }
    m_polyData->ShallowCopy(polyData);
    m_polyData->Modified();
    m_actor->SetVisibility(m_polyData->GetNumberOfCells() > 0);
}

void SurfaceActor::clear() {
    m_polyData->Initialize();
    m_polyData->Modified();
    m_actor->SetVisibility(false);
}

vtkActor* SurfaceActor::actor() const {
    return m_actor;
}

vtkPolyData* SurfaceActor::polyData() const {
    return m_polyData;
}

bool SurfaceActor::empty() const {
    return m_polyData->GetNumberOfCells() == 0;
}

Bounds SurfaceActor::bounds() const {
    Bounds b{1, -1, 1, -1, 1, -1};
    if (!empty())
        m_polyData->GetBounds(b.data());
    return b;
}

} // namespace resect
