#include "scenario/replay.h"

#include "core/mesh/quality.h"
#include "core/mesh/topology.h"
#include "core/sim/tool_contact_effect.h"

#include <algorithm>
#include <cmath>
#include <map>

namespace resect {
namespace {

/// Steps of a span: ceil(span / dt) less this slack, so that a span that is a whole number of
/// steps up to rounding does not get one more (dimensionless, in steps).
constexpr double kStepCountSlack = 1e-9;
/// Progress is reported (and cancellation checked) every this many steps.
constexpr long long kProgressInterval = 64;

/// The tool's points at time t of a stroke: linear between the two nearest samples.
std::vector<Vec3> toolAt(const ReplayStroke& s, double t) {
    if (t <= s.times.front())
        return s.tool.front();
    if (t >= s.times.back())
        return s.tool.back();
    const auto it = std::upper_bound(s.times.begin(), s.times.end(), t);
    const std::size_t i = static_cast<std::size_t>(it - s.times.begin());
    const double span = s.times[i] - s.times[i - 1];  // > 0: pose times increase strictly
    const double a = span > 0 ? (t - s.times[i - 1]) / span : 1.0;
    std::vector<Vec3> points(s.tool[i].size());
    for (std::size_t k = 0; k < points.size(); ++k)
        points[k] = (1 - a) * s.tool[i - 1][k] + a * s.tool[i][k];
    return points;
}

} // namespace

std::vector<Vec3> withdrawnTool(const std::vector<Vec3>& pose, const TetMesh& mesh) {
    const auto [lo, hi] = boundingBox(mesh.positions());
    const double lift = 2 * (hi - lo).norm() + (hi.z() - lo.z());
    std::vector<Vec3> points = pose;
    for (Vec3& p : points)
        p.z() += lift;
    return points;
}

Status makeTissue(ReplayPlan& plan, Tissue& out) {
    return Tissue::create(std::move(plan.mesh), std::move(plan.surface), plan.material, plan.anchors, out);
}

SimulationSetup simulationSetup(const ReplayPlan& plan) {
    return {plan.simulation, plan.effects, plan.effectSettings};
}

namespace {

/// The resected volume fraction: reference volume of the pieces holding no anchored node
/// over the total (with no anchors: every piece but the largest).
double resectedVolumeFraction(const Tissue& tissue) {
    const TetMesh& mesh = tissue.mesh();
    const Components& comp = tissue.pieces();
    std::vector<double> volume(comp.count, 0.0);
    for (int t = 0; t < mesh.tetCount(); ++t)
        volume[comp.tetComponent[t]] += mesh.referenceVolume(t);
    std::vector<bool> anchored(comp.count, false);
    bool anyAnchored = false;
    for (int n : tissue.anchors().nodes())
        if (comp.nodeComponent[n] >= 0) {
            anchored[comp.nodeComponent[n]] = true;
            anyAnchored = true;
        }
    if (!anyAnchored && comp.count > 0)
        anchored[std::max_element(volume.begin(), volume.end()) - volume.begin()] = true;
    double all = 0, resected = 0;
    for (int c = 0; c < comp.count; ++c) {
        all += volume[c];
        if (!anchored[c])
            resected += volume[c];
    }
    return all > 0 ? resected / all : 0;
}

} // namespace

Status replay(ReplayPlan plan, ReplayOutcome& out, const ReplayProgress& progress) {
    out = {};
    out.tetsBefore = plan.mesh.tetCount();

    // The tool starts withdrawn above the first pose of the first stroke that has poses.
    const bool wantsTool = std::find(plan.effects.begin(), plan.effects.end(), "tool-contact") != plan.effects.end();
    if (wantsTool)
        for (const ReplayStroke& s : plan.strokes)
            if (!s.tool.empty()) {
                plan.effectSettings.tool.points = withdrawnTool(s.tool.front(), plan.mesh);
                break;
            }

    Tissue tissue;
    if (Status s = makeTissue(plan, tissue); !s.ok())
        return s;
    if (Status s = tissue.startSimulation(simulationSetup(plan)); !s.ok())
        return s;
    Simulator& sim = *tissue.simulator();
    auto* tool = dynamic_cast<ToolContactEffect*>(sim.findEffect("tool-contact"));

    // Total simulated time, for progress.
    double total = plan.duration;
    for (const ReplayStroke& s : plan.strokes)
        if (tool && s.times.size() >= 2)
            total += s.times.back() - s.times.front();
    double done = 0;
    const auto report = [&](double t) { return !progress || progress(total > 0 ? std::min(1.0, t / total) : 1.0); };

    out.kineticInitial = out.kineticMax = sim.kineticEnergy();
    bool diverged = false;
    // Runs the simulation for `span` seconds; `pose` gives the tool's points at a time.
    const auto simulate = [&](double span, const std::function<std::vector<Vec3>(double)>& pose) -> Status {
        if (span <= 0 || diverged)
            return Status::success();
        // The stable estimate holds for small deformations; a tool pushing surface nodes by
        // projection deforms small elements strongly within a step, so an explicit
        // integrator at "stable" keeps the margin the simulator advises.
        double dt = sim.timeStep();
        if (plan.simulation.dt <= 0 && tool && isExplicit(plan.simulation.integrator))
            dt *= kLargeDeformationMargin;
        if (!(dt > 0) || !std::isfinite(dt))
            return Status::error("the simulation has no usable time step");
        const long long steps = static_cast<long long>(std::ceil(span / dt - kStepCountSlack));
        if (out.steps + steps > plan.maxSteps)
            return Status::error("the scenario needs more than " + std::to_string(plan.maxSteps) +
                                 " simulation steps at dt = " + formatNumber(dt) +
                                 " s: shorten the duration, or use a larger time step with the implicit integrator");
        const double h = span / static_cast<double>(steps);
        for (long long i = 0; i < steps; ++i) {
            if (tool && pose)
                if (Status s = tool->setPose(pose(i * h)); !s.ok())
                    return s;
            if (Status s = tissue.step(h); !s.ok()) {
                out.finite = false;
                out.failure = s.message();
                diverged = true;
                return Status::success();
            }
            ++out.steps;
            out.dt = h;
            out.kineticMax = std::max(out.kineticMax, sim.lastStep().kineticEnergy);
            out.maxSpeed = std::max(out.maxSpeed, sim.lastStep().maxSpeed);
            if (i % kProgressInterval == 0 && !report(done + i * h))
                return Status::error("cancelled");
        }
        done += span;
        return Status::success();
    };

    for (const ReplayStroke& stroke : plan.strokes) {
        TissueCut cut;
        if (Status s = tissue.cut(stroke.sweep, plan.cut, &cut); !s.ok())
            return Status::error(stroke.name + ": " + s.message());
        out.cutTotals += cut.tets;
        out.surfaceCapTriangles += cut.surface.surface.capTriangles;
        if (tool && stroke.times.size() >= 2) {
            const double t0 = stroke.times.front();
            if (Status s = simulate(stroke.times.back() - t0, [&](double t) { return toolAt(stroke, t0 + t); }); !s.ok())
                return s;
            if (Status s = tool->setPose(withdrawnTool(stroke.tool.back(), tissue.mesh())); !s.ok())
                return s;
        }
        if (!report(done))
            return Status::error("cancelled");
    }
    if (Status s = simulate(plan.duration, {}); !s.ok())
        return s;

    // Outcome.
    tissue.updateSurface();
    out.stableDt = sim.stableTimeStep();
    if (out.dt == 0)
        out.dt = sim.timeStep();
    out.kineticFinal = sim.kineticEnergy();
    out.effectTimes = sim.totalTimes();
    const TetMesh& mesh = tissue.mesh();
    out.finite = out.finite && std::isfinite(out.kineticFinal);
    for (int n = 0; n < mesh.nodeCount() && out.finite; ++n)
        out.finite = mesh.pos(n).allFinite();
    for (int t = 0; t < mesh.tetCount(); ++t)
        out.inverted += mesh.currentVolume(t) > 0 ? 0 : 1;
    out.pieces = tissue.pieces().count;
    out.resectedVolumeFraction = resectedVolumeFraction(tissue);
    out.minRadiusRatio = summarizeQuality(mesh).minRadiusRatio;
    out.surface = tissue.surface().surface();
    tissue.stopSimulation();
    out.mesh = std::move(tissue).takeMesh();
    report(total);
    return Status::success();
}

} // namespace resect
