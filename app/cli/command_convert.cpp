// resect convert MESH --out OUT [--mesh-format KEY]: a tet mesh from one format into
// another (README, "Tet mesh files"). Reads with readTetMesh, writes with writeTetMesh:
// reference positions, masses and velocities the input carries are kept; quality and piece
// are recomputed.
#include "app/cli/cli_common.h"

#include <cstdio>

namespace resect::cli {

int runConvert(Args args) {
    const MeshOutput out = meshOutput(args.requiredOption("--out"), args.option("--mesh-format"));
    const auto files = args.positionals();
    args.finish();
    if (files.size() != 1)
        badInput("expected exactly one MESH file");
    requireDistinctMesh(files[0], out.path);
    TetMesh mesh;
    MeshReadReport read;
    requireOk(readTetMesh(files[0], mesh, &read));
    printReadNotes(files[0], read);
    writeMeshOutput(out, mesh);
    std::printf("%s (%s): %d nodes, %d tets -> %s (%s)\n", files[0].c_str(), read.format.c_str(),
                mesh.nodeCount(), mesh.tetCount(), out.path.c_str(),
                std::string(meshFormatInfo(out.format).name).c_str());
    return kOk;
}

} // namespace resect::cli
