// Legacy VTK unstructured grids (.vtk; https://vtk.org/wp-content/uploads/2015/04/file-formats.pdf).
//
// Reading: the file is parsed and checked by checkVtkLegacyFile (vtk_legacy_guard.h), and
// VTK's vtkUnstructuredGridReader reads the checked copy it returns, with VTK's messages
// captured (vtk_messages.h). VTK_TETRA cells are kept, VTK_QUADRATIC_TETRA cells read as
// their four corners, other cells dropped and counted. Point data reference_position, mass
// and velocity are taken when present; cell data gmsh:physical, CellEntityIds or piece
// become volume groups.
//
// Writing is by hand, DataFile Version 4.2 ("CELLS n 5n" layout), because VTK's legacy
// writer prints ASCII doubles with too few digits: ASCII uses the shortest exact text
// (exactText), binary big-endian doubles as the format requires. Every array is a FIELD
// array (VTK's reader keeps only the first SCALARS / VECTORS unless told otherwise):
//   POINT_DATA: reference_position (3 doubles), mass, velocity (3 doubles)
//   CELL_DATA:  quality (radius ratio, double), piece (int)

#include "scenario/atomic_file.h"
#include "scenario/mesh_io.h"
#include "scenario/mesh_io_detail.h"
#include "scenario/vtk_legacy_guard.h"
#include "scenario/vtk_messages.h"

#include <vtkCellArray.h>
#include <vtkCellData.h>
#include <vtkCellType.h>
#include <vtkDataArray.h>
#include <vtkExecutive.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkSmartPointer.h>
#include <vtkUnsignedCharArray.h>
#include <vtkUnstructuredGrid.h>
#include <vtkUnstructuredGridReader.h>

#include <bit>
#include <cmath>
#include <cstdint>
#include <string>
#include <vector>

