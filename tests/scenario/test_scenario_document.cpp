// The scenario document: load, save and load gives an equal document, unknown fields
// included; every kind of validation error is reported with its JSON path, several at once;
// a hand-written version-0 document migrates; saving is atomic and rewrites relative paths;
// strokes become the expected sweep curves; the cut settings of the mesh improvement default
// to CutOptions', round-trip, are refused out of CutLimits' ranges with the key named and reach
// toCutOptions; the bundled examples load cleanly, say what becomes of their chips, and their
// strokes cut the sample anatomy into pieces.

#include "scenario/scenario_document.h"
#include "scenario/scenario_load.h"
#include "scenario/scenario_save.h"
#include "scenario/scenario_sweeps.h"

#include "core/cut/hybrid_cutter.h"
#include "core/mesh/quality.h"
#include "core/mesh/topology.h"
#include "scenario/anatomy.h"
#include "scenario/sweep_io.h"

#include "scenario_test_util.h"

#include <QJsonArray>
#include <QJsonDocument>
#include <QRegularExpression>
#include <QTemporaryDir>
#include <QtTest>

#include <cmath>
#include <filesystem>
#include <limits>
#include <random>
#include <unistd.h>

using namespace resect;
using namespace resect::test;

namespace {

/// A valid document using every section; relative files: none (the tissue is a sample).
const char* kBaseDocument = R"({
  "format": "resect-scenario", "version": 1,
  "metadata": {"title": "Test", "author": "QA", "description": "a test case",
               "learning_objectives": ["one", "two"], "difficulty": 3},
  "tissues": [{"name": "polyp", "surface": "sample:polyp",
               "meshing": {"edge_length": 0, "seed": 7},
               "material": {"density": 0.001, "stiffness": 1000000, "damping": 2},
               "fixed_regions": [{"min": [-5, -5, -1], "max": [5, 5, 1]}]}],
  "tool": {"name": "loop", "size": 2, "curve": [[-1, 0, 0], [0, 0, -1], [1, 0, 0]]},
  "strokes": [{"name": "pull", "poses": [
      {"t": 0, "position": [0, -10, 8], "orientation": [1, 0, 0, 0]},
      {"t": 0.5, "position": [0, 0, 8], "orientation": [1, 0, 0, 0]},
      {"t": 1, "position": [0, 10, 8], "orientation": [1, 0, 0, 0]}]}],
  "sweeps": [{"name": "plane", "curves": [[[-10, -10, 5], [10, -10, 5]], [[-10, 10, 5], [10, 10, 5]]]}],
  "cut_settings": {"method": "hybrid", "triangulation": "enhanced", "d": 0.2, "snap": true,
                   "relax_steps": 10, "w_spring": 1, "w_particle": 0.2, "damping": 10, "rings": 2,
                   "improve": false, "improve_quality": 1.5, "improve_short_edge": 0.8,
                   "improve_coarsen": 0.25},
  "effects": [{"name": "deformation", "parameters": {"distance": true}},
              {"name": "gravity", "parameters": {"acceleration": [0, 0, -9810]}},
              {"name": "fixed", "parameters": {}},
              {"name": "tool-contact", "parameters": {"radius": 0.2}},
              {"name": "damping", "parameters": {"coefficient": 5}}],
  "simulation": {"integrator": "velocity-verlet", "time_step": "stable", "duration": 1},
  "expectations": [{"kind": "pieces_at_least", "value": 2},
                   {"kind": "resected_volume_fraction_at_least", "value": 0.1, "tissue": "polyp"},
                   {"kind": "min_radius_ratio_at_least", "value": 0.01},
                   {"kind": "stays_finite", "value": true},
                   {"kind": "max_inverted_tets", "value": 0}]
})";

QJsonObject baseObject() {
    return QJsonDocument::fromJson(kBaseDocument).object();
}
QByteArray bytes(const QJsonObject& o) {
    return QJsonDocument(o).toJson(QJsonDocument::Compact);
}

/// "tissues[0].material.density" -> {"tissues", 0, "material", "density"} (ints as numbers).
QVariantList pathSteps(const QString& path) {
    QVariantList steps;
    static const QRegularExpression token(R"(([^.\[\]]+)|\[(\d+)\])");
    auto it = token.globalMatch(path);
    while (it.hasNext()) {
        const auto m = it.next();
        if (m.captured(1).isEmpty())
            steps << m.captured(2).toInt();
        else
            steps << m.captured(1);
    }
    return steps;
}

/// Sets (or, with an undefined value, removes) the value at `steps` inside `v`.
QJsonValue setAt(const QJsonValue& v, const QVariantList& steps, int k, const QJsonValue& value) {
    if (k == steps.size())
        return value;
    if (steps[k].typeId() == QMetaType::Int) {
        QJsonArray a = v.toArray();
        const int i = steps[k].toInt();
        if (k + 1 == steps.size() && value.isUndefined())
            a.removeAt(i);
        else
            a[i] = setAt(a[i], steps, k + 1, value);
        return a;
    }
    QJsonObject o = v.toObject();
    const QString key = steps[k].toString();
    if (k + 1 == steps.size() && value.isUndefined())
        o.remove(key);
    else
        o[key] = setAt(o.value(key), steps, k + 1, value);
    return o;
}

QJsonObject modified(QJsonObject o, const QString& path, const QByteArray& valueJson) {
    const QJsonValue value = valueJson == "<remove>"
                                 ? QJsonValue(QJsonValue::Undefined)
                                 : QJsonDocument::fromJson("[" + valueJson + "]").array().at(0);
    return setAt(o, pathSteps(path), 0, value).toObject();
}

QString issuesText(const ScenarioDiagnostics& d) {
    return QString::fromStdString(d.format("doc"));
}

QString resourcePath(const QString& name) {
    return QStringLiteral(RESECT_SOURCE_DIR "/resources/scenarios/") + name;
}

/// What the expectations measure after the cuts (scenario_document.h).
struct Measured {
    int pieces = 0;
    double resectedFraction = 0;
    double minRadiusRatio = 0;
};

Measured measure(const TetMesh& mesh, const TissueSpec& tissue) {
    Measured m;
    const Components c = connectedComponents(mesh);
    m.pieces = c.count;
    std::vector<double> volume(c.count, 0.0);
    std::vector<char> attached(c.count, 0);
    double total = 0;
    for (int t = 0; t < mesh.tetCount(); ++t) {
        const Tet& tet = mesh.tet(t);
        const double v =
            signedVolume(mesh.ref(tet[0]), mesh.ref(tet[1]), mesh.ref(tet[2]), mesh.ref(tet[3]));
        volume[c.tetComponent[t]] += v;
        total += v;
    }
    for (int n = 0; n < mesh.nodeCount(); ++n)
        for (const FixedRegion& r : tissue.fixedRegions)
            if (c.nodeComponent[n] >= 0 && r.contains(mesh.ref(n)))
                attached[c.nodeComponent[n]] = 1;
    if (tissue.fixedRegions.empty() && c.count > 0)
        attached[std::max_element(volume.begin(), volume.end()) - volume.begin()] = 1;
    double resected = 0;
    for (int i = 0; i < c.count; ++i)
        if (!attached[i])
            resected += volume[i];
    m.resectedFraction = total > 0 ? resected / total : 0;
    m.minRadiusRatio = summarizeQuality(mesh).minRadiusRatio;
    return m;
}

bool near(const Vec3& a, const Vec3& b) {
    return (a - b).norm() < 1e-12;
}

using Quaternion = std::array<double, 4>; // w, x, y, z

} // namespace

class TestScenarioDocument : public QObject {
    Q_OBJECT

private slots:
    void baseDocumentIsValid();
    void roundTrip_data();
    void roundTrip();
    void unknownFieldsWarnAndSurvive();
    void validationErrors_data();
    void validationErrors();
    void severalErrorsAtOnce();
    void malformedJson_data();
    void malformedJson();
    void absurdSizesAreCapped();
    void damagedDocumentsNeverCrash();
    void missingReferencedFiles();
    void aTissueMayBeItsTetMeshAlone();
    void migratesVersion0();
    void version0StructuralErrors();
    void saveIsAtomic();
    void saveToReadOnlyFolderKeepsFile();
    void saveRebasesRelativePaths();
    void toCutOptionsMapsEveryField();
    void improvementDefaultsAreCutOptions_data();
    void improvementDefaultsAreCutOptions();
    void improvementRoundTrip_data();
    void improvementRoundTrip();
    void improvementOutOfRangeNamesKeyRangeAndValue_data();
    void improvementOutOfRangeNamesKeyRangeAndValue();
    void strokeCurves_data();
    void strokeCurves();
    void poseInterpolation();
    void stillPosesAddNoCurve();
    void nonUnitQuaternionsAreNormalised();
    void bundledExamplesLoad_data();
    void bundledExamplesLoad();
    void bundledExamplesSayWhatBecomesOfChips();
    void bundledStrokesCutTheSample_data();
    void bundledStrokesCutTheSample();
};

