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
    if (Status s = Tissue::create(std::move(plan.mesh), std::move(plan.surface), plan.material, plan.anchors, out);
        !s.ok())
        return s;
    out.setResectedPieces(plan.resected);
    return Status::success();
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
    double all = tissue.resectedVolume(), resected = tissue.resectedVolume();
    for (int c = 0; c < comp.count; ++c) {
        all += volume[c];
        if (!anchored[c])
            resected += volume[c];
    }
    return all > 0 ? resected / all : 0;
}

} // namespace

namespace {

/// One replay in progress: the tissue with its simulation, the tool, the clock and progress.
class ReplayRun {
public:
    ReplayRun(ReplayPlan& plan, ReplayOutcome& out, const ReplayProgress& progress)
        : m_plan(plan), m_out(out), m_progress(progress) {}

    /// The tissue and its simulation; the tool starts withdrawn above the first pose.
    Status start() {
        const auto& effects = m_plan.effects;
        if (std::find(effects.begin(), effects.end(), "tool-contact") != effects.end())
            for (const ReplayStroke& s : m_plan.strokes)
                if (!s.tool.empty()) {
                    m_plan.effectSettings.tool.points = withdrawnTool(s.tool.front(), m_plan.mesh);
                    break;
                }
        if (Status s = makeTissue(m_plan, m_tissue); !s.ok())
            return s;
        if (Status s = m_tissue.startSimulation(simulationSetup(m_plan)); !s.ok())
            return s;
        m_sim = m_tissue.simulator();
        m_tool = dynamic_cast<ToolContactEffect*>(m_sim->findEffect("tool-contact"));
        m_total = m_plan.duration;
        for (const ReplayStroke& s : m_plan.strokes)
            if (m_tool && s.times.size() >= 2)
                m_total += s.times.back() - s.times.front();
        m_out.kineticInitial = m_out.kineticMax = m_sim->kineticEnergy();
        return Status::success();
    }

    /// One stroke: its cut, then (with tool contact and poses) the simulation over its time
    /// span with the tool moving along it, after which the tool is withdrawn.
    Status stroke(const ReplayStroke& stroke) {
        TissueCut cut;
        if (Status s = m_tissue.cut(stroke.sweep, m_plan.cut, &cut); !s.ok()) {
            // (A failed cut leaves the tissue as it was: the outcome so far is reported.)
            m_out.cutFailure = stroke.name + ": " + s.message();
            return Status::success();
        }
        m_out.cutTotals += cut.tets;
        m_out.surfaceCapTriangles += cut.surface.surface.capTriangles;
        if (cut.simulationRebuilt) {
            // The tissue rebuilt its simulation (tets were resected or removed by the
            // improvement step): the effects are new objects.
            m_sim = m_tissue.simulator();
            m_tool = dynamic_cast<ToolContactEffect*>(m_sim->findEffect("tool-contact"));
        }
        if (m_tool && stroke.times.size() >= 2) {
            const double t0 = stroke.times.front();
            if (Status s = simulate(stroke.times.back() - t0, [&](double t) { return toolAt(stroke, t0 + t); }); !s.ok())
                return s;
            if (Status s = m_tool->setPose(withdrawnTool(stroke.tool.back(), m_tissue.mesh())); !s.ok())
                return s;
        }
        return report(m_done) ? Status::success() : Status::error("cancelled");
    }

