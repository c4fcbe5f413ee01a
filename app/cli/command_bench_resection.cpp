// resect bench resection [--sample polyp,myoma] [--surface PATH ...] [--passes 20] --out DIR
//                        [--no-plots]
// A whole resection, pass by pass (issue 16): K loop scoops (K = 1..passes; resectionScoop in
// core/sweep/stroke_shapes.h, each pull turned by the golden angle and a little deeper) through
// Tissue::cut, the tissue anchored at the bottom 5 % of its height and resected pieces removed,
// with three methods:
//   subdivision     the baseline (standard face triangulation, no improvement);
//   hybrid          the paper's pipeline alone (enhanced, d = 0.2, snapping, 10 relaxation
//                   steps; no improvement);
//   hybrid+improve  the product's defaults (the same and the improvement step).
// Meshes: the built-in samples (meshed as `resect mesh --sample` does) and scanned surfaces
// (any format loadAnatomy reads, meshed at the default edge length). After every pass the
// remaining tissue is measured: tets, worst radius ratio (3 r_in / R_circ), shortest edge
// (reference), stable explicit time step (stable_time_step.h), the pass's wall time
// (TissueCut::totalMs), the chips resected so far, the ratios to the input's values, and the
// tissue's overlap with itself (deepestOverlap, core/mesh/validity.h: the depth of the boundary
// node deepest inside a tet it is not a corner of; `overlap` in mm, `overlap_rel` in the
// input's mean edges; issue 16's known defect where both walls of a crack stay).
// A failed cut is recorded (status "failed", the tissue as it was) and ends that series only.
//
// Writes DIR/resection.csv (one row per mesh, method and pass), DIR/resection.md (inputs;
// per mesh and method the values after pass 1, 10 and 20 and the minimum of the ratios over
// all passes) and DIR/resection.png (drawn by resect-plot --resection, as `resect bench` draws
// its plots). Exit codes: 0 all written; 2 bad input (nothing written); 1 a plot could not be
// drawn (the CSV and the markdown are written all the same).
#include "app/cli/bench_common.h"
#include "app/cli/plotter.h"

#include "core/mesh/quality.h"
#include "core/mesh/stable_time_step.h"
#include "core/mesh/validity.h"
#include "core/mesh/topology.h"
#include "core/mesher/samples.h"
#include "core/sweep/stroke_shapes.h"
#include "core/tissue/tissue.h"
#include "scenario/anatomy.h"

#include <QCoreApplication>
#include <QDir>
#include <QFileInfo>
#include <QProcess>
#include <QStandardPaths>
#include <QThread>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <limits>
#include <sstream>
#include <thread>

