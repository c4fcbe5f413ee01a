// Fuzz targets of the tet mesh readers (scenario/mesh_io.h), each through readTetMesh with
// the input written to a file of the format's extension:
//   vtu     VTK XML unstructured grid (VTK's reader behind the project's pre-flight check)
//   msh     Gmsh 4.1 ASCII
//   tetgen  TetGen .node/.ele: the input is the .node file, then a line "@@ele@@", then the
//           .ele file (no separator: an empty .ele file)
//   vtk     legacy VTK (VTK's reader behind the project's pre-flight check)
//   medit   Medit .mesh

#include "fuzz/fuzz_inputs.h"

#include "scenario/mesh_io.h"

#include <algorithm>

namespace resect::fuzz {
namespace {

/// Reads `path` with readTetMesh and checks the result; `paths` are the names an error may
/// give (the file or the other file of a pair).
Outcome readMesh(const std::string& path, std::initializer_list<std::string_view> paths,
                 bool importedMesh) {
    TetMesh mesh;
    if (Status s = readTetMesh(path, mesh); !s) {
        if (mesh.nodeCount() != 0 || mesh.tetCount() != 0)
            return Outcome::broken("the mesh was changed by a failed read");
        return rejected(s, paths);
    }
    if (std::string bad = checkTetMesh(mesh, importedMesh); !bad.empty())
        return Outcome::broken(bad);
    return Outcome::accepted();
}

Outcome vtuInput(std::span<const std::uint8_t> input) {
    const std::string path = writeScratchFile("fuzz.vtu", input);
    return readMesh(path, {path}, false);
}

Outcome mshInput(std::span<const std::uint8_t> input) {
    const std::string path = writeScratchFile("fuzz.msh", input);
    return readMesh(path, {path}, true);
}

Outcome vtkInput(std::span<const std::uint8_t> input) {
    const std::string path = writeScratchFile("fuzz.vtk", input);
    // Like .vtu, the file may carry masses, and zero masses are accepted from files.
    return readMesh(path, {path}, false);
}

Outcome meditInput(std::span<const std::uint8_t> input) {
    const std::string path = writeScratchFile("fuzz.mesh", input);
    return readMesh(path, {path}, true);
}

constexpr std::string_view kTetGenSeparator = "\n@@ele@@\n";

Outcome tetgenInput(std::span<const std::uint8_t> input) {
    const auto* begin = input.data();
    const auto* end = begin + input.size();
    const auto* sep = std::search(begin, end, kTetGenSeparator.begin(), kTetGenSeparator.end());
    const std::size_t nodeBytes = static_cast<std::size_t>(sep - begin);
    const std::size_t eleStart = std::min(input.size(), nodeBytes + kTetGenSeparator.size());
    const std::string node = writeScratchFile("fuzz.node", input.subspan(0, nodeBytes));
    const std::string ele = writeScratchFile("fuzz.ele", input.subspan(eleStart));
    return readMesh(node, {node, ele}, true);
}

} // namespace

RESECT_FUZZ_TARGET(vtu, vtuInput);
RESECT_FUZZ_TARGET(msh, mshInput);
RESECT_FUZZ_TARGET(tetgen, tetgenInput);
RESECT_FUZZ_TARGET(vtk, vtkInput);
RESECT_FUZZ_TARGET(medit, meditInput);

} // namespace resect::fuzz