namespace resect {
namespace {

using namespace detail;

/// The name of a VTK cell type for the read report ("VTK_TRIANGLE").
std::string cellTypeName(int type) {
    switch (type) {
    case VTK_EMPTY_CELL: return "VTK_EMPTY_CELL";
    case VTK_VERTEX: return "VTK_VERTEX";
    case VTK_POLY_VERTEX: return "VTK_POLY_VERTEX";
    case VTK_LINE: return "VTK_LINE";
    case VTK_POLY_LINE: return "VTK_POLY_LINE";
    case VTK_TRIANGLE: return "VTK_TRIANGLE";
    case VTK_TRIANGLE_STRIP: return "VTK_TRIANGLE_STRIP";
    case VTK_POLYGON: return "VTK_POLYGON";
    case VTK_PIXEL: return "VTK_PIXEL";
    case VTK_QUAD: return "VTK_QUAD";
    case VTK_VOXEL: return "VTK_VOXEL";
    case VTK_HEXAHEDRON: return "VTK_HEXAHEDRON";
    case VTK_WEDGE: return "VTK_WEDGE";
    case VTK_PYRAMID: return "VTK_PYRAMID";
    case VTK_QUADRATIC_EDGE: return "VTK_QUADRATIC_EDGE";
    case VTK_QUADRATIC_TRIANGLE: return "VTK_QUADRATIC_TRIANGLE";
    case VTK_QUADRATIC_QUAD: return "VTK_QUADRATIC_QUAD";
    case VTK_QUADRATIC_HEXAHEDRON: return "VTK_QUADRATIC_HEXAHEDRON";
    case VTK_QUADRATIC_WEDGE: return "VTK_QUADRATIC_WEDGE";
    case VTK_QUADRATIC_PYRAMID: return "VTK_QUADRATIC_PYRAMID";
    default: return "VTK cell type " + std::to_string(type);
    }
}

/// The cells of `grid` as tets: VTK_TETRA (4 nodes) and the corners of VTK_QUADRATIC_TETRA
/// (10 nodes, corners first); every other cell is dropped and counted in `report`.
/// `cellOf[t]` receives the cell index of tet t.
Status gridTets(const std::string& path, vtkUnstructuredGrid* grid, ImportedMesh& imported,
                std::vector<vtkIdType>& cellOf, MeshReadReport& report) {
    const vtkIdType cellCount = grid->GetNumberOfCells();
    vtkUnsignedCharArray* types = grid->GetCellTypesArray();
    vtkCellArray* cells = grid->GetCells();
    if (cellCount == 0 || !types || !cells || types->GetNumberOfTuples() != cellCount)
        return Status::error(path + ": no cells");
    std::int64_t quadratic = 0;
    for (vtkIdType c = 0; c < cellCount; ++c) {
        const int type = types->GetValue(c);
        if (type != VTK_TETRA && type != VTK_QUADRATIC_TETRA) {
            report.drop(cellTypeName(type));
            continue;
        }
        vtkIdType n = 0;
        const vtkIdType* ids = nullptr;
        cells->GetCellAtId(c, n, ids);
        const vtkIdType expected = type == VTK_TETRA ? 4 : 10;
        if (n != expected)
            return Status::error(path + ": cell " + std::to_string(c) + " is a " +
                                 (type == VTK_TETRA ? "VTK_TETRA" : "VTK_QUADRATIC_TETRA") +
                                 " with " + std::to_string(n) + " nodes, expected " +
                                 std::to_string(expected));
        Tet t;
        for (int k = 0; k < 4; ++k)
            // Out-of-range ids are reported by finishImportedMesh; keep them representable.
            t[k] = ids[k] <= kMaxMeshItems ? static_cast<int>(ids[k]) : -1;
        imported.tets.push_back(t);
        cellOf.push_back(c);
        quadratic += type == VTK_QUADRATIC_TETRA;
    }
    if (quadratic > 0)
        report.notes.push_back(std::to_string(quadratic) +
                               " 10-node tetrahedra read as their corners");
    if (imported.tets.empty())
        return Status::error(path + ": no tetrahedra (no VTK_TETRA or VTK_QUADRATIC_TETRA cells)");
    return Status::success();
}

/// Volume groups from the first integer cell array of gmsh:physical, CellEntityIds and
/// piece (whose tags are piece + 1, as the Medit and TetGen writers number them).
Status cellGroups(const std::string& path, vtkUnstructuredGrid* grid,
                  const std::vector<vtkIdType>& cellOf, ImportedMesh& imported,
                  MeshReadReport& report) {
    const vtkIdType cells = grid->GetNumberOfCells();
    for (const char* name : {"gmsh:physical", "CellEntityIds", "piece"}) {
        vtkDataArray* array = nullptr;
        if (Status s = vtkArrayOfShape(path, grid->GetCellData(), "cell array", name, 1, cells,
                                       array);
            !s)
            return s;
        if (!array)
            continue;
        const std::int64_t offset = std::string_view(name) == "piece" ? 1 : 0;
        std::vector<std::int64_t> tags;
        tags.reserve(cellOf.size());
        for (vtkIdType c : cellOf) {
            const double v = array->GetComponent(c, 0);
            if (!(std::fabs(v) < 1e15) || v != std::floor(v))
                return Status::error(path + ": cell array '" + name + "' of cell " +
                                     std::to_string(c) + " is " + std::to_string(v) +
                                     ", not an integer");
            tags.push_back(static_cast<std::int64_t>(v) + offset);
        }
        for (std::int64_t tag : tags) {
            if (tag == 0)
                continue;
            const auto same = [&](const MeshReadReport::Group& g) { return g.tag == tag; };
            if (std::find_if(report.groups.begin(), report.groups.end(), same) ==
                report.groups.end())
                report.groups.push_back({3, tag, "", 0});
        }
        imported.tetGroup = std::move(tags);
        return Status::success();
    }
    return Status::success();
}

Status readImpl(const std::string& path, TetMesh& out, MeshReadReport* report) {
    std::string bytes;
    if (Status s = readWholeFile(path, bytes); !s)
        return s;
    VtkLegacyFile checked;
    if (Status s = checkVtkLegacyFile(path, bytes, checked); !s)
        return s;
    bytes.clear();
    bytes.shrink_to_fit();

    auto reader = vtkSmartPointer<vtkUnstructuredGridReader>::New();
    reader->ReadFromInputStringOn();
    reader->SetInputString(checked.forVtk.data(), static_cast<int>(checked.forVtk.size()));
    vtkUnstructuredGrid* grid = nullptr;
    if (Status s = updateGridReader(reader, path, "legacy VTK unstructured grid", grid); !s)
        return s;
    const vtkIdType pointCount = grid->GetNumberOfPoints();
    if (pointCount == 0 || !grid->GetPoints())
        return Status::error(path + ": no points");

    MeshReadReport local;
    local.format = checked.binary ? "Legacy VTK binary" : "Legacy VTK ASCII";
    ImportedMesh imported;
    if (Status s = vtkArrayToVectors(path, grid->GetPoints()->GetData(), "the position",
                                     imported.points);
        !s)
        return s;
    std::vector<vtkIdType> cellOf;
    if (Status s = gridTets(path, grid, imported, cellOf, local); !s)
        return s;
    if (Status s = gridNodeData(path, grid, imported.reference, imported.mass, imported.velocity); !s)
        return s;
    if (Status s = cellGroups(path, grid, cellOf, imported, local); !s)
        return s;
    imported.tetLabel = [cellOf](int t) {
        return "cell " + std::to_string(cellOf[static_cast<std::size_t>(t)]);
    };
    if (Status s = finishImportedMesh(path, std::move(imported), out, &local); !s)
        return s;
    if (report)
        *report = std::move(local);
    return Status::success();
}

// --- writing ---

/// Appends values as the legacy format wants them: binary big-endian, ASCII one tuple a line.
class VtkText {
public:
    explicit VtkText(bool binary) : m_binary(binary) {}
    std::string& text() { return m_text; }
    void line(const std::string& s) { m_text += s + "\n"; }

