// resect bench cut-scaling [--sizes 10000,100000,1000000] [--repeats 7] [--out scaling.csv]
// The same local cut on structured meshes of growing size: the cut must cost in proportion to
// the tets it touches, not to the mesh size. The accuracy-versus-time study (`resect bench
// [--quick] --out DIR`) is in command_bench_study.cpp.
#include "app/cli/cli_common.h"

#include "core/mesh/box_mesh.h"
#include "core/mesher/samples.h"
#include "core/mesher/tetrahedralize.h"
#include "core/sim/parallel.h"
#include "core/tissue/tissue.h"
#include "scenario/accuracy_study.h"
#include "scenario/atomic_file.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <sstream>

namespace resect::cli {

namespace {

int runCutScaling(Args& args) {
    std::vector<int> sizes{10000, 100000, 1000000};
    if (auto text = args.option("--sizes")) {
        sizes.clear();
        std::stringstream ss(*text);
        std::string item;
        while (std::getline(ss, item, ',')) {
            char* end = nullptr;
            const long v = std::strtol(item.c_str(), &end, 10);
            if (end == item.c_str() || *end != 0 || v < 6 || v > 20000000)
                badInput("--sizes: expected tet counts between 6 and 2e7, got '" + item + "'");
            sizes.push_back(static_cast<int>(v));
        }
    }
    const int repeats = args.integer("--repeats", 1, 1000).value_or(7);
    const auto out = args.option("--out");
    args.finish();

    std::string csv = "mesh_tets,touched_tets,added_tets,cut_ms_median,cut_ms_min,us_per_touched_tet,"
                      "improve_ms_median,us_per_touched_tet_without_improvement\n";
    std::printf("%10s %12s %10s %14s %12s %18s %18s %18s\n", "mesh_tets", "touched_tets", "added", "cut_ms_median",
                "cut_ms_min", "us_per_touched_tet", "improve_ms_median", "us_without_improve");
    const auto medianOf = [](std::vector<double> v) {
        std::sort(v.begin(), v.end());
        return v[v.size() / 2];
    };
    for (int target : sizes) {
        // n^3 unit cubes of 6 tets each; every mesh sees the same local cut (accuracy_study.h).
        const int n = scalingBoxCells(target);
        const TetMesh base = makeBoxTetMesh(Vec3::Zero(), Vec3::Constant(n), n, n, n);
        const SweepSurface sweep = scalingSweep(n);
        std::vector<double> times, improve, without;
        int touched = 0, added = 0;
        Tissue loaded;  // grid and mean edge: once per loaded mesh, not per cut
        requireOk(Tissue::create(base, {}, Material{}, {}, loaded));
        for (int r = 0; r < repeats; ++r) {
            Tissue tissue(loaded);
            TissueCut result;
            if (Status s = tissue.cut(sweep, CutOptions{}, &result); !s.ok())
                throw CliError{kInternal, s.message()};
            times.push_back(result.totalMs);
            improve.push_back(result.improveMs);
            without.push_back(result.totalMs - result.improveMs);
            touched = result.tets.touchedTets;
            added = result.tets.addedTets;
        }
        const double median = medianOf(times);
        const double perTet = 1000.0 * median / std::max(1, touched);
        const double perTetWithout = 1000.0 * medianOf(without) / std::max(1, touched);
        char line[256];
        std::snprintf(line, sizeof line, "%d,%d,%d,%.4f,%.4f,%.3f,%.4f,%.3f\n", base.tetCount(), touched, added,
                      median, *std::min_element(times.begin(), times.end()), perTet, medianOf(improve),
                      perTetWithout);
        csv += line;
        std::printf("%10d %12d %10d %14.4f %12.4f %18.3f %18.4f %18.3f\n", base.tetCount(), touched, added, median,
                    *std::min_element(times.begin(), times.end()), perTet, medianOf(improve), perTetWithout);
        std::fflush(stdout);
    }
    if (out)
        requireOk(writeFileAtomically(*out, csv));
    return kOk;
}

} // namespace

/// Memory bandwidth of this machine as a STREAM-like copy of two 128 MB arrays (bytes read +
/// written per second, write-allocate not counted), on `threads` threads: the yardstick of the
/// surface update, which streams its arrays once per frame.
double copyBandwidthGBps(int threads) {
    const std::int64_t n = 16 << 20;  // doubles per array
    std::vector<double> a(n, 1.0), b(n, 0.0);
    double best = 1e30;
    for (int r = 0; r < 5; ++r) {
        const auto t0 = std::chrono::steady_clock::now();
        parallelRun(threads, [&](int t) {
            const std::int64_t lo = chunkBegin(n, threads, t), hi = chunkBegin(n, threads, t + 1);
            for (std::int64_t i = lo; i < hi; ++i)
                b[i] = a[i] + 1.0;
        });
        best = std::min(best, std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count());
        std::swap(a, b);
    }
    return 16.0 * n / best / 1e9;
}

/// Embedded-surface costs (section 5): bind once, apply per frame (per vertex, on one and two
/// threads, with the bandwidth it reaches), and after a cut re-bind (per re-bound vertex) and
/// cut the surface, for a myoma surface of growing size.
int runSurface(Args& args) {
    std::vector<double> details{1, 5};
    if (auto text = args.option("--details")) {
        details.clear();
        std::stringstream ss(*text);
        std::string item;
        while (std::getline(ss, item, ',')) {
            char* end = nullptr;
            const double v = std::strtod(item.c_str(), &end);
            if (end == item.c_str() || *end != 0 || !(v > 0) || v > 50)
                badInput("--details: expected numbers in (0, 50], got '" + item + "'");
            details.push_back(v);
        }
    }
    args.finish();
    std::printf("memory bandwidth (copy, as STREAM counts it): %.1f GB/s on 1 thread, %.1f GB/s on 2\n",
                copyBandwidthGBps(1), copyBandwidthGBps(2));
    std::printf("apply streams %d bytes per vertex (tet index, weights w1..w3, position written)\n",
                SurfaceBinding::kStreamedBytesPerVertex);
    std::printf("%10s %10s %12s %10s %10s %10s %10s %16s %14s %12s %12s %12s\n", "triangles", "vertices",
                "create_ms", "apply_ns_1t", "GB/s_1t", "apply_ns_2t", "GB/s_2t", "rebound_vertices", "rebind_us_vtx",
                "near_tris", "surf_cut_ms", "bind_new_ms");
    for (double detail : details) {
        TriangleSurface surface = sampleSurface(Sample::Myoma, detail);
        TetMesh mesh;
        requireOk(tetrahedralize(surface, MeshingOptions{}, mesh));
        const auto ms = [](auto t0) {
            return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
        };
        auto t0 = std::chrono::steady_clock::now();
        Tissue tissue;
        requireOk(Tissue::create(std::move(mesh), std::move(surface), Material{}, {}, tissue));
        const double createMs = ms(t0);  // Tissue::create: masses, spatial index, surface binding
        const int vertices = tissue.surface().surface().vertexCount();
        const int triangles = tissue.surface().surface().triangleCount();
        // Median of 15 updates into a buffer that already has its size (as every frame but the first).
        std::vector<Vec3> scratch;
        tissue.surface().binding().apply(tissue.mesh(), scratch);
        double nsPerVertex[2] = {0, 0};
        for (int threads : {1, 2}) {
            std::vector<double> apply;
            for (int r = 0; r < 15; ++r) {
                t0 = std::chrono::steady_clock::now();
                tissue.surface().binding().apply(tissue.mesh(), scratch, nullptr, threads);
                apply.push_back(ms(t0));
            }
            std::sort(apply.begin(), apply.end());
            nsPerVertex[threads - 1] = 1e6 * apply[apply.size() / 2] / vertices;
        }
        const auto gbps = [](double ns) { return SurfaceBinding::kStreamedBytesPerVertex / ns; };
        const auto [lo, hi] = boundingBox(tissue.mesh().positions());
        const double z = 0.5 * (lo.z() + hi.z()) + 0.013;
        SweepSurface sweep;
        requireOk(SweepSurface::fromStartEnd({Vec3(lo.x() - 5, lo.y() - 5, z), Vec3(hi.x() + 5, lo.y() - 5, z + 0.2)},
                                             {Vec3(lo.x() - 5, hi.y() + 5, z + 0.1), Vec3(hi.x() + 5, hi.y() + 5, z + 0.3)},
                                             sweep));
        tissue.updateSurface();
        TissueCut result;
        requireOk(tissue.cut(sweep, CutOptions{}, &result));
        const EmbeddedCut& cut = result.surface;
        std::printf("%10d %10d %12.1f %10.2f %10.1f %10.2f %10.1f %16d %14.3f %12d %12.2f %12.2f\n", triangles,
                    vertices, createMs, nsPerVertex[0], gbps(nsPerVertex[0]), nsPerVertex[1], gbps(nsPerVertex[1]),
                    cut.reboundVertices, 1e3 * cut.rebindMs / std::max(1, cut.reboundVertices),
                    cut.surface.candidateTriangles, cut.cutMs, cut.bindNewMs);
        std::fflush(stdout);
    }
    return kOk;
}

int runBenchResection(Args& args);  // resect bench resection (command_bench_resection.cpp)
int runBenchRealtime(Args& args);   // resect bench realtime (command_bench_realtime.cpp)

int runBench(Args args) {
    if (args.flag("resection"))
        return runBenchResection(args);
    if (args.flag("realtime"))
        return runBenchRealtime(args);
    if (args.flag("sim"))
        return runBenchSim(args);
    if (args.flag("surface"))
        return runSurface(args);
    if (args.flag("cut-scaling"))
        return runCutScaling(args);
    return runBenchStudy(args);
}

} // namespace resect::cli
