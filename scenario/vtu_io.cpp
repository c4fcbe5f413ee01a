// .vtu (VTK XML unstructured grid), the project's tet mesh format; see DESIGN.md,
// "Tet mesh files (.vtu)". Written with binary appended data (zlib-compressed, doubles, so
// every value round-trips exactly); read with VTK's XML reader, whose messages are captured
// (vtk_messages.h) and returned as a Status instead of being printed. Before VTK sees a file,
// checkVtkXmlFile rejects the damage that VTK itself would crash on.

#include "scenario/atomic_file.h"
#include "scenario/mesh_io.h"
#include "scenario/mesh_io_detail.h"
#include "scenario/vtk_convert.h"
#include "scenario/vtk_legacy_guard.h"
#include "scenario/vtk_messages.h"
#include "scenario/vtk_xml_guard.h"

#include "core/mesh/predicates.h"

#include <vtkCellArray.h>
#include <vtkCellData.h>
#include <vtkCellType.h>
#include <vtkCellTypes.h>
#include <vtkDataArray.h>
#include <vtkExecutive.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkSmartPointer.h>
#include <vtkUnsignedCharArray.h>
#include <vtkUnstructuredGrid.h>
#include <vtkXMLUnstructuredGridReader.h>
#include <vtkXMLUnstructuredGridWriter.h>

#include <algorithm>
#include <cmath>
#include <exception>
#include <string>
#include <vector>

