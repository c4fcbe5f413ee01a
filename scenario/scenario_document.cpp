#include "scenario/scenario_document.h"

#include <QJsonArray>

#include <cmath>
#include <filesystem>

namespace resect {

namespace {

namespace fs = std::filesystem;

QString qs(const std::string& s) {
    return QString::fromStdString(s);
}

QJsonArray vec3Json(const Vec3& v) {
    return QJsonArray{v.x(), v.y(), v.z()};
}

QJsonArray pointsJson(const std::vector<Vec3>& points) {
    QJsonArray a;
    for (const Vec3& p : points)
        a.append(vec3Json(p));
    return a;
}

/// `known` with the unknown fields added (known keys win; they cannot collide after a load).
QJsonObject withExtra(QJsonObject known, const QJsonObject& extra) {
    for (auto it = extra.begin(); it != extra.end(); ++it)
        if (!known.contains(it.key()))
            known.insert(it.key(), it.value());
    return known;
}

const char* methodName(CutMethod m) {
    return m == CutMethod::Hybrid ? "hybrid" : "subdivision";
}
const char* triangulationName(FaceTriangulation t) {
    return t == FaceTriangulation::Enhanced ? "enhanced" : "standard";
}

QJsonObject tissueJson(const TissueSpec& t) {
    QJsonObject o;
    o["name"] = qs(t.name);
    if (!t.surface.empty()) // absent: the tet mesh alone (scenario_document.h)
        o["surface"] = qs(t.surface);
    if (!t.mesh.empty())
        o["mesh"] = qs(t.mesh);
    else
        o["meshing"] = withExtra(
            {{"edge_length", t.meshing.edgeLength}, {"seed", static_cast<qint64>(t.meshing.seed)}},
            t.meshing.extra);
    o["material"] = withExtra({{"density", t.material.density},
                               {"stiffness", t.material.stiffness},
                               {"damping", t.material.damping}},
                              t.material.extra);
    QJsonArray regions;
    for (const FixedRegion& r : t.fixedRegions)
        regions.append(withExtra({{"min", vec3Json(r.min)}, {"max", vec3Json(r.max)}}, r.extra));
    o["fixed_regions"] = regions;
    return withExtra(o, t.extra);
}

QJsonObject strokeJson(const Stroke& s) {
    QJsonArray poses;
    for (const ToolPose& p : s.poses) {
        const Eigen::Vector4d& q = p.orientation;
        poses.append(withExtra({{"t", p.t},
                                {"position", vec3Json(p.position)},
                                {"orientation", QJsonArray{q[0], q[1], q[2], q[3]}}},
                               p.extra));
    }
    QJsonObject o;
    if (!s.name.empty())
        o["name"] = qs(s.name);
    o["poses"] = poses;
    return withExtra(o, s.extra);
}

QJsonObject sweepJson(const SweepSpec& s) {
    QJsonObject o;
    if (!s.name.empty())
        o["name"] = qs(s.name);
    if (!s.file.empty()) {
        o["file"] = qs(s.file);
    } else {
        QJsonArray curves;
        for (const auto& c : s.curves)
            curves.append(pointsJson(c));
        o["curves"] = curves;
    }
    return withExtra(o, s.extra);
}

QJsonObject expectationJson(const Expectation& e) {
    QJsonObject o;
    o["kind"] = expectationKindName(e.kind);
    switch (e.kind) {
    case ExpectationKind::StaysFinite:
        o["value"] = e.value != 0;
        break;
    case ExpectationKind::PiecesAtLeast:
    case ExpectationKind::MaxInvertedTets:
        // Counts are written as integers; anything else (only from code, never from a
        // loaded file) is written as it is, for validation to report.
        if (std::abs(e.value) <= 1e15 && e.value == std::floor(e.value))
            o["value"] = static_cast<qint64>(e.value);
        else
            o["value"] = e.value;
        break;
    default:
        o["value"] = e.value;
    }
    if (!e.tissue.empty())
        o["tissue"] = qs(e.tissue);
    return withExtra(o, e.extra);
}

} // namespace

CutOptions toCutOptions(const CutSettings& s, const MaterialSpec& material) {
    CutOptions o;
    o.method = s.method;
    o.triangulation = s.triangulation;
    o.d = s.d;
    o.snap = s.snap;
    o.relaxSteps = s.relaxSteps;
    o.wSpring = s.wSpring;
    o.wParticle = s.wParticle;
    o.relaxDamping = s.damping;
    o.relaxRings = s.rings;
    o.improve = s.improve;
    o.improveQuality = s.improveQuality;
    o.improveShortEdge = s.improveShortEdge;
    o.improveCoarsen = s.improveCoarsen;
    o.density = material.density;
    return o;
}

double EffectSpec::number(const char* key, double fallback) const {
    const QJsonValue v = parameters.value(key);
    return v.isDouble() ? v.toDouble() : fallback;
}

Vec3 EffectSpec::vector(const char* key, const Vec3& fallback) const {
    const QJsonValue v = parameters.value(key);
    const QJsonArray a = v.toArray();
    if (!v.isArray() || a.size() != 3 || !a[0].isDouble() || !a[1].isDouble() || !a[2].isDouble())
        return fallback;
    return {a[0].toDouble(), a[1].toDouble(), a[2].toDouble()};
}

bool EffectSpec::flag(const char* key, bool fallback) const {
    const QJsonValue v = parameters.value(key);
    return v.isBool() ? v.toBool() : fallback;
}

const std::vector<std::string>& knownEffectNames() {
    static const std::vector<std::string> names{"deformation", "gravity", "fixed", "tool-contact",
                                                "damping"};
    return names;
}

const char* expectationKindName(ExpectationKind kind) {
    switch (kind) {
    case ExpectationKind::PiecesAtLeast:
        return "pieces_at_least";
    case ExpectationKind::ResectedVolumeFractionAtLeast:
        return "resected_volume_fraction_at_least";
    case ExpectationKind::MinRadiusRatioAtLeast:
        return "min_radius_ratio_at_least";
    case ExpectationKind::StaysFinite:
        return "stays_finite";
    case ExpectationKind::MaxInvertedTets:
        return "max_inverted_tets";
    }
    return "?";
}

const std::vector<ExpectationKind>& allExpectationKinds() {
    static const std::vector<ExpectationKind> kinds{
        ExpectationKind::PiecesAtLeast, ExpectationKind::ResectedVolumeFractionAtLeast,
        ExpectationKind::MinRadiusRatioAtLeast, ExpectationKind::StaysFinite,
        ExpectationKind::MaxInvertedTets};
    return kinds;
}

const EffectSpec* Scenario::findEffect(const std::string& name) const {
    for (const EffectSpec& e : effects)
        if (e.name == name)
            return &e;
    return nullptr;
}

const TissueSpec* Scenario::findTissue(const std::string& name) const {
    for (const TissueSpec& t : tissues)
        if (t.name == name)
            return &t;
    return nullptr;
}

bool Scenario::operator==(const Scenario& o) const {
    return metadata == o.metadata && tissues == o.tissues && tool == o.tool &&
           strokes == o.strokes && sweeps == o.sweeps && cut == o.cut && effects == o.effects &&
           simulation == o.simulation && expectations == o.expectations && extra == o.extra;
}

QJsonObject scenarioToJson(const Scenario& s) {
    QJsonObject root;
    root["format"] = kScenarioFormat;
    root["version"] = kScenarioVersion;

    QJsonArray objectives;
    for (const std::string& o : s.metadata.learningObjectives)
        objectives.append(qs(o));
    root["metadata"] = withExtra({{"title", qs(s.metadata.title)},
                                  {"author", qs(s.metadata.author)},
                                  {"description", qs(s.metadata.description)},
                                  {"learning_objectives", objectives},
                                  {"difficulty", s.metadata.difficulty}},
                                 s.metadata.extra);

    QJsonArray tissues;
    for (const TissueSpec& t : s.tissues)
        tissues.append(tissueJson(t));
    root["tissues"] = tissues;

    if (!s.tool.curve.empty() || !s.tool.extra.isEmpty())
        root["tool"] = withExtra(
            {{"name", qs(s.tool.name)}, {"size", s.tool.size}, {"curve", pointsJson(s.tool.curve)}},
            s.tool.extra);

    QJsonArray strokes;
    for (const Stroke& st : s.strokes)
        strokes.append(strokeJson(st));
    root["strokes"] = strokes;

    QJsonArray sweeps;
    for (const SweepSpec& sw : s.sweeps)
        sweeps.append(sweepJson(sw));
    root["sweeps"] = sweeps;

    const CutSettings& c = s.cut;
    root["cut_settings"] = withExtra({{"method", methodName(c.method)},
                                      {"triangulation", triangulationName(c.triangulation)},
                                      {"d", c.d},
                                      {"snap", c.snap},
                                      {"relax_steps", c.relaxSteps},
                                      {"w_spring", c.wSpring},
                                      {"w_particle", c.wParticle},
                                      {"damping", c.damping},
                                      {"rings", c.rings},
                                      {"improve", c.improve},
                                      {"improve_quality", c.improveQuality},
                                      {"improve_short_edge", c.improveShortEdge},
                                      {"improve_coarsen", c.improveCoarsen}},
                                     c.extra);

    QJsonArray effects;
    for (const EffectSpec& e : s.effects)
        effects.append(withExtra({{"name", qs(e.name)}, {"parameters", e.parameters}}, e.extra));
    root["effects"] = effects;

    const SimulationSettings& sim = s.simulation;
    QJsonObject simulation{{"integrator", qs(sim.integrator)},
                           {"time_step", sim.stableTimeStep() ? QJsonValue("stable") : QJsonValue(sim.timeStep)},
                           {"duration", sim.duration},
                           {"resected_pieces", qs(sim.resectedPieces)}};
    if (sim.iterations != SimulationSettings{}.iterations)
        simulation["iterations"] = sim.iterations;
    root["simulation"] = withExtra(simulation, sim.extra);

    QJsonArray expectations;
    for (const Expectation& e : s.expectations)
        expectations.append(expectationJson(e));
    root["expectations"] = expectations;

    return withExtra(root, s.extra);
}

bool isSampleSource(const std::string& source) {
    return source.rfind("sample:", 0) == 0;
}

std::string resolveScenarioPath(const std::string& baseDir, const std::string& path) {
    if (path.empty() || isSampleSource(path))
        return path;
    const fs::path p(path);
    if (p.is_absolute() || baseDir.empty())
        return p.lexically_normal().string();
    return (fs::path(baseDir) / p).lexically_normal().string();
}

namespace {

/// The folder as an absolute, lexically normal path without a trailing separator.
fs::path absoluteFolder(const std::string& dir) {
    std::error_code ec;
    fs::path p = fs::absolute(dir.empty() ? fs::path(".") : fs::path(dir), ec).lexically_normal();
    if (p.has_relative_path() && p.filename().empty())
        p = p.parent_path();
    return p;
}

} // namespace

void rebaseScenarioPaths(Scenario& scenario, const std::string& newBaseDir) {
    const fs::path from = absoluteFolder(scenario.baseDir);
    const fs::path to = absoluteFolder(newBaseDir);
    const auto rebase = [&](std::string& path) {
        if (path.empty() || isSampleSource(path) || fs::path(path).is_absolute())
            return;
        const fs::path target = (from / path).lexically_normal();
        fs::path relative = target.lexically_relative(to);
        path = relative.empty() ? target.string() : relative.string();
    };
    for (TissueSpec& t : scenario.tissues) {
        rebase(t.surface);
        rebase(t.mesh);
    }
    for (SweepSpec& s : scenario.sweeps)
        rebase(s.file);
    scenario.baseDir = to.string();
}

} // namespace resect
