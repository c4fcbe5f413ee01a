// resect: the command-line twin of Resect Studio. See DESIGN.md "Command line".
#include "app/cli/cli_common.h"

#include <QCoreApplication>

#include <cstdio>
#include <exception>
#include <string>
#include <vector>

namespace {

const char* kUsage = R"(usage: resect COMMAND [options]

commands:
  info MESH                         JSON summary of a tet mesh: format, counts, quality,
                                    dropped elements, physical groups
  convert MESH --out OUT [--mesh-format KEY]
                                    a tet mesh into another format
  mesh (SURFACE | --sample NAME) --out OUT [--edge-length L] [--repair] [--seed N]
      [--min-dihedral 10] [--protect-features [--feature-angle 60]] [--no-volume-match]
      [--report R.json]
                                    tetrahedralize a closed surface (any format assimp
                                    reads) or a built-in sample (polyp, myoma) into a
                                    coarse mesh (default edge length: a few hundred to a
                                    few thousand tets); re-meshed with the next seed until
                                    every dihedral angle is >= --min-dihedral; boundary
                                    nodes moved so the volume is the surface's; sharp
                                    edges kept only with --protect-features (CAD input)
  demo [--out DIR] [--sample NAME]  headless demo: mesh a sample, print its quality,
                                    write the mesh, surface and summary to DIR
  cut MESH --sweep S.json [--sweep S2.json ...] --out OUT [--report R.json]
      [--method hybrid|subdivision] [--triangulation enhanced|standard] [--d 0.2] [--snap|--no-snap]
      [--relax-steps N] [--w-spring W] [--w-particle W] [--surface HI_RES --surface-out OUT.obj]
      [--improve on|off] [--improve-quality Q] [--improve-short-edge S]
      [--fix-box x0 y0 z0 x1 y1 z1 [--resected remove|keep] [--resected-out CHIPS.vtu]]
                                    cut along one or more sweep surfaces, one after another;
                                    hybrid snaps and relaxes (10 steps) unless told not to;
                                    the tets around each cut are improved (collapses,
                                    smoothing) unless --improve off; with --fix-box, pieces
                                    left without a node in the box are resected (removed)
  simulate MESH --steps N --out OUT [--report R.json] [--dt S]
      [--integrator explicit|implicit|velocity-verlet] [--effects deformation,gravity,...]
      [--fix-box x0 y0 z0 x1 y1 z1] [--damping C] [--tool x,y,z,... --tool-radius R]
      [--threads N] [--resected rigid|remove|deformable]
                                    run the tissue model (effects: deformation, gravity,
                                    fixed, damping, tool-contact); dt defaults to the stable
                                    explicit step; exit 1 if it diverged (report still written);
                                    with --fix-box, pieces off the box are resected (rigid)
  table1 [--sample polyp|myoma ...] [--d 0.2] [--out TABLE.md]
                                    the paper's Table 1 on the built-in samples
  run SCENARIO.json [--report R.json]
                                    replay the scenario's strokes, cuts and simulation and
                                    check its expectations (exit 3 if one fails; exit 1 if
                                    a cut fails: the replay stops there, report still written)
  export SCENARIO.json --out DIR [--force]
                                    a self-contained trainer package (meshes, glTF surfaces,
                                    the expert's result, manifest with SHA-256)
  bench [--quick] --out DIR [--no-plots]
                                    what accuracy costs in time: DIR/accuracy_time.csv,
                                    scaling.csv, summary.md (targets, run time) and PNG
                                    plots (drawn by resect-plot, under xvfb-run -a if
                                    DISPLAY is unset); --quick: a few minutes. Exit 1 if
                                    the plots cannot be drawn (the CSVs are still written)
  bench cut-scaling [--sizes 10000,100000,1000000] [--repeats 7] [--out scaling.csv]
                                    the same local cut on meshes of growing size
  bench sim [--sizes 10000,100000,1000000] [--threads 1,2] [--steps N] [--shuffle]
                                    cost of one explicit simulation step per tet (--shuffle:
                                    also numbered at random, and reordered along a curve)
  bench surface [--details 1,5]     embedded surface: bind, apply, re-bind, cut (myoma
                                    surface at 40k x detail triangles)
  bench resection --out DIR [--sample polyp,myoma|none] [--surface PATH ...] [--passes 20]
      [--no-plots]                  a whole resection: K = 1..passes loop scoops with
                                    subdivision, hybrid and hybrid + improvement; per pass
                                    tets, worst radius ratio, shortest edge, stable dt, ms:
                                    DIR/resection.csv, resection.md, resection.png
  bench realtime --out DIR [--quick] [--sizes 1000,10000,100000] [--scoops 12] [--no-plots]
                                    real-time factor (simulated s per wall s) of projective
                                    dynamics (5 and 1 iterations), backward Euler and explicit
                                    Euler at 1 ms and 1/60 s on the samples, the samples after
                                    loop scoops and boxes of --sizes tets; refactorisation
                                    after a cut, peak memory: DIR/realtime.csv, .md, .png

tet mesh files (MESH, OUT): .vtu (VTK XML), .msh (Gmsh 2.2 / 4.1, ASCII / binary), .vtk
(legacy VTK), .mesh (Medit), .node/.ele (TetGen); read by extension and header, written
by OUT's extension in its default format, or in --mesh-format KEY: vtu, msh41 (.msh
default), msh41-binary, msh22, msh22-binary, vtk (binary, .vtk default), vtk-ascii,
medit, tetgen. An unknown extension is refused before any work.

exit codes: 0 success, 2 bad input, 1 internal failure (also: simulate diverged; run: a
cut failed, the report still written), 3 run: an expectation failed (stays_finite for a
divergence)
)";

} // namespace

int main(int argc, char** argv) {
    using namespace resect::cli;
    QCoreApplication app(argc, argv);  // for Qt's JSON and file helpers; no event loop
    std::vector<std::string> args(argv + 1, argv + argc);
    if (args.empty() || args[0] == "--help" || args[0] == "-h" || args[0] == "help") {
        std::fputs(kUsage, args.empty() ? stderr : stdout);
        return args.empty() ? kBadInput : kOk;
    }
    const std::string command = args[0];
    args.erase(args.begin());
    try {
        if (command == "info")
            return runInfo(Args(args));
        if (command == "convert")
            return runConvert(Args(args));
        if (command == "mesh")
            return runMesh(Args(args));
        if (command == "demo")
            return runDemo(Args(args));
        if (command == "cut")
            return runCut(Args(args));
        if (command == "simulate")
            return runSimulate(Args(args));
        if (command == "table1")
            return runTable1(Args(args));
        if (command == "run")
            return runRun(Args(args));
        if (command == "export")
            return runExport(Args(args));
        if (command == "bench")
            return runBench(Args(args));
        throw CliError{kBadInput, "unknown command '" + command + "' (try resect --help)"};
    } catch (const CliError& e) {
        std::fprintf(stderr, "resect %s: %s\n", command.c_str(), e.message.c_str());
        return e.code;
    } catch (const std::bad_alloc&) {
        std::fprintf(stderr, "resect %s: out of memory\n", command.c_str());
        return kInternal;
    } catch (const std::exception& e) {
        std::fprintf(stderr, "resect %s: internal error: %s\n", command.c_str(), e.what());
        return kInternal;
    } catch (...) {
        std::fprintf(stderr, "resect %s: internal error\n", command.c_str());
        return kInternal;
    }
}