void TestScenarioDocument::baseDocumentIsValid() {
    Scenario s;
    ScenarioDiagnostics d;
    const Status st = parseScenario(kBaseDocument, "", "base", s, d);
    QVERIFY2(st.ok(), qPrintable(issuesText(d)));
    QCOMPARE(d.warningCount(), 0);
    QCOMPARE(s.metadata.difficulty, 3);
    QCOMPARE(s.metadata.learningObjectives.size(), std::size_t(2));
    QCOMPARE(s.tissues.size(), std::size_t(1));
    QCOMPARE(s.tissues[0].meshing.seed, 7u);
    QCOMPARE(s.tissues[0].material.damping, 2.0);
    QCOMPARE(s.tool.curve.size(), std::size_t(3));
    QCOMPARE(s.strokes[0].poses.size(), std::size_t(3));
    QCOMPARE(s.sweeps[0].curves.size(), std::size_t(2));
    QCOMPARE(s.effects.size(), std::size_t(5));
    QCOMPARE(s.findEffect("tool-contact")->number("radius", 0), 0.2);
    QVERIFY(near(s.findEffect("gravity")->vector("acceleration", Vec3::Zero()), Vec3(0, 0, -9810)));
    QCOMPARE(s.simulation.integrator, std::string("velocity-verlet"));
    QVERIFY(s.simulation.stableTimeStep());
    QCOMPARE(s.expectations.size(), std::size_t(5));
    QCOMPARE(s.expectations[3].value, 1.0);
    QCOMPARE(s.expectations[1].tissue, std::string("polyp"));
    QCOMPARE(s.cut.improve, false);
    QCOMPARE(s.cut.improveQuality, 1.5);
    QCOMPARE(s.cut.improveShortEdge, 0.8);
    QCOMPARE(s.cut.improveCoarsen, 0.25);
}

void TestScenarioDocument::roundTrip_data() {
    QTest::addColumn<QByteArray>("json");
    QTest::newRow("every section") << QByteArray(kBaseDocument);
    QTest::newRow("minimal") << QByteArray(
        R"({"format": "resect-scenario", "version": 1,
            "tissues": [{"name": "m", "surface": "sample:myoma"}]})");
    QTest::newRow("numbers needing 17 digits") << bytes(modified(
        modified(baseObject(), "tool.curve[1]", "[0.1, 0.30000000000000004, -1e-300]"),
        "strokes[0].poses[1].orientation", "[0.99999999999999989, 1.4901161193847656e-08, 0, 0]"));
    QTest::newRow("file sweep, explicit step")
        << bytes(modified(modified(baseObject(), "sweeps[0]", R"({"file": "cut.json"})"),
                          "simulation.time_step", "0.0001"));
    QTest::newRow("unknown fields everywhere")
        << bytes(modified(modified(modified(modified(baseObject(), "colour", R"({"r": 1})"),
                                            "tissues[0].material.poisson", "0.45"),
                                   "strokes[0].poses[2].pressure", "[1, 2]"),
                          "effects[1].parameters.note", "\"ignored\""));
    QTest::newRow("subdivision defaults")
        << bytes(modified(modified(baseObject(), "cut_settings", R"({"method": "subdivision"})"),
                          "metadata", "<remove>"));
}

void TestScenarioDocument::roundTrip() {
    QFETCH(QByteArray, json);
    QTemporaryDir dir;
    QVERIFY(dir.isValid());
    // A sweep file for the rows that reference one.
    SweepSurface plane;
    QVERIFY(SweepSurface::fromStartEnd({{-10, -10, 5}, {10, -10, 5}}, {{-10, 10, 5}, {10, 10, 5}},
                                       plane)
                .ok());
    QVERIFY(writeSweep(dir.filePath("cut.json").toStdString(), plane).ok());
    const std::string first = dir.filePath("first.json").toStdString();
    QVERIFY(writeBytes(QString::fromStdString(first), json));

    Scenario a, b;
    ScenarioDiagnostics d;
    QVERIFY2(loadScenario(first, a, d).ok(), qPrintable(issuesText(d)));
    const std::string second = dir.filePath("second.json").toStdString();
    QVERIFY2(saveScenario(second, a).ok(), saveScenario(second, a).message().c_str());
    QVERIFY2(loadScenario(second, b, d).ok(), qPrintable(issuesText(d)));
    QVERIFY(a == b);
    // Saving again gives the same bytes (nothing drifts), and changing a field is noticed.
    const QByteArray text = readBytes(QString::fromStdString(second));
    QVERIFY(saveScenario(second, b).ok());
    QCOMPARE(readBytes(QString::fromStdString(second)), text);
    b.cut.d += 0.01;
    QVERIFY(!(a == b));
}

void TestScenarioDocument::unknownFieldsWarnAndSurvive() {
    QJsonObject o = baseObject();
    o = modified(o, "colour", "\"blue\"");
    o = modified(o, "metadata.licence", "\"CC-BY\"");
    o = modified(o, "tissues[0].meshing.quality", "2");
    o = modified(o, "tissues[0].fixed_regions[0].label", "\"base\"");
    o = modified(o, "tool.wire", R"({"radius": 0.2})");
    o = modified(o, "strokes[0].poses[1].force", "[0, 0, 1]");
    o = modified(o, "sweeps[0].colour", "\"red\"");
    o = modified(o, "cut_settings.speed", "\"fast\"");
    o = modified(o, "effects[3].parameters.stiffness", "100");
    o = modified(o, "simulation.threads", "4");
    o = modified(o, "expectations[0].comment", "\"head off\"");
    const QStringList paths{"colour",
                            "metadata.licence",
                            "tissues[0].meshing.quality",
                            "tissues[0].fixed_regions[0].label",
                            "tool.wire",
                            "strokes[0].poses[1].force",
                            "sweeps[0].colour",
                            "cut_settings.speed",
                            "effects[3].parameters.stiffness",
                            "simulation.threads",
                            "expectations[0].comment"};
    Scenario s;
    ScenarioDiagnostics d;
    QVERIFY2(parseScenario(bytes(o), "", "doc", s, d).ok(), qPrintable(issuesText(d)));
    QCOMPARE(d.errorCount(), 0);
    QCOMPARE(d.warningCount(), static_cast<int>(paths.size()));
    for (const QString& p : paths) {
        const ScenarioIssue* w = d.find(p.toStdString(), ScenarioIssue::Severity::Warning);
        QVERIFY2(w, qPrintable(p + "\n" + issuesText(d)));
        QVERIFY(QString::fromStdString(w->message).contains("unknown field"));
    }
    QCOMPARE(s.extra.value("colour").toString(), QString("blue"));
    QCOMPARE(s.tool.extra.value("wire").toObject().value("radius").toDouble(), 0.2);
    // Written back where they were found.
    const QJsonObject written = scenarioToJson(s);
    for (const QString& p : paths) {
        QJsonValue v = written;
        for (const QVariant& step : pathSteps(p))
            v = step.typeId() == QMetaType::Int ? v.toArray().at(step.toInt())
                                                : v.toObject().value(step.toString());
        QVERIFY2(!v.isUndefined(), qPrintable(p));
    }
}

