#pragma once
// Private helpers shared by the tet mesh readers (mesh_io.cpp, vtu_io.cpp, gmsh_reader.cpp,
// tetgen_io.cpp, vtk_legacy_io.cpp, medit_io.cpp, gmsh_writer.cpp): file access, a line reader for the text formats, strict number
// parsing and the final validation of imported meshes. Not part of the public API.

#include "core/mesh/tet_mesh.h"
#include "scenario/mesh_io.h"
#include "core/status.h"

#include <cstdint>
#include <functional>
#include <string>
#include <string_view>
#include <vector>

namespace resect::detail {

/// Ok if `path` names an existing regular file; else "PATH: no such file" or
/// "PATH: not a regular file".
Status checkRegularFile(const std::string& path);

/// Runs `body` and turns any exception into an error naming the file (`action`: "reading"
/// or "writing"), so that no exception leaves the readers and writers.
Status guarded(const std::string& path, const char* action, const std::function<Status()>& body);

/// Reads the whole file into `out` (bytes as they are). Errors name the file.
Status readWholeFile(const std::string& path, std::string& out);

/// Lower-case extension including the dot (".vtu"), or "" if the name has none.
std::string lowerExtension(const std::string& path);

/// Splits `line` at ASCII whitespace into `out` (cleared first).
void splitTokens(std::string_view line, std::vector<std::string_view>& out);

/// Strict parsers: the whole token must be a number (a leading '+' is accepted).
bool parseInt64(std::string_view token, std::int64_t& value);
bool parseDouble(std::string_view token, double& value);

/// Reads a text buffer line by line (LF or CRLF), counting lines for error messages.
class LineReader {
public:
    explicit LineReader(std::string_view text);
    /// Next line without its line ending; false at the end of the text.
    bool next(std::string_view& line);
    /// Next line that is not blank after removing everything from `comment` on (if comment
    /// is not '\0'); false at the end of the text.
    bool nextContent(std::string_view& line, char comment = '\0');
    /// 1-based number of the line last returned by next().
    std::int64_t lineNumber() const { return m_lineNumber; }
    /// Lines not yet returned (an upper bound on how many records the rest can hold).
    std::int64_t remainingLines() const { return m_totalLines - m_lineNumber; }

private:
    std::string_view m_text;
    std::size_t m_pos = 0;
    std::int64_t m_lineNumber = 0;
    std::int64_t m_totalLines = 0;
};

/// Nodes and tets as read from an import format (Gmsh, TetGen, Medit, legacy VTK), before
/// validation. `tetLabel(t)` names tet t in error messages the way the file does (e.g.
/// "element 17").
struct ImportedMesh {
    std::vector<Vec3> points; ///< as the file gives them: current positions
    std::vector<Tet> tets;
    std::function<std::string(int)> tetLabel;
    /// Optional per-node data the project's own writers add: empty if the file has none,
    /// else one value per point. Orientation is judged on `reference` when given.
    std::vector<Vec3> reference; ///< reference_position
    std::vector<Vec3> velocity;
    std::vector<double> mass;    ///< must be finite and >= 0
    /// Optional per-tet group tag (MeshReadReport::tetGroup): empty, or one per tet.
    std::vector<std::int64_t> tetGroup;
};

/// Turns an imported mesh into a TetMesh: checks indices and finiteness (of the optional
/// arrays too, and their sizes), reorders negatively oriented tets (swaps their last two
/// nodes) and rejects zero-volume ones (exact orient3d in the reference configuration),
/// drops nodes that no tet uses (keeping the file's order), and takes the file's masses or
/// computes lumped masses from Material{}.density. Fills report->tetGroup from
/// imported.tetGroup (and the groups' tet counts) if `report` is given.
/// Errors are prefixed with `path`.
Status finishImportedMesh(const std::string& path, ImportedMesh imported, TetMesh& out,
                          MeshReadReport* report = nullptr);

/// What every writer carries besides positions: per tet its radius ratio (reference
/// configuration) and piece (connected component, 0-based), and the number of pieces.
struct TetAttributes {
    std::vector<double> quality;
    std::vector<int> piece;
    int pieceCount = 0;
};
TetAttributes tetAttributes(const TetMesh& mesh);

/// Ok if `mesh` can be written: node arrays of equal size, valid indices.
/// Errors are prefixed with `path`.
Status checkWritableMesh(const std::string& path, const TetMesh& mesh);

/// A double as the shortest text that reads back to the same value (std::to_chars).
std::string exactText(double value);

/// Computes lumped masses from Material{}.density and checks them: every node's mass must
/// be finite and positive. Finite coordinates can still give a tet volume that overflows
/// (edges of about 1e103 and longer) or a mass that underflows to zero (edges of about
/// 1e-107 and shorter), and such a mass breaks the simulation. Errors are prefixed with `path` and name the first bad node.
Status computeCheckedMasses(const std::string& path, TetMesh& mesh);

/// The limit on node and tet counts: TetMesh indexes with int.
inline constexpr std::int64_t kMaxMeshItems = 2'147'483'647;

} // namespace resect::detail
