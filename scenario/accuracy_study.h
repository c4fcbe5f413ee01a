#pragma once
// What accuracy costs in time: the benchmark study behind `resect bench` (and the studio's
// benchmark panel). Two parts, each a function with progress and cancel:
//
//  * runAccuracyStudy: on the sample polyp and myoma and a finer myoma, the loop-electrode
//    cut of Table 1 (cut_study.h) with subdivision and both hybrid triangulations, every
//    combination of snapping (on, off) and relaxation steps, for every cut-node threshold d.
//    One StudyRow per combination: how far the cut faces lie from the sweep (accuracy), what
//    the cut leaves behind (tets, worst element, stable time step) and what it costs (cut and
//    embedded-surface time, simulation time per simulated second). runAccuracyStudyOn does
//    the same on a given mesh and sweep (the open scenario's tissue and cut).
//  * runScalingStudy: the same local cut (a 4 x 4 cell patch) on Kuhn box meshes from about
//    10k to about 1M tets, the cost of one explicit simulation step per tet on one and two
//    threads and of the embedded-surface update per vertex.
//
// Subdivision does not depend on d (it has no distance-chosen cut nodes); it is nevertheless
// measured at every d, so that the d plots show it as the reference line it is.
//
// All times are wall-clock medians of repeats on whatever else the machine is doing; the
// rows also keep the fastest repeat. Nothing here asserts a time: targets are evaluated into
// a table (evaluateTargets) for the report, never into a failure.

#include "core/mesh/material.h"
#include "core/mesher/samples.h"
#include "core/status.h"

#include <functional>
#include <string>
#include <vector>

namespace resect {

class EmbeddedSurface;
class SweepSurface;
class TetMesh;

enum class StudyMethod { Subdivision, HybridStandard, HybridEnhanced };
/// "subdivision", "hybrid-standard", "hybrid-enhanced".
const char* studyMethodName(StudyMethod method);

/// One anatomy mesh of the accuracy study.
struct StudyMesh {
    std::string name;          ///< as written in the CSV: "polyp", "myoma", "myoma-fine"
    Sample sample = Sample::Myoma;
    double edgeScale = 1.0;    ///< edge length = edgeScale * defaultEdgeLength (about 900 tets at 1)
    double cutHeight = 0.55;   ///< loopScoopSweep's height fraction
};

struct StudyConfig {
    // --- accuracy study ---
    std::vector<StudyMesh> meshes;
    std::vector<StudyMethod> methods;
    std::vector<double> dValues;      ///< fractions of the mean edge length
    std::vector<bool> snapOptions;    ///< hybrid methods only (subdivision: off)
    std::vector<int> relaxSteps;      ///< hybrid methods only (subdivision: 0)
    int repeats = 5;                  ///< cuts per row; times are medians
    int simSteps = 10;                ///< timed explicit steps per row (after 2 warm-up steps)
    int simThreads = 1;               ///< threads of the per-row simulation timing
    /// Detail of the embedded surface (sampleSurface): 0.05 gives about 2000 triangles, the
    /// paper's case.
    double surfaceDetail = 0.05;
    Material material;

    // --- scaling study ---
    std::vector<int> scalingSizes;    ///< target tet counts (Kuhn boxes of n^3 cubes)
    int scalingRepeats = 3;           ///< cuts per size; median
    int scalingMaxSteps = 200;        ///< timed steps per size and thread count: 2e7 / tets, in [5, this]
    int surfaceUpdates = 9;           ///< timed surface updates per size; median
    /// Embedded surface of the scaling meshes: about this many triangles per tet (the paper's
    /// case has two: 2000 triangles on about 1000 tets).
    double surfaceTrianglesPerTet = 2.0;

