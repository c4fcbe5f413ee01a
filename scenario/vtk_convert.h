#pragma once
// Conversions between core meshes and VTK data sets, shared by the file writers and the
// renderers.

#include "core/mesh/tet_mesh.h"
#include "core/mesh/triangle_surface.h"

#include <vtkSmartPointer.h>

class vtkUnstructuredGrid;
class vtkPolyData;

namespace resect {

/// Points = current positions; point data reference_position, mass, velocity; VTK_TETRA
/// cells; cell data quality (radius ratio, reference configuration) and piece.
vtkSmartPointer<vtkUnstructuredGrid> toUnstructuredGrid(const TetMesh& mesh);

/// Points, triangles and (if present) texture coordinates.
vtkSmartPointer<vtkPolyData> toPolyData(const TriangleSurface& surface);

/// The boundary faces of the tet mesh as a surface (current positions), with cell data
/// quality of the owning tet.
vtkSmartPointer<vtkPolyData> boundaryToPolyData(const TetMesh& mesh);

} // namespace resect