void TestScenarioDocument::validationErrors_data() {
    QTest::addColumn<QString>("path");      // where the base document is changed
    QTest::addColumn<QByteArray>("value");  // the new JSON value, or <remove>
    QTest::addColumn<QString>("errorPath"); // where the error is reported
    QTest::addColumn<QString>("text");      // part of the message
    const auto row = [](const char* tag, const char* path, const char* value, const char* errorPath,
                        const char* text) {
        QTest::newRow(tag) << QString(path) << QByteArray(value) << QString(errorPath)
                           << QString(text);
    };

    row("format wrong", "format", "\"resect-mesh\"", "format", "not a scenario");
    row("format missing", "format", "<remove>", "format", "missing");
    row("version newer", "version", "2", "version", "newer");
    row("version fraction", "version", "1.5", "version", "integer");
    row("version string", "version", "\"1\"", "version", "got a string");
    row("version negative", "version", "-1", "version", "out of range");
    row("version missing", "version", "<remove>", "version", "missing");
    row("metadata not object", "metadata", "[]", "metadata", "expected an object");
    row("title not string", "metadata.title", "3", "metadata.title", "expected a string");
    row("objective not string", "metadata.learning_objectives[1]", "{}",
        "metadata.learning_objectives[1]", "expected a string");
    row("difficulty above 5", "metadata.difficulty", "7", "metadata.difficulty", "out of range");
    row("tissues missing", "tissues", "<remove>", "tissues", "missing");
    row("tissues empty", "tissues", "[]", "tissues", "at least one");
    row("tissue not object", "tissues[0]", "\"polyp\"", "tissues[0]", "expected an object");
    row("tissue name missing", "tissues[0].name", "<remove>", "tissues[0].name", "missing");
    row("tissue name empty", "tissues[0].name", "\"\"", "tissues[0].name", "empty");
    row("unknown sample", "tissues[0].surface", "\"sample:liver\"", "tissues[0].surface",
        "unknown sample 'liver'");
    row("surface file missing", "tissues[0].surface", "\"anatomy/polyp.obj\"", "tissues[0].surface",
        "file not found");
    row("mesh file missing", "tissues[0].mesh", "\"polyp.vtu\"", "tissues[0].mesh",
        "file not found");
    row("mesh and meshing", "tissues[0].mesh", "\"polyp.vtu\"", "tissues[0]",
        "either \"mesh\" or \"meshing\"");
    row("edge length negative", "tissues[0].meshing.edge_length", "-1",
        "tissues[0].meshing.edge_length", "out of range");
    row("seed fraction", "tissues[0].meshing.seed", "0.5", "tissues[0].meshing.seed", "integer");
    row("density negative", "tissues[0].material.density", "-0.001", "tissues[0].material.density",
        "out of range: -0.001");
    row("density zero", "tissues[0].material.density", "0", "tissues[0].material.density",
        "(0, 1]");
    row("density string", "tissues[0].material.density", "\"1e-3\"", "tissues[0].material.density",
        "expected a number, got a string");
    row("stiffness absurd", "tissues[0].material.stiffness", "1e300",
        "tissues[0].material.stiffness", "out of range");
    row("damping null", "tissues[0].material.damping", "null", "tissues[0].material.damping",
        "got null");
    row("fixed region inverted", "tissues[0].fixed_regions[0].max", "[5, -6, 1]",
        "tissues[0].fixed_regions[0]", "min exceeds max in y");
    row("fixed region short", "tissues[0].fixed_regions[0].min", "[1, 2]",
        "tissues[0].fixed_regions[0].min", "[x, y, z]");
    row("fixed region absurd", "tissues[0].fixed_regions[0].min[2]", "-1e200",
        "tissues[0].fixed_regions[0].min[2]", "out of range");
    row("tool curve one point", "tool.curve", "[[0, 0, 0]]", "tool.curve", "at least two");
    row("tool curve bad point", "tool.curve[1]", "[0, \"a\", 0]", "tool.curve[1][1]",
        "expected a number");
    row("tool size zero", "tool.size", "0", "tool.size", "out of range");
    row("tool missing", "tool", "<remove>", "tool", "strokes need a tool");
    row("stroke empty", "strokes[0].poses", "[]", "strokes[0].poses", "empty stroke");
    row("stroke one pose", "strokes[0].poses[2]", "<remove>", "", "");
    row("stroke poses missing", "strokes[0].poses", "<remove>", "strokes[0].poses", "missing");
    row("time stamps unsorted", "strokes[0].poses[1].t", "2", "strokes[0].poses[2].t",
        "must increase");
    row("time stamps equal", "strokes[0].poses[1].t", "0", "strokes[0].poses[1].t",
        "must increase");
    row("time missing", "strokes[0].poses[0].t", "<remove>", "strokes[0].poses[0].t", "missing");
    row("quaternion zero", "strokes[0].poses[0].orientation", "[0, 0, 0, 0]",
        "strokes[0].poses[0].orientation", "zero length");
    row("quaternion three numbers", "strokes[0].poses[0].orientation", "[1, 0, 0]",
        "strokes[0].poses[0].orientation", "quaternion");
    row("position absurd", "strokes[0].poses[1].position[0]", "1e300",
        "strokes[0].poses[1].position[0]", "out of range");
    row("tool does not move", "strokes[0].poses",
        R"([{"t": 0, "position": [0, 0, 0]}, {"t": 1, "position": [0, 0, 0]}])", "strokes[0]",
        "does not move");
    row("sweep curves of different lengths", "sweeps[0].curves[1]",
        "[[-10, 10, 5], [0, 10, 5], [10, 10, 5]]", "sweeps[0].curves[1]", "same count");
    row("sweep one curve", "sweeps[0].curves", "[[[0, 0, 0], [1, 0, 0]]]", "sweeps[0].curves",
        "at least two curves");
    row("sweep zero area", "sweeps[0].curves", "[[[0, 0, 0], [1, 0, 0]], [[0, 0, 0], [1, 0, 0]]]",
        "sweeps[0].curves", "not a usable sweep");
    row("sweep file and curves", "sweeps[0].file", "\"cut.json\"", "sweeps[0]", "not both");
    row("sweep neither", "sweeps[0].curves", "<remove>", "sweeps[0]", "missing");
    row("sweep file missing", "sweeps[0]", R"({"file": "cuts/first.json"})", "sweeps[0].file",
        "file not found");
    row("method unknown", "cut_settings.method", "\"laser\"", "cut_settings.method",
        "unknown value 'laser'");
    row("enhanced with subdivision", "cut_settings.method", "\"subdivision\"",
        "cut_settings.triangulation", "hybrid method only");
    row("d above 0.5", "cut_settings.d", "0.7", "cut_settings.d", "[0, 0.5]");
    row("d negative", "cut_settings.d", "-0.1", "cut_settings.d", "out of range");
    row("snap not bool", "cut_settings.snap", "1", "cut_settings.snap", "true or false");
    row("relax steps fraction", "cut_settings.relax_steps", "2.5", "cut_settings.relax_steps",
        "integer");
    row("relax damping zero", "cut_settings.damping", "0", "cut_settings.damping", "out of range");
    // The reader's ranges are the cutter's (CutLimits): a value it accepts never fails a cut.
    row("rings above the cutter's limit", "cut_settings.rings",
        QByteArray::number(CutLimits::kMaxRelaxRings + 1).constData(), "cut_settings.rings", "out of range");
    row("rings huge", "cut_settings.rings", "1000", "cut_settings.rings", "out of range");
    row("effect unknown", "effects[0].name", "\"magnetism\"", "effects[0].name", "unknown value");
    row("effect twice", "effects[1].name", "\"deformation\"", "effects[1].name", "twice");
    row("effect name missing", "effects[0].name", "<remove>", "effects[0].name", "missing");
    row("parameters not object", "effects[1].parameters", "[0, 0, -9810]", "effects[1].parameters",
        "expected an object");
    row("gravity short", "effects[1].parameters.acceleration", "[0, -9810]",
        "effects[1].parameters.acceleration", "[x, y, z]");
    row("deformation flag", "effects[0].parameters.distance", "\"yes\"",
        "effects[0].parameters.distance", "true or false");
    row("contact radius missing", "effects[3].parameters.radius", "<remove>",
        "effects[3].parameters.radius", "missing");
    row("contact radius negative", "effects[3].parameters.radius", "-0.2",
        "effects[3].parameters.radius", "out of range");
    row("damping without coefficient", "effects[4].parameters", "{}", "", "");
    row("fixed without regions", "tissues[0].fixed_regions", "[]", "effects[2]", "fixed_regions");
    row("integrator unknown", "simulation.integrator", "\"rk4\"", "simulation.integrator",
        "symplectic-euler, velocity-verlet, backward-euler");
    row("iterations zero", "simulation.iterations", "0", "simulation.iterations", "out of range");
    row("iterations fractional", "simulation.iterations", "2.5", "simulation.iterations", "expected an integer");
    row("time step word", "simulation.time_step", "\"fast\"", "simulation.time_step", "\"stable\"");
    row("time step zero", "simulation.time_step", "0", "simulation.time_step", "out of range");
    row("too many steps", "simulation.time_step", "1e-12", "simulation", "steps");
    row("duration negative", "simulation.duration", "-1", "simulation.duration", "out of range");
    row("expectation kind unknown", "expectations[0].kind", "\"looks_nice\"",
        "expectations[0].kind", "pieces_at_least");
    row("pieces zero", "expectations[0].value", "0", "expectations[0].value", "out of range");
    row("pieces fraction", "expectations[0].value", "2.5", "expectations[0].value", "integer");
    row("fraction above 1", "expectations[1].value", "1.5", "expectations[1].value", "[0, 1]");
    row("stays finite string", "expectations[3].value", "\"yes\"", "expectations[3].value",
        "true or false");
    row("expectation value missing", "expectations[2].value", "<remove>", "expectations[2].value",
        "missing");
    row("inverted negative", "expectations[4].value", "-1", "expectations[4].value",
        "out of range");
    row("expectation tissue unknown", "expectations[1].tissue", "\"myoma\"",
        "expectations[1].tissue", "no tissue named 'myoma'");
    row("list instead of object", "cut_settings", "[1]", "cut_settings", "expected an object");
    row("object instead of list", "strokes", "{}", "strokes", "expected an array");
}

void TestScenarioDocument::validationErrors() {
    QFETCH(QString, path);
    QFETCH(QByteArray, value);
    QFETCH(QString, errorPath);
    QFETCH(QString, text);
    QJsonObject o = modified(baseObject(), path, value);
    // Rows whose error sits elsewhere than the edit are completed here.
    if (QTest::currentDataTag() == QByteArray("stroke one pose")) {
        o = modified(o, "strokes[0].poses[1]", "<remove>");
        errorPath = "strokes[0].poses";
        text = "single pose";
    } else if (QTest::currentDataTag() == QByteArray("damping without coefficient")) {
        o = modified(o, "tissues[0].material.damping", "0");
        errorPath = "effects[4]";
        text = "no coefficient";
    }
    Scenario s;
    s.metadata.title = "untouched";
    ScenarioDiagnostics d;
    const Status st = parseScenario(bytes(o), "", "doc.json", s, d);
    QVERIFY2(!st.ok(), qPrintable(issuesText(d)));
    QVERIFY(d.hasErrors());
    QCOMPARE(s.metadata.title, std::string("untouched")); // unchanged on failure
    const ScenarioIssue* e = d.find(errorPath.toStdString());
    QVERIFY2(e, qPrintable("no error at '" + errorPath + "':\n" + issuesText(d)));
    QVERIFY2(QString::fromStdString(e->message).contains(text), e->message.c_str());
    // The Status names the file and the first error's path.
    QVERIFY2(QString::fromStdString(st.message()).startsWith("doc.json"), st.message().c_str());
}

