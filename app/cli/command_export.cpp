// resect export SCENARIO --out DIR [--force]: a self-contained package for the trainer.
// The work is scenario/trainer_export.h (package layout, atomicity, what is refused); this
// maps its failures to exit codes (bad input 2, internal 1) and prints one summary line.
#include "app/cli/cli_common.h"

#include "scenario/trainer_export.h"

#include <cstdio>

namespace resect::cli {

Scenario loadScenarioOrFail(const std::string& path);

int runExport(Args args) {
    const std::string out = args.requiredOption("--out");
    ExportOptions options;
    options.force = args.flag("--force");
    const auto files = args.positionals();
    args.finish();
    if (files.size() != 1)
        badInput("expected exactly one SCENARIO file");
    const Scenario scenario = loadScenarioOrFail(files[0]);
    options.scenarioFile = files[0];

    ExportSummary summary;
    if (const Status s = exportTrainerPackage(scenario, out, options, summary); !s.ok())
        throw CliError{summary.failure == ExportFailure::BadInput ? kBadInput : kInternal,
                       s.message()};
    std::printf("%s: %zu files, expectations %s\n", out.c_str(), summary.files.size(),
                summary.expectationsPassed ? "passed" : "FAILED");
    return kOk;
}

} // namespace resect::cli
