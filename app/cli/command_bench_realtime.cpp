// resect bench realtime --out DIR [--quick] [--sizes 1000,10000,100000] [--scoops 12]
//                       [--no-plots]
// How fast the tissue model runs against the clock (issue 17, item 5). A benchmark, not a test:
// it prints and writes the figures and judges nothing but the goals below.
//
// Every case simulates an anchored tissue (the bottom 5 % of its height fixed, as `resect bench
// resection` anchors it: bench_common.h) under gravity with the deformation model, through
// Tissue (its simulation: effects deformation, gravity, fixed) and measures the real-time factor,
// simulated seconds per wall second, at a step h of 1 ms (a haptic trainer's rate) and of
// 1/60 s (a display's), with
//   projective-dynamics  the product's implicit integrator (projective_dynamics.h), at its
//                        default iterations and at 1 iteration;
//   backward-euler       the linearised backward Euler with conjugate gradients, up to
//                        kBackwardEulerMaxTets tets (above, one step takes seconds);
//   symplectic-euler     the explicit integrator at the simulator's default step (its stable
//                        estimate, Simulator::timeStep()); its real-time factor does not depend
//                        on the frame step: covering a frame takes frame / step sub-steps.
// Meshes: Kuhn boxes of unit cubes (box_mesh.h) of about --sizes tets, named box-SIZE; the
// samples polyp and myoma as the product meshes them; and the samples after --scoops
// intersecting loop scoops of a resection (the product's cut options, resected pieces removed),
// named SAMPLE-Kscoops.
//
// One step runs before the clock starts (the first factorisation of projective dynamics, its
// factor_ms; buffers); then steps run until the case has simulated kFull.simulatedS or spent
// kFull.wallS of wall time, whichever comes first (kQuick with --quick), at least one. For
// projective dynamics one more scoop is then cut through the running simulation and one step
// taken: refactor_ms is the factorisation that step needed (Simulator::applyCut invalidated
// it). peak_rss_mb is the process's peak resident memory during the case (Linux: the peak is
// reset before each case through /proc/self/clear_refs; getrusage's ru_maxrss after it), the
// loaded tissue and the process's own included.
//
// Writes DIR/realtime.csv (one row per case: mesh, tets, nodes, integrator, iterations (PD only),
// dt (s, the step taken), steps (timed), wall_s, realtime_factor, ms_per_step, factor_ms,
// peak_rss_mb, diverged (0/1), refactor_ms, simulated_s, threads; factor_ms and refactor_ms are
// empty where not measured), DIR/realtime.md (real-time factors per mesh and
// integrator, the goals and whether they are met) and DIR/realtime.png (resect-plot --realtime).
// Exit codes: 0 all written; 2 bad input (nothing written); 1 the plot could not be drawn (the
// CSV and the markdown are written all the same).
#include "app/cli/bench_common.h"
#include "app/cli/plotter.h"

#include "core/mesh/box_mesh.h"

#include <QDir>
#include <QFileInfo>
#include <QString>
#include <QStringList>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <limits>
#include <thread>

#include <malloc.h>
#include <sys/resource.h>

