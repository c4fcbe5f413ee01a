// resect bench sim [--sizes 10000,100000,1000000] [--threads 1,2] [--steps N] [--shuffle]
// Cost of one explicit step (symplectic Euler, deformation with all three terms) per tet, on
// Kuhn box meshes of growing size with unit cells. Not a test: it prints the figures.
// The time step is given explicitly (no eigenvalue estimate runs on the large meshes; the
// step's cost does not depend on its length): that of the Gershgorin bound of a small box
// with the same cells, which holds for any box of these cells and is never above the limit
// (the estimate of the small box is not: it grows with the box, by 6 % from 8^3 to 32^3 cells).
// --shuffle also runs each box numbered at random (as a mesher's output is) and that numbering
// after reorderForLocality (what the mesher now does): the cost of memory order.
#include "app/cli/cli_common.h"

#include "core/mesh/box_mesh.h"
#include "core/mesh/masses.h"
#include "core/mesh/reorder.h"
#include "core/mesh/stable_time_step.h"
#include "core/sim/deformation_effect.h"
#include "core/sim/simulator.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <numeric>
#include <random>
#include <sstream>

#include <time.h>

namespace resect::cli {
namespace {

std::vector<int> parseList(Args& args, const std::string& name, std::vector<int> fallback, long lo,
                           long hi) {
    const auto text = args.option(name);
    if (!text)
        return fallback;
    std::vector<int> values;
    std::stringstream ss(*text);
    std::string item;
    while (std::getline(ss, item, ',')) {
        char* end = nullptr;
        const long v = std::strtol(item.c_str(), &end, 10);
        if (end == item.c_str() || *end != 0 || v < lo || v > hi)
            badInput(name + ": expected whole numbers in [" + std::to_string(lo) + ", " +
                     std::to_string(hi) + "], got '" + item + "'");
        values.push_back(static_cast<int>(v));
    }
    if (values.empty())
        badInput(name + ": empty list");
    return values;
}

/// CPU time of the whole process (all threads), ms.
double processCpuMs() {
    timespec t{};
    clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
    return 1e3 * static_cast<double>(t.tv_sec) + 1e-6 * static_cast<double>(t.tv_nsec);
}

/// n^3 unit cubes of six tets, a box as close to `tets` as a cube allows, slightly deformed.
TetMesh benchMesh(int tets) {
    const int n = std::max(1, static_cast<int>(std::lround(std::cbrt(tets / 6.0))));
    TetMesh mesh = makeBoxTetMesh(Vec3::Zero(), Vec3::Constant(n), n, n, n);
    computeLumpedMasses(mesh, Material{}.density);
    std::mt19937 rng(1);
    std::uniform_real_distribution<double> u(-0.01, 0.01);
    for (Vec3& p : mesh.positions())
        p += Vec3(u(rng), u(rng), u(rng));
    return mesh;
}

/// The mesh with its nodes and tets numbered at random.
TetMesh shuffled(const TetMesh& mesh) {
    std::mt19937 rng(7);
    std::vector<int> newNode(mesh.nodeCount()), newTet(mesh.tetCount());
    std::iota(newNode.begin(), newNode.end(), 0);
    std::iota(newTet.begin(), newTet.end(), 0);
    std::shuffle(newNode.begin(), newNode.end(), rng);
    std::shuffle(newTet.begin(), newTet.end(), rng);
    std::vector<Vec3> ref(mesh.nodeCount());
    for (int n = 0; n < mesh.nodeCount(); ++n)
        ref[newNode[n]] = mesh.ref(n);
    std::vector<Tet> tets(mesh.tetCount());
    for (int t = 0; t < mesh.tetCount(); ++t) {
        Tet q = mesh.tet(t);
        for (int& v : q)
            v = newNode[v];
        tets[newTet[t]] = q;
    }
    TetMesh out = TetMesh::fromArrays(std::move(ref), std::move(tets));
    for (int n = 0; n < mesh.nodeCount(); ++n)
        out.positions()[newNode[n]] = mesh.pos(n);
    computeLumpedMasses(out, Material{}.density);
    return out;
}

} // namespace

int runBenchSim(Args& args) {
    const std::vector<int> sizes =
        parseList(args, "--sizes", {10000, 100000, 1000000}, 6, 20000000);
    const std::vector<int> threadCounts = parseList(args, "--threads", {1, 2}, 1, 256);
    const auto steps = args.integer("--steps", 1, 100000);
    const bool shuffle = args.flag("--shuffle");
    args.finish();

    double dt = 0;
    {
        TetMesh small = benchMesh(6 * 512);
        StableTimeStepOptions bound;
        bound.areaTerm = true;   // the deformation effect's terms
        bound.maxIterations = 0; // the Gershgorin bound's step
        dt = stableTimeStep(small, Material{}, bound).dt;
    }
    std::printf(
        "explicit step (symplectic Euler; deformation: distance, volume, area), dt = %.4g s\n", dt);
    std::printf(
        "per step: the fastest and the median wall time, and the process CPU time divided by the\n"
        "threads (cpu_ms; what the wall time would be on an idle machine if the threads share the\n"
        "work evenly; run with OMP_WAIT_POLICY=passive so that waiting threads do not spin).\n"
        "deformation_ms and other_ms: mean wall time in the deformation effect and outside it.\n");
    std::printf("%10s %10s %10s %10s %8s %7s %9s %10s %9s %11s %11s %11s %15s %9s\n", "order", "tets", "nodes",
                "edges", "threads", "steps", "min_ms", "median_ms", "cpu_ms", "ns_tet_min",
                "ns_tet_med", "ns_tet_cpu", "deformation_ms", "other_ms");
    std::vector<std::string> orders{"box"};
    if (shuffle)
        orders.insert(orders.end(), {"shuffled", "reordered"});
    for (int target : sizes) {
        for (const std::string& order : orders) {
            TetMesh base = benchMesh(target);
            if (order != "box")
                base = shuffled(base);
            if (order == "reordered")
                reorderForLocality(base);
            for (int threads : threadCounts) {
                TetMesh mesh = base;
                SimulatorOptions options;
                options.threads = threads;
                options.dt = dt;
                Simulator sim(mesh, Material{}, options);
                requireOk(sim.addEffect("deformation"));
                const int edges = static_cast<DeformationEffect*>(sim.findEffect("deformation"))
                                      ->model()
                                      .liveEdgeCount();
                const int n =
                    steps.value_or(std::clamp(static_cast<int>(3e7 / mesh.tetCount()), 5, 2000));
                for (int s = 0; s < 3; ++s) // warm-up: buffers, first touch, caches
                    if (Status st = sim.step(); !st.ok())
                        throw CliError{kInternal, st.message()};
                std::vector<double> ms;
                double deformation = 0;
                const double cpu0 = processCpuMs();
                for (int s = 0; s < n; ++s) {
                    const auto t0 = std::chrono::steady_clock::now();
                    if (Status st = sim.step(); !st.ok())
                        throw CliError{kInternal, st.message()};
                    ms.push_back(
                        std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0)
                            .count());
                    deformation += sim.lastStep().effects[0].ms;
                }
                const double cpu = (processCpuMs() - cpu0) / n / sim.threads();
                std::sort(ms.begin(), ms.end());
                const double median = ms[ms.size() / 2];
                double mean = 0;
                for (double v : ms)
                    mean += v;
                mean /= static_cast<double>(ms.size());
                deformation /= n; // mean per step, like other_ms
                std::printf(
                    "%10s %10d %10d %10d %8d %7d %9.3f %10.3f %9.3f %11.2f %11.2f %11.2f %15.3f %9.3f\n",
                    order.c_str(), mesh.tetCount(), mesh.nodeCount(), edges, sim.threads(), n, ms.front(), median, cpu,
                    1e6 * ms.front() / mesh.tetCount(), 1e6 * median / mesh.tetCount(),
                    1e6 * cpu / mesh.tetCount(), deformation, mean - deformation);
                std::fflush(stdout);
            }
        }
    }
    return kOk;
}

} // namespace resect::cli