void TestScenarioDocument::severalErrorsAtOnce() {
    QJsonObject o = baseObject();
    o = modified(o, "tissues[0].material.density", "-1");
    o = modified(o, "cut_settings.d", "0.9");
    o = modified(o, "strokes[0].poses[2].t", "0.25");
    o = modified(o, "sweeps[0].curves[1]", "[[0, 0, 0]]");
    o = modified(o, "effects[0].name", "\"wind\"");
    o = modified(o, "expectations[2].value", "-3");
    o = modified(o, "surplus", "1");
    Scenario s;
    ScenarioDiagnostics d;
    const Status st = parseScenario(bytes(o), "", "doc.json", s, d);
    QVERIFY(!st.ok());
    for (const char* p : {"tissues[0].material.density", "cut_settings.d", "strokes[0].poses[2].t",
                          "sweeps[0].curves[1]", "effects[0].name", "expectations[2].value"})
        QVERIFY2(d.find(p), qPrintable(QString(p) + "\n" + issuesText(d)));
    QCOMPARE(d.errorCount(), 6);
    QCOMPARE(d.warningCount(), 1);
    QVERIFY(d.find("surplus", ScenarioIssue::Severity::Warning));
    QVERIFY2(QString::fromStdString(st.message()).contains("and 5 more errors"),
             st.message().c_str());
    const QString report = issuesText(d);
    QCOMPARE(report.count("\n"), 7);
    QVERIFY(report.contains("doc: tissues[0].material.density: error: out of range"));
}

void TestScenarioDocument::malformedJson_data() {
    QTest::addColumn<QByteArray>("json");
    QTest::addColumn<QString>("text");
    QTest::newRow("empty") << QByteArray() << "not valid JSON";
    QTest::newRow("truncated") << QByteArray(kBaseDocument).left(300) << "offset";
    QTest::newRow("trailing garbage") << QByteArray(kBaseDocument) + "}"
                                      << "offset";
    QTest::newRow("array") << QByteArray("[1, 2]") << "expected a JSON object";
    QTest::newRow("number too large")
        << QByteArray(R"({"format": "resect-scenario", "version": 1e999})") << "";
    QTest::newRow("nul bytes") << QByteArray("{\"format\0\": 1}", 15) << "";
    QTest::newRow("deep nesting") << QByteArray(100000, '[') << "not valid JSON";
}

void TestScenarioDocument::malformedJson() {
    QFETCH(QByteArray, json);
    QFETCH(QString, text);
    Scenario s;
    ScenarioDiagnostics d;
    const Status st = parseScenario(json, "", "doc.json", s, d);
    QVERIFY(!st.ok());
    QVERIFY2(QString::fromStdString(st.message()).contains(text), st.message().c_str());
    QVERIFY(QString::fromStdString(st.message()).startsWith("doc.json"));
}

// The studio imports a tet mesh as a tissue without an embedded surface: such a document is
// valid, written without "surface" and read back equal; without "mesh" the surface is
// still required.
void TestScenarioDocument::aTissueMayBeItsTetMeshAlone() {
    QTemporaryDir dir;
    QVERIFY(dir.isValid());
    {
        QFile mesh(dir.filePath("m.vtu"));
        QVERIFY(mesh.open(QIODevice::WriteOnly)); // only its existence is checked here
    }
    const QByteArray json = R"({"format": "resect-scenario", "version": 1,
        "tissues": [{"name": "m", "mesh": "m.vtu"}]})";
    Scenario s;
    ScenarioDiagnostics d;
    QVERIFY2(parseScenario(json, dir.path().toStdString(), "mesh-only.json", s, d).ok(),
             qPrintable(issuesText(d)));
    QCOMPARE(s.tissues.front().surface, std::string());
    const QJsonObject written = scenarioToJson(s);
    QVERIFY(!written["tissues"].toArray()[0].toObject().contains("surface"));
    Scenario again;
    QVERIFY2(parseScenario(QJsonDocument(written).toJson(), dir.path().toStdString(), "again.json",
                           again, d)
                 .ok(),
             qPrintable(issuesText(d)));
    QVERIFY(again == s);

    const QByteArray neither = R"({"format": "resect-scenario", "version": 1,
        "tissues": [{"name": "m"}]})";
    QVERIFY(!parseScenario(neither, "", "neither.json", s, d).ok());
    QVERIFY2(d.find("tissues[0].surface"), qPrintable(issuesText(d)));
}

void TestScenarioDocument::absurdSizesAreCapped() {
    // 1,000,001 poses over two strokes: the second stroke, and every later one, is refused
    // with one message.
    QByteArray json = R"({"format": "resect-scenario", "version": 1,
        "tissues": [{"name": "m", "surface": "sample:myoma"}],
        "tool": {"curve": [[0, 0, 0], [1, 0, 0], [2, 0, 0]]}, "strokes": [)";
    for (int stroke = 0; stroke < 2; ++stroke) {
        json += stroke ? ",{\"poses\": [" : "{\"poses\": [";
        const int n = stroke ? 500001 : 500000;
        for (int i = 0; i < n; ++i) {
            json += i ? "," : "";
            json += "{\"t\":" + QByteArray::number(i) + ",\"position\":[0," +
                    QByteArray::number(i) + ",0]}";
        }
        json += "]}";
    }
    json += R"(,{"poses": [{"t": 0, "position": [0, 0, 0]}]})"; // one pose: not read either
    json += "]}";
    Scenario s;
    ScenarioDiagnostics d;
    QVERIFY(!parseScenario(json, "", "big.json", s, d).ok());
    const ScenarioIssue* e = d.find("strokes[1].poses");
    QVERIFY2(e, qPrintable(issuesText(d)));
    QVERIFY2(QString::fromStdString(e->message).contains("1000000 poses"), e->message.c_str());
    // The first stroke is read, but its sweep (1.5e6 vertices) is too large to build.
    QVERIFY2(d.find("strokes[0]") &&
                 QString::fromStdString(d.find("strokes[0]")->message).contains("limit"),
             qPrintable(issuesText(d)));
    QCOMPARE(d.errorCount(), 2);

    // A stroke whose sweep would be too large is refused before it is built.
    QByteArray tool = "[";
    for (int j = 0; j <= 200; ++j)
        tool += (j ? "," : "") + QByteArray("[") + QByteArray::number(j) + ",0,0]";
    tool += "]";
    QByteArray poses = "[";
    for (int i = 0; i < 5001; ++i)
        poses += (i ? "," : "") + QByteArray(R"({"t":)") + QByteArray::number(i) +
                 R"(,"position":[0,)" + QByteArray::number(i) + ",0]}";
    poses += "]";
    QJsonObject o = modified(modified(baseObject(), "tool.curve", tool), "strokes[0].poses", poses);
    QVERIFY(!parseScenario(bytes(o), "", "big.json", s, d).ok());
    QVERIFY2(d.find("strokes[0]") &&
                 QString::fromStdString(d.find("strokes[0]")->message).contains("limit"),
             qPrintable(issuesText(d)));

    // Thousands of problems: the report keeps the first kMaxIssues and counts the rest.
    QByteArray objectives = "[";
    for (int i = 0; i < 5000; ++i)
        objectives += i ? ",0" : "0";
    objectives += "]";
    QVERIFY(
        !parseScenario(bytes(modified(baseObject(), "metadata.learning_objectives", objectives)),
                       "", "doc", s, d)
             .ok());
    QCOMPARE(d.errorCount(), 5000);
    QCOMPARE(static_cast<int>(d.issues().size()), ScenarioDiagnostics::kMaxIssues);
    QCOMPARE(d.dropped(), 5000 - ScenarioDiagnostics::kMaxIssues);
    QVERIFY(issuesText(d).contains("4000 more problems"));
}

void TestScenarioDocument::damagedDocumentsNeverCrash() {
    // Truncations and byte changes of a valid document: every result is a clean success or
    // an error (the fuzz target goes much further).
    const QByteArray base = kBaseDocument;
    std::mt19937 rng(7);
    int failures = 0;
    for (int i = 0; i < 600; ++i) {
        QByteArray json = base;
        if (i % 3 == 0) {
            json.truncate(static_cast<int>(rng() % base.size()));
        } else {
            static const char kBytes[] = "{}[],:\"-0e9.x\\ \0";
            for (int k = 0; k < 1 + i % 4; ++k)
                json[static_cast<int>(rng() % json.size())] = kBytes[rng() % (sizeof(kBytes) - 1)];
        }
        Scenario s;
        ScenarioDiagnostics d;
        const Status st = parseScenario(json, "", "damaged", s, d);
        QCOMPARE(st.ok(), !d.hasErrors());
        failures += st.ok() ? 0 : 1;
    }
    QVERIFY(failures > 300);
}