namespace resect::cli {
namespace {

/// The frame steps measured (s): a haptic trainer's 1 ms and a display's 1/60 s.
constexpr double kFrameSteps[] = {0.001, 1.0 / 60};
constexpr int kDefaultScoops = 12;
constexpr int kMaxScoops = 100;
/// Backward Euler is measured up to this many tets (at 100k one step takes seconds).
constexpr int kBackwardEulerMaxTets = 20000;
/// A case runs until it has simulated simulatedS or spent wallS of wall time (at least a step).
struct Budget {
    double wallS;
    double simulatedS;
};
constexpr Budget kFull{2.0, 1.0}, kQuick{0.2, 0.05};
const std::vector<int> kFullSizes{1000, 10000, 100000}, kQuickSizes{1000, 10000};
const std::vector<std::string> kSamples{"polyp", "myoma"};
constexpr double kNan = std::numeric_limits<double>::quiet_NaN();

/// "" for NaN (a value that was not measured), else printf's rendering.
std::string cell(const char* f, double v) {
    return std::isnan(v) ? "" : format(f, v);
}

// ---------------------------------------------------------------- memory

/// Returns freed memory to the system and resets the process's peak resident set to what is
/// resident now (Linux: /proc/self/clear_refs); without that, peakMemoryMb() is the peak of the
/// whole run so far.
void resetPeakMemory() {
    malloc_trim(0);
    std::ofstream("/proc/self/clear_refs") << "5";
}

/// The process's peak resident memory (MB) since the last resetPeakMemory().
double peakMemoryMb() {
    rusage usage{};
    getrusage(RUSAGE_SELF, &usage);
    return static_cast<double>(usage.ru_maxrss) / 1024.0; // kB on Linux
}

/// The system's 1-minute load average (Linux: /proc/loadavg), or NaN: wall times on a shared
/// machine are only as good as it is idle.
double loadAverage() {
    double load = kNan;
    std::ifstream("/proc/loadavg") >> load;
    return load;
}

// ---------------------------------------------------------------- request

struct Request {
    std::vector<int> sizes;
    int scoops = kDefaultScoops;
    Budget budget = kFull;
    bool quick = false;
    std::string out;
    bool plots = true;
};

Request parseRequest(Args& args) {
    Request r;
    r.quick = args.flag("--quick");
    r.budget = r.quick ? kQuick : kFull;
    r.sizes = r.quick ? kQuickSizes : kFullSizes;
    if (const auto text = args.option("--sizes")) {
        r.sizes.clear();
        for (const QString& item : QString::fromStdString(*text).split(',')) {
            bool ok = false;
            const int v = item.toInt(&ok);
            if (!ok || v < 6 || v > 2000000)
                badInput("--sizes: expected tet counts between 6 and 2000000, got '" +
                         item.toStdString() + "'");
            r.sizes.push_back(v);
        }
    }
    r.scoops = args.integer("--scoops", 0, kMaxScoops).value_or(kDefaultScoops);
    r.out = args.option("--out").value_or("");
    r.plots = !args.flag("--no-plots");
    const auto rest = args.positionals();
    args.finish();
    if (!rest.empty())
        badInput("unexpected argument '" + rest.front() + "'");
    if (r.out.empty())
        badInput("--out DIR is required");
    const QFileInfo outInfo(QString::fromStdString(r.out));
    if (outInfo.exists() && !outInfo.isDir())
        badInput("--out: " + r.out + " exists and is not a folder");
    return r;
}

// ---------------------------------------------------------------- workloads

/// A tissue to simulate: anchored, perhaps already cut; the scoops continue on `body`.
struct Workload {
    std::string name;
    const Body* body = nullptr;
    Tissue start;
    int scoops = 0; ///< scoops cut so far (the next one measures the refactorisation)
};

/// n^3 unit cubes of six tets, n the cube root of tets / 6 rounded; its axis through the centre.
Body boxBody(int tets) {
    const int n = std::max(1, static_cast<int>(std::lround(std::cbrt(tets / 6.0))));
    Body body;
    body.name = "box-" + std::to_string(tets);
    body.mesh = makeBoxTetMesh(Vec3::Zero(), Vec3::Constant(n), n, n, n);
    body.axis = Vec3::Constant(0.5 * n);
    return body;
}

/// The body's anchored tissue after `scoops` scoops (the product's cut options); a failed scoop
/// ends the series there (noted on stderr, the name tells how many were cut).
Workload scooped(const Body& body, const Tissue& fresh, int scoops) {
    Workload w{"", &body, Tissue(fresh), 0};
    for (; w.scoops < scoops; ++w.scoops)
        if (Status s = cutScoop(w.start, body, w.scoops, CutOptions{}, nullptr); !s.ok()) {
            std::fprintf(stderr, "[realtime] %s: scoop %d failed (%s); simulating after %d\n",
                         body.name.c_str(), w.scoops + 1, s.message().c_str(), w.scoops);
            break;
        }
    w.name = body.name + "-" + std::to_string(w.scoops) + "scoops";
    return w;
}

// ---------------------------------------------------------------- cases

struct Case {
    Integrator integrator;
    int iterations = 0; ///< projective dynamics: local-global iterations per step
    double dt = 0;      ///< s; 0: the simulator's default (the explicit stable step)
};

std::vector<Case> casesFor(int tets) {
    std::vector<Case> cases;
    for (double dt : kFrameSteps) {
        cases.push_back({Integrator::ProjectiveDynamics, ProjectiveDynamicsOptions{}.iterations, dt});
        cases.push_back({Integrator::ProjectiveDynamics, 1, dt});
        if (tets <= kBackwardEulerMaxTets)
            cases.push_back({Integrator::BackwardEuler, 0, dt});
    }
    cases.push_back({Integrator::SymplecticEuler, 0, 0});
    return cases;
}

struct Row {
    std::string mesh;
    int tets = 0, nodes = 0, threads = 0;
    Case run;
    double dt = 0; ///< the step taken (s)
    int steps = 0; ///< timed
    double simulated = 0, wall = 0;      ///< s, of the timed steps
    double factorMs = kNan, refactorMs = kNan; ///< projective dynamics
    double peakMb = 0;
    bool diverged = false;
    double factor() const { return wall > 0 ? simulated / wall : 0; }
    double msPerStep() const { return steps > 0 ? 1e3 * wall / steps : 0; }
};

/// The factorisation (ms) after one more scoop through the running projective-dynamics
/// simulation: the cut, then the step that re-factors. NaN if the cut or the step failed.
double refactorAfterCut(Tissue& tissue, const Workload& w, double h) {
    const int before = tissue.simulator()->projectiveStats()->factorizations;
    TissueCut cut;
    if (Status s = cutScoop(tissue, *w.body, w.scoops, CutOptions{}, &cut); !s.ok()) {
        std::fprintf(stderr, "[realtime] %s: the scoop after the run failed (%s): no refactor_ms\n",
                     w.name.c_str(), s.message().c_str());
        return kNan;
    }
    if (!tissue.step(h).ok())
        return kNan;
    const ProjectiveDynamicsStats& stats = *tissue.simulator()->projectiveStats();
    // a rebuilt simulation (pieces resected) starts counting anew
    return cut.simulationRebuilt || stats.factorizations > before ? stats.factorMs : kNan;
}

Row runCase(const Workload& w, const Case& run, const Budget& budget) {
    resetPeakMemory();
    Tissue tissue(w.start);
    SimulationSetup setup;
    setup.options.integrator = run.integrator;
    if (run.iterations > 0)
        setup.options.projective.iterations = run.iterations;
    setup.effects = {"deformation", "gravity", "fixed"};
    if (Status s = tissue.startSimulation(setup); !s.ok())
        throw CliError{kInternal, w.name + ": " + s.message()};
    Simulator& sim = *tissue.simulator();
    Row row{w.name, tissue.mesh().tetCount(), tissue.mesh().nodeCount(), sim.threads(), run};
    row.dt = run.dt > 0 ? run.dt : sim.timeStep();
    Status s = tissue.step(row.dt); // warm-up: the first factorisation, buffers
    if (s.ok()) {
        if (const ProjectiveDynamicsStats* pd = sim.projectiveStats())
            row.factorMs = pd->factorMs;
        const double t0 = sim.time();
        const auto start = std::chrono::steady_clock::now();
        while (s.ok() && (row.steps == 0 || (sim.time() - t0 < budget.simulatedS &&
                                             secondsSince(start) < budget.wallS))) {
            s = tissue.step(row.dt);
            row.steps += s.ok();
        }
        row.wall = secondsSince(start);
        row.simulated = sim.time() - t0;
    }
    row.diverged = !s.ok();
    if (row.diverged)
        std::fprintf(stderr, "[realtime] %s / %s: diverged (%s)\n", w.name.c_str(),
                     integratorName(run.integrator), s.message().c_str());
    else if (run.integrator == Integrator::ProjectiveDynamics)
        row.refactorMs = refactorAfterCut(tissue, w, row.dt);
    row.peakMb = peakMemoryMb();
    return row;
}

// ---------------------------------------------------------------- outputs

std::string iterationsText(const Row& r) {
    return r.run.iterations > 0 ? std::to_string(r.run.iterations) : "";
}

std::string realtimeCsv(const std::vector<Row>& rows) {
    std::string s = "mesh,tets,nodes,integrator,iterations,dt,steps,wall_s,realtime_factor,"
                    "ms_per_step,factor_ms,peak_rss_mb,diverged,refactor_ms,simulated_s,threads\n";
    for (const Row& r : rows)
        s += r.mesh + "," + std::to_string(r.tets) + "," + std::to_string(r.nodes) + "," +
             integratorName(r.run.integrator) + "," + iterationsText(r) + "," +
             format("%.6g", r.dt) + "," + std::to_string(r.steps) + "," + format("%.6g", r.wall) +
             "," + format("%.6g", r.factor()) + "," + format("%.6g", r.msPerStep()) + "," +
             cell("%.6g", r.factorMs) + "," + format("%.1f", r.peakMb) + "," +
             (r.diverged ? "1" : "0") + "," + cell("%.6g", r.refactorMs) + "," +
             format("%.6g", r.simulated) + "," + std::to_string(r.threads) + "\n";
    return s;
}

/// The row of a mesh and case, or null.
const Row* find(const std::vector<Row>& rows, const std::string& mesh, const Case& c) {
    for (const Row& r : rows)
        if (r.mesh == mesh && r.run.integrator == c.integrator && r.run.iterations == c.iterations &&
            r.run.dt == c.dt)
            return &r;
    return nullptr;
}

std::string factorText(const Row* r) {
    if (!r)
        return "-";
    return format(r->factor() < 10 ? "%.2gx" : "%.0fx", r->factor()) +
           (r->diverged ? " (diverged)" : "");
}

std::string stepLabel(double dt) {
    return dt == kFrameSteps[0] ? "1 ms" : dt == kFrameSteps[1] ? "1/60 s" : format("%g s", dt);
}

/// "| a | b |\n"
std::string markdownRow(const std::vector<std::string>& cells) {
    std::string s = "|";
    for (const std::string& c : cells)
        s.append(" ").append(c).append(" |");
    return s + "\n";
}

/// One row per mesh: the real-time factors of every case, the factorisation costs, the memory.
std::string factorsMarkdown(const std::vector<Row>& rows, const std::vector<std::string>& meshes) {
    const int iterations = ProjectiveDynamicsOptions{}.iterations;
    std::vector<std::pair<std::string, Case>> columns;
    for (double dt : kFrameSteps) {
        columns.push_back({"PD " + std::to_string(iterations) + " it, " + stepLabel(dt),
                           {Integrator::ProjectiveDynamics, iterations, dt}});
        columns.push_back({"PD 1 it, " + stepLabel(dt), {Integrator::ProjectiveDynamics, 1, dt}});
        columns.push_back({"BE, " + stepLabel(dt), {Integrator::BackwardEuler, 0, dt}});
    }
    columns.push_back({"explicit (its step)", {Integrator::SymplecticEuler, 0, 0}});
    std::vector<std::string> header{"mesh", "tets"}, rule{"---", "---:"};
    for (const auto& [title, c] : columns)
        header.push_back(title);
    header.insert(header.end(), {"explicit step (s)", "factor ms", "refactor ms after a cut", "peak MB"});
    rule.resize(header.size(), "---:");
    std::string s = markdownRow(header) + markdownRow(rule);
    for (const std::string& mesh : meshes) {
        const Row* any = nullptr;
        double peak = 0;
        for (const Row& r : rows)
            if (r.mesh == mesh) {
                any = &r;
                peak = std::max(peak, r.peakMb);
            }
        if (!any)
            continue;
        std::vector<std::string> cells{mesh, std::to_string(any->tets)};
        for (const auto& [title, c] : columns)
            cells.push_back(factorText(find(rows, mesh, c)));
        const Row* expl = find(rows, mesh, columns.back().second);
        const Row* pd = find(rows, mesh, columns.front().second);
        cells.push_back(expl ? format("%.2g", expl->dt) : "-");
        cells.push_back(pd ? cell("%.3g", pd->factorMs) : "-");
        cells.push_back(pd ? cell("%.3g", pd->refactorMs) : "-");
        cells.push_back(format("%.0f", peak));
        s += markdownRow(cells);
    }
    return s;
}

/// Issue 17's goals: the real-time factor of projective dynamics at its default iterations and
/// at 1 iteration on the meshes each goal names.
std::string goalsMarkdown(const std::vector<Row>& rows, const std::vector<std::string>& samples,
                          const std::vector<std::string>& scoopedSamples) {
    struct Goal {
        std::string what;
        std::vector<std::string> meshes;
        double dt, factor;
    };
    const std::vector<Goal> goals{
        {"samples at 1 ms", samples, kFrameSteps[0], 20},
        {"10k tets at 1 ms", {"box-10000"}, kFrameSteps[0], 1},
        {"100k tets at 1/60 s", {"box-100000"}, kFrameSteps[1], 1},
        {"after the scoops at 1 ms", scoopedSamples, kFrameSteps[0], 10}};
    const int iterations = ProjectiveDynamicsOptions{}.iterations;
    std::string s = markdownRow({"goal", "mesh", "PD " + std::to_string(iterations) + " iterations",
                                 "PD 1 iteration"}) +
                    markdownRow({"---", "---", "---", "---"});
    for (const Goal& goal : goals)
        for (const std::string& mesh : goal.meshes) {
            std::vector<std::string> cells{goal.what + ": >= " + format("%g", goal.factor) + "x", mesh};
            for (int it : {iterations, 1}) {
                const Row* r = find(rows, mesh, {Integrator::ProjectiveDynamics, it, goal.dt});
                const bool met = r && r->factor() >= goal.factor && !r->diverged;
                cells.push_back(r ? factorText(r) + (met ? " met" : " **not met**") : "not run");
            }
            s += markdownRow(cells);
        }
    return s;
}

void printRow(const Row& r) {
    std::printf("%-18s %7d %-20s %3s %9.4g %6d %8.3f %9.3g %10.3g %9s %11s %8.0f%s\n",
                r.mesh.c_str(), r.tets, integratorName(r.run.integrator), iterationsText(r).c_str(),
                r.dt, r.steps, r.wall, r.factor(), r.msPerStep(), cell("%.3g", r.factorMs).c_str(),
                cell("%.3g", r.refactorMs).c_str(), r.peakMb, r.diverged ? "  DIVERGED" : "");
    std::fflush(stdout);
}

} // namespace

int runBenchRealtime(Args& args) {
    const Request request = parseRequest(args);
    const auto t0 = std::chrono::steady_clock::now();
    const double loadBefore = loadAverage();
    const std::vector<Body> samples = loadBodies(kSamples, {}, "[realtime]");
    const QString dir = QString::fromStdString(request.out);
    if (!QDir().mkpath(dir))
        badInput("--out: cannot create the folder " + request.out);
    const std::string base = QDir(dir).absolutePath().toStdString();

    std::printf("%-18s %7s %-20s %3s %9s %6s %8s %9s %10s %9s %11s %8s\n", "mesh", "tets",
                "integrator", "it", "dt", "steps", "wall_s", "rt_factor", "ms_per_step",
                "factor_ms", "refactor_ms", "peak_MB");
    std::vector<Row> rows;
    std::vector<std::string> meshes, sampleNames, scoopedNames;
    const auto run = [&](const Workload& w) {
        meshes.push_back(w.name);
        for (const Case& c : casesFor(w.start.mesh().tetCount())) {
            rows.push_back(runCase(w, c, request.budget));
            printRow(rows.back());
        }
    };
    for (const Body& body : samples) {
        const Workload fresh{body.name, &body, anchoredTissue(body), 0};
        run(fresh);
        sampleNames.push_back(fresh.name);
        if (request.scoops > 0) {
            const Workload cut = scooped(body, fresh.start, request.scoops);
            run(cut);
            scoopedNames.push_back(cut.name);
        }
    }
    for (int size : request.sizes) {
        const Body body = boxBody(size);
        run(Workload{body.name, &body, anchoredTissue(body), 0});
    }
    const double seconds = secondsSince(t0);
    writeText(base + "/realtime.csv", realtimeCsv(rows));
    const std::string md =
        "# resect bench realtime\n\nReal-time factor (simulated s per wall s) of the anchored "
        "tissue under gravity, deformation model; PD projective dynamics, BE backward Euler, "
        "explicit symplectic Euler at its stable step (the simulator's default). Run time " +
        format("%.0f s", seconds) + (request.quick ? " (--quick)" : "") + "; hardware threads " +
        std::to_string(std::thread::hardware_concurrency()) + ", simulation threads " +
        std::to_string(rows.empty() ? 0 : rows.front().threads) + "; load average " +
        format("%.1f", loadBefore) + " at the start, " + format("%.1f", loadAverage()) +
        " at the end.\n\n" +
        factorsMarkdown(rows, meshes) + "\n## Goals\n\n" +
        goalsMarkdown(rows, sampleNames, scoopedNames);
    writeText(base + "/realtime.md", md);
    std::printf("\n%s", md.c_str());
    std::fflush(stdout);

    if (!request.plots)
        return kOk;
    const QString qbase = QString::fromStdString(base);
    if (const std::string why = runPlotter({"--realtime", qbase + "/realtime.csv", "--out", qbase},
                                           "resect bench realtime");
        !why.empty())
        throw CliError{kInternal,
                       "realtime.csv and realtime.md are written, but no plot: " + why +
                           " (draw it later with resect-plot --realtime, or pass --no-plots)"};
    return kOk;
}

} // namespace resect::cli
