#pragma once
// Running a scenario document (issue 7, `resect run`): every tissue is loaded or meshed, its
// surface bound, every stroke and sweep replayed on it (scenario/replay.h) with the declared
// effects and simulation settings, and the expectations evaluated per tissue.

#include "core/mesher/tetrahedralize.h"
#include "scenario/mesh_io.h"
#include "scenario/replay.h"
#include "scenario/scenario_document.h"

#include <QJsonObject>

#include <atomic>
#include <functional>
#include <string>
#include <vector>

namespace resect {

struct ExpectationResult {
    std::string kind;     ///< "pieces_at_least", ...
    std::string tissue;
    double expected = 0;  ///< the bound
    double actual = 0;
    bool passed = false;
};

struct TissueRun {
    std::string name;
    ReplayOutcome outcome;
};

struct ScenarioRun {
    std::vector<TissueRun> tissues;
    std::vector<ExpectationResult> expectations;
    /// Every expectation passed and every cut succeeded.
    bool allPassed() const;
    /// No tissue's replay stopped at a failed cut (ReplayOutcome::cutFailure).
    bool cutsSucceeded() const;
};

/// Builds the replay plan of one tissue: loads or meshes it (masses from its material),
/// loads its surface, turns strokes and sweeps into cuts and the effects into simulator
/// settings. Errors name the tissue, file or field.
Status planTissue(const Scenario& scenario, const TissueSpec& tissue, ReplayPlan& plan);
/// The first half of planTissue: loads the tissue's surface (if any) and its tet mesh, read
/// or meshed (masses from its material). Meshing stops with an error when *cancel turns
/// true; `progress` (optional) is called on the calling thread as each meshing stage starts
/// (MeshingOptions::progress; not called for a tissue read from a tet mesh). `readReport`
/// (optional) gets what reading a tet mesh noticed (mesh_io.h: dropped elements, groups).
/// On failure the outputs are unchanged.
Status loadTissue(const Scenario& scenario, const TissueSpec& tissue, TetMesh& mesh,
                  TriangleSurface& surface, const std::atomic<bool>* cancel = nullptr,
                  std::function<void(const MeshingProgress&)> progress = {},
                  MeshReadReport* readReport = nullptr);
/// The second half: the plan for an already loaded tissue (the studio plans on the mesh it
/// has cut; fixed nodes are those of `mesh` inside the fixed regions).
Status planLoadedTissue(const Scenario& scenario, const TissueSpec& tissue, TetMesh mesh, TriangleSurface surface,
                        ReplayPlan& plan);

/// The nodes of `mesh` whose reference position lies in one of the tissue's fixed regions
/// (bounds included), sorted: the anchors replay gives the tissue. With one fixed region (every
/// example scenario) the region is also the anchors' box, as `resect cut --fix-box` makes it:
/// nodes a later cut or the improvement puts in it are anchored too, and the improvement may
/// move anchored nodes within it (ImproveOptions::keepOut, moveAnchored). With several, nodes a
/// later cut adds are anchored only as copies of anchored ones.
FixedSelection regionAnchors(const TissueSpec& tissue, const TetMesh& mesh);

/// What starting replay's simulation of `scenario` on `tissue` (the first tissue's spec
/// `spec`, loaded and anchored: an uncut Tissue as makeTissue makes it) would refuse: the plan
/// (the fixed effect holding no node) and every declared effect's parameters on the tissue
/// (EffectRegistry, with the tissue's anchors as the fixed effect's). Errors are those of
/// planLoadedTissue and "effect 'NAME': ...", as Tissue::startSimulation words them. Cost: a
/// copy of the mesh and the construction of the effects (no integrator, no step).
Status checkSimulation(const Scenario& scenario, const TissueSpec& spec, const Tissue& tissue);

/// Replays every tissue and evaluates the expectations. Progress covers all tissues.
Status runScenario(const Scenario& scenario, ScenarioRun& out, const ReplayProgress& progress = {});

/// The run as JSON (the `resect run` report): per tissue its outcome, per expectation its
/// result, "passed". Every timing is under a key "time_ms" (or "effects"[].time_ms), so two
/// runs compare equal once those are dropped (stripTimings).
QJsonObject scenarioRunJson(const ScenarioRun& run);
/// A copy of `report` without its timings (keys "time_ms", recursively).
QJsonObject stripTimings(const QJsonObject& report);

/// Evaluates the expectations against finished tissue runs (exposed for tests).
std::vector<ExpectationResult> evaluateExpectations(const Scenario& scenario, const std::vector<TissueRun>& tissues);

} // namespace resect
