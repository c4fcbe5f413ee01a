// resect mesh (SURFACE | --sample NAME) --out OUT.vtu [--edge-length L] [--repair] [--seed N]
#include "app/cli/cli_common.h"

#include "core/mesh/quality.h"
#include "scenario/anatomy.h"
#include "scenario/mesh_io.h"

#include <cstdio>

namespace resect::cli {

int runMesh(Args args) {
    const auto sample = args.option("--sample");
    const std::string out = args.requiredOption("--out");
    AnatomyMeshing options;
    if (auto l = args.number("--edge-length", 0.0, 1e300)) {
        if (!(*l > 0))
            badInput("--edge-length must be positive, got " + std::to_string(*l));
        options.meshing.edgeLength = *l;  // absurdly small values are rejected by the mesher
    }
    if (auto seed = args.integer("--seed", 0, 1 << 30))
        options.meshing.seed = static_cast<unsigned>(*seed);
    options.repair = args.flag("--repair");
    const auto files = args.positionals();
    args.finish();
    if (sample && !files.empty())
        badInput("give either a SURFACE file or --sample, not both");
    if (!sample && files.size() != 1)
        badInput("expected one SURFACE file or --sample polyp|myoma");

    const std::string source = sample ? "sample:" + *sample : files[0];
    if (!sample)
        requireDistinct(files[0], out);
    TriangleSurface surface;
    requireOk(loadAnatomy(source, surface));
    TetMesh mesh;
    std::string log;
    requireOk(meshAnatomy(surface, options, mesh, &log));
    if (!log.empty())
        std::fputs(log.c_str(), stderr);
    requireOk(writeVtu(out, mesh));
    const QualitySummary q = summarizeQuality(mesh);
    std::printf("%s: %d nodes, %d tets, volume %.6g (surface %.6g), min radius ratio %.4f -> %s\n",
                source.c_str(), q.nodes, q.tets, q.volume, enclosedVolume(surface),
                q.minRadiusRatio, out.c_str());
    return kOk;
}

} // namespace resect::cli
