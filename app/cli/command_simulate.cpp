// resect simulate MESH --steps N --out OUT [--mesh-format KEY] [--report R.json] [--dt S]
//     [--integrator explicit|implicit|symplectic-euler|velocity-verlet|projective-dynamics|backward-euler]
//     [--iterations N]
//     [--effects deformation,gravity,...] [--fix-box x0 y0 z0 x1 y1 z1]
//     [--damping C] [--tool x,y,z,x,y,z,... --tool-radius R] [--threads N]
//     [--resected rigid|remove|deformable]
//
// Runs the tissue model (core/sim) for N steps and writes the deformed mesh and a report:
//   {"steps", "requested_steps", "substeps", "dt", "stable_dt", "integrator", "threads", "time_s",
//    "wall_s", "realtime_factor" (simulated s per wall s of the steps),
//    "effects": [{"name", "time_ms"}, ...]   (only the effects run, in run order)
//    implicit only: "iterations", "factorizations", "factor_ms" (the last assembly and
//    factorisation), "halvings" (iterates pulled back because they raised the step's objective),
//    "restarts" (steps started from x instead of x + h v: violent motion),
//    "finite", "max_speed", "kinetic_energy": {"initial", "max", "final"}, "inverted",
//    "error" (only when the simulation diverged),
//    "resected": {"policy", "pieces", "volume", "mass", "mass_before", "mass_remaining"}}
// Units: mm, g, s; speeds in mm/s, energies in g mm^2/s^2. max_speed is the largest node
// speed seen after any step; inverted counts tets with non-positive current volume at the end.
//
// Defaults: effects "deformation", integrator explicit (symplectic Euler), dt the stable
// explicit step of the mesh (also reported as stable_dt), which the simulator splits into
// sub-steps where the deformed tissue needs it ("substeps" counts them all). --fix-box
// anchors the nodes whose reference position lies in the box and adds the "fixed" effect;
// "fixed" without --fix-box, "tool-contact" without --tool, and --damping without "damping"
// are bad input.
// With --fix-box, pieces of the input without a node in the box are resected (a mesh cut with
// `resect cut --resected keep`): by default each falls as one rigid body onto the tissue or
// the plane under the input's lowest point and is written with the tissue where it came to
// rest (rigid),
// or leaves (remove), or is simulated like the rest (deformable).
//
// Exit codes: 0 success; 2 bad input (one line naming the option or file); 1 if the
// simulation diverged: the report is still written, with "finite": false, "steps" the steps
// completed and "error" the simulator's message, and OUT is not written.
#include "app/cli/cli_common.h"

#include "core/mesh/masses.h"
#include "core/mesh/topology.h"
#include "core/sim/anchors.h"
#include "core/sim/simulator.h"
#include "core/tissue/resect_pieces.h"
#include "scenario/mesh_io.h"

#include <QJsonArray>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <sstream>