namespace resect::cli {
namespace {

constexpr int kDefaultPasses = 20;
constexpr int kMaxPasses = 100;
/// Anchored: nodes in the bottom kAnchorFraction of the body's height (and a margin around).
constexpr double kAnchorFraction = 0.05;
/// Where the scoops pass the polyp: its head, where the leaning stalk ends (x, y; mm;
/// core/mesher/samples.cpp); other bodies are scooped around their bounding box's centre.
const Vec3 kPolypAxis(1.2, 0.5, 0);
/// The passes the markdown table reports (those up to --passes, and the last one).
constexpr int kReportedPasses[] = {1, 10, 20};

/// Commas and line breaks would break a CSV cell or a markdown row.
std::string cellText(std::string s) {
    for (char& c : s)
        if (c == ',' || c == '\n' || c == '\r' || c == '|')
            c = ';';
    return s;
}

// ---------------------------------------------------------------- inputs

struct Method {
    const char* name;
    CutOptions options;
};

const Method kMethods[] = {
    {"subdivision", CutOptions{.method = CutMethod::Subdivision,
                               .triangulation = FaceTriangulation::Standard,
                               .improve = false}},
    {"hybrid", CutOptions{.snap = true, .relaxSteps = 10, .improve = false}},
    {"hybrid+improve", CutOptions{.snap = true, .relaxSteps = 10}},
};

struct Request {
    std::vector<std::string> samples;
    std::vector<std::string> surfaces;
    int passes = kDefaultPasses;
    std::string out;
    bool plots = true;
};

Request parseRequest(Args& args) {
    Request r;
    const std::vector<std::string> sampleLists = args.options("--sample");
    r.surfaces = args.options("--surface");
    r.passes = args.integer("--passes", 1, kMaxPasses).value_or(kDefaultPasses);
    r.out = args.option("--out").value_or("");
    r.plots = !args.flag("--no-plots");
    const auto rest = args.positionals();
    args.finish();
    if (!rest.empty())
        badInput("unexpected argument '" + rest.front() +
                 "' (meshes are given with --sample and --surface)");
    if (r.out.empty())
        badInput("--out DIR is required");
    if (sampleLists.empty())
        r.samples = {"polyp", "myoma"};
    for (const std::string& list : sampleLists) {
        std::stringstream ss(list);
        std::string name;
        while (std::getline(ss, name, ',')) {
            if (name == "none")
                continue;
            if (!sampleFromName(name)) {
                std::string known;
                for (const std::string& n : sampleNames())
                    known += (known.empty() ? "" : ", ") + n;
                badInput("--sample: unknown sample '" + name + "' (known: " + known + ", or none)");
            }
            if (std::find(r.samples.begin(), r.samples.end(), name) == r.samples.end())
                r.samples.push_back(name);
        }
    }
    if (r.samples.empty() && r.surfaces.empty())
        badInput("no mesh to cut: --sample none needs at least one --surface PATH");
    const QFileInfo outInfo(QString::fromStdString(r.out));
    if (outInfo.exists() && !outInfo.isDir())
        badInput("--out: " + r.out + " exists and is not a folder");
    return r;
}

} // namespace

/// The notes are printed only once every body is meshed, so that bad input stays one line.
std::vector<Body> loadBodies(const std::vector<std::string>& samples,
                             const std::vector<std::string>& surfaces, const char* who) {
    struct Source {
        std::string source, name, option; // option: where a bad source came from
        TriangleSurface surface;
    };
    std::vector<Source> sources;
    for (const std::string& sample : samples) // names checked by the caller
        sources.push_back({"sample:" + sample, sample, "--sample", {}});
    for (const std::string& path : surfaces) {
        const QFileInfo info(QString::fromStdString(path));
        if (!info.isFile() || !info.isReadable())
            badInput("--surface: " + path + ": cannot read (not a readable file)");
        sources.push_back({path, info.completeBaseName().toStdString(), "--surface", {}});
    }
    for (Source& source : sources)
        if (Status s = loadAnatomy(source.source, source.surface); !s.ok())
            badInput(source.option + ": " + s.message());

    std::vector<Body> bodies;
    std::string notes;
    for (Source& source : sources) {
        const auto t0 = std::chrono::steady_clock::now();
        Body body;
        std::string log;
        if (Status s = meshAnatomy(source.surface, AnatomyMeshing{}, body.mesh, &log); !s.ok())
            badInput(source.option + " " + source.source + ": " + s.message());
        body.name = cellText(source.name);
        while (std::any_of(bodies.begin(), bodies.end(),
                           [&](const Body& b) { return b.name == body.name; }))
            body.name += '-' + std::to_string(bodies.size() + 1); // two surfaces of the same name
        const auto [lo, hi] = boundingBox(body.mesh.positions());
        body.axis = source.source == "sample:polyp" ? kPolypAxis : Vec3(0.5 * (lo + hi));
        body.meshSeconds = secondsSince(t0);
        notes += std::string(who) + " meshed " + body.name + ": " + std::to_string(body.mesh.tetCount()) +
                 " tets in " + format("%.1f s", body.meshSeconds) + "\n" + log;
        bodies.push_back(std::move(body));
    }
    std::fputs(notes.c_str(), stderr);
    return bodies;
}

Tissue anchoredTissue(const Body& body) {
    const auto [lo, hi] = boundingBox(body.mesh.positions());
    FixedSelection anchors;
    const Vec3 margin = Vec3::Constant(0.01 * (hi - lo).norm());
    anchors.box = std::array<Vec3, 2>{
        lo - margin, Vec3(hi.x(), hi.y(), lo.z() + kAnchorFraction * (hi.z() - lo.z())) + margin};
    Tissue tissue;
    if (Status s = Tissue::create(body.mesh, {}, Material{}, anchors, tissue); !s.ok())
        badInput(body.name + ": " + s.message());
    tissue.setResectedPieces(ResectedPieces::Remove);
    return tissue;
}

Status cutScoop(Tissue& tissue, const Body& body, int k, const CutOptions& options, TissueCut* out) {
    const auto [lo, hi] = boundingBox(body.mesh.positions());
    SweepSurface sweep;
    Status s = SweepSurface::fromCurves(
        loopScoop(resectionScoop(Eigen::AlignedBox3d(lo, hi), body.axis, k)), sweep);
    return s.ok() ? tissue.cut(sweep, options, out) : s;
}

namespace {

// ---------------------------------------------------------------- passes

/// What is measured on the remaining tissue.
struct Measures {
    int tets = 0;
    double worstRatio = 0;   ///< smallest radius ratio 3 r_in / R_circ
    double shortestEdge = 0; ///< reference configuration
    double stableDt = 0;     ///< s, stableTimeStep()
    double meanEdge = 0;     ///< reference configuration
    /// Depth of the boundary node deepest inside a tet it is not a corner of (deepestOverlap,
    /// reference configuration): the tissue overlapping itself, 0 up to rounding when it does not.
    double overlap = 0;
};

Measures measure(const TetMesh& mesh, const Material& material) {
    Measures m;
    m.tets = mesh.tetCount();
    m.worstRatio = summarizeQuality(mesh).minRadiusRatio;
    m.shortestEdge = std::numeric_limits<double>::infinity();
    double sum = 0;
    std::size_t count = 0;
    for (const auto& e : uniqueEdges(mesh)) {
        const double length = (mesh.ref(e[0]) - mesh.ref(e[1])).norm();
        m.shortestEdge = std::min(m.shortestEdge, length);
        sum += length;
        ++count;
    }
    m.meanEdge = count ? sum / static_cast<double>(count) : 0;
    m.stableDt = stableTimeStep(mesh, material).dt;
    m.overlap = deepestOverlap(mesh).depth;
    return m;
}

struct PassRow {
    std::string mesh, method;
    int pass = 0;
    std::string failure; ///< empty: the cut succeeded
    Measures after, input;
    double ms = 0; ///< the pass's wall time (the whole cut)
    int chips = 0; ///< pieces resected so far
    double tetsRel() const { return static_cast<double>(after.tets) / input.tets; }
    double ratioRel() const { return after.worstRatio / input.worstRatio; }
    double edgeRel() const { return after.shortestEdge / input.shortestEdge; }
    double dtRel() const { return after.stableDt / input.stableDt; }
    /// The overlap in the input's mean edges.
    double overlapRel() const { return input.meanEdge > 0 ? after.overlap / input.meanEdge : 0; }
};

/// One series: `passes` scoops with one method on a copy of `start`; stops at a failed cut.
std::vector<PassRow> runSeries(const Body& body, const Tissue& start, const Measures& input,
                               const Method& method, int passes) {
    Tissue tissue(start);
    std::vector<PassRow> rows;
    for (int k = 0; k < passes; ++k) {
        PassRow row;
        row.mesh = body.name;
        row.method = method.name;
        row.pass = k + 1;
        row.input = input;
        TissueCut cut;
        const auto t0 = std::chrono::steady_clock::now();
        const Status s = cutScoop(tissue, body, k, method.options, &cut);
        row.ms = s.ok() ? cut.totalMs : 1e3 * secondsSince(t0);
        row.failure = s.ok() ? "" : cellText(s.message());
        row.after = measure(tissue.mesh(), tissue.material()); // as it was, if the cut failed
        row.chips = static_cast<int>(tissue.chips().size());
        rows.push_back(row);
        if (!s.ok()) {
            std::fprintf(stderr, "[resection] %s / %s: pass %d failed (%s); the series stops\n",
                         body.name.c_str(), method.name, k + 1, row.failure.c_str());
            break;
        }
    }
    return rows;
}

// ---------------------------------------------------------------- outputs

std::string resectionCsv(const std::vector<PassRow>& rows) {
    std::string s =
        "mesh,method,pass,status,tets,worst_ratio,shortest_edge,stable_dt,ms,chips,tets_rel,"
        "worst_ratio_rel,shortest_edge_rel,stable_dt_rel,input_tets,input_worst_ratio,"
        "input_shortest_edge,input_stable_dt,overlap,overlap_rel,message\n";
    for (const PassRow& r : rows)
        s += r.mesh + "," + r.method + "," + std::to_string(r.pass) + "," +
             (r.failure.empty() ? "ok" : "failed") + "," + std::to_string(r.after.tets) + "," +
             format("%.6g", r.after.worstRatio) + "," + format("%.6g", r.after.shortestEdge) + "," +
             format("%.6g", r.after.stableDt) + "," + format("%.6g", r.ms) + "," +
             std::to_string(r.chips) + "," + format("%.6g", r.tetsRel()) + "," +
             format("%.6g", r.ratioRel()) + "," + format("%.6g", r.edgeRel()) + "," +
             format("%.6g", r.dtRel()) + "," + std::to_string(r.input.tets) + "," +
             format("%.6g", r.input.worstRatio) + "," + format("%.6g", r.input.shortestEdge) + "," +
             format("%.6g", r.input.stableDt) + "," + format("%.6g", r.after.overlap) + "," +
             format("%.6g", r.overlapRel()) + "," + r.failure + "\n";
    return s;
}

std::string inputsMarkdown(const std::vector<Body>& bodies, const std::vector<Measures>& inputs) {
    std::string s =
        "| mesh | tets | worst radius ratio | shortest edge | stable dt (s) | meshing (s) |\n"
        "|---|---:|---:|---:|---:|---:|\n";
    for (std::size_t i = 0; i < bodies.size(); ++i)
        s += "| " + bodies[i].name + " | " + std::to_string(inputs[i].tets) + " | " +
             format("%.4f", inputs[i].worstRatio) + " | " + format("%.4g", inputs[i].shortestEdge) +
             " | " + format("%.3g", inputs[i].stableDt) + " | " +
             format("%.2f", bodies[i].meshSeconds) + " |\n";
    return s;
}

/// Per mesh and method: the rows after the reported passes, and the minimum of the ratios.
std::string passesMarkdown(const std::vector<PassRow>& rows, int passes) {
    std::vector<int> reported;
    for (int p : kReportedPasses)
        if (p <= passes)
            reported.push_back(p);
    if (reported.back() != passes)
        reported.push_back(passes);
    std::string s = "| mesh | method | pass | tets | tets / input | worst ratio | / input | "
                    "shortest edge | / input | "
                    "stable dt (s) | / input | ms | chips | overlap (mean edges) |\n"
                    "|---|---|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|\n";
    std::string failures;
    for (std::size_t begin = 0; begin < rows.size();) {
        std::size_t end = begin;
        while (end < rows.size() && rows[end].mesh == rows[begin].mesh &&
               rows[end].method == rows[begin].method)
            ++end;
        double minTets = INFINITY, minRatio = INFINITY, minEdge = INFINITY, minDt = INFINITY, maxOverlap = 0;
        for (std::size_t i = begin; i < end; ++i) {
            const PassRow& r = rows[i];
            minTets = std::min(minTets, r.tetsRel());
            minRatio = std::min(minRatio, r.ratioRel());
            minEdge = std::min(minEdge, r.edgeRel());
            minDt = std::min(minDt, r.dtRel());
            maxOverlap = std::max(maxOverlap, r.overlapRel());
            if (!r.failure.empty())
                failures += "- " + r.mesh + " / " + r.method + ": the cut of pass " +
                            std::to_string(r.pass) + " failed (" + r.failure +
                            "); the series stopped there.\n";
            if (std::find(reported.begin(), reported.end(), r.pass) == reported.end() &&
                r.failure.empty())
                continue;
            s += "| " + r.mesh + " | " + r.method + " | " + std::to_string(r.pass) +
                 (r.failure.empty() ? "" : " (failed)") + " | " + std::to_string(r.after.tets) +
                 " | " + format("%.3g", r.tetsRel()) + " | " + format("%.4g", r.after.worstRatio) +
                 " | " + format("%.3g", r.ratioRel()) + " | " +
                 format("%.4g", r.after.shortestEdge) + " | " + format("%.3g", r.edgeRel()) +
                 " | " + format("%.3g", r.after.stableDt) + " | " + format("%.3g", r.dtRel()) +
                 " | " + format("%.1f", r.ms) + " | " + std::to_string(r.chips) + " | " +
                 format("%.2g", r.overlapRel()) + " |\n";
        }
        s += "| " + rows[begin].mesh + " | " + rows[begin].method + " | min over " +
             std::to_string(end - begin) + " | | " + format("%.3g", minTets) + " | | " +
             format("%.3g", minRatio) + " | | " + format("%.3g", minEdge) + " | | " +
             format("%.3g", minDt) + " | | | max " + format("%.2g", maxOverlap) + " |\n";
        begin = end;
    }
    return failures.empty() ? s : s + "\n" + failures;
}

// ---------------------------------------------------------------- plots


} // namespace

int runBenchResection(Args& args) {
    const Request request = parseRequest(args);
    const auto t0 = std::chrono::steady_clock::now();
    const std::vector<Body> bodies = loadBodies(request.samples, request.surfaces, "[resection]");
    std::vector<Tissue> starts; // all before the folder is made: nothing written on bad input
    for (const Body& body : bodies)
        starts.push_back(anchoredTissue(body));
    const double meshingSeconds = secondsSince(t0);
    const QString dir = QString::fromStdString(request.out);
    if (!QDir().mkpath(dir))
        badInput("--out: cannot create the folder " + request.out);
    const std::string base = QDir(dir).absolutePath().toStdString();

    std::vector<PassRow> rows;
    std::vector<Measures> inputs;
    std::string timings;
    for (std::size_t b = 0; b < bodies.size(); ++b) {
        const Body& body = bodies[b];
        const Tissue& start = starts[b];
        inputs.push_back(measure(start.mesh(), start.material()));
        for (const Method& method : kMethods) {
            const auto ts = std::chrono::steady_clock::now();
            const std::vector<PassRow> series =
                runSeries(body, start, inputs.back(), method, request.passes);
            rows.insert(rows.end(), series.begin(), series.end());
            const double seconds = secondsSince(ts);
            std::fprintf(stderr, "[resection] %s / %s: %zu passes in %.1f s\n", body.name.c_str(),
                         method.name, series.size(), seconds);
            timings += (timings.empty() ? "" : ", ") + body.name + " / " + method.name + " " +
                       format("%.1f s", seconds);
        }
    }
    const double totalSeconds = secondsSince(t0);
    writeText(base + "/resection.csv", resectionCsv(rows));

    const CutOptions& hybrid = kMethods[1].options;
    std::string md =
        "# resect bench resection\n\n" + std::to_string(request.passes) +
        " loop scoops (resectionScoop) per mesh and method through Tissue::cut, anchored at the "
        "bottom " +
        format("%g", 100 * kAnchorFraction) +
        " % of the height, resected pieces removed. Methods: " +
        "subdivision (standard triangulation); hybrid (enhanced, d = " + format("%g", hybrid.d) +
        ", snapping, " + std::to_string(hybrid.relaxSteps) +
        " relaxation steps); hybrid+improve (the "
        "same and the improvement step: the product's defaults). Ratios are to the input mesh. "
        "Measured on the remaining tissue after each pass; ms is the pass's wall time.\n\n" +
        "Run time " + format("%.1f s", totalSeconds) + " (meshing " +
        format("%.1f s", meshingSeconds) + "; " + timings +
        "); hardware threads: " + std::to_string(std::thread::hardware_concurrency()) +
        ".\n\n## Inputs\n\n" + inputsMarkdown(bodies, inputs) + "\n## Passes\n\n" +
        passesMarkdown(rows, request.passes);
    writeText(base + "/resection.md", md);
    std::printf("%s", md.c_str());
    std::fflush(stdout);

    if (!request.plots)
        return kOk;
    const QString qbase = QString::fromStdString(base);
    if (const std::string why =
            runPlotter({"--resection", qbase + "/resection.csv", "--out", qbase}, "resect bench resection");
        !why.empty())
        throw CliError{kInternal,
                       "resection.csv and resection.md are written, but no plot: " + why +
                           " (draw it later with resect-plot --resection, or pass --no-plots)"};
    return kOk;
}

} // namespace resect::cli