    /// Simulates `span` seconds; `pose` (optional) gives the tool's points at a time. A
    /// divergence ends the simulation (recorded in the outcome), not the replay.
    Status simulate(double span, const std::function<std::vector<Vec3>(double)>& pose) {
        if (span <= 0 || m_diverged)
            return Status::success();
        // At the stable step the simulator sub-steps where the deformed tissue needs it
        // (simulator.h, "Time step"), tool contact included.
        const double dt = m_sim->timeStep();
        if (!(dt > 0) || !std::isfinite(dt))
            return Status::error("the simulation has no usable time step");
        const long long steps = static_cast<long long>(std::ceil(span / dt - kStepCountSlack));
        if (m_out.steps + steps > m_plan.maxSteps)
            return Status::error("the scenario needs more than " + std::to_string(m_plan.maxSteps) +
                                 " simulation steps at dt = " + formatNumber(dt) +
                                 " s: shorten the duration, or use a larger time step with the implicit integrator");
        const double h = span / static_cast<double>(steps);
        for (long long i = 0; i < steps; ++i) {
            if (m_tool && pose)
                if (Status s = m_tool->setPose(pose(i * h)); !s.ok())
                    return s;
            if (Status s = m_tissue.step(h); !s.ok()) {
                m_out.finite = false;
                m_out.failure = s.message();
                m_diverged = true;
                return Status::success();
            }
            ++m_out.steps;
            m_out.substeps += m_sim->lastStep().substeps;
            m_out.dt = h;
            m_out.kineticMax = std::max(m_out.kineticMax, m_sim->lastStep().kineticEnergy);
            m_out.maxSpeed = std::max(m_out.maxSpeed, m_sim->lastStep().maxSpeed);
            if (i % kProgressInterval == 0 && !report(m_done + i * h))
                return Status::error("cancelled");
        }
        m_done += span;
        return Status::success();
    }

    /// The outcome (see replay.h); the tissue's mesh and surface move into it.
    void finish() {
        m_tissue.updateSurface();
        m_out.stableDt = m_sim->stableTimeStep();
        if (m_out.dt == 0)
            m_out.dt = m_sim->timeStep();
        m_out.kineticFinal = m_sim->kineticEnergy();
        m_out.effectTimes = m_sim->totalTimes();
        const TetMesh& mesh = m_tissue.mesh();
        m_out.finite = m_out.finite && std::isfinite(m_out.kineticFinal);
        for (int n = 0; n < mesh.nodeCount() && m_out.finite; ++n)
            m_out.finite = mesh.pos(n).allFinite();
        for (int t = 0; t < mesh.tetCount(); ++t)
            m_out.inverted += mesh.currentVolume(t) > 0 ? 0 : 1;
        m_out.pieces = m_tissue.pieces().count + static_cast<int>(m_tissue.chips().size());
        m_out.resectedPieces = static_cast<int>(m_tissue.chips().size());
        m_out.resectedMass = m_tissue.resectedMass();
        m_out.resectedVolumeFraction = resectedVolumeFraction(m_tissue);
        m_out.minRadiusRatio = summarizeQuality(mesh).minRadiusRatio;
        m_out.surface = m_tissue.surface().surface();
        m_tissue.stopSimulation();
        m_sim = nullptr;
        m_out.mesh = std::move(m_tissue).takeMesh();
        report(m_total);
    }

private:
    bool report(double t) const { return !m_progress || m_progress(m_total > 0 ? std::min(1.0, t / m_total) : 1.0); }

    ReplayPlan& m_plan;
    ReplayOutcome& m_out;
    const ReplayProgress& m_progress;
    Tissue m_tissue;
    Simulator* m_sim = nullptr;
    ToolContactEffect* m_tool = nullptr;
    double m_total = 0, m_done = 0;  ///< simulated seconds: in all, and so far
    bool m_diverged = false;
};

} // namespace

Status replay(ReplayPlan plan, ReplayOutcome& out, const ReplayProgress& progress) {
    out = {};
    out.tetsBefore = plan.mesh.tetCount();
    ReplayRun run(plan, out, progress);
    if (Status s = run.start(); !s.ok())
        return s;
    for (const ReplayStroke& stroke : plan.strokes) {
        if (Status s = run.stroke(stroke); !s.ok())
            return s;
        if (!out.cutFailure.empty())
            break;
    }
    if (out.cutFailure.empty())
        if (Status s = run.simulate(plan.duration, {}); !s.ok())
            return s;
    run.finish();
    return Status::success();
}

} // namespace resect
