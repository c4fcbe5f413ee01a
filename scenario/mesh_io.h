#pragma once
// Tet mesh files: .vtu (VTK XML, the project's format, see DESIGN.md "Tet mesh files"),
// Gmsh .msh (v4 ASCII, import) and TetGen .node/.ele (import).

#include "core/mesh/tet_mesh.h"
#include "core/status.h"

#include <string>

namespace resect {

/// Reads a tet mesh, choosing the format by extension: .vtu, .msh, .node or .ele (for
/// TetGen the other file of the pair is found next to it). Every reader checks counts,
/// indices, finiteness and orientation: tets negatively oriented in the reference
/// configuration are an error, except for .msh and .node/.ele, whose tets are reordered to
/// positive orientation. Missing masses are computed from the default material density.
/// Errors name the file and what is wrong; `out` is untouched on error.
Status readTetMesh(const std::string& path, TetMesh& out);
/// True if readTetMesh reads `path` by its extension (.vtu, .msh, .node, .ele, any case);
/// anything else is taken for a surface to mesh.
bool isTetMeshPath(const std::string& path);

/// Writes .vtu atomically: points = current positions; point data reference_position
/// (3 components), mass, velocity; cells VTK_TETRA; cell data quality (radius ratio) and
/// piece (connected component).
Status writeVtu(const std::string& path, const TetMesh& mesh);

Status readVtu(const std::string& path, TetMesh& out);
Status readGmsh(const std::string& path, TetMesh& out);
Status readTetGen(const std::string& path, TetMesh& out);

} // namespace resect
