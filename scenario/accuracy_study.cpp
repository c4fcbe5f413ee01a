#include "scenario/accuracy_study.h"

#include "core/cut/hybrid_cutter.h"
#include "core/embed/embedded_surface.h"
#include "core/mesh/box_mesh.h"
#include "core/mesh/masses.h"
#include "core/mesh/quality.h"
#include "core/mesh/stable_time_step.h"
#include "core/mesher/tetrahedralize.h"
#include "core/sim/simulator.h"
#include "core/tissue/tissue.h"
#include "scenario/anatomy.h"
#include "scenario/cut_study.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <limits>
#include <random>

namespace resect {

const char* studyMethodName(StudyMethod method) {
    switch (method) {
    case StudyMethod::Subdivision: return "subdivision";
    case StudyMethod::HybridStandard: return "hybrid-standard";
    case StudyMethod::HybridEnhanced: return "hybrid-enhanced";
    }
    return "?";
}

namespace {

std::vector<StudyMesh> sampleMeshes(double fineScale) {
    return {{"polyp", Sample::Polyp, 1.0, 0.35},
            {"myoma", Sample::Myoma, 1.0, 0.55},
            {"myoma-fine", Sample::Myoma, fineScale, 0.55}};
}

const std::vector<StudyMethod> kAllMethods{StudyMethod::Subdivision, StudyMethod::HybridStandard,
                                           StudyMethod::HybridEnhanced};

} // namespace

StudyConfig tinyConfig() {
    StudyConfig c;
    c.label = "tiny";
    c.meshes = {{"myoma", Sample::Myoma, 1.0, 0.55}};
    c.methods = kAllMethods;
    c.dValues = {0.0, 0.2, 0.5};
    c.snapOptions = {false, true};
    c.relaxSteps = {0, 10};
    c.repeats = 1;
    c.simSteps = 2;
    c.scalingSizes = {3000, 24000};
    c.scalingRepeats = 1;
    c.scalingMaxSteps = 5;
    c.surfaceUpdates = 1;
    c.surfaceTrianglesPerTet = 0.5;
    return c;
}

StudyConfig quickConfig() {
    StudyConfig c;
    c.label = "quick";
    c.meshes = sampleMeshes(0.5);
    c.methods = kAllMethods;
    c.dValues = {0.0, 0.1, 0.2, 0.3, 0.4, 0.5};
    c.snapOptions = {false, true};
    c.relaxSteps = {0, 10, 30};
    c.repeats = 5;
    c.simSteps = 10;
    c.scalingSizes = {10000, 100000, 1000000};
    c.scalingRepeats = 3;
    c.scalingMaxSteps = 40;
    c.surfaceUpdates = 5;
    return c;
}

StudyConfig fullConfig() {
    StudyConfig c = quickConfig();
    c.label = "full";
    c.dValues.clear();
    for (int i = 0; i <= 10; ++i)
        c.dValues.push_back(0.05 * i);
    c.repeats = 15;
    c.simSteps = 50;
    c.scalingSizes = {10000, 30000, 100000, 300000, 1000000};
    c.scalingRepeats = 7;
    c.scalingMaxSteps = 400;
    c.surfaceUpdates = 15;
    return c;
}

namespace {

using Clock = std::chrono::steady_clock;

double msSince(Clock::time_point t0) {
    return std::chrono::duration<double, std::milli>(Clock::now() - t0).count();
}

double median(std::vector<double> v) {
    if (v.empty())
        return std::numeric_limits<double>::quiet_NaN();
    std::sort(v.begin(), v.end());
    const std::size_t n = v.size();
    return n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}

double minimum(const std::vector<double>& v) {
    return v.empty() ? std::numeric_limits<double>::quiet_NaN() : *std::min_element(v.begin(), v.end());
}

double minRadiusRatio(const TetMesh& mesh) {
    double r = std::numeric_limits<double>::infinity();
    for (const Tet& t : mesh.tets())
        r = std::min(r, radiusRatio(mesh.ref(t[0]), mesh.ref(t[1]), mesh.ref(t[2]), mesh.ref(t[3])));
    return r;
}

/// Progress with cancellation, counting units of work.
class Ticker {
public:
    Ticker(const StudyProgress& progress, double total) : m_progress(progress), m_total(std::max(1.0, total)) {}
    /// False if the caller cancelled.
    bool report(const std::string& stage) const {
        return !m_progress || m_progress(std::clamp(m_done / m_total, 0.0, 1.0), stage);
    }
    void advance(double units = 1) { m_done += units; }

private:
    const StudyProgress& m_progress;
    double m_total;
    double m_done = 0;
};

Status cancelled() { return Status::error("cancelled"); }

/// Wall-time statistics of `steps` explicit steps after two warm-up steps; false if a step
/// failed (message in `error`).
struct StepTimes {
    double medianMs = 0, minMs = 0;
};
Status timeSteps(Simulator& sim, int steps, double h, StepTimes& out) {
    for (int s = 0; s < 2; ++s)
        if (Status st = sim.step(h); !st.ok())
            return st;
    std::vector<double> ms;
    ms.reserve(steps);
    for (int s = 0; s < steps; ++s) {
        const auto t0 = Clock::now();
        if (Status st = sim.step(h); !st.ok())
            return st;
        ms.push_back(msSince(t0));
    }
    out.medianMs = median(ms);
    out.minMs = minimum(ms);
    return Status::success();
}

/// Small deterministic displacements (a fraction of the mean edge), so that the timed steps
/// see non-zero forces.
void perturb(TetMesh& mesh, double amplitude) {
    std::mt19937 rng(1);
    std::uniform_real_distribution<double> u(-amplitude, amplitude);
    for (Vec3& p : mesh.positions())
        p += Vec3(u(rng), u(rng), u(rng));
}

struct Variant {
    StudyMethod method;
    double d;
    bool snap;
    int relax;
};

std::vector<Variant> variantsOf(const StudyConfig& config) {
    std::vector<Variant> out;
    for (StudyMethod m : config.methods)
        for (double d : config.dValues) {
            if (m == StudyMethod::Subdivision) {
                out.push_back({m, d, false, 0});
                continue;
            }
            for (bool snap : config.snapOptions)
                for (int relax : config.relaxSteps)
                    out.push_back({m, d, snap, relax});
        }
    return out;
}

Status validate(const StudyConfig& c) {
    if (c.repeats < 1 || c.simSteps < 1 || c.simThreads < 1 || c.scalingRepeats < 1 ||
        c.scalingMaxSteps < 1 || c.surfaceUpdates < 1)
        return Status::error("study configuration: repeats, steps and threads must be at least 1");
    for (double d : c.dValues)
        if (!(d >= 0 && d <= 0.5))
            return Status::error("study configuration: d must lie in [0, 0.5]");
    for (int r : c.relaxSteps)
        if (r < 0)
            return Status::error("study configuration: relaxation steps must not be negative");
    for (int n : c.scalingSizes)
        if (n < 6)
            return Status::error("study configuration: scaling sizes must be at least 6 tets");
    return Status::success();
}

/// One row: cut copies of `base` (with its bound surface) `repeats` times, then measure the
/// last result.
Status measureVariant(const StudyConfig& config, const StudyMesh& meshInfo, const Tissue& base,
                      const SweepSurface& sweep, double baseMinRatio,
                      const Variant& v, const Ticker& ticker, StudyRow& row) {
    CutOptions options;
    options.method = v.method == StudyMethod::Subdivision ? CutMethod::Subdivision : CutMethod::Hybrid;
    options.triangulation =
        v.method == StudyMethod::HybridEnhanced ? FaceTriangulation::Enhanced : FaceTriangulation::Standard;
    options.d = v.d;
    options.snap = v.snap;
    options.relaxSteps = v.relax;
    // The variants are the paper's settings: what each costs and gives in one cut, without the
    // mesh improvement the defaults add after it (step 7 of Tissue::cut; see bench resection).
    options.improve = false;
    options.density = config.material.density;

    row = StudyRow{};
    row.mesh = meshInfo.name;
    row.meshTets = base.mesh().tetCount();
    row.meshMinRadiusRatio = baseMinRatio;
    row.method = studyMethodName(v.method);
    row.d = v.d;
    row.snap = v.snap;
    row.relaxSteps = v.relax;
    row.surfaceTriangles = base.surface().surface().triangleCount();

    std::vector<double> cutMs, surfaceMs, totalMs;
    TetMesh mesh;
    TissueCut result;
    const double meanEdge = base.meanEdgeLength();
    for (int r = 0; r < config.repeats; ++r) {
        if (!ticker.report(meshInfo.name + ": " + row.method))
            return cancelled();
        // A fresh copy of the loaded tissue (grid, unit of d and bound surface: built once per
        // loaded mesh, not timed).
        Tissue tissue(base);
        if (Status s = tissue.cut(sweep, options, &result); !s.ok())
            return Status::error(meshInfo.name + ", " + row.method + ", d = " + formatNumber(v.d) + ": " + s.message());
        cutMs.push_back(result.tets.timeMs.total);
        surfaceMs.push_back(result.surfaceMs);
        totalMs.push_back(result.totalMs);
        if (r + 1 == config.repeats)
            mesh = std::move(tissue).takeMesh();
    }
    row.cutMs = median(cutMs);
    row.cutMsMin = minimum(cutMs);
    row.surfaceMs = median(surfaceMs);
    row.totalMs = median(totalMs);
    row.tets = mesh.tetCount();
    row.addedTets = result.tets.addedTets;
    row.cutNodes = result.tets.cutNodes;
    row.snappedNodes = result.tets.snappedNodes;
    row.minRadiusRatio = minRadiusRatio(mesh);

    // Accuracy: the nodes of the cut faces against the sweep, in units of the mean edge.
    const auto& nodes = result.changes.cutSurfaceNodes;
    row.cutSurfaceNodes = static_cast<int>(nodes.size());
    double sum = 0, worst = 0;
    for (int n : nodes) {
        const double dist = sweep.closestPoint(mesh.ref(n)).distance / meanEdge;
        sum += dist;
        worst = std::max(worst, dist);
    }
    row.sweepErrorMax = worst;
    row.sweepErrorMean = nodes.empty() ? 0.0 : sum / static_cast<double>(nodes.size());

    // Cost of simulating the result: explicit steps at its stable time step.
    perturb(mesh, 1e-3 * meanEdge);
    SimulatorOptions simOptions;
    simOptions.threads = config.simThreads;
    Simulator sim(mesh, config.material, simOptions);
    if (Status s = sim.addEffect("deformation"); !s.ok())
        return s;
    row.stableDt = sim.stableTimeStep();
    // Steps of the stable estimate, which the simulator sub-steps where the configuration
    // needs it (simulator.h; a fixed step at the estimate made the slivers of a subdivided
    // myoma diverge within 50 steps in the full study): the time per step is the time per
    // stable step of simulated time.
    StepTimes steps;
    if (Status s = timeSteps(sim, config.simSteps, sim.timeStep(), steps); !s.ok())
        return Status::error(meshInfo.name + ", " + row.method + ": simulation: " + s.message());
    row.simMsPerStep = steps.medianMs;
    row.simMsPerSecond = steps.medianMs / row.stableDt;
    return Status::success();
}

} // namespace

namespace {

/// Every variant of the configuration on one loaded tissue (its surface following its tets)
/// with its sweep; one ticker unit per row.
Status studyMesh(const StudyConfig& config, const StudyMesh& meshInfo, const Tissue& base, const SweepSurface& sweep,
                 const std::vector<Variant>& variants, Ticker& ticker, std::vector<StudyRow>& rows) {
    const double baseMinRatio = minRadiusRatio(base.mesh());
    for (const Variant& v : variants) {
        StudyRow row;
        if (Status s = measureVariant(config, meshInfo, base, sweep, baseMinRatio, v, ticker, row); !s.ok())
            return s;
        rows.push_back(std::move(row));
        ticker.advance();
    }
    return Status::success();
}

} // namespace

Status runAccuracyStudy(const StudyConfig& config, std::vector<StudyRow>& rows, const StudyProgress& progress) {
    rows.clear();
    if (Status s = validate(config); !s.ok())
        return s;
    const std::vector<Variant> variants = variantsOf(config);
    // Units: one per mesh (meshing and binding) and one per row.
    Ticker ticker(progress, static_cast<double>(config.meshes.size() * (variants.size() + 1)));
    for (const StudyMesh& m : config.meshes) {
        if (!ticker.report(m.name + ": meshing"))
            return cancelled();
        TriangleSurface anatomy = sampleSurface(m.sample);
        AnatomyMeshing meshing;
        meshing.material = config.material;
        meshing.meshing.edgeLength = m.edgeScale * defaultEdgeLength(anatomy);
        TetMesh base;
        if (Status s = meshAnatomy(anatomy, meshing, base); !s.ok())
            return Status::error(m.name + ": " + s.message());
        computeLumpedMasses(base, config.material.density);
        const SweepSurface sweep = loopScoopSweep(base, m.cutHeight);
        Tissue tissue;
        if (Status s = Tissue::create(std::move(base), sampleSurface(m.sample, config.surfaceDetail), config.material,
                                      {}, tissue);
            !s.ok())
            return Status::error(m.name + ": embedded surface: " + s.message());
        tissue.updateSurface();  // once here, not in every timed cut
        ticker.advance();
        if (Status s = studyMesh(config, m, tissue, sweep, variants, ticker, rows); !s.ok())
            return s;
    }
    ticker.report("done");
    return Status::success();
}

Status runAccuracyStudyOn(const TetMesh& mesh, const SweepSurface& sweep, const std::string& name,
                          const StudyConfig& config, std::vector<StudyRow>& rows, const StudyProgress& progress,
                          const EmbeddedSurface* surface) {
    rows.clear();
    if (Status s = validate(config); !s.ok())
        return s;
    if (mesh.tetCount() == 0)
        return Status::error(name + ": the mesh has no tets");
    const std::vector<Variant> variants = variantsOf(config);
    // Units: one for preparing the mesh and one per row.
    Ticker ticker(progress, static_cast<double>(variants.size() + 1));
    if (!ticker.report(name + ": preparing"))
        return cancelled();
    StudyMesh info;
    info.name = name;
    TetMesh copy = mesh;
    computeLumpedMasses(copy, config.material.density);
    Tissue base;
    if (Status s = Tissue::create(std::move(copy), surface ? surface->surface() : TriangleSurface{}, config.material,
                                  {}, base);
        !s.ok())
        return Status::error(name + ": " + s.message());
    base.updateSurface();  // once here, not in every timed cut
    ticker.advance();
    if (Status s = studyMesh(config, info, base, sweep, variants, ticker, rows); !s.ok())
        return s;
    ticker.report("done");
    return Status::success();
}

namespace {

} // namespace

int scalingBoxCells(int tets) {
    return std::max(1, static_cast<int>(std::lround(std::cbrt(tets / 6.0))));
}

SweepSurface scalingSweep(int n) {
    const double c = std::floor(0.5 * n);
    const double h = std::min(2.0, 0.4 * n);
    SweepSurface sweep;
    (void)SweepSurface::fromStartEnd({Vec3(c - h, c - h, c + 0.37), Vec3(c + h, c - h, c + 0.41)},
                                     {Vec3(c - h, c + h, c + 0.45), Vec3(c + h, c + h, c + 0.49)},
                                     sweep);  // valid by construction
    return sweep;
}

namespace {

/// The myoma surface scaled into the box [0, n]^3 (80 % of its width), about `triangles`
/// triangles.
TriangleSurface boxSurface(int n, double triangles) {
    TriangleSurface s = sampleSurface(Sample::Myoma, std::max(0.01, triangles / 40000.0));
    const auto [lo, hi] = boundingBox(s.positions);
    const Vec3 centre = 0.5 * (lo + hi);
    constexpr double kWidthFraction = 0.8;  // of the box the surface spans
    const double scale = kWidthFraction * n / (hi - lo).maxCoeff();
    for (Vec3& p : s.positions)
        p = Vec3::Constant(0.5 * n) + scale * (p - centre);
    return s;
}

} // namespace

Status runScalingStudy(const StudyConfig& config, std::vector<ScalingRow>& rows, const StudyProgress& progress) {
    rows.clear();
    if (Status s = validate(config); !s.ok())
        return s;
    // Units: proportional to the mesh size (the large meshes dominate the run time).
    double total = 0;
    for (int size : config.scalingSizes)
        total += size;
    Ticker ticker(progress, total);
    // Time step: given explicitly, so that no eigenvalue estimate runs on the large meshes
    // (the cost of a step does not depend on its length): that of the Gershgorin bound of a
    // small box with the same cells, which holds for any box of these cells and is never above
    // the limit (the small box's estimate is not: it grows with the box).
    double dt = 0;
    {
        const int n = 8;
        TetMesh small = makeBoxTetMesh(Vec3::Zero(), Vec3::Constant(n), n, n, n);
        computeLumpedMasses(small, config.material.density);
        StableTimeStepOptions bound;
        bound.areaTerm = true;   // the deformation effect's terms
        bound.maxIterations = 0; // the Gershgorin bound's step
        dt = stableTimeStep(small, config.material, bound).dt;
    }
    for (int target : config.scalingSizes) {
        const std::string stage = std::to_string(target) + " tets";
        if (!ticker.report(stage + ": cut"))
            return cancelled();
        const int n = scalingBoxCells(target);
        TetMesh base = makeBoxTetMesh(Vec3::Zero(), Vec3::Constant(n), n, n, n);
        computeLumpedMasses(base, config.material.density);
        ScalingRow row;
        row.meshTets = base.tetCount();

        const SweepSurface sweep = scalingSweep(n);
        Tissue baseTissue;
        if (Status s = Tissue::create(base, {}, config.material, {}, baseTissue); !s.ok())
            return Status::error(stage + ": " + s.message());
        std::vector<double> cutMs, hybridMs;
        for (int r = 0; r < config.scalingRepeats; ++r) {
            if (r > 0 && !ticker.report(stage + ": cut"))
                return cancelled();
            Tissue tissue(baseTissue);  // grid and unit of d: built once per mesh, not timed
            TissueCut result;
            if (Status s = tissue.cut(sweep, CutOptions{}, &result); !s.ok())
                return Status::error(stage + ": " + s.message());
            cutMs.push_back(result.totalMs);
            hybridMs.push_back(result.totalMs - result.improveMs);
            row.touchedTets = result.tets.touchedTets;
            row.addedTets = result.tets.addedTets;
        }
        row.cutMs = median(cutMs);
        row.cutMsMin = minimum(cutMs);
        row.usPerTouchedTet = 1000.0 * row.cutMs / std::max(1, row.touchedTets);
        row.usPerTouchedTetHybrid = 1000.0 * median(hybridMs) / std::max(1, row.touchedTets);

        const int steps = std::clamp(static_cast<int>(2e7 / row.meshTets), 5, config.scalingMaxSteps);
        for (int threads : {1, 2}) {
            if (!ticker.report(stage + ": simulation, " + std::to_string(threads) + " thread(s)"))
                return cancelled();
            TetMesh mesh = base;
            perturb(mesh, 0.01);
            SimulatorOptions options;
            options.threads = threads;
            options.dt = dt;
            Simulator sim(mesh, config.material, options);
            if (Status s = sim.addEffect("deformation"); !s.ok())
                return s;
            StepTimes times;
            if (Status s = timeSteps(sim, steps, sim.timeStep(), times); !s.ok())
                return Status::error(stage + ": simulation: " + s.message());
            const double perTet = 1e6 / row.meshTets;
            (threads == 1 ? row.stepNsPerTet1 : row.stepNsPerTet2) = times.medianMs * perTet;
            (threads == 1 ? row.stepNsPerTetMin1 : row.stepNsPerTetMin2) = times.minMs * perTet;
        }

        if (!ticker.report(stage + ": embedded surface"))
            return cancelled();
        EmbeddedSurface surface;
        if (Status s = surface.bind(base, boxSurface(n, config.surfaceTrianglesPerTet * row.meshTets)); !s.ok())
            return Status::error(stage + ": embedded surface: " + s.message());
        row.surfaceVertices = surface.surface().vertexCount();
        std::vector<double> updateMs;
        for (int r = 0; r < config.surfaceUpdates; ++r) {
            const auto t0 = Clock::now();
            surface.update(base);
            updateMs.push_back(msSince(t0));
        }
        row.surfaceUpdateMs = median(updateMs);
        row.surfaceNsPerVertex = 1e6 * row.surfaceUpdateMs / std::max(1, row.surfaceVertices);
        row.surfaceGBps = row.surfaceNsPerVertex > 0 ? SurfaceBinding::kStreamedBytesPerVertex / row.surfaceNsPerVertex : 0;
        rows.push_back(row);
        ticker.advance(target);
    }
    ticker.report("done");
    return Status::success();
}

namespace {

std::string format(const char* f, double v) {
    char buf[64];
    std::snprintf(buf, sizeof buf, f, v);
    return buf;
}

} // namespace

std::string accuracyCsv(const std::vector<StudyRow>& rows) {
    std::string s =
        "mesh,mesh_tets,mesh_min_radius_ratio,method,d,snap,relax_steps,cut_surface_nodes,"
        "sweep_error_max,sweep_error_mean,tets,added_tets,cut_nodes,snapped_nodes,min_radius_ratio,"
        "stable_dt,cut_ms,cut_ms_min,surface_ms,total_ms,surface_triangles,sim_ms_per_step,"
        "sim_ms_per_second\n";
    for (const StudyRow& r : rows) {
        s += r.mesh + "," + std::to_string(r.meshTets) + "," + format("%.6g", r.meshMinRadiusRatio) + "," +
             r.method + "," + format("%.4g", r.d) + "," + (r.snap ? "1" : "0") + "," +
             std::to_string(r.relaxSteps) + "," + std::to_string(r.cutSurfaceNodes) + "," +
             format("%.6g", r.sweepErrorMax) + "," + format("%.6g", r.sweepErrorMean) + "," +
             std::to_string(r.tets) + "," + std::to_string(r.addedTets) + "," + std::to_string(r.cutNodes) + "," +
             std::to_string(r.snappedNodes) + "," + format("%.6g", r.minRadiusRatio) + "," +
             format("%.6g", r.stableDt) + "," + format("%.6g", r.cutMs) + "," + format("%.6g", r.cutMsMin) + "," +
             format("%.6g", r.surfaceMs) + "," + format("%.6g", r.totalMs) + "," +
             std::to_string(r.surfaceTriangles) + "," + format("%.6g", r.simMsPerStep) + "," +
             format("%.6g", r.simMsPerSecond) + "\n";
    }
    return s;
}

std::string scalingCsv(const std::vector<ScalingRow>& rows) {
    std::string s =
        "mesh_tets,touched_tets,added_tets,cut_ms,cut_ms_min,us_per_touched_tet,us_per_touched_tet_hybrid,"
        "step_ns_per_tet_1t,"
        "step_ns_per_tet_2t,step_ns_per_tet_min_1t,step_ns_per_tet_min_2t,surface_vertices,"
        "surface_update_ms,surface_ns_per_vertex,surface_gb_per_s\n";
    for (const ScalingRow& r : rows)
        s += std::to_string(r.meshTets) + "," + std::to_string(r.touchedTets) + "," + std::to_string(r.addedTets) +
             "," + format("%.6g", r.cutMs) + "," + format("%.6g", r.cutMsMin) + "," +
             format("%.6g", r.usPerTouchedTet) + "," + format("%.6g", r.usPerTouchedTetHybrid) + "," +
             format("%.6g", r.stepNsPerTet1) + "," +
             format("%.6g", r.stepNsPerTet2) + "," + format("%.6g", r.stepNsPerTetMin1) + "," +
             format("%.6g", r.stepNsPerTetMin2) + "," + std::to_string(r.surfaceVertices) + "," +
             format("%.6g", r.surfaceUpdateMs) + "," + format("%.6g", r.surfaceNsPerVertex) + "," +
             format("%.6g", r.surfaceGBps) + "\n";
    return s;
}

std::vector<TargetCheck> evaluateTargets(const std::vector<StudyRow>& accuracy,
                                         const std::vector<ScalingRow>& scaling) {
    const double nan = std::numeric_limits<double>::quiet_NaN();
    std::vector<TargetCheck> out;
    const auto add = [&](std::string name, double value, double limit, std::string unit) {
        out.push_back({std::move(name), value, limit, std::move(unit), std::isfinite(value) && value <= limit});
    };
    if (!scaling.empty()) {
        auto [lo, hi] = std::minmax_element(scaling.begin(), scaling.end(),
                                            [](const ScalingRow& a, const ScalingRow& b) { return a.meshTets < b.meshTets; });
        add("cut time per touched tet, " + std::to_string(hi->meshTets) + " tets / " + std::to_string(lo->meshTets) +
                " tets",
            hi->usPerTouchedTet / lo->usPerTouchedTet, 1.5, "x");
        add("cut time per touched tet at " + std::to_string(hi->meshTets) + " tets, without the improvement step",
            hi->usPerTouchedTetHybrid, 10.0, "us");
        add("cut time per touched tet at " + std::to_string(hi->meshTets) + " tets, with the improvement step",
            hi->usPerTouchedTet, 10.0, "us");
        add("explicit step per tet at " + std::to_string(hi->meshTets) + " tets, 2 threads (median)",
            hi->stepNsPerTet2, 10.0, "ns");
        add("explicit step per tet at " + std::to_string(hi->meshTets) + " tets, 2 threads (fastest step)",
            hi->stepNsPerTetMin2, 10.0, "ns");
        add("surface update per vertex at " + std::to_string(hi->surfaceVertices) + " vertices",
            hi->surfaceNsPerVertex, 2.0, "ns");
    }
    for (const char* mesh : {"polyp", "myoma"}) {
        double value = nan;
        int tets = 0, triangles = 0;
        for (const StudyRow& r : accuracy)
            if (r.mesh == mesh && r.method == std::string("hybrid-enhanced") && r.snap && r.relaxSteps == 10 &&
                std::abs(r.d - 0.2) < 1e-9) {
                value = r.totalMs;
                tets = r.meshTets;
                triangles = r.surfaceTriangles;
            }
        if (tets > 0)
            add(std::string("paper's case, ") + mesh + " (" + std::to_string(tets) + " tets, " +
                    std::to_string(triangles) + " surface triangles): cut, snap, relax 10, re-bind",
                value, std::string(mesh) == "polyp" ? 1.0 : 3.0, "ms");  // the myoma's cut is deeper (issue 20)
    }
    return out;
}

std::string targetsMarkdown(const std::vector<TargetCheck>& checks) {
    std::string s = "| target | measured | limit | met |\n|---|---:|---:|---|\n";
    for (const TargetCheck& c : checks)
        s += "| " + c.name + " | " + format("%.3g", c.value) + " " + c.unit + " | " + format("%.3g", c.limit) + " " +
             c.unit + " | " + (c.met ? "yes" : "**no**") + " |\n";
    return s;
}

} // namespace resect
