#include "widgets/tet_mesh_actor.h"

#include "scenario/vtk_convert.h"
#include "widgets/quality_colors.h"

#include <vtkActor.h>
#include <vtkLookupTable.h>
#include <vtkPolyData.h>
#include <vtkPolyDataMapper.h>
#include <vtkProperty.h>

namespace resect {

namespace {

/// Name of the cell array written by boundaryToPolyData (scenario/vtk_convert.h).
constexpr const char* kQualityArray = "quality";

} // namespace

TetMeshActor::TetMeshActor()
    : m_boundary(vtkSmartPointer<vtkPolyData>::New()),
      m_mapper(vtkSmartPointer<vtkPolyDataMapper>::New()),
      m_actor(vtkSmartPointer<vtkActor>::New()) {
    m_mapper->SetInputData(m_boundary);
    m_mapper->SetLookupTable(makeQualityLookupTable());
    m_mapper->SetScalarRange(kQualityScaleMin, kQualityScaleMax);
    m_mapper->SetScalarModeToUseCellFieldData();
    m_mapper->SelectColorArray(kQualityArray);
    m_mapper->SetColorModeToMapScalars();
    m_mapper->ScalarVisibilityOn();

    m_actor->SetMapper(m_mapper);
    vtkProperty* property = m_actor->GetProperty();
    property->SetRepresentationToSurface();
    property->EdgeVisibilityOn();
    property->SetEdgeColor(0.12, 0.12, 0.14);
    property->SetLineWidth(1.0);
    property->SetAmbient(0.15);
    property->SetDiffuse(0.8);
    property->SetSpecular(0.15);
    property->SetSpecularPower(20.0);
    m_actor->SetVisibility(false);
}

void TetMeshActor::setMesh(const TetMesh& mesh) {
    if (mesh.empty()) {
        clear();
        return;
    }
    vtkSmartPointer<vtkPolyData> boundary = boundaryToPolyData(mesh);
    if (boundary == nullptr) {
        clear();
        return;
    }
    // Keep the mapper's input object and copy the new structure into it, so that anything
    // holding boundary() stays connected.
    m_boundary->ShallowCopy(boundary);
    m_boundary->Modified();
    m_actor->SetVisibility(m_boundary->GetNumberOfCells() > 0);
}

void TetMeshActor::clear() {
    m_boundary->Initialize();
    m_boundary->Modified();
    m_actor->SetVisibility(false);
}

vtkActor* TetMeshActor::actor() const {
    return m_actor;
}

vtkPolyData* TetMeshActor::boundary() const {
    return m_boundary;
}

bool TetMeshActor::empty() const {
    return m_boundary->GetNumberOfCells() == 0;
}

Bounds TetMeshActor::bounds() const {
    Bounds b{1, -1, 1, -1, 1, -1};
    if (!empty())
        m_boundary->GetBounds(b.data());
    return b;
}

} // namespace resect