void TestScenarioDocument::missingReferencedFiles() {
    QTemporaryDir dir;
    QVERIFY(QDir(dir.path()).mkdir("meshes"));
    QVERIFY(writeBytes(dir.filePath("meshes/polyp.vtu"), "placeholder"));
    QJsonObject o = modified(baseObject(), "tissues[0].meshing", "<remove>");
    o = modified(o, "tissues[0].mesh", "\"meshes/polyp.vtu\"");
    const QString file = dir.filePath("case.json");
    QVERIFY(writeBytes(file, bytes(o)));
    Scenario s;
    ScenarioDiagnostics d;
    QVERIFY2(loadScenario(file.toStdString(), s, d).ok(), qPrintable(issuesText(d)));
    QCOMPARE(resolveScenarioPath(s.baseDir, s.tissues[0].mesh),
             dir.filePath("meshes/polyp.vtu").toStdString());

    // Relative to the file's folder, not the current one: the same document one folder up
    // misses the mesh, and names where it looked.
    QVERIFY(QDir(dir.path()).mkdir("sub"));
    QVERIFY(writeBytes(dir.filePath("sub/case.json"), bytes(o)));
    QVERIFY(!loadScenario(dir.filePath("sub/case.json").toStdString(), s, d).ok());
    const ScenarioIssue* e = d.find("tissues[0].mesh");
    QVERIFY2(e, qPrintable(issuesText(d)));
    QVERIFY(QString::fromStdString(e->message).contains(dir.filePath("sub/meshes/polyp.vtu")));
    // A folder is not a file.
    o = modified(o, "tissues[0].mesh", "\"meshes\"");
    QVERIFY(writeBytes(file, bytes(o)));
    QVERIFY(!loadScenario(file.toStdString(), s, d).ok());
    QVERIFY(d.find("tissues[0].mesh") &&
            QString::fromStdString(d.find("tissues[0].mesh")->message).contains("folder"));
    // A damaged sweep file is reported at the sweep with the reader's message.
    QVERIFY(writeBytes(dir.filePath("bad-sweep.json"), R"({"curves": [[[0, 0, 0]]]})"));
    o = modified(baseObject(), "sweeps[0]", R"({"file": "bad-sweep.json"})");
    QVERIFY(writeBytes(file, bytes(o)));
    QVERIFY(!loadScenario(file.toStdString(), s, d).ok());
    QVERIFY2(d.find("sweeps[0].file"), qPrintable(issuesText(d)));
    // The scenario file itself.
    QVERIFY(!loadScenario(dir.filePath("nothing.json").toStdString(), s, d).ok());
    QVERIFY(!loadScenario(dir.path().toStdString(), s, d).ok());
}

void TestScenarioDocument::migratesVersion0() {
    // A hand-written version-0 document (layout in scenario_migrate.h).
    const QByteArray v0 = R"({
      "format": "resect-scenario", "version": 0,
      "title": "Old polyp case", "author": "Dr. A", "description": "from the first prototype",
      "tissue": {"surface": "sample:polyp", "edge_length": 2.5, "seed": 3,
                 "density": 0.0011, "stiffness": 500000, "damping": 1.5,
                 "fixed_box": [-5, -5, -1, 5, 5, 1], "colour": "pink"},
      "tool": {"points": [[-1, 0, 0], [0, 0, -1], [1, 0, 0]], "scale": 3},
      "strokes": [[{"t": 0, "position": [0, -10, 9], "rotation": [1, 0, 0, 0]},
                   {"t": 1, "position": [0, 10, 9], "rotation": [1, 0, 0, 0]}]],
      "cut": {"method": "hybrid", "threshold": 0.25, "snap": false, "relax_steps": 3},
      "effects": ["deformation", "gravity"],
      "integrator": "implicit", "time_step": 0.001, "duration": 2,
      "expect": {"pieces": 2, "min_radius_ratio": 0.02},
      "reviewed": true
    })";
    Scenario s;
    ScenarioDiagnostics d;
    QVERIFY2(parseScenario(v0, "", "old.json", s, d).ok(), qPrintable(issuesText(d)));
    const ScenarioIssue* w = d.find("version", ScenarioIssue::Severity::Warning);
    QVERIFY2(w && QString::fromStdString(w->message).contains("migrated"),
             qPrintable(issuesText(d)));
    // Unknown fields of the old layout are carried over and warned about at their new place.
    QVERIFY(d.find("tissues[0].colour", ScenarioIssue::Severity::Warning));
    QVERIFY(d.find("reviewed", ScenarioIssue::Severity::Warning));
    QCOMPARE(d.warningCount(), 3);

    Scenario expected;
    expected.metadata.title = "Old polyp case";
    expected.metadata.author = "Dr. A";
    expected.metadata.description = "from the first prototype";
    TissueSpec t;
    t.name = "tissue";
    t.surface = "sample:polyp";
    t.meshing.edgeLength = 2.5;
    t.meshing.seed = 3;
    t.material.density = 0.0011;
    t.material.stiffness = 500000;
    t.material.damping = 1.5;
    t.fixedRegions.push_back({Vec3(-5, -5, -1), Vec3(5, 5, 1), {}});
    t.extra["colour"] = "pink";
    expected.tissues.push_back(t);
    expected.tool.curve = {{-1, 0, 0}, {0, 0, -1}, {1, 0, 0}};
    expected.tool.size = 3;
    Stroke stroke;
    stroke.poses.push_back({0, Vec3(0, -10, 9), Eigen::Vector4d(1, 0, 0, 0), {}});
    stroke.poses.push_back({1, Vec3(0, 10, 9), Eigen::Vector4d(1, 0, 0, 0), {}});
    expected.strokes.push_back(stroke);
    expected.cut.d = 0.25;
    expected.cut.snap = false;
    expected.cut.relaxSteps = 3;
    expected.effects = {{"deformation", {}, {}}, {"gravity", {}, {}}};
    expected.simulation.integrator = "backward-euler";
    expected.simulation.timeStep = 0.001;
    expected.simulation.duration = 2;
    expected.expectations = {{ExpectationKind::PiecesAtLeast, 2, "", {}},
                             {ExpectationKind::MinRadiusRatioAtLeast, 0.02, "", {}}};
    expected.extra["reviewed"] = true;
    QVERIFY(s == expected);

    // Saved, it is a version-1 document.
    QTemporaryDir dir;
    const QString file = dir.filePath("new.json");
    QVERIFY(saveScenario(file.toStdString(), s).ok());
    const QJsonObject written = QJsonDocument::fromJson(readBytes(file)).object();
    QCOMPARE(written.value("version").toInt(), 1);
    QVERIFY(written.contains("tissues") && !written.contains("tissue") &&
            written.contains("cut_settings"));
    Scenario again;
    QVERIFY(loadScenario(file.toStdString(), again, d).ok());
    QVERIFY(again == s);
    QCOMPARE(d.warningCount(), 2); // the two unknown fields, no migration
}

void TestScenarioDocument::version0StructuralErrors() {
    const QByteArray v0 = R"({"format": "resect-scenario", "version": 0,
      "tissue": "polyp", "strokes": [{"t": 0}], "effects": ["gravity", 3],
      "cut": {"threshold": 0.9}, "integrator": "rk4", "expect": {"volume": 0.5}})";
    Scenario s;
    ScenarioDiagnostics d;
    QVERIFY(!parseScenario(v0, "", "old.json", s, d).ok());
    for (const char* p : {"tissue", "strokes[0]", "effects[1]", "integrator", "expect.volume",
                          "cut_settings.d" /* the migrated threshold, checked as d */})
        QVERIFY2(d.find(p), qPrintable(QString(p) + "\n" + issuesText(d)));
}

void TestScenarioDocument::saveIsAtomic() {
    QTemporaryDir dir;
    const QString file = dir.filePath("case.json");
    QVERIFY(writeBytes(file, "previous contents"));
    Scenario s;
    ScenarioDiagnostics d;
    QVERIFY(parseScenario(kBaseDocument, dir.path().toStdString(), "base", s, d).ok());

    // An invalid document is not written; the existing file and the folder are unchanged.
    Scenario bad = s;
    bad.cut.d = 3;
    bad.strokes[0].poses[1].t = -1;
    const QStringList before = entries(dir.path());
    const Status st = saveScenario(file.toStdString(), bad);
    QVERIFY(!st.ok());
    QVERIFY2(QString::fromStdString(st.message()).contains("strokes[0].poses[1].t"),
             st.message().c_str());
    QVERIFY2(QString::fromStdString(st.message()).contains("and 1 more error"),
             st.message().c_str());
    QVERIFY2(QString::fromStdString(st.message()).contains(file), st.message().c_str());
    QCOMPARE(readBytes(file), QByteArray("previous contents"));
    QCOMPARE(entries(dir.path()), before);

    // Values no file can hold (set in code) are refused too.
    Scenario nan = s;
    nan.tissues[0].material.density = std::numeric_limits<double>::quiet_NaN();
    nan.expectations[0].value = std::numeric_limits<double>::infinity();
    nan.tool.curve[0].x() = std::numeric_limits<double>::quiet_NaN();
    QVERIFY(!saveScenario(file.toStdString(), nan).ok());
    QCOMPARE(readBytes(file), QByteArray("previous contents"));

    // Neither a missing folder nor a folder as the target loses anything.
    QVERIFY(!saveScenario(dir.filePath("no/such/folder/case.json").toStdString(), s).ok());
    QVERIFY(QDir(dir.path()).mkdir("folder"));
    QVERIFY(!saveScenario(dir.filePath("folder").toStdString(), s).ok());
    QVERIFY(QFileInfo(dir.filePath("folder")).isDir());

    // A valid save replaces the file and leaves no temporary behind.
    QVERIFY(saveScenario(file.toStdString(), s).ok());
    QCOMPARE(entries(dir.path()), before + QStringList{"folder"});
    Scenario back;
    QVERIFY(loadScenario(file.toStdString(), back, d).ok());
    QVERIFY(back == s);
}