namespace resect::cli {
namespace {

Integrator integratorOption(const std::string& text) {
    Integrator integrator{};
    if (!parseIntegrator(text, integrator))
        badInput("--integrator: expected explicit, implicit, symplectic-euler, velocity-verlet, "
                 "projective-dynamics or backward-euler, got '" +
                 text + "'");
    return integrator;
}

std::vector<Vec3> parseTool(const std::string& text) {
    std::vector<double> values;
    std::stringstream ss(text);
    std::string item;
    while (std::getline(ss, item, ',')) {
        std::size_t used = 0;
        double v = 0;
        try {
            v = std::stod(item, &used);
        } catch (...) {
            used = 0;
        }
        if (used == 0 || used != item.size() || !std::isfinite(v))
            badInput("--tool: expected finite numbers x,y,z,x,y,z,..., got '" + item + "'");
        values.push_back(v);
    }
    if (values.empty() || values.size() % 3 != 0)
        badInput("--tool: expected a multiple of 3 numbers (points x,y,z of the tool's polyline)");
    std::vector<Vec3> points;
    for (std::size_t i = 0; i < values.size(); i += 3)
        points.emplace_back(values[i], values[i + 1], values[i + 2]);
    return points;
}

int countInverted(const TetMesh& mesh) {
    int inverted = 0;
    for (int t = 0; t < mesh.tetCount(); ++t)
        inverted += !(mesh.currentVolume(t) > 0);
    return inverted;
}

/// A JSON number, or null if not finite (JSON has no NaN).
QJsonValue number(double v) {
    return std::isfinite(v) ? QJsonValue(v) : QJsonValue();
}

} // namespace

int runSimulate(Args args) {
    const int steps = args.integer("--steps", 1, 100000000).value_or(0);
    const auto dt = args.number("--dt", 0.0, 1e6);
    const Integrator integrator = integratorOption(args.option("--integrator").value_or("explicit"));
    const std::string effectList = args.option("--effects").value_or("deformation");
    const auto box = args.numbers("--fix-box", 6, "x0 y0 z0 x1 y1 z1");
    const auto resectedText = args.option("--resected");
    const auto damping = args.number("--damping", 0.0, 1e12);
    const auto toolText = args.option("--tool");
    const auto toolRadius = args.number("--tool-radius", 0.0, 1e12);
    const int threads = args.integer("--threads", 1, 256).value_or(0);
    const auto iterations = args.integer("--iterations", 1, 1000);
    const MeshOutput output = meshOutput(args.requiredOption("--out"), args.option("--mesh-format"));
    const std::string& out = output.path;
    const auto reportPath = args.option("--report");
    const auto files = args.positionals();
    args.finish();
    if (files.size() != 1)
        badInput("expected exactly one MESH file");
    if (steps == 0)
        badInput("--steps is required (a whole number >= 1)");
    if (dt && !(*dt > 0))
        badInput("--dt must be positive, got " + std::to_string(*dt));
    // Pieces of the input holding no node in the fixed box are resected: rigid chips by
    // default, or removed, or simulated as deformable tissue like the rest.
    ResectedPieces resected = ResectedPieces::Rigid;
    if (resectedText) {
        if (!parseResectedPieces(*resectedText, resected) || *resectedText == "keep")
            badInput("--resected: expected rigid, remove or deformable, got '" + *resectedText + "'");
        if (!box)
            badInput("--resected needs --fix-box x0 y0 z0 x1 y1 z1 (the pieces off the box are resected)");
    }

    const EffectRegistry registry = EffectRegistry::withBuiltins();
    std::vector<std::string> effects;
    if (Status s = registry.parseList(effectList, effects); !s.ok())
        badInput("--effects: " + s.message());
    const auto requested = [&](const std::string& name) {
        return std::find(effects.begin(), effects.end(), name) != effects.end();
    };
    EffectSettings settings;
    if (box) {
        const Vec3 lo((*box)[0], (*box)[1], (*box)[2]), hi((*box)[3], (*box)[4], (*box)[5]);
        if ((lo.array() > hi.array()).any())
            badInput("--fix-box: expected x0 <= x1, y0 <= y1, z0 <= z1");
        settings.fixed.box = std::array<Vec3, 2>{lo, hi};
        if (!requested("fixed"))
            effects.push_back("fixed");
    } else if (requested("fixed")) {
        badInput("--effects: 'fixed' needs --fix-box x0 y0 z0 x1 y1 z1");
    }
    if (damping) {
        if (!requested("damping"))
            badInput("--damping: add 'damping' to --effects");
        if (!(*damping > 0))
            badInput("--damping must be positive (1/s), got " + std::to_string(*damping));
        settings.damping = *damping;
    } else if (requested("damping")) {
        badInput("--effects: 'damping' needs --damping C (1/s)");
    }
    if (toolText || toolRadius) {
        if (!toolText || !toolRadius)
            badInput("--tool and --tool-radius go together");
        if (!requested("tool-contact"))
            badInput("--tool: add 'tool-contact' to --effects");
        if (!(*toolRadius > 0))
            badInput("--tool-radius must be positive, got " + std::to_string(*toolRadius));
        settings.tool = Tool{parseTool(*toolText), *toolRadius};
    } else if (requested("tool-contact")) {
        badInput("--effects: 'tool-contact' needs --tool x,y,z,... and --tool-radius R");
    }
    requireDistinctMesh(files[0], out);
    if (reportPath) {
        requireDistinct(files[0], *reportPath);
        if (*reportPath == out)
            badInput("--report and --out name the same file");
    }

    TetMesh mesh;
    MeshReadReport read;
    requireOk(readTetMesh(files[0], mesh, &read));
    printReadNotes(files[0], read);
    std::vector<Chip> chips;
    const double massBefore = sumOfMasses(mesh);
    if (box && resected != ResectedPieces::Keep) {
        Anchors anchors;
        FixedSelection selection;
        selection.box = settings.fixed.box;
        if (Status s = Anchors::create(mesh, selection, anchors); !s.ok())
            badInput("--fix-box: " + s.message());
        const Components pieces = connectedComponents(mesh);
        if (!anchors.empty() && pieces.count > 1) {
            (void)resectPieces(mesh, pieces, anchors, 0, chips);
            for (Chip& chip : chips)
                makeRigidBody(chip);
        }
    }
    double resectedVolume = 0, resectedMass = 0;
    for (const Chip& chip : chips) {
        resectedVolume += chip.volume;
        resectedMass += chip.mass;
    }
    // Rigid chips fall onto the plane under the input's lowest point.
    double floor = std::numeric_limits<double>::infinity();
    for (const Vec3& p : mesh.referencePositions())
        floor = std::min(floor, p.z());
    for (const Chip& chip : chips)
        for (int n = 0; n < chip.mesh.nodeCount(); ++n)
            floor = std::min(floor, chip.mesh.ref(n).z());
    const bool rigidChips = resected == ResectedPieces::Rigid && !chips.empty();
    // What they land on: the tissue's boundary (its topology does not change here).
    std::vector<Tri> restingTriangles;
    RestingSurface resting;
    if (rigidChips)
        for (const BoundaryFace& f : boundaryFaces(mesh))
            restingTriangles.push_back(f.nodes);
    SimulatorOptions options;
    options.integrator = integrator;
    options.threads = threads;
    options.dt = dt.value_or(0.0);
    if (iterations)
        options.projective.iterations = *iterations;
    Simulator sim(mesh, Material{}, options);
    for (const std::string& name : effects)
        if (Status s = sim.addEffect(name, settings, registry); !s.ok())
            badInput("--effects: " + s.message());

    const double stableDt = sim.stableTimeStep();
    const double h = sim.timeStep();
    if (!std::isfinite(h) || !(h > 0))
        throw CliError{kInternal,
                       "no usable time step (stable estimate " + std::to_string(stableDt) + " s)"};
    const double initialKinetic = sim.kineticEnergy();
    double maxKinetic = initialKinetic, maxSpeed = 0, finalKinetic = initialKinetic;
    Status failure;
    const auto wallStart = std::chrono::steady_clock::now();
    for (int s = 0; s < steps; ++s) {
        failure = sim.step(h);
        if (!failure.ok())
            break;
        if (rigidChips) {
            resting.build(restingTriangles, mesh.positions());
            stepChips(chips, h, requested("gravity") ? settings.gravity : Vec3::Zero(), floor, &resting);
        }
        maxKinetic = std::max(maxKinetic, sim.lastStep().kineticEnergy);
        maxSpeed = std::max(maxSpeed, sim.lastStep().maxSpeed);
        finalKinetic = sim.lastStep().kineticEnergy;
    }
    const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - wallStart).count();
    bool finite = failure.ok();
    for (const Vec3& p : mesh.positions())
        finite = finite && p.allFinite();

