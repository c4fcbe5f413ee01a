#include "scenario/scenario_run.h"

#include "core/mesh/masses.h"
#include "core/sim/effect_registry.h"
#include "core/tissue/tissue.h"
#include "scenario/anatomy.h"
#include "scenario/mesh_io.h"
#include "scenario/scenario_sweeps.h"

#include <QJsonArray>

#include <algorithm>
#include <functional>

namespace resect {
namespace {

Integrator integratorOf(const std::string& name) {
    Integrator integrator = Integrator::SymplecticEuler;  // (the loader accepts known names only)
    parseIntegrator(name, integrator);
    return integrator;
}

} // namespace

bool ScenarioRun::allPassed() const {
    return cutsSucceeded() &&
           std::all_of(expectations.begin(), expectations.end(), [](const ExpectationResult& e) { return e.passed; });
}

bool ScenarioRun::cutsSucceeded() const {
    return std::all_of(tissues.begin(), tissues.end(), [](const TissueRun& t) { return t.outcome.cutFailure.empty(); });
}

Status loadTissue(const Scenario& scenario, const TissueSpec& tissue, TetMesh& mesh,
                  TriangleSurface& surface, const std::atomic<bool>* cancel,
                  std::function<void(const MeshingProgress&)> progress, MeshReadReport* readReport) {
    const std::string where = "tissue '" + tissue.name + "'";
    const Material material = tissue.material.toMaterial();
    TriangleSurface loaded;
    TetMesh meshed;
    if (!tissue.surface.empty()) {
        const std::string source =
            isSampleSource(tissue.surface) ? tissue.surface : resolveScenarioPath(scenario.baseDir, tissue.surface);
        if (Status s = loadAnatomy(source, loaded); !s.ok())
            return Status::error(where + ": " + s.message());
    }
    if (!tissue.mesh.empty()) {
        if (Status s = readTetMesh(resolveScenarioPath(scenario.baseDir, tissue.mesh), meshed, readReport); !s.ok())
            return Status::error(where + ": " + s.message());
        computeLumpedMasses(meshed, material.density);
    } else {
        if (loaded.triangles.empty())
            return Status::error(where + ": needs a surface to mesh or a tet mesh");
        AnatomyMeshing meshing;
        meshing.meshing.edgeLength = tissue.meshing.edgeLength;
        meshing.meshing.seed = tissue.meshing.seed;
        meshing.meshing.cancel = cancel;
        meshing.meshing.progress = std::move(progress);
        meshing.material = material;
        if (Status s = meshAnatomy(loaded, meshing, meshed); !s.ok())
            return Status::error(where + ": " + s.message());
    }
    mesh = std::move(meshed);
    surface = std::move(loaded);
    return Status::success();
}

Status planTissue(const Scenario& scenario, const TissueSpec& tissue, ReplayPlan& plan) {
    TetMesh mesh;
    TriangleSurface surface;
    if (Status s = loadTissue(scenario, tissue, mesh, surface); !s.ok())
        return s;
    return planLoadedTissue(scenario, tissue, std::move(mesh), std::move(surface), plan);
}

Status planLoadedTissue(const Scenario& scenario, const TissueSpec& tissue, TetMesh mesh, TriangleSurface surface,
                        ReplayPlan& plan) {
    plan = {};
    const std::string where = "tissue '" + tissue.name + "'";
    plan.material = tissue.material.toMaterial();
    plan.mesh = std::move(mesh);
    plan.surface = std::move(surface);

    // Cuts: strokes (with the tool's points at every pose, for tool contact), then sweeps.
    std::vector<ScenarioCut> cuts;
    if (Status s = scenarioCuts(scenario, cuts); !s.ok())
        return s;
    for (std::size_t i = 0; i < cuts.size(); ++i) {
        ReplayStroke stroke;
        stroke.name = cuts[i].label;
        stroke.sweep = std::move(cuts[i].sweep);
        if (i < scenario.strokes.size())
            for (const ToolPose& pose : scenario.strokes[i].poses) {
                stroke.times.push_back(pose.t);
                stroke.tool.push_back(toolCurveAt(scenario.tool, pose));
            }
        plan.strokes.push_back(std::move(stroke));
    }

    // Anchors: the nodes in the tissue's fixed regions (held by the `fixed` effect, and what
    // tells anchored pieces from resected ones).
    plan.anchors = regionAnchors(tissue, plan.mesh);

    plan.cut = toCutOptions(scenario.cut, tissue.material);
    for (const EffectSpec& e : scenario.effects) {
        plan.effects.push_back(e.name);
        if (e.name == "deformation") {
            plan.effectSettings.deformation.distance = e.flag("distance", true);
            plan.effectSettings.deformation.volume = e.flag("volume", true);
            plan.effectSettings.deformation.area = e.flag("area", true);
        } else if (e.name == "gravity") {
            plan.effectSettings.gravity = e.vector("acceleration", Vec3(0, 0, -9810));
        } else if (e.name == "tool-contact") {
            plan.effectSettings.tool.radius = e.number("radius", 0);
            if (!scenario.tool.curve.empty() && !scenario.strokes.empty() && !scenario.strokes[0].poses.empty())
                plan.effectSettings.tool.points = toolCurveAt(scenario.tool, scenario.strokes[0].poses[0]);
            else if (!scenario.tool.curve.empty())
                plan.effectSettings.tool.points = toolCurveAt(scenario.tool, ToolPose{});
        } else if (e.name == "damping") {
            if (e.parameters.contains("coefficient"))
                plan.effectSettings.damping = e.number("coefficient", 0);
        } else if (e.name == "fixed") {
            if (plan.anchors.nodes.empty())
                return Status::error(where + ": the fixed effect holds no node (no node lies in its fixed_regions)");
        }
    }
    plan.simulation.integrator = integratorOf(scenario.simulation.integrator);
    plan.simulation.dt = scenario.simulation.timeStep;  // 0: stable
    plan.simulation.projective.iterations = scenario.simulation.iterations;
    // An implicit integrator has no stability limit: "stable" is the trainer's haptic rate.
    if (plan.simulation.dt <= 0 && !isExplicit(plan.simulation.integrator))
        plan.simulation.dt = kImplicitDefaultStep;
    // One thread: a scenario replays to the same result on any machine.
    plan.simulation.threads = 1;
    plan.effectSettings.threads = 1;
    plan.duration = scenario.simulation.duration;
    (void)parseResectedPieces(scenario.simulation.resectedPieces, plan.resected);  // validated when read
    return Status::success();
}

FixedSelection regionAnchors(const TissueSpec& tissue, const TetMesh& mesh) {
    FixedSelection anchors;
    // (One box only: FixedSelection and the improvement's keepOut hold one. Without it a cut
    // through the region left unanchored nodes there, which the improvement may not move within
    // it, and anchored ones it may not move at all: the worst tets of two of the four random
    // partway pulls that ended below half their input's worst ratio, issue 16.)
    if (tissue.fixedRegions.size() == 1)
        anchors.box = std::array<Vec3, 2>{tissue.fixedRegions.front().min, tissue.fixedRegions.front().max};
    for (int n = 0; n < mesh.nodeCount(); ++n)
        for (const FixedRegion& r : tissue.fixedRegions)
            if (r.contains(mesh.ref(n))) {
                anchors.nodes.push_back(n);
                break;
            }
    return anchors;
}

Status checkSimulation(const Scenario& scenario, const TissueSpec& spec, const Tissue& tissue) {
    if (tissue.empty())
        return Status::error("tissue '" + spec.name + "': no tets to simulate");
    ReplayPlan plan;
    if (Status s = planLoadedTissue(scenario, spec, tissue.mesh(), {}, plan); !s.ok())
        return s;
    // As Tissue::startSimulation adds them: the fixed effect holds the tissue's anchors.
    EffectSettings settings = plan.effectSettings;
    settings.fixed = tissue.anchors().selection();
    const EffectRegistry registry = EffectRegistry::withBuiltins();
    for (const std::string& name : plan.effects) {
        std::unique_ptr<Effect> effect;
        if (Status s = registry.create(name, tissue.mesh(), tissue.material(), settings, effect); !s.ok())
            return Status::error("effect '" + name + "': " + s.message());
    }
    return Status::success();
}

std::vector<ExpectationResult> evaluateExpectations(const Scenario& scenario, const std::vector<TissueRun>& tissues) {
    std::vector<ExpectationResult> results;
    for (const Expectation& e : scenario.expectations)
        for (const TissueRun& t : tissues) {
            if (!e.tissue.empty() && e.tissue != t.name)
                continue;
            ExpectationResult r;
            r.kind = expectationKindName(e.kind);
            r.tissue = t.name;
            r.expected = e.value;
            const ReplayOutcome& o = t.outcome;
            switch (e.kind) {
            case ExpectationKind::PiecesAtLeast:
                r.actual = o.pieces;
                r.passed = o.pieces >= e.value;
                break;
            case ExpectationKind::ResectedVolumeFractionAtLeast:
                r.actual = o.resectedVolumeFraction;
                r.passed = o.resectedVolumeFraction >= e.value;
                break;
            case ExpectationKind::MinRadiusRatioAtLeast:
                r.actual = o.minRadiusRatio;
                r.passed = o.minRadiusRatio >= e.value;
                break;
            case ExpectationKind::StaysFinite:
                r.actual = o.finite ? 1 : 0;
                r.passed = (e.value != 0) == o.finite;
                break;
            case ExpectationKind::MaxInvertedTets:
                r.actual = o.inverted;
                r.passed = o.inverted <= e.value;
                break;
            }
            results.push_back(r);
        }
    return results;
}

Status runScenario(const Scenario& scenario, ScenarioRun& out, const ReplayProgress& progress) {
    out = {};
    const int count = static_cast<int>(scenario.tissues.size());
    for (int i = 0; i < count; ++i) {
        const TissueSpec& tissue = scenario.tissues[i];
        ReplayPlan plan;
        if (Status s = planTissue(scenario, tissue, plan); !s.ok())
            return s;
        TissueRun run;
        run.name = tissue.name;
        const ReplayProgress part = [&](double p) { return !progress || progress((i + p) / count); };
        if (Status s = replay(std::move(plan), run.outcome, part); !s.ok())
            return Status::error("tissue '" + tissue.name + "': " + s.message());
        out.tissues.push_back(std::move(run));
    }
    out.expectations = evaluateExpectations(scenario, out.tissues);
    return Status::success();
}

QJsonObject scenarioRunJson(const ScenarioRun& run) {
    QJsonArray tissues;
    for (const TissueRun& t : run.tissues) {
        const ReplayOutcome& o = t.outcome;
        QJsonArray effects;
        for (const EffectTime& e : o.effectTimes)
            effects.append(QJsonObject{{"name", QString::fromStdString(e.name)}, {"time_ms", e.ms}});
        tissues.append(QJsonObject{
            {"name", QString::fromStdString(t.name)},
            {"tets_before", o.tetsBefore},
            {"tets", o.mesh.tetCount()},
            {"nodes", o.mesh.nodeCount()},
            {"pieces", o.pieces},
            {"resected", QJsonObject{{"pieces", o.resectedPieces}, {"mass", o.resectedMass}}},
            {"resected_volume_fraction", o.resectedVolumeFraction},
            {"min_radius_ratio", o.minRadiusRatio},
            {"finite", o.finite},
            {"inverted", o.inverted},
            {"steps", static_cast<double>(o.steps)},
            {"dt", o.dt},
            {"stable_dt", o.stableDt},
            {"max_speed", o.maxSpeed},
            {"kinetic_energy", QJsonObject{{"initial", o.kineticInitial}, {"max", o.kineticMax}, {"final", o.kineticFinal}}},
            {"failure", QString::fromStdString(o.failure)},
            {"cut_failure", QString::fromStdString(o.cutFailure)},
            {"cut", QJsonObject{{"cut_edges", o.cutTotals.cutEdges},
                                {"cut_nodes", o.cutTotals.cutNodes},
                                {"decomposed_tets", o.cutTotals.decomposedTets},
                                {"snapped_nodes", o.cutTotals.snappedNodes},
                                {"separated_tets", o.cutTotals.separatedTets},
                                {"surface_cap_triangles", o.surfaceCapTriangles},
                                {"time_ms", o.cutTotals.timeMs.total}}},
            {"surface", QJsonObject{{"vertices", o.surface.vertexCount()}, {"triangles", o.surface.triangleCount()}}},
            {"effects", effects}});
    }
    QJsonArray expectations;
    for (const ExpectationResult& e : run.expectations)
        expectations.append(QJsonObject{{"kind", QString::fromStdString(e.kind)},
                                        {"tissue", QString::fromStdString(e.tissue)},
                                        {"expected", e.expected},
                                        {"actual", e.actual},
                                        {"passed", e.passed}});
    return QJsonObject{{"tissues", tissues}, {"expectations", expectations}, {"passed", run.allPassed()}};
}

QJsonObject stripTimings(const QJsonObject& report) {
    const std::function<QJsonValue(const QJsonValue&)> strip = [&](const QJsonValue& v) -> QJsonValue {
        if (v.isObject()) {
            QJsonObject o;
            const QJsonObject in = v.toObject();
            for (auto it = in.begin(); it != in.end(); ++it)
                if (it.key() != "time_ms")
                    o[it.key()] = strip(it.value());
            return o;
        }
        if (v.isArray()) {
            QJsonArray a;
            for (const QJsonValue& x : v.toArray())
                a.append(strip(x));
            return a;
        }
        return v;
    };
    return strip(report).toObject();
}

} // namespace resect
