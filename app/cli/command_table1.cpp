// resect table1 [--sample polyp|myoma ...] [--d 0.2] [--out TABLE.md]
// Reproduces the paper's Table 1 on the built-in samples: the same loop-electrode scoop cut
// by traditional subdivision, hybrid (standard triangulation) and hybrid (enhanced).
#include "app/cli/cli_common.h"

#include "scenario/anatomy.h"
#include "scenario/atomic_file.h"
#include "scenario/cut_study.h"

#include <cstdio>

namespace resect::cli {

int runTable1(Args args) {
    std::vector<std::string> samples = args.options("--sample");
    if (samples.empty())
        samples = {"polyp", "myoma"};
    const double d = args.number("--d", 0.0, CutLimits::kMaxD).value_or(0.2);
    const auto out = args.option("--out");
    args.finish();

    std::string text;
    for (const std::string& name : samples) {
        TriangleSurface surface;
        requireOk(loadAnatomy("sample:" + name, surface));
        TetMesh mesh;
        AnatomyMeshing options;
        requireOk(meshAnatomy(surface, options, mesh));
        // Polyp: the scoop passes through the stalk under the head; myoma: it takes the cap.
        const SweepSurface sweep = loopScoopSweep(mesh, name == "polyp" ? 0.35 : 0.55);
        CutStudy study;
        requireOk(runCutStudy(mesh, sweep, d, options.material, study));
        char head[160];
        std::snprintf(head, sizeof head, "### %s (d = %.2g of the mean edge length)\n\n", name.c_str(), d);
        text += head + formatCutStudy(study) + "\n";
    }
    std::fputs(text.c_str(), stdout);
    if (out)
        requireOk(writeFileAtomically(*out, text));
    return kOk;
}

} // namespace resect::cli
