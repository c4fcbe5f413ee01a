// readTetMesh: chooses the reader by extension. The readers live in vtu_io.cpp,
// gmsh_reader.cpp and tetgen_reader.cpp; their shared checks in mesh_io_detail.cpp.

#include "scenario/mesh_io.h"
#include "scenario/mesh_io_detail.h"

namespace resect {

bool isTetMeshPath(const std::string& path) {
    const std::string ext = detail::lowerExtension(path);
    return ext == ".vtu" || ext == ".msh" || ext == ".node" || ext == ".ele";
}

Status readTetMesh(const std::string& path, TetMesh& out) {
    const std::string ext = detail::lowerExtension(path);
    if (ext == ".vtu")
        return readVtu(path, out);
    if (ext == ".msh")
        return readGmsh(path, out);
    if (ext == ".node" || ext == ".ele")
        return readTetGen(path, out);
    if (ext.empty())
        return Status::error(path + ": no file extension; expected .vtu, .msh, .node or .ele");
    return Status::error(path + ": unknown tet mesh extension '" + ext +
                         "'; expected .vtu, .msh, .node or .ele");
}

} // namespace resect