void TestScenarioDocument::saveToReadOnlyFolderKeepsFile() {
    Scenario s;
    ScenarioDiagnostics d;
    QTemporaryDir dir;
    QVERIFY(parseScenario(kBaseDocument, dir.path().toStdString(), "base", s, d).ok());
    if (geteuid() == 0) {
        // Root ignores folder permissions (CI runs as root): /proc/self is a folder no one can
        // create files in, and its `comm` an existing file with contents to keep.
        const QString file = QStringLiteral("/proc/self/comm");
        const QByteArray previous = readBytes(file);
        QVERIFY(!previous.isEmpty());
        const QStringList before = entries(QStringLiteral("/proc/self"));
        const Status st = saveScenario(file.toStdString(), s);
        QVERIFY(!st.ok());
        QVERIFY2(QString::fromStdString(st.message()).contains("temporary"), st.message().c_str());
        QCOMPARE(readBytes(file), previous);
        QCOMPARE(entries(QStringLiteral("/proc/self")), before);
        return;
    }
    const QString file = dir.filePath("case.json");
    QVERIFY(writeBytes(file, "previous contents"));
    QVERIFY(QFile::setPermissions(dir.path(), QFile::ReadOwner | QFile::ExeOwner));
    const Status st = saveScenario(file.toStdString(), s);
    QFile::setPermissions(dir.path(), QFile::ReadOwner | QFile::WriteOwner | QFile::ExeOwner);
    QVERIFY(!st.ok());
    QVERIFY2(QString::fromStdString(st.message()).contains("temporary"), st.message().c_str());
    QCOMPARE(readBytes(file), QByteArray("previous contents"));
    QCOMPARE(entries(dir.path()), QStringList{"case.json"});
}

void TestScenarioDocument::saveRebasesRelativePaths() {
    QTemporaryDir dir;
    QDir root(dir.path());
    QVERIFY(root.mkpath("cases/a/meshes") && root.mkpath("export/b"));
    QVERIFY(writeBytes(dir.filePath("cases/a/meshes/polyp.vtu"), "placeholder"));
    SweepSurface plane;
    QVERIFY(SweepSurface::fromStartEnd({{0, 0, 0}, {1, 0, 0}}, {{0, 1, 0}, {1, 1, 0}}, plane).ok());
    QVERIFY(writeSweep(dir.filePath("cases/shared-cut.json").toStdString(), plane).ok());
    QJsonObject o = modified(baseObject(), "tissues[0].meshing", "<remove>");
    o = modified(o, "tissues[0].mesh", "\"meshes/polyp.vtu\"");
    o = modified(o, "sweeps[0]", R"({"file": "../shared-cut.json"})");
    QJsonArray tissues = o["tissues"].toArray();
    QJsonObject absolute = tissues[0].toObject();
    absolute["name"] = "absolute";
    absolute["mesh"] = dir.filePath("cases/a/meshes/polyp.vtu");
    tissues.append(absolute);
    o["tissues"] = tissues;
    const QString source = dir.filePath("cases/a/case.json");
    QVERIFY(writeBytes(source, bytes(o)));
    Scenario s;
    ScenarioDiagnostics d;
    QVERIFY2(loadScenario(source.toStdString(), s, d).ok(), qPrintable(issuesText(d)));

    const QString target = dir.filePath("export/b/case.json");
    QVERIFY2(saveScenario(target.toStdString(), s).ok(),
             saveScenario(target.toStdString(), s).message().c_str());
    const QJsonObject written = QJsonDocument::fromJson(readBytes(target)).object();
    QCOMPARE(written["tissues"].toArray()[0].toObject()["mesh"].toString(),
             QString("../../cases/a/meshes/polyp.vtu"));
    QCOMPARE(written["tissues"].toArray()[0].toObject()["surface"].toString(),
             QString("sample:polyp"));
    QCOMPARE(written["tissues"].toArray()[1].toObject()["mesh"].toString(),
             dir.filePath("cases/a/meshes/polyp.vtu"));
    QCOMPARE(written["sweeps"].toArray()[0].toObject()["file"].toString(),
             QString("../../cases/shared-cut.json"));
    Scenario moved;
    QVERIFY2(loadScenario(target.toStdString(), moved, d).ok(), qPrintable(issuesText(d)));
    QCOMPARE(resolveScenarioPath(moved.baseDir, moved.tissues[0].mesh),
             resolveScenarioPath(s.baseDir, s.tissues[0].mesh));
    QCOMPARE(resolveScenarioPath(moved.baseDir, moved.sweeps[0].file),
             resolveScenarioPath(s.baseDir, s.sweeps[0].file));
    // The saved document differs only in its paths.
    Scenario rebased = s;
    rebaseScenarioPaths(rebased, dir.filePath("export/b").toStdString());
    QVERIFY(moved == rebased);
    QCOMPARE(rebased.baseDir, dir.filePath("export/b").toStdString());
    // A trailing separator names the same folder.
    Scenario again = s;
    rebaseScenarioPaths(again, dir.filePath("export/b/").toStdString());
    QVERIFY(again == rebased);
}

void TestScenarioDocument::toCutOptionsMapsEveryField() {
    CutSettings c;
    c.method = CutMethod::Subdivision;
    c.triangulation = FaceTriangulation::Standard;
    c.d = 0.3;
    c.snap = false;
    c.relaxSteps = 4;
    c.wSpring = 2;
    c.wParticle = 0.5;
    c.damping = 7;
    c.rings = 3;
    MaterialSpec m;
    m.density = 0.002;
    const CutOptions o = toCutOptions(c, m);
    QCOMPARE(o.method, CutMethod::Subdivision);
    QCOMPARE(o.triangulation, FaceTriangulation::Standard);
    QCOMPARE(o.d, 0.3);
    QCOMPARE(o.snap, false);
    QCOMPARE(o.relaxSteps, 4);
    QCOMPARE(o.wSpring, 2.0);
    QCOMPARE(o.wParticle, 0.5);
    QCOMPARE(o.relaxDamping, 7.0);
    QCOMPARE(o.relaxRings, 3);
    QCOMPARE(o.density, 0.002);
    // The improvement step: values other than the defaults, so that a field left out fails.
    c.improve = !CutOptions{}.improve;
    c.improveQuality = 2.5;
    c.improveShortEdge = 1.25;
    c.improveCoarsen = 0.75;
    const CutOptions improved = toCutOptions(c, m);
    QCOMPARE(improved.improve, !CutOptions{}.improve);
    QCOMPARE(improved.improveQuality, 2.5);
    QCOMPARE(improved.improveShortEdge, 1.25);
    QCOMPARE(improved.improveCoarsen, 0.75);
    QVERIFY(validateCutOptions(improved).ok());
}

void TestScenarioDocument::improvementDefaultsAreCutOptions_data() {
    QTest::addColumn<QByteArray>("cutSettings"); // the cut_settings object, improvement keys absent
    QTest::newRow("no cut_settings") << QByteArray("<remove>");
    QTest::newRow("empty cut_settings") << QByteArray("{}");
    QTest::newRow("hybrid") << QByteArray(R"({"method": "hybrid", "d": 0.3})");
    QTest::newRow("subdivision") << QByteArray(R"({"method": "subdivision"})");
}

void TestScenarioDocument::improvementDefaultsAreCutOptions() {
    QFETCH(QByteArray, cutSettings);
    const CutOptions defaults;
    // The struct's own defaults, then those of a document that leaves the keys out.
    const CutSettings fresh;
    QCOMPARE(fresh.improve, defaults.improve);
    QCOMPARE(fresh.improveQuality, defaults.improveQuality);
    QCOMPARE(fresh.improveShortEdge, defaults.improveShortEdge);
    QCOMPARE(fresh.improveCoarsen, defaults.improveCoarsen);

    Scenario s;
    ScenarioDiagnostics d;
    QVERIFY2(parseScenario(bytes(modified(baseObject(), "cut_settings", cutSettings)), "", "doc", s, d).ok(),
             qPrintable(issuesText(d)));
    QCOMPARE(d.warningCount(), 0);
    QCOMPARE(s.cut.improve, defaults.improve);
    QCOMPARE(s.cut.improveQuality, defaults.improveQuality);
    QCOMPARE(s.cut.improveShortEdge, defaults.improveShortEdge);
    QCOMPARE(s.cut.improveCoarsen, defaults.improveCoarsen);
    const CutOptions o = toCutOptions(s.cut, s.tissues[0].material);
    QCOMPARE(o.improve, defaults.improve);
    QCOMPARE(o.improveQuality, defaults.improveQuality);
    QCOMPARE(o.improveShortEdge, defaults.improveShortEdge);
    QCOMPARE(o.improveCoarsen, defaults.improveCoarsen);
    // Saving writes them (every field is written), with the default values.
    const QJsonObject written = scenarioToJson(s).value("cut_settings").toObject();
    QCOMPARE(written.value("improve").toBool(false), defaults.improve);
    QCOMPARE(written.value("improve_quality").toDouble(-1), defaults.improveQuality);
    QCOMPARE(written.value("improve_short_edge").toDouble(-1), defaults.improveShortEdge);
    QCOMPARE(written.value("improve_coarsen").toDouble(-1), defaults.improveCoarsen);
}