namespace resect {
namespace {

using namespace detail;

/// Reads the tets from the grid's cells, checking cell types and the cell array layout.
Status readTets(const std::string& path, vtkUnstructuredGrid* grid, std::vector<Tet>& tets) {
    const vtkIdType cellCount = grid->GetNumberOfCells();
    if (cellCount == 0)
        return Status::error(path + ": no cells");
    vtkUnsignedCharArray* types = grid->GetCellTypesArray();
    vtkCellArray* cells = grid->GetCells();
    if (!types || !cells || types->GetNumberOfTuples() != cellCount)
        return Status::error(path + ": damaged cell arrays");
    for (vtkIdType c = 0; c < cellCount; ++c) {
        const int type = types->GetValue(c);
        if (type != VTK_TETRA) {
            const char* name = vtkCellTypes::GetClassNameFromTypeId(type);
            return Status::error(path + ": cell " + std::to_string(c) + " has VTK cell type " +
                                 std::to_string(type) + " (" + (name ? name : "unknown") +
                                 "); only VTK_TETRA (10) cells are supported");
        }
    }
    vtkDataArray* offsets = cells->GetOffsetsArray();
    vtkDataArray* connectivity = cells->GetConnectivityArray();
    if (!offsets || !connectivity || offsets->GetNumberOfTuples() != cellCount + 1 ||
        connectivity->GetNumberOfTuples() != 4 * cellCount)
        return Status::error(path + ": the cell connectivity does not hold 4 nodes per cell");
    tets.resize(static_cast<std::size_t>(cellCount));
    for (vtkIdType c = 0; c < cellCount; ++c) {
        const double begin = offsets->GetComponent(c, 0);
        const double end = offsets->GetComponent(c + 1, 0);
        if (begin != static_cast<double>(4 * c) || end != static_cast<double>(4 * c + 4))
            return Status::error(path + ": cell " + std::to_string(c) +
                                 " does not have exactly 4 nodes");
        for (int k = 0; k < 4; ++k) {
            const double id = connectivity->GetComponent(4 * c + k, 0);
            // Out-of-range ids are reported by checkTetIndices; keep them representable.
            tets[static_cast<std::size_t>(c)][k] =
                (id >= 0 && id <= static_cast<double>(kMaxMeshItems)) ? static_cast<int>(id) : -1;
        }
    }
    return Status::success();
}

Status readVtuImpl(const std::string& path, TetMesh& out) {
    if (Status s = checkRegularFile(path); !s)
        return s;
    if (Status s = checkVtkXmlFile(path); !s)
        return s;

    auto reader = vtkSmartPointer<vtkXMLUnstructuredGridReader>::New();
    reader->SetFileName(path.c_str());
    vtkUnstructuredGrid* grid = nullptr;
    if (Status s = updateGridReader(reader, path, "VTK unstructured grid", grid); !s)
        return s;

    const vtkIdType pointCount = grid->GetNumberOfPoints();
    if (pointCount == 0 || !grid->GetPoints())
        return Status::error(path + ": no points");
    if (pointCount > kMaxMeshItems || grid->GetNumberOfCells() > kMaxMeshItems)
        return Status::error(path + ": too many points or cells");

    std::vector<Tet> tets;
    if (Status s = readTets(path, grid, tets); !s)
        return s;
    if (const std::string bad = checkTetIndices(static_cast<int>(pointCount), tets); !bad.empty())
        return Status::error(path + ": " + bad);

    std::vector<Vec3> positions;
    if (Status s = vtkArrayToVectors(path, grid->GetPoints()->GetData(), "the position", positions); !s)
        return s;

    std::vector<Vec3> reference, velocity;
    std::vector<double> mass;
    if (Status s = gridNodeData(path, grid, reference, mass, velocity); !s)
        return s;
    if (reference.empty())
        reference = positions;
    if (velocity.empty())
        velocity.assign(static_cast<std::size_t>(pointCount), Vec3::Zero());
    for (std::size_t i = 0; i < mass.size(); ++i)
        if (!std::isfinite(mass[i]) || mass[i] < 0)
            return Status::error(path + ": mass of point " + std::to_string(i) + " is " +
                                 std::to_string(mass[i]) + "; masses must be finite and >= 0");

    // DESIGN.md: tets are positively oriented in the reference configuration (exact test).
    for (std::size_t t = 0; t < tets.size(); ++t) {
        const Tet& q = tets[t];
        const int o = orient3d(reference[q[0]], reference[q[1]], reference[q[2]], reference[q[3]]);
        if (o <= 0)
            return Status::error(path + ": tet " + std::to_string(t) +
                                 (o == 0 ? " has zero volume" : " is inverted") +
                                 " in the reference configuration; tets must have "
                                 "det[p1-p0, p2-p0, p3-p0] > 0");
    }

    TetMesh mesh = TetMesh::fromArrays(std::move(reference), std::move(tets));
    std::copy(positions.begin(), positions.end(), mesh.positions().begin());
    std::copy(velocity.begin(), velocity.end(), mesh.velocities().begin());
    if (!mass.empty())
        std::copy(mass.begin(), mass.end(), mesh.masses().begin());
    else if (Status s = computeCheckedMasses(path, mesh); !s)
        return s;
    out = std::move(mesh);
    return Status::success();
}

Status writeVtuImpl(const std::string& path, const TetMesh& mesh) {
    const auto n = static_cast<std::size_t>(mesh.nodeCount());
    if (mesh.positions().size() != n || mesh.velocities().size() != n || mesh.masses().size() != n)
        return Status::error(path + ": cannot write a mesh whose node arrays differ in size");
    if (const std::string bad = checkTetIndices(mesh.nodeCount(), mesh.tets()); !bad.empty())
        return Status::error(path + ": cannot write an invalid mesh: " + bad);
    vtkSmartPointer<vtkUnstructuredGrid> grid = toUnstructuredGrid(mesh);
    return writeAtomically(path, [&](const std::string& tmp) {
        ScopedVtkMessageCapture messages;
        auto writer = vtkSmartPointer<vtkXMLUnstructuredGridWriter>::New();
        writer->SetFileName(tmp.c_str());
        writer->SetInputData(grid);
        writer->SetDataModeToAppended();
        writer->EncodeAppendedDataOff();
        writer->SetCompressorTypeToZLib();
        writer->SetHeaderTypeToUInt64();
        const int ok = writer->Write();
        if (!ok || messages.errorCount() > 0)
            return Status::error(path + ": VTK could not write the file (" +
                                 (messages.firstError().empty() ? std::string("unknown VTK error")
                                                                : messages.firstError()) +
                                 ")");
        return Status::success();
    });
}

} // namespace

Status readVtu(const std::string& path, TetMesh& out, MeshReadReport* report) {
    if (report)
        report->format = "VTK XML unstructured grid";
    return detail::guarded(path, "reading", [&] { return readVtuImpl(path, out); });
}

Status writeVtu(const std::string& path, const TetMesh& mesh) {
    return detail::guarded(path, "writing", [&] { return writeVtuImpl(path, mesh); });
}

} // namespace resect
