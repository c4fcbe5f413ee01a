#pragma once
// Trainer export (issue 8): a self-contained package of a scenario for the trainer, written
// by `resect export` and by the studio (widgets/export_runner.h runs it on a worker thread).
//
// OUT/
//   scenario.json          the scenario, paths rewritten to the files below
//   NAME.vtu               each tissue's tet mesh before any cut (replaces its meshing step)
//   NAME-surface.EXT       each tissue's surface file, copied as it was (samples stay built in)
//   NAME-visual.glb        each tissue's visual surface (binary glTF with texture coordinates)
//   sweep-I.json           sweep files the scenario refers to
//   result/NAME.vtu        the expert's recorded result: the tet mesh after the replay,
//   result/NAME.glb        the cut surface, deformed with it,
//   result/report.json     and the run report (as `resect run --report`)
//   manifest.json          every other file with its path, size and SHA-256:
//                          {"format": "resect-package", "version": 1,
//                           "files": [{"path", "size", "sha256"}, ...]}   (sorted by path)
//
// NAME is the tissue's name with every character other than letters, digits, '-' and '_'
// replaced by '_' ("tissue-I" if that leaves nothing).
//
// Atomicity: the package is written into a temporary folder next to OUT
// (".OUT.tmp-XXXXXX") and renamed into place once complete. An existing non-empty OUT is
// refused unless ExportOptions::force; with force it is moved aside (".OUT.old-XXXXXX"), the
// new package renamed in, and only then the old one removed (if the rename fails the old
// one is put back). Whatever fails or is cancelled, no temporary folder is left behind, OUT
// is as it was, and parent folders of OUT created for the export are removed again. OUT may
// not hold the scenario file (ExportOptions::scenarioFile) or any file the scenario refers
// to (a forced export would delete it).

#include "core/status.h"
#include "scenario/scenario_document.h"
#include "scenario/scenario_run.h"

#include <functional>
#include <string>
#include <vector>

namespace resect {

struct ExportOptions {
    /// Replace an existing non-empty output folder (as a whole, once the package is complete).
    bool force = false;
    /// The scenario's own file, if it has one: protected like the files it refers to (the
    /// path overload of exportTrainerPackage sets it).
    std::string scenarioFile;
};

/// Why an export failed: the CLI maps BadInput to exit 2 and Internal to exit 1.
enum class ExportFailure { None, BadInput, Internal, Cancelled };

struct ExportSummary {
    std::string outDir;              ///< the package folder, absolute and normalised
    std::vector<std::string> files;  ///< every file written, relative to outDir, sorted,
                                     ///< "manifest.json" last
    ScenarioRun run;                 ///< the recorded result (as in result/report.json)
    bool expectationsPassed = false; ///< run.allPassed()
    ExportFailure failure = ExportFailure::None; ///< set on every failure
};

/// Progress in [0, 1] and the current stage; return false to cancel. Called on the thread
/// running the export, often during a replay (callers throttle what they show). Stages:
///   "checking"               the output folder and the inputs
///   "meshing:NAME"           loading or meshing tissue NAME (not cancellable inside)
///   "writing:NAME"           its tet mesh, surface copy and visual surface
///   "replaying:NAME"         its strokes, cuts and simulation (cancellable every 64 steps)
///   "writing-result:NAME"    its result mesh and surface
///   "packaging"              sweeps, scenario.json and result/report.json
///   "manifest"               hashing every file
///   "finishing"              moving the package into place (last chance to cancel)
///   "done"                   progress 1; the package is in place (the return is ignored)
using ExportProgress = std::function<bool(double progress, const std::string& stage)>;

/// Writes the trainer package of `scenario` (its relative paths resolved against
/// scenario.baseDir) into `outDir`. `out` is reset first. On failure the Status names the
/// folder or file and what is wrong (`outDir` appears as given), out.failure says what
/// kind of failure it was, and nothing is left on disk (see above). Cancellation gives the
/// error "cancelled" exactly. Never throws.
Status exportTrainerPackage(const Scenario& scenario, const std::string& outDir,
                            const ExportOptions& options, ExportSummary& out,
                            const ExportProgress& progress = {});

/// Loads and validates the scenario file (scenario_load.h; failure: BadInput with the first
/// error) and exports it as above, protecting the file itself as an input.
Status exportTrainerPackage(const std::string& scenarioPath, const std::string& outDir,
                            const ExportOptions& options, ExportSummary& out,
                            const ExportProgress& progress = {});

} // namespace resect