void TestScenarioDocument::improvementRoundTrip_data() {
    QTest::addColumn<bool>("improve");
    QTest::addColumn<double>("quality");
    QTest::addColumn<double>("shortEdge");
    QTest::addColumn<double>("coarsen");
    QTest::newRow("off, odd values") << false << 0.3 << 1.7 << 0.1;
    QTest::newRow("on, every criterion off") << true << 0.0 << 0.0 << 0.0;
    QTest::newRow("on, the upper limits")
        << true << CutLimits::kMaxImproveQuality << CutLimits::kMaxImproveShortEdge
        << CutLimits::kMaxImproveCoarsen;
    QTest::newRow("17 digits") << true << 0.30000000000000004 << 1.0000000000000002 << 0.1 + 0.2;
}

void TestScenarioDocument::improvementRoundTrip() {
    QFETCH(bool, improve);
    QFETCH(double, quality);
    QFETCH(double, shortEdge);
    QFETCH(double, coarsen);
    QTemporaryDir dir;
    QVERIFY(dir.isValid());
    Scenario a;
    ScenarioDiagnostics d;
    QVERIFY2(parseScenario(kBaseDocument, dir.path().toStdString(), "base", a, d).ok(),
             qPrintable(issuesText(d)));
    a.cut.improve = improve;
    a.cut.improveQuality = quality;
    a.cut.improveShortEdge = shortEdge;
    a.cut.improveCoarsen = coarsen;
    QVERIFY2(validateScenario(a, d).ok(), qPrintable(issuesText(d)));

    const std::string file = dir.filePath("improve.json").toStdString();
    QVERIFY(saveScenario(file, a).ok());
    const QJsonObject written =
        QJsonDocument::fromJson(readBytes(QString::fromStdString(file))).object().value("cut_settings").toObject();
    QCOMPARE(written.value("improve").toBool(!improve), improve);
    QCOMPARE(written.value("improve_quality").toDouble(-1), quality);
    QCOMPARE(written.value("improve_short_edge").toDouble(-1), shortEdge);
    QCOMPARE(written.value("improve_coarsen").toDouble(-1), coarsen);

    Scenario b;
    QVERIFY2(loadScenario(file, b, d).ok(), qPrintable(issuesText(d)));
    QCOMPARE(d.warningCount(), 0);
    QCOMPARE(b.cut.improve, improve);
    QCOMPARE(b.cut.improveQuality, quality);
    QCOMPARE(b.cut.improveShortEdge, shortEdge);
    QCOMPARE(b.cut.improveCoarsen, coarsen);
    QVERIFY(a == b);
    // Each field takes part in the comparison.
    for (int field = 0; field < 4; ++field) {
        Scenario c = b;
        switch (field) {
        case 0: c.cut.improve = !c.cut.improve; break;
        case 1: c.cut.improveQuality += 0.5; break;
        case 2: c.cut.improveShortEdge += 0.5; break;
        default: c.cut.improveCoarsen = c.cut.improveCoarsen > 0.5 ? 0.25 : 0.75; break;
        }
        QVERIFY2(!(c == b), qPrintable(QString::number(field)));
    }
}

void TestScenarioDocument::improvementOutOfRangeNamesKeyRangeAndValue_data() {
    QTest::addColumn<QString>("key");
    QTest::addColumn<QByteArray>("value"); // JSON
    QTest::addColumn<QString>("expected"); // the message's text after the path
    const auto range = [](double hi) {
        return QStringLiteral("[0, %1]").arg(QString::number(hi, 'g', QLocale::FloatingPointShortest));
    };
    const auto outOfRange = [&](const char* value, double hi) {
        return QStringLiteral("out of range: %1 (expected a number in %2)").arg(value, range(hi));
    };
    QTest::newRow("quality above the limit")
        << "improve_quality" << QByteArray("4.5") << outOfRange("4.5", CutLimits::kMaxImproveQuality);
    QTest::newRow("quality negative")
        << "improve_quality" << QByteArray("-0.1") << outOfRange("-0.1", CutLimits::kMaxImproveQuality);
    QTest::newRow("short edge above the limit")
        << "improve_short_edge" << QByteArray("12") << outOfRange("12", CutLimits::kMaxImproveShortEdge);
    QTest::newRow("short edge negative")
        << "improve_short_edge" << QByteArray("-2") << outOfRange("-2", CutLimits::kMaxImproveShortEdge);
    QTest::newRow("coarsen above the limit")
        << "improve_coarsen" << QByteArray("1.5") << outOfRange("1.5", CutLimits::kMaxImproveCoarsen);
    QTest::newRow("coarsen huge")
        << "improve_coarsen" << QByteArray("1e300") << outOfRange("1e+300", CutLimits::kMaxImproveCoarsen);
    QTest::newRow("quality a string")
        << "improve_quality" << QByteArray("\"1\"") << QStringLiteral("expected a number, got a string");
    QTest::newRow("improve a number")
        << "improve" << QByteArray("1") << QStringLiteral("expected true or false, got a number");
    QTest::newRow("improve null")
        << "improve" << QByteArray("null") << QStringLiteral("expected true or false, got null");
}

void TestScenarioDocument::improvementOutOfRangeNamesKeyRangeAndValue() {
    QFETCH(QString, key);
    QFETCH(QByteArray, value);
    QFETCH(QString, expected);
    const QString path = "cut_settings." + key;
    Scenario s;
    s.metadata.title = "untouched";
    ScenarioDiagnostics d;
    const Status st = parseScenario(bytes(modified(baseObject(), path, value)), "", "doc.json", s, d);
    QVERIFY(!st.ok());
    QCOMPARE(d.errorCount(), 1);
    QCOMPARE(s.metadata.title, std::string("untouched"));
    // The one line a user sees: the file, the key's path, the value and the range.
    QCOMPARE(QString::fromStdString(st.message()), "doc.json: " + path + ": " + expected);
}

void TestScenarioDocument::strokeCurves_data() {
    // Tool curve (-1, 0, 0), (0, 0, -1), (1, 0, 0), size 2; poses at (1, 2, 3) and (6, 7, 8)
    // (the motion leaves the loop's plane in every row, so each sweep is a proper surface).
    QTest::addColumn<Quaternion>("q");
    QTest::addColumn<std::vector<Vec3>>("firstCurve");
    const double h = std::sqrt(0.5);
    QTest::newRow("identity") << Quaternion{1, 0, 0, 0}
                              << std::vector<Vec3>{{-1, 2, 3}, {1, 2, 1}, {3, 2, 3}};
    QTest::newRow("90 degrees about z") << Quaternion{h, 0, 0, h} // x -> y
                                        << std::vector<Vec3>{{1, 0, 3}, {1, 2, 1}, {1, 4, 3}};
    QTest::newRow("90 degrees about y") << Quaternion{h, 0, h, 0} // z -> x, x -> -z
                                        << std::vector<Vec3>{{1, 2, 5}, {-1, 2, 3}, {1, 2, 1}};
    QTest::newRow("unnormalised 90 degrees about x")
        << Quaternion{3, 3, 0, 0} // y -> z, z -> -y
        << std::vector<Vec3>{{-1, 2, 3}, {1, 4, 3}, {3, 2, 3}};
}

void TestScenarioDocument::strokeCurves() {
    QFETCH(Quaternion, q);
    QFETCH(std::vector<Vec3>, firstCurve);
    Scenario s;
    s.tool.curve = {{-1, 0, 0}, {0, 0, -1}, {1, 0, 0}};
    s.tool.size = 2;
    Stroke stroke;
    const Eigen::Vector4d orientation(q[0], q[1], q[2], q[3]);
    stroke.poses.push_back({0, Vec3(1, 2, 3), orientation, {}});
    stroke.poses.push_back({1, Vec3(6, 7, 8), orientation, {}});
    s.strokes.push_back(stroke);
    const std::vector<Vec3> c = toolCurveAt(s.tool, stroke.poses[0]);
    QCOMPARE(c.size(), firstCurve.size());
    for (std::size_t j = 0; j < c.size(); ++j)
        QVERIFY2(
            near(c[j], firstCurve[j]),
            qPrintable(
                QString("point %1: %2 %3 %4").arg(j).arg(c[j].x()).arg(c[j].y()).arg(c[j].z())));

    SweepSurface sweep;
    const Status st = strokeSweep(s, 0, sweep);
    QVERIFY2(st.ok(), st.message().c_str());
    QCOMPARE(sweep.curveCount(), 2);
    QCOMPARE(sweep.pointsPerCurve(), 3);
    const auto curves = sweep.curves();
    for (std::size_t j = 0; j < firstCurve.size(); ++j) {
        QVERIFY(near(curves[0][j], firstCurve[j]));
        QVERIFY(near(curves[1][j], firstCurve[j] + Vec3(5, 5, 5)));
    }
    std::vector<ScenarioCut> cuts;
    QVERIFY(scenarioCuts(s, cuts).ok());
    QCOMPARE(cuts.size(), std::size_t(1));
    QCOMPARE(cuts[0].label, std::string("strokes[0]"));
}

