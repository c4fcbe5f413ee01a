#pragma once
// Private helpers shared by the tet mesh readers (mesh_io.cpp, vtu_io.cpp, gmsh_reader.cpp,
// tetgen_reader.cpp): file access, a line reader for the text formats, strict number
// parsing and the final validation of imported meshes. Not part of the public API.

#include "core/mesh/tet_mesh.h"
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

/// Nodes and tets as read from an import format (Gmsh, TetGen), before validation.
/// `tetLabel(t)` names tet t in error messages the way the file does (e.g. "element 17").
struct ImportedMesh {
    std::vector<Vec3> points;
    std::vector<Tet> tets;
    std::function<std::string(int)> tetLabel;
};

/// Turns an imported mesh into a TetMesh: checks indices and finiteness, reorders
/// negatively oriented tets (swaps their last two nodes) and rejects zero-volume ones
/// (exact orient3d in the reference configuration), drops nodes that no tet uses (keeping
/// the file's order), and computes lumped masses from Material{}.density.
/// Errors are prefixed with `path`.
Status finishImportedMesh(const std::string& path, ImportedMesh imported, TetMesh& out);

/// Computes lumped masses from Material{}.density and checks them: every node's mass must
/// be finite and positive. Finite coordinates can still give a tet volume that overflows
/// (edges of about 1e103 and longer) or a mass that underflows to zero (edges of about
/// 1e-107 and shorter), and such a mass breaks the simulation. Errors are prefixed with `path` and name the first bad node.
Status computeCheckedMasses(const std::string& path, TetMesh& mesh);

/// The limit on node and tet counts: TetMesh indexes with int.
inline constexpr std::int64_t kMaxMeshItems = 2'147'483'647;

} // namespace resect::detail
