#pragma once
// What the two VTK readers (vtu_io.cpp, vtk_legacy_io.cpp) share, private to resect_scenario:
//  - the pre-flight parse of legacy VTK files (.vtk). VTK 9.1's vtkUnstructuredGridReader
//    trusts the counts and cell sizes of the file (it allocates what POINTS or FIELD arrays
//    declare, walks legacy CELLS by their own size fields, indexes cells through unchecked
//    OFFSETS), so a hostile file could crash it or make it allocate without bound. The file
//    is therefore parsed here first, without VTK, and VTK reads a rewritten copy:
//    the header, POINTS, CELLS, CELL_TYPES and the point and cell data arrays the reader
//    uses, with every count checked against the bytes that back it;
//  - checks of the unstructured grid VTK returns (point arrays and their conversion).

#include "core/mesh/tet_mesh.h"
#include "core/status.h"

#include <string>
#include <string_view>
#include <vector>

class vtkDataArray;
class vtkFieldData;
class vtkUnstructuredGrid;

namespace resect::detail {

/// The result of checkVtkLegacyFile.
struct VtkLegacyFile {
    bool binary = false;
    /// The file's version ("4.2"); what VTK reads says the same.
    int majorVersion = 0;
    int minorVersion = 0;
    /// The file for VTK (vtkDataReader::SetInputString): an equivalent legacy unstructured
    /// grid with the header, POINTS, the cells in the OFFSETS/CONNECTIVITY layout (version
    /// 5.1, vtktypeint64), CELL_TYPES and only the point arrays in kVtkPointArrays and cell
    /// arrays in kVtkCellArrays, byte for byte as the file has them.
    std::string forVtk;
    /// Sections and arrays left out ("SCALARS 'temperature'", "METADATA"), for notes.
    std::vector<std::string> skipped;
};

/// The point and cell arrays that VtkLegacyFile::forVtk keeps.
inline constexpr std::string_view kVtkPointArrays[] = {"reference_position", "mass", "velocity"};
inline constexpr std::string_view kVtkCellArrays[] = {"piece", "gmsh:physical", "CellEntityIds"};

/// Parses the legacy VTK file `bytes` (named `path` in errors). Refuses, naming what is
/// wrong: a header that is not "# vtk DataFile Version X.Y" (1.0 to 5.1), no ASCII/BINARY
/// line, a DATASET other than UNSTRUCTURED_GRID, an unknown section or data type, a count
/// larger than the rest of the file can hold (binary: its exact bytes; ASCII: one value
/// per two bytes), truncated data, cells whose sizes or offsets do not add up, CELL_TYPES
/// or POINT_DATA/CELL_DATA counts that differ from the points and cells, a cell type VTK
/// does not know or VTK_POLYHEDRON. Point coordinates and array values are not parsed
/// here (VTK does); cell sizes, offsets, node ids and cell types are.
Status checkVtkLegacyFile(const std::string& path, std::string_view bytes, VtkLegacyFile& out);

/// The array `name` of `data` with `components` components and `tuples` tuples: nullptr in
/// `array` if there is none; an error (naming `what`, e.g. "point array") if it exists but
/// is not numeric or has another shape.
Status vtkArrayOfShape(const std::string& path, vtkFieldData* data, const char* what,
                       const char* name, int components, long long tuples, vtkDataArray*& array);

/// Copies a 3-component array into Vec3s, rejecting non-finite values (`what` names the
/// array in errors, e.g. "reference_position").
Status vtkArrayToVectors(const std::string& path, vtkDataArray* array, const char* what,
                         std::vector<Vec3>& out);

/// The point data the project's writers add to a grid (.vtu and .vtk): reference_position,
/// mass and velocity, each checked for its shape (vtkArrayOfShape) and, for the vectors,
/// finiteness (vtkArrayToVectors); a vector is left empty where the grid has no such array.
/// Masses are copied as they are (callers check them).
Status gridNodeData(const std::string& path, vtkUnstructuredGrid* grid, std::vector<Vec3>& reference,
                    std::vector<double>& mass, std::vector<Vec3>& velocity);

} // namespace resect::detail
