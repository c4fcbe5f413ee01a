#include "scenario/vtk_convert.h"

#include "core/mesh/quality.h"
#include "core/mesh/topology.h"

#include <vtkCellArray.h>
#include <vtkCellData.h>
#include <vtkCellType.h>
#include <vtkDoubleArray.h>
#include <vtkIdTypeArray.h>
#include <vtkIntArray.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkUnstructuredGrid.h>

#include <span>

namespace resect {
namespace {

/// #n x 3 double array named `name` (or unnamed if name is null) holding `values`.
vtkSmartPointer<vtkDoubleArray> vectorArray(const char* name, std::span<const Vec3> values) {
    auto a = vtkSmartPointer<vtkDoubleArray>::New();
    if (name)
        a->SetName(name);
    a->SetNumberOfComponents(3);
    a->SetNumberOfTuples(static_cast<vtkIdType>(values.size()));
    double* raw = a->GetPointer(0);
    for (std::size_t i = 0; i < values.size(); ++i) {
        raw[3 * i + 0] = values[i].x();
        raw[3 * i + 1] = values[i].y();
        raw[3 * i + 2] = values[i].z();
    }
    return a;
}

/// Double-precision points holding `positions`.
vtkSmartPointer<vtkPoints> makePoints(std::span<const Vec3> positions) {
    auto points = vtkSmartPointer<vtkPoints>::New();
    points->SetData(vectorArray(nullptr, positions));
    return points;
}

/// Cell array of fixed-size cells (k nodes each) from a flat list of node indices.
template <std::size_t K>
vtkSmartPointer<vtkCellArray> makeCells(std::span<const std::array<int, K>> cells) {
    auto offsets = vtkSmartPointer<vtkIdTypeArray>::New();
    auto connectivity = vtkSmartPointer<vtkIdTypeArray>::New();
    offsets->SetNumberOfValues(static_cast<vtkIdType>(cells.size()) + 1);
    connectivity->SetNumberOfValues(static_cast<vtkIdType>(cells.size() * K));
    for (std::size_t c = 0; c <= cells.size(); ++c)
        offsets->SetValue(static_cast<vtkIdType>(c), static_cast<vtkIdType>(c * K));
    for (std::size_t c = 0; c < cells.size(); ++c)
        for (std::size_t k = 0; k < K; ++k)
            connectivity->SetValue(static_cast<vtkIdType>(c * K + k), cells[c][k]);
    auto array = vtkSmartPointer<vtkCellArray>::New();
    array->SetData(offsets, connectivity);
    return array;
}

} // namespace

vtkSmartPointer<vtkUnstructuredGrid> toUnstructuredGrid(const TetMesh& mesh) {
    auto grid = vtkSmartPointer<vtkUnstructuredGrid>::New();
    grid->SetPoints(makePoints(mesh.positions()));

    vtkPointData* pd = grid->GetPointData();
    pd->AddArray(vectorArray("reference_position", mesh.referencePositions()));
    auto mass = vtkSmartPointer<vtkDoubleArray>::New();
    mass->SetName("mass");
    mass->SetNumberOfValues(mesh.nodeCount());
    for (int n = 0; n < mesh.nodeCount(); ++n)
        mass->SetValue(n, mesh.masses()[n]);
    pd->AddArray(mass);
    pd->AddArray(vectorArray("velocity", mesh.velocities()));

    grid->SetCells(VTK_TETRA, makeCells<4>(std::span<const Tet>(mesh.tets())));

    const std::vector<TetQuality> qualities = tetQualities(mesh);
    const Components components = connectedComponents(mesh);
    auto quality = vtkSmartPointer<vtkDoubleArray>::New();
    quality->SetName("quality");
    quality->SetNumberOfValues(mesh.tetCount());
    auto piece = vtkSmartPointer<vtkIntArray>::New();
    piece->SetName("piece");
    piece->SetNumberOfValues(mesh.tetCount());
    for (int t = 0; t < mesh.tetCount(); ++t) {
        quality->SetValue(t, qualities[t].radiusRatio);
        piece->SetValue(t, components.tetComponent[t]);
    }
    grid->GetCellData()->AddArray(quality);
    grid->GetCellData()->AddArray(piece);
    return grid;
}

vtkSmartPointer<vtkPolyData> toPolyData(const TriangleSurface& surface) {
    auto poly = vtkSmartPointer<vtkPolyData>::New();
    poly->SetPoints(makePoints(surface.positions));
    poly->SetPolys(makeCells<3>(std::span<const Tri>(surface.triangles)));
    if (!surface.uvs.empty() && surface.uvs.size() == surface.positions.size()) {
        auto uv = vtkSmartPointer<vtkDoubleArray>::New();
        uv->SetName("uv");
        uv->SetNumberOfComponents(2);
        uv->SetNumberOfTuples(static_cast<vtkIdType>(surface.uvs.size()));
        for (std::size_t i = 0; i < surface.uvs.size(); ++i) {
            uv->SetComponent(static_cast<vtkIdType>(i), 0, surface.uvs[i].x());
            uv->SetComponent(static_cast<vtkIdType>(i), 1, surface.uvs[i].y());
        }
        poly->GetPointData()->SetTCoords(uv);
    }
    return poly;
}

vtkSmartPointer<vtkPolyData> boundaryToPolyData(const TetMesh& mesh) {
    const std::vector<BoundaryFace> faces = boundaryFaces(mesh);
    const std::vector<TetQuality> qualities = tetQualities(mesh);
    std::vector<Tri> triangles;
    triangles.reserve(faces.size());
    auto quality = vtkSmartPointer<vtkDoubleArray>::New();
    quality->SetName("quality");
    quality->SetNumberOfValues(static_cast<vtkIdType>(faces.size()));
    for (std::size_t f = 0; f < faces.size(); ++f) {
        triangles.push_back(faces[f].nodes);
        quality->SetValue(static_cast<vtkIdType>(f), qualities[faces[f].tet].radiusRatio);
    }
    auto poly = vtkSmartPointer<vtkPolyData>::New();
    // All mesh nodes are points (interior ones unused), so point i is node i and a position
    // update copies the node array without re-indexing.
    poly->SetPoints(makePoints(mesh.positions()));
    poly->SetPolys(makeCells<3>(std::span<const Tri>(triangles)));
    poly->GetCellData()->AddArray(quality);
    return poly;
}

} // namespace resect