void TestScenarioDocument::poseInterpolation() {
    Stroke stroke;
    const double h = std::sqrt(0.5);
    stroke.poses.push_back({1, Vec3(0, 0, 0), Eigen::Vector4d(1, 0, 0, 0), {}});
    stroke.poses.push_back({2, Vec3(4, 0, 0), Eigen::Vector4d(h, 0, 0, h), {}});
    stroke.poses.push_back({3, Vec3(4, 4, 0), Eigen::Vector4d(h, 0, 0, h), {}});
    const ToolPose mid = poseAt(stroke, 1.5);
    QVERIFY(near(mid.position, Vec3(2, 0, 0)));
    const double angle = 2 * std::acos(mid.orientation[0]);
    QVERIFY(std::abs(angle - M_PI / 4) < 1e-12);
    QVERIFY(near(poseAt(stroke, 2.5).position, Vec3(4, 2, 0)));
    QVERIFY(near(poseAt(stroke, -5).position, Vec3(0, 0, 0)));
    QVERIFY(near(poseAt(stroke, 9).position, Vec3(4, 4, 0)));
    QCOMPARE(poseAt(stroke, 2).t, 2.0);
}

void TestScenarioDocument::stillPosesAddNoCurve() {
    Scenario s;
    s.tool.curve = {{-1, 0, 0}, {1, 0, 0}};
    Stroke stroke;
    for (int i = 0; i < 4; ++i) // held still between t = 1 and t = 2
        stroke.poses.push_back(
            {double(i), Vec3(0, i < 2 ? 0.0 : 1.0 * i, 0), Eigen::Vector4d(1, 0, 0, 0), {}});
    stroke.poses[1].position = stroke.poses[0].position;
    s.strokes.push_back(stroke);
    SweepSurface sweep;
    QVERIFY(strokeSweep(s, 0, sweep).ok());
    QCOMPARE(sweep.curveCount(), 3);
    std::vector<SweepSurface> all;
    QVERIFY(strokeSweeps(s, all).ok());
    QCOMPARE(all.size(), std::size_t(1));
}

void TestScenarioDocument::nonUnitQuaternionsAreNormalised() {
    QJsonObject o = modified(baseObject(), "strokes[0].poses[0].orientation", "[2, 0, 0, 0]");
    o = modified(o, "strokes[0].poses[2].orientation", "[0.5, 0, 0, 0]");
    Scenario s;
    ScenarioDiagnostics d;
    QVERIFY2(parseScenario(bytes(o), "", "doc", s, d).ok(), qPrintable(issuesText(d)));
    QCOMPARE(d.warningCount(), 1); // once per stroke
    QVERIFY(d.find("strokes[0].poses[0].orientation", ScenarioIssue::Severity::Warning));
    QCOMPARE(s.strokes[0].poses[0].orientation, Eigen::Vector4d(2, 0, 0, 0)); // kept as written
    const std::vector<Vec3> c = toolCurveAt(s.tool, s.strokes[0].poses[0]);
    QVERIFY(near(c[1], Vec3(0, -10, 6))); // (0, 0, -1) * size 2 + (0, -10, 8), not rotated
}

void TestScenarioDocument::bundledExamplesLoad_data() {
    QTest::addColumn<QString>("file");
    QTest::newRow("polyp") << "polyp-resection.json";
    QTest::newRow("myoma") << "myoma-enucleation.json";
}

void TestScenarioDocument::bundledExamplesLoad() {
    QFETCH(QString, file);
    Scenario s;
    ScenarioDiagnostics d;
    QVERIFY2(loadScenario(resourcePath(file).toStdString(), s, d).ok(), qPrintable(issuesText(d)));
    QVERIFY2(d.issues().empty(), qPrintable(issuesText(d)));
    QCOMPARE(s.strokes.size(), std::size_t(3));
    QVERIFY(!s.metadata.title.empty() && !s.metadata.learningObjectives.empty());
    for (const char* e : {"deformation", "gravity", "tool-contact", "fixed"})
        QVERIFY2(s.findEffect(e), e);
    QVERIFY(!s.tissues[0].fixedRegions.empty());
    QCOMPARE(s.tool.curve.size(), std::size_t(9)); // a half loop of 8 segments
}

/// Every bundled example says what becomes of the pieces its cuts take off (issue 16: the
/// examples use remove or rigid chips), in the file itself rather than by the default.
void TestScenarioDocument::bundledExamplesSayWhatBecomesOfChips() {
    const QStringList files = QDir(resourcePath(QString())).entryList({"*.json"}, QDir::Files, QDir::Name);
    QVERIFY2(files.size() >= 3, qPrintable(files.join(", ")));
    for (const QString& file : files) {
        const QJsonObject raw = QJsonDocument::fromJson(readBytes(resourcePath(file))).object();
        const QString policy = raw.value("simulation").toObject().value("resected_pieces").toString();
        QVERIFY2(policy == "rigid" || policy == "remove", qPrintable(file + ": '" + policy + "'"));
        Scenario s;
        ScenarioDiagnostics d;
        QVERIFY2(loadScenario(resourcePath(file).toStdString(), s, d).ok(), qPrintable(issuesText(d)));
        QVERIFY2(d.issues().empty(), qPrintable(issuesText(d)));
        QCOMPARE(QString::fromStdString(s.simulation.resectedPieces), policy);
    }
}

void TestScenarioDocument::bundledStrokesCutTheSample_data() {
    bundledExamplesLoad_data();
}

void TestScenarioDocument::bundledStrokesCutTheSample() {
    QFETCH(QString, file);
    Scenario s;
    ScenarioDiagnostics d;
    QVERIFY(loadScenario(resourcePath(file).toStdString(), s, d).ok());
    const TissueSpec& tissue = s.tissues[0];
    TriangleSurface surface;
    QVERIFY(loadAnatomy(resolveScenarioPath(s.baseDir, tissue.surface), surface).ok());
    AnatomyMeshing meshing;
    meshing.meshing.edgeLength = tissue.meshing.edgeLength;
    meshing.meshing.seed = tissue.meshing.seed;
    meshing.material = tissue.material.toMaterial();
    TetMesh mesh;
    QVERIFY(meshAnatomy(surface, meshing, mesh).ok());
    // The fixed region holds part of the base.
    int fixedNodes = 0;
    for (int n = 0; n < mesh.nodeCount(); ++n)
        fixedNodes += tissue.fixedRegions[0].contains(mesh.ref(n)) ? 1 : 0;
    QVERIFY2(fixedNodes >= 3, qPrintable(QString::number(fixedNodes)));

    std::vector<ScenarioCut> cuts;
    QVERIFY(scenarioCuts(s, cuts).ok());
    QCOMPARE(cuts.size(), std::size_t(3));
    HybridCutter cutter(mesh);
    const CutOptions options = toCutOptions(s.cut, tissue.material);
    // Every stroke goes right through the tissue: each takes at least one more piece off.
    int pieces = connectedComponents(mesh).count;
    QCOMPARE(pieces, 1);
    for (const ScenarioCut& c : cuts) {
        CutResult result;
        const Status st = cutter.cut(c.sweep, options, result);
        QVERIFY2(st.ok(), (c.label + ": " + st.message()).c_str());
        const int after = connectedComponents(mesh).count;
        QVERIFY2(after > pieces, c.label.c_str());
        pieces = after;
    }
    const Measured m = measure(mesh, tissue);
    qInfo("%s: %d pieces, resected volume fraction %.4f, min radius ratio %.4f", qPrintable(file),
          m.pieces, m.resectedFraction, m.minRadiusRatio);
    QVERIFY(m.pieces >= 2);
    // The expectations the file declares for the cut hold.
    for (const Expectation& e : s.expectations) {
        switch (e.kind) {
        case ExpectationKind::PiecesAtLeast:
            QVERIFY(m.pieces >= e.value);
            break;
        case ExpectationKind::ResectedVolumeFractionAtLeast:
            QVERIFY(m.resectedFraction >= e.value);
            break;
        case ExpectationKind::MinRadiusRatioAtLeast:
            QVERIFY(m.minRadiusRatio >= e.value);
            break;
        default:
            break; // need the simulation (resect run)
        }
    }
}

QTEST_GUILESS_MAIN(TestScenarioDocument)
#include "test_scenario_document.moc"
