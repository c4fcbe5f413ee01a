#pragma once
// The .vtu contract of DESIGN.md ("Tet mesh files") checked on a VTK grid, whether it came
// from toUnstructuredGrid() or from a file read back with VTK's own reader.

#include "core/mesh/quality.h"
#include "core/mesh/tet_mesh.h"

#include <vtkCellData.h>
#include <vtkCellType.h>
#include <vtkDataArray.h>
#include <vtkIdList.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkSmartPointer.h>
#include <vtkUnstructuredGrid.h>

#include <QString>

#include <vector>

namespace resect::test {

/// Empty if `grid` holds `mesh` as the contract says: points are the current positions in
/// double precision; point data reference_position (3), mass (1), velocity (3); VTK_TETRA
/// cells with the mesh's node order; cell data quality (the radius ratio, in (0, 1]) and
/// piece (int, equal to `expectedPiece`). Otherwise the first difference.
inline QString gridContractProblem(vtkUnstructuredGrid* grid, const TetMesh& mesh,
                                   const std::vector<int>& expectedPiece) {
    if (grid->GetNumberOfPoints() != mesh.nodeCount() || grid->GetNumberOfCells() != mesh.tetCount())
        return "point or cell count differs";
    if (grid->GetPoints()->GetDataType() != VTK_DOUBLE)
        return "points are not doubles";
    vtkPointData* pd = grid->GetPointData();
    vtkDataArray* ref = pd->GetArray("reference_position");
    vtkDataArray* mass = pd->GetArray("mass");
    vtkDataArray* vel = pd->GetArray("velocity");
    if (!ref || !mass || !vel)
        return "a point data array is missing";
    if (ref->GetNumberOfComponents() != 3 || mass->GetNumberOfComponents() != 1 || vel->GetNumberOfComponents() != 3)
        return "a point data array has the wrong number of components";
    const auto tuple = [](vtkDataArray* a, int i) {
        return Vec3(a->GetComponent(i, 0), a->GetComponent(i, 1), a->GetComponent(i, 2));
    };
    for (int n = 0; n < mesh.nodeCount(); ++n) {
        double p[3];
        grid->GetPoint(n, p);
        if (Vec3(p[0], p[1], p[2]) != mesh.positions()[n])
            return QString("point %1 is not the current position").arg(n);
        if (tuple(ref, n) != mesh.referencePositions()[n] || tuple(vel, n) != mesh.velocities()[n] ||
            mass->GetComponent(n, 0) != mesh.masses()[n])
            return QString("point data of node %1 differs").arg(n);
    }
    vtkDataArray* quality = grid->GetCellData()->GetArray("quality");
    vtkDataArray* piece = grid->GetCellData()->GetArray("piece");
    if (!quality || !piece)
        return "a cell data array is missing";
    if (piece->GetDataType() != VTK_INT)
        return "piece is not an int array";
    const std::vector<TetQuality> q = tetQualities(mesh);
    auto ids = vtkSmartPointer<vtkIdList>::New();
    for (int t = 0; t < mesh.tetCount(); ++t) {
        if (grid->GetCellType(t) != VTK_TETRA)
            return QString("cell %1 is not a tetra").arg(t);
        grid->GetCellPoints(t, ids);
        if (ids->GetNumberOfIds() != 4)
            return QString("cell %1 does not have 4 points").arg(t);
        for (int k = 0; k < 4; ++k)
            if (ids->GetId(k) != mesh.tet(t)[k])
                return QString("cell %1 has other nodes").arg(t);
        const double quality_t = quality->GetComponent(t, 0);
        if (quality_t != q[t].radiusRatio || !(quality_t > 0 && quality_t <= 1 + 1e-12))
            return QString("quality of cell %1 is %2").arg(t).arg(quality_t);
        if (static_cast<int>(piece->GetComponent(t, 0)) != expectedPiece[t])
            return QString("piece of cell %1 differs").arg(t);
    }
    return {};
}

} // namespace resect::test