    QJsonObject report;
    report["steps"] = sim.stepsTaken();
    report["requested_steps"] = steps;
    report["substeps"] = static_cast<double>(sim.substepsTaken()); // integrator steps (simulator.h)
    report["dt"] = h;
    report["stable_dt"] = number(stableDt);
    report["integrator"] = integratorName(integrator);
    report["threads"] = sim.threads();
    report["time_s"] = sim.time();
    report["wall_s"] = wall;
    report["realtime_factor"] = number(wall > 0 ? sim.time() / wall : 0.0);
    if (const ProjectiveDynamicsStats* pd = sim.projectiveStats()) {
        report["iterations"] = sim.options().projective.iterations;
        report["factorizations"] = pd->factorizations;
        report["factor_ms"] = pd->factorMs;
        report["halvings"] = static_cast<double>(pd->halvings);
        report["restarts"] = static_cast<double>(pd->restarts);
    }
    QJsonArray effectTimes;
    for (const EffectTime& e : sim.totalTimes()) {
        QJsonObject o;
        o["name"] = QString::fromStdString(e.name);
        o["time_ms"] = e.ms;
        effectTimes.append(o);
    }
    report["effects"] = effectTimes;
    report["finite"] = finite;
    report["max_speed"] = number(maxSpeed);
    QJsonObject kinetic;
    kinetic["initial"] = number(initialKinetic);
    kinetic["max"] = number(maxKinetic);
    kinetic["final"] = number(finalKinetic);
    report["kinetic_energy"] = kinetic;
    report["inverted"] = countInverted(mesh);
    report["resected"] = QJsonObject{{"policy", box ? resectedPiecesName(resected) : "none"},
                                     {"pieces", static_cast<int>(chips.size())},
                                     {"volume", resectedVolume},
                                     {"mass", resectedMass},
                                     {"mass_before", massBefore},
                                     {"mass_remaining", sumOfMasses(mesh)}};
    if (!failure.ok())
        report["error"] = QString::fromStdString(failure.message());
    if (reportPath)
        if (Status s = writeJson(*reportPath, report); !s.ok())
            throw CliError{kInternal, s.message()};
    if (!finite)
        throw CliError{kInternal, failure.ok() ? "the simulation produced non-finite positions; " +
                                                     out + " not written"
                                               : failure.message() + "; " + out + " not written"};
    // Rigid chips are part of the scene: written with the tissue, where they came to rest.
    TetMesh scene = mesh;
    if (rigidChips)
        for (const Chip& chip : chips) {
            const int base = scene.nodeCount();
            for (int n = 0; n < chip.mesh.nodeCount(); ++n) {
                const int added = scene.addNode(chip.mesh.ref(n), chip.mesh.pos(n));
                scene.setMass(added, chip.mesh.masses()[n]);
            }
            for (Tet q : chip.mesh.tets()) {
                for (int& v : q)
                    v += base;
                scene.addTet(q);
            }
        }
    if (Status s = writeTetMesh(out, scene, output.format); !s.ok())
        throw CliError{kInternal, s.message()};
    std::printf(
        "%s: %d steps of %.4g s (%s, stable %.4g s) in %.3g s wall (%.3gx real time), max speed %.4g mm/s, %d inverted -> %s\n",
        files[0].c_str(), sim.stepsTaken(), h, integratorName(integrator), stableDt, wall,
        wall > 0 ? sim.time() / wall : 0.0, maxSpeed, countInverted(mesh), out.c_str());
    return kOk;
}

} // namespace resect::cli
