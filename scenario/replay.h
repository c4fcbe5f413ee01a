#pragma once
// Replay of a scenario's strokes, cuts and simulation (issue 7: `resect run`), independent of
// the document format: the document is turned into a ReplayPlan (scenario_replay.h), which
// this runs.
//
// Timeline. Strokes run in order. A stroke cuts the tissue along its sweep (Tissue::cut: the
// tets, the embedded surface and the simulation follow) and, when the scene has the
// `tool-contact` effect and the stroke has time-stamped poses, the simulation then runs over
// the stroke's time span with the tool at the pose interpolated linearly between samples.
// Between strokes and after the last one the tool is withdrawn (moved above the tissue by
// twice the tissue's size). After all strokes the simulation runs for `duration` seconds.
//
// Time step: the plan's, or the stable explicit step, which the simulator keeps stable where
// the tissue deforms (sub-steps, core/sim/simulator.h); `steps` counts the steps of the plan's
// time step, `substeps` the integrator's.
//
// Resected pieces. A piece a cut separates from every anchored node leaves the tissue as the
// plan says (`resected`: rigid chips by default, resect_pieces.h).
//
// Outcome. `pieces` are the tet mesh's connected components plus the resected chips; the
// resected volume fraction is the reference volume of the chips and of the pieces holding no
// anchored node (Tissue::anchors) over the total (with no anchored nodes: all pieces but the
// largest); `inverted` counts tets with non-positive
// current volume at the end. A simulation that diverges stops the replay with
// `finite = false` and the reason in `failure` (the replay itself succeeds: expectations
// decide).
//
// Determinism: the same plan gives the same outcome (timings aside) for the same thread
// count (the simulator is deterministic per thread count, core/sim/parallel.h).

#include "core/cut/hybrid_cutter.h"
#include "core/mesh/material.h"
#include "core/sim/simulator.h"
#include "core/status.h"
#include "core/tissue/tissue.h"

#include <atomic>
#include <functional>
#include <string>
#include <vector>

namespace resect {

struct ReplayStroke {
    std::string name;                     ///< for messages ("strokes[2]", "sweeps[0]")
    SweepSurface sweep;                   ///< the surface the stroke sweeps
    std::vector<double> times;            ///< s, one per pose (empty: an explicit sweep)
    std::vector<std::vector<Vec3>> tool;  ///< per pose: the tool's points in world space (mm)
};

struct ReplayPlan {
    TetMesh mesh;                  ///< the tissue, masses set
    TriangleSurface surface;       ///< the embedded high-resolution surface (may be empty)
    FixedSelection anchors;        ///< the tissue's anchored nodes (its fixed regions; may be empty)
    std::vector<ReplayStroke> strokes;
    CutOptions cut;
    Material material;
    std::vector<std::string> effects;  ///< names for the EffectRegistry, in order
    EffectSettings effectSettings;     ///< their parameters (gravity, tool, ...; `fixed` holds `anchors`)
    SimulatorOptions simulation;       ///< integrator and dt (0: the stable step)
    ResectedPieces resected = ResectedPieces::Rigid;  ///< pieces a cut separates from the anchors
    double duration = 0;               ///< s simulated after the strokes
    long long maxSteps = 2'000'000;    ///< refuse plans that need more steps than this
};

struct ReplayOutcome {
    TetMesh mesh;              ///< the tissue at the end
    TriangleSurface surface;   ///< the embedded surface at the end (deformed with the tets)
    int tetsBefore = 0;
    int pieces = 0;            ///< pieces the tissue was cut into: the tissue's and the resected ones
    int resectedPieces = 0;    ///< pieces that left the tissue (chips)
    double resectedMass = 0;   ///< g, their mass
    double resectedVolumeFraction = 0;
    double minRadiusRatio = 0;
    bool finite = true;
    int inverted = 0;
    long long steps = 0;
    long long substeps = 0;    ///< integrator steps (sub-steps included)
    double dt = 0, stableDt = 0;
    double maxSpeed = 0;
    double kineticInitial = 0, kineticMax = 0, kineticFinal = 0;
    std::string failure;       ///< why the simulation stopped early (empty if it did not)
    /// The stroke whose cut failed, and why (empty if every cut succeeded). The replay stops
    /// there: the outcome is the tissue as it was before that cut.
    std::string cutFailure;
    CutStats cutTotals;        ///< summed over the strokes (times included)
    int surfaceCapTriangles = 0;
    std::vector<EffectTime> effectTimes;  ///< ms per effect over the whole run
};

/// The tool's points `pose` lifted straight up, clear of the tissue (by its height plus twice
/// its diagonal, current positions): where the tool rests between strokes.
std::vector<Vec3> withdrawnTool(const std::vector<Vec3>& pose, const TetMesh& mesh);

/// Progress in [0, 1]; return false to cancel (the replay then fails with "cancelled").
using ReplayProgress = std::function<bool(double)>;

/// The tissue of a plan: its mesh, surface, material and anchors (the plan's mesh and surface
/// are moved into it).
Status makeTissue(ReplayPlan& plan, Tissue& out);
/// The simulation of a plan: integrator, step, effects and their parameters.
SimulationSetup simulationSetup(const ReplayPlan& plan);

/// Runs the plan (consumed). Errors: a cut that fails (naming the stroke), bad effect
/// parameters, a plan needing more than maxSteps steps, cancellation.
Status replay(ReplayPlan plan, ReplayOutcome& out, const ReplayProgress& progress = {});

} // namespace resect
