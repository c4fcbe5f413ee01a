#pragma once
// Tet mesh files as the field writes and reads them (README, "Tet mesh files"):
//   .vtu            VTK XML unstructured grid, the project's own format (DESIGN.md)
//   .msh            Gmsh 2.2 and 4.1, ASCII and binary, with physical groups
//   .vtk            legacy VTK unstructured grid, ASCII and binary (read through VTK)
//   .mesh           Medit (mmg, TetWild, fTetWild)
//   .node + .ele    TetGen
// Every format is read and written. A read chooses the reader by extension and the variant
// by the file's own header; a write chooses the format by extension, and where one
// extension has several variants (.msh, .vtk) by a format key (meshFormats()).

#include "core/mesh/tet_mesh.h"
#include "core/status.h"

#include <cstdint>
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace resect {

enum class MeshFormat {
    Vtu,
    Msh41,       ///< Gmsh 4.1 ASCII (what .msh writes by default)
    Msh41Binary,
    Msh22,       ///< Gmsh 2.2 ASCII (SOFA's MeshGmshLoader, older projects)
    Msh22Binary,
    Vtk,         ///< legacy VTK 4.2, binary (what .vtk writes by default: doubles exactly)
    VtkAscii,    ///< legacy VTK 4.2, ASCII (17 significant digits)
    Medit,       ///< Medit .mesh, ASCII, MeshVersionFormatted 2 (doubles)
    TetGen,      ///< TetGen .node + .ele (both written; either name may be given)
};

/// One writable (and readable) format.
struct MeshFormatInfo {
    MeshFormat format;
    std::string_view key;        ///< the CLI's --mesh-format value: "msh22-binary", ...
    std::string_view name;       ///< for dialogs and messages: "Gmsh 2.2 binary"
    std::string_view extensions; ///< lower case, space-separated: ".msh", ".node .ele"
    bool extensionDefault;       ///< written when only the extension is given
    std::string_view carries;    ///< what of ours it holds beyond positions and tets
};

/// Every format, in the order dialogs list them (the project's .vtu first).
std::span<const MeshFormatInfo> meshFormats();
const MeshFormatInfo& meshFormatInfo(MeshFormat format);
/// The format with this key ("vtu", "msh41", "msh41-binary", "msh22", "msh22-binary",
/// "vtk", "vtk-ascii", "medit", "tetgen"), or nullptr.
const MeshFormatInfo* findMeshFormat(std::string_view key);
/// The readable extensions, for messages: ".vtu, .msh, .vtk, .mesh, .node or .ele".
std::string tetMeshExtensionList();

/// The formats as read: one entry per extension group, with every variant the reader takes
/// ("Gmsh 2.2 and 4.1, ASCII and binary", ".msh"), for the Open dialogs.
struct MeshFileFamily {
    std::string_view name;
    std::string_view extensions; ///< as in MeshFormatInfo
};
std::span<const MeshFileFamily> meshFileFamilies();

/// The format a mesh named `path` is written in: `key`'s format if given (it must be one
/// of the path's extension), else the extension's default. An error names the path and
/// what is wrong (no extension, unknown extension, a key that is not a format or does not
/// fit the extension). Cheap and touches no file: commands call it before any work.
Status chooseMeshWriteFormat(const std::string& path, std::string_view key, MeshFormat& out);

/// What a reader noticed and did not refuse.
struct MeshReadReport {
    /// The variant read, e.g. "Gmsh 2.2 binary".
    std::string format;
    /// Elements that are not 4-node tetrahedra and were left out, by kind ("3-node
    /// triangle", "8-node hexahedron", ...), in the order first met.
    struct Dropped {
        std::string what;
        std::int64_t count = 0;
    };
    std::vector<Dropped> dropped;
    /// Physical groups (Gmsh), element references (Medit) or region attributes (TetGen),
    /// every dimension; `tets` counts the tets of the output mesh in the group.
    struct Group {
        int dimension = 3;
        std::int64_t tag = 0;
        std::string name; ///< empty if the file names none
        std::int64_t tets = 0;
    };
    std::vector<Group> groups;
    /// Per tet of the output mesh, its volume group's tag (0: none); empty if the file has
    /// no volume groups. A tet listed in several groups keeps the first.
    std::vector<std::int64_t> tetGroup;
    /// Anything else worth telling (10-node tets read as their corners, duplicates removed).
    std::vector<std::string> notes;

    /// One line for users: "Gmsh 2.2 ASCII; dropped 136 elements that are not 4-node
    /// tetrahedra (3-node triangle 112, 2-node line 24); volume groups: 3 'tissue' (184
    /// tets)". Empty parts are left out.
    std::string summary() const;
    /// Adds `count` to the dropped kind `what`.
    void drop(const std::string& what, std::int64_t count = 1);
};

/// Reads a tet mesh, choosing the reader by extension (any case): .vtu, .msh, .vtk, .mesh,
/// .node or .ele (for TetGen the other file of the pair is found next to it). Every reader
/// checks counts, indices, finiteness and orientation; tets negatively oriented in the
/// reference configuration are an error in .vtu, and reordered to positive orientation in
/// the other formats. Points are current positions; reference positions, masses and
/// velocities are taken from the file where it carries them (the project's own outputs),
/// else reference = current and masses from the default material density. Errors name the
/// file and what is wrong; `out` (and `report`) are untouched on error.
Status readTetMesh(const std::string& path, TetMesh& out, MeshReadReport* report = nullptr);
/// True if readTetMesh reads `path` by its extension; anything else is taken for a surface
/// to mesh.
bool isTetMeshPath(const std::string& path);

/// Writes `mesh` atomically in `format`, which must fit the path's extension (see
/// chooseMeshWriteFormat). Points = current positions; reference_position, mass, velocity,
/// quality (radius ratio) and piece (connected component) are carried where the format can
/// hold them (meshFormatInfo(format).carries).
Status writeTetMesh(const std::string& path, const TetMesh& mesh, MeshFormat format);
/// The same, in the extension's default format.
Status writeTetMesh(const std::string& path, const TetMesh& mesh);

// --- the individual formats (readTetMesh / writeTetMesh dispatch to these) ---

/// .vtu: points = current positions; point data reference_position (3 components), mass,
/// velocity; cells VTK_TETRA; cell data quality (radius ratio) and piece.
Status writeVtu(const std::string& path, const TetMesh& mesh);
Status readVtu(const std::string& path, TetMesh& out, MeshReadReport* report = nullptr);

/// Gmsh .msh 2.2 / 4.1, ASCII or binary (the file's $MeshFormat decides on reading).
Status readGmsh(const std::string& path, TetMesh& out, MeshReadReport* report = nullptr);
/// version 22 or 41. Node data views reference_position, mass, velocity; element data
/// views quality, piece; every piece a volume entity in physical group "piece N".
Status writeGmsh(const std::string& path, const TetMesh& mesh, int version, bool binary);

/// Legacy VTK unstructured grid, read through VTK's vtkUnstructuredGridReader.
Status readVtkLegacy(const std::string& path, TetMesh& out, MeshReadReport* report = nullptr);
/// The same point and cell data as .vtu.
Status writeVtkLegacy(const std::string& path, const TetMesh& mesh, bool binary);

/// Medit .mesh (ASCII). Element references become groups.
Status readMedit(const std::string& path, TetMesh& out, MeshReadReport* report = nullptr);
/// Vertices (reference 0), boundary Triangles and Tetrahedra with reference piece + 1.
Status writeMedit(const std::string& path, const TetMesh& mesh);

/// TetGen .node/.ele; `path` names either file of the pair.
Status readTetGen(const std::string& path, TetMesh& out, MeshReadReport* report = nullptr);
/// Writes both files of the pair; node attributes reference position and mass, tet region
/// attribute piece.
Status writeTetGen(const std::string& path, const TetMesh& mesh);

} // namespace resect