    std::string label;                ///< "tiny", "quick", "full"
};

/// The configurations of `resect bench --tiny` (tests: a few seconds), `--quick` (a few
/// minutes on two cores) and the full study.
StudyConfig tinyConfig();
StudyConfig quickConfig();
StudyConfig fullConfig();

/// One row of accuracy_time.csv (one mesh, method, d, snapping and relaxation).
struct StudyRow {
    std::string mesh;
    int meshTets = 0;             ///< before the cut
    double meshMinRadiusRatio = 0;///< before the cut
    std::string method;           ///< studyMethodName
    double d = 0;
    bool snap = false;
    int relaxSteps = 0;
    int cutSurfaceNodes = 0;      ///< nodes on the cut faces (CutChanges::cutSurfaceNodes)
    /// Distance of the cut-face nodes (reference positions) to the sweep surface, as a
    /// fraction of the mean edge length: maximum and mean.
    double sweepErrorMax = 0;
    double sweepErrorMean = 0;
    int tets = 0;                 ///< after the cut
    int addedTets = 0;
    int cutNodes = 0;
    int snappedNodes = 0;
    double minRadiusRatio = 0;    ///< 3 r_in / R_circ over the whole mesh after the cut
    double stableDt = 0;          ///< s: the simulated model's stable explicit step (deformation
                                  ///< effect: springs, volume and area terms)
    double cutMs = 0;             ///< median of repeats: the tet cut of Tissue::cut (CutStats::timeMs.total)
    double cutMsMin = 0;
    double surfaceMs = 0;         ///< median: the surface stages of Tissue::cut (update, cut, re-bind, bind new)
    double totalMs = 0;           ///< median of cut + surface per repeat
    int surfaceTriangles = 0;     ///< embedded surface before the cut
    double simMsPerStep = 0;      ///< median wall time of one explicit step
    double simMsPerSecond = 0;    ///< simMsPerStep / stableDt: compute ms per simulated second
};

/// One row of scaling.csv.
struct ScalingRow {
    int meshTets = 0;
    int touchedTets = 0;
    int addedTets = 0;
    double cutMs = 0;             ///< median of repeats
    double cutMsMin = 0;
    double usPerTouchedTet = 0;   ///< 1000 * cutMs / touchedTets (Tissue::cut at the defaults)
    double usPerTouchedTetHybrid = 0;  ///< the same without the improvement step (median)
    /// One explicit step (symplectic Euler, deformation effect), ns per tet, on 1 and 2
    /// threads: median and fastest step.
    double stepNsPerTet1 = 0, stepNsPerTet2 = 0;
    double stepNsPerTetMin1 = 0, stepNsPerTetMin2 = 0;
    int surfaceVertices = 0;
    double surfaceUpdateMs = 0;   ///< median EmbeddedSurface::update (every vertex)
    double surfaceNsPerVertex = 0;
    /// Bytes the update streams (SurfaceBinding::kStreamedBytesPerVertex per vertex) per second
    /// of surfaceUpdateMs, GB/s: to compare with the machine's memory bandwidth.
    double surfaceGBps = 0;
};

/// Progress: fraction done in [0, 1] and what runs now. Return false to cancel; the study
/// then stops at the next row or repeat and returns an error "cancelled" (rows done so far
/// are kept in `rows`).
using StudyProgress = std::function<bool(double fraction, const std::string& stage)>;

/// The scaling study's meshes and cut: n^3 unit cubes of six tets (the n closest to `tets`), and
/// the same local cut on every box, a 4 x 4 cell patch in the middle (smaller boxes: what fits)
/// at the same place relative to the cells (the middle cell rounded down: with n odd, the exact
/// middle would put the cut half a cell off, and it would be another cut).
int scalingBoxCells(int tets);
SweepSurface scalingSweep(int cells);

Status runAccuracyStudy(const StudyConfig& config, std::vector<StudyRow>& rows,
                        const StudyProgress& progress = {});
/// The accuracy study on a given tissue and cut (the studio's open scenario) instead of the
/// samples: the rows of runAccuracyStudy for every method, d, snapping and relaxation of
/// `config` (config.meshes is ignored), cutting copies of `mesh` with `sweep`; every row's
/// `mesh` is `name`. Masses are recomputed with config.material (as for the samples), so the
/// rows compare with runAccuracyStudy's. `surface`, if given and not empty, is the embedded
/// surface bound to `mesh` and is cut along (surfaceMs); otherwise surfaceMs and
/// surfaceTriangles are 0. Progress and cancel as in runAccuracyStudy.
Status runAccuracyStudyOn(const TetMesh& mesh, const SweepSurface& sweep, const std::string& name,
                          const StudyConfig& config, std::vector<StudyRow>& rows,
                          const StudyProgress& progress = {}, const EmbeddedSurface* surface = nullptr);
Status runScalingStudy(const StudyConfig& config, std::vector<ScalingRow>& rows,
                       const StudyProgress& progress = {});

/// CSV text with a header line (column names as in the issue: method, d, snap, relax_steps,
/// sweep_error_max, sweep_error_mean, tets, min_radius_ratio, stable_dt, cut_ms,
/// sim_ms_per_second, ...; mesh_tets, touched_tets, cut_ms, step_ns_per_tet_1t, ...).
std::string accuracyCsv(const std::vector<StudyRow>& rows);
std::string scalingCsv(const std::vector<ScalingRow>& rows);

/// One performance target of the issue and the measured value.
struct TargetCheck {
    std::string name;    ///< what is measured
    double value = 0;    ///< measured (NaN if the study has no row for it)
    double limit = 0;
    std::string unit;
    bool met = false;
};
/// The targets from the rows: cut time per touched tet (ratio largest / smallest mesh
/// and the absolute value), the paper's case (hybrid-enhanced, snapping, 10 relaxation steps,
/// d = 0.2 on the polyp and the myoma: cut + surface), the explicit step per tet on two
/// threads and the surface update per vertex at the largest mesh.
std::vector<TargetCheck> evaluateTargets(const std::vector<StudyRow>& accuracy,
                                         const std::vector<ScalingRow>& scaling);
/// A Markdown table of the checks.
std::string targetsMarkdown(const std::vector<TargetCheck>& checks);

} // namespace resect
