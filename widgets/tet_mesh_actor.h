#pragma once
// TetMeshActor: rendering adapter for a TetMesh, its boundary surface coloured by the
// quality of the owning tet (quality_colors.h) with the element edges drawn on top.
//
// setMesh() rebuilds the VTK data (a topology change). Position-only updates that just
// mark the points modified (STYLE.md item 8) come with the simulation; the adapter is the
// place for them.

#include "core/mesh/tet_mesh.h"
#include "widgets/orbit_camera.h"

#include <vtkSmartPointer.h>

class vtkActor;
class vtkPolyData;
class vtkPolyDataMapper;

namespace resect {

class TetMeshActor {
public:
    TetMeshActor();

    /// Replaces the displayed mesh; an empty mesh shows nothing.
    void setMesh(const TetMesh& mesh);
    void clear();

    vtkActor* actor() const;
    /// The boundary surface as displayed (current positions, cell data "quality").
    vtkPolyData* boundary() const;
    bool empty() const;
    /// Bounds of the displayed boundary; invalid (min > max) when empty.
    Bounds bounds() const;

private:
    vtkSmartPointer<vtkPolyData> m_boundary;
    vtkSmartPointer<vtkPolyDataMapper> m_mapper;
    vtkSmartPointer<vtkActor> m_actor;
};

} // namespace resect