    void add(double v) {
        if (m_binary)
            put(std::bit_cast<std::uint64_t>(v), 8);
        else
            word(exactText(v));
    }
    void add(std::int32_t v) {
        if (m_binary)
            put(static_cast<std::uint32_t>(v), 4);
        else
            word(std::to_string(v));
    }
    /// Ends a tuple (ASCII: a line) or a block of binary data.
    void endTuple() {
        if (!m_binary)
            m_text += "\n";
        m_first = true;
    }
    void endBlock() {
        if (m_binary)
            m_text += "\n";
        m_first = true;
    }

private:
    void put(std::uint64_t v, int bytes) {
        for (int b = bytes - 1; b >= 0; --b)
            m_text.push_back(static_cast<char>((v >> (8 * b)) & 0xff));
    }
    void word(const std::string& s) {
        if (!m_first)
            m_text += " ";
        m_text += s;
        m_first = false;
    }
    bool m_binary;
    bool m_first = true;
    std::string m_text;
};

std::string vtkLegacyText(const TetMesh& mesh, bool binary) {
    const TetAttributes attributes = tetAttributes(mesh);
    const int n = mesh.nodeCount();
    const int t = mesh.tetCount();
    VtkText out(binary);
    out.line("# vtk DataFile Version 4.2");
    out.line("Resect Studio tet mesh");
    out.line(binary ? "BINARY" : "ASCII");
    out.line("DATASET UNSTRUCTURED_GRID");
    const auto vectors = [&](std::span<const Vec3> values) {
        for (const Vec3& p : values) {
            out.add(p.x());
            out.add(p.y());
            out.add(p.z());
            out.endTuple();
        }
        out.endBlock();
    };
    out.line("POINTS " + std::to_string(n) + " double");
    vectors(mesh.positions());
    out.line("CELLS " + std::to_string(t) + " " + std::to_string(5LL * t));
    for (const Tet& q : mesh.tets()) {
        out.add(std::int32_t{4});
        for (int v : q)
            out.add(static_cast<std::int32_t>(v));
        out.endTuple();
    }
    out.endBlock();
    out.line("CELL_TYPES " + std::to_string(t));
    for (int c = 0; c < t; ++c) {
        out.add(std::int32_t{VTK_TETRA});
        out.endTuple();
    }
    out.endBlock();
    out.line("CELL_DATA " + std::to_string(t));
    out.line("FIELD FieldData 2");
    out.line("quality 1 " + std::to_string(t) + " double");
    for (double q : attributes.quality) {
        out.add(q);
        out.endTuple();
    }
    out.endBlock();
    out.line("piece 1 " + std::to_string(t) + " int");
    for (int p : attributes.piece) {
        out.add(static_cast<std::int32_t>(p));
        out.endTuple();
    }
    out.endBlock();
    out.line("POINT_DATA " + std::to_string(n));
    out.line("FIELD FieldData 3");
    out.line("reference_position 3 " + std::to_string(n) + " double");
    vectors(mesh.referencePositions());
    out.line("mass 1 " + std::to_string(n) + " double");
    for (double m : mesh.masses()) {
        out.add(m);
        out.endTuple();
    }
    out.endBlock();
    out.line("velocity 3 " + std::to_string(n) + " double");
    vectors(mesh.velocities());
    return std::move(out.text());
}

} // namespace

Status readVtkLegacy(const std::string& path, TetMesh& out, MeshReadReport* report) {
    return guarded(path, "reading", [&] { return readImpl(path, out, report); });
}

Status writeVtkLegacy(const std::string& path, const TetMesh& mesh, bool binary) {
    return guarded(path, "writing", [&] {
        if (Status s = checkWritableMesh(path, mesh); !s)
            return s;
        return writeFileAtomically(path, vtkLegacyText(mesh, binary));
    });
}

} // namespace resect
