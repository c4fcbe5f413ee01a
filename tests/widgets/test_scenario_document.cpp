// ScenarioDocument (widgets/scenario_document.h): the studio's document model. Every edit
// does, undoes and redoes; numeric settings merge; the modified flag follows the undo stack;
// files round-trip, fail cleanly and atomically; recent files; autosave and recovery.

#include "widgets/scenario_document.h"

#include "core/mesher/samples.h"
#include "scenario/scenario_load.h"
#include "scenario/scene_defaults.h"

#include <QDateTime>
#include <QDir>
#include <QFile>
#include <QFileInfo>
#include <QJsonArray>
#include <QSettings>
#include <QSignalSpy>
#include <QTemporaryDir>
#include <QTest>

#include <functional>
#include <memory>

using namespace resect;

namespace {

QByteArray readAll(const QString& path) {
    QFile file(path);
    if (!file.open(QIODevice::ReadOnly))
        return {};
    return file.readAll();
}

bool writeAll(const QString& path, const QByteArray& bytes) {
    QFile file(path);
    return file.open(QIODevice::WriteOnly) && file.write(bytes) == bytes.size();
}

Stroke sampleStroke(const char* name, double x) {
    Stroke s;
    s.name = name;
    for (int i = 0; i < 3; ++i) {
        ToolPose p;
        p.t = 0.2 * i;
        // Across the loop's plane (the tool curve lies in x-z), so the sweep is not flat.
        p.position = Vec3(x, -8 + 8 * i, 10);
        s.poses.push_back(p);
    }
    return s;
}

SweepSpec sampleSweep(const char* name) {
    SweepSpec s;
    s.name = name;
    s.curves = {{Vec3(-10, 0, 5), Vec3(10, 0, 5)}, {Vec3(-10, 0, 15), Vec3(10, 0, 15)}};
    return s;
}

using Signal = void (ScenarioDocument::*)();

/// One edit: `prepare` sets the document up (not undoable afterwards), `edit` is the edit
/// under test, `signal` the specific signal it must emit.
struct EditCase {
    const char* name;
    std::function<void(ScenarioDocument&)> prepare;
    std::function<void(ScenarioDocument&)> edit;
    Signal signal;
};

} // namespace

class TestScenarioDocument : public QObject {
    Q_OBJECT

private:
    std::unique_ptr<QTemporaryDir> m_dir;
    std::unique_ptr<QSettings> m_settings;

    /// A document using this test's settings and autosave folder.
    std::unique_ptr<ScenarioDocument> makeDocument() {
        auto doc = std::make_unique<ScenarioDocument>();
        doc->setSettings(m_settings.get());
        doc->setAutosaveDirectory(m_dir->filePath("autosave"));
        return doc;
    }
    QString path(const QString& name) const { return m_dir->filePath(name); }

private slots:
    void init() {
        m_dir = std::make_unique<QTemporaryDir>();
        QVERIFY(m_dir->isValid());
        m_settings = std::make_unique<QSettings>(path("settings.ini"), QSettings::IniFormat);
    }
    void cleanup() {
        m_settings.reset();
        m_dir.reset();
    }

    void newFromSample_data() {
        QTest::addColumn<QString>("name");
        QTest::newRow("polyp") << "polyp";
        QTest::newRow("myoma") << "myoma";
    }
    void newFromSample() {
        QFETCH(QString, name);
        auto doc = makeDocument();
        QSignalSpy reset(doc.get(), &ScenarioDocument::documentReset);
        QVERIFY(doc->newFromSample(name));
        QCOMPARE(reset.count(), 1);
        const Scenario& s = doc->scenario();
        QCOMPARE(s.tissues.size(), std::size_t(1));
        QCOMPARE(QString::fromStdString(s.tissues[0].surface), "sample:" + name);
        QVERIFY(!s.tool.curve.empty());
        QVERIFY(!doc->isModified());
        QVERIFY(doc->filePath().isEmpty());
        QCOMPARE(doc->undoStack()->count(), 0);
        ScenarioDiagnostics diag;
        const Status valid = validateScenario(s, diag);
        QVERIFY2(valid.ok(), valid.message().c_str());
    }

    void newFromUnknownSampleFails() {
        auto doc = makeDocument();
        QVERIFY(doc->newFromSample("polyp"));
        const Scenario before = doc->scenario();
        QString error;
        QVERIFY(!doc->newFromSample("liver", &error));
        QVERIFY2(error.contains("liver"), qPrintable(error));
        QVERIFY(doc->scenario() == before);
    }

    void editDoesUndoesRedoes() {
        const auto nothing = [](ScenarioDocument&) {};
        const auto withStrokeAndSweep = [](ScenarioDocument& d) {
            d.addStroke(sampleStroke("first", 0));
            d.addStroke(sampleStroke("second", 2));
            d.addSweep(sampleSweep("a"));
            d.addSweep(sampleSweep("b"));
        };
        const std::vector<EditCase> cases{
            {"d", nothing, [](ScenarioDocument& d) { d.setD(0.3); },
             &ScenarioDocument::cutSettingsChanged},
            {"method", nothing,
             [](ScenarioDocument& d) {
                 d.setTriangulation(FaceTriangulation::Standard);
                 d.setMethod(CutMethod::Subdivision);
             },
             &ScenarioDocument::cutSettingsChanged},
            {"triangulation", nothing,
             [](ScenarioDocument& d) { d.setTriangulation(FaceTriangulation::Standard); },
             &ScenarioDocument::cutSettingsChanged},
            {"snap", nothing, [](ScenarioDocument& d) { d.setSnap(false); },
             &ScenarioDocument::cutSettingsChanged},
            {"relax steps", nothing, [](ScenarioDocument& d) { d.setRelaxSteps(3); },
             &ScenarioDocument::cutSettingsChanged},
            {"w_spring", nothing, [](ScenarioDocument& d) { d.setWSpring(2); },
             &ScenarioDocument::cutSettingsChanged},
            {"w_particle", nothing, [](ScenarioDocument& d) { d.setWParticle(0.5); },
             &ScenarioDocument::cutSettingsChanged},
            {"damping", nothing, [](ScenarioDocument& d) { d.setRelaxDamping(4); },
             &ScenarioDocument::cutSettingsChanged},
            {"rings", nothing, [](ScenarioDocument& d) { d.setRings(3); },
             &ScenarioDocument::cutSettingsChanged},
            {"improve", nothing, [](ScenarioDocument& d) { d.setImprove(false); },
             &ScenarioDocument::cutSettingsChanged},
            {"improve quality", nothing, [](ScenarioDocument& d) { d.setImproveQuality(2); },
             &ScenarioDocument::cutSettingsChanged},
            {"improve short edge", nothing, [](ScenarioDocument& d) { d.setImproveShortEdge(1.5); },
             &ScenarioDocument::cutSettingsChanged},
            {"improve coarsen", nothing, [](ScenarioDocument& d) { d.setImproveCoarsen(0.1); },
             &ScenarioDocument::cutSettingsChanged},
            {"all cut settings", nothing,
             [](ScenarioDocument& d) {
                 CutSettings s;
                 s.d = 0.1;
                 s.snap = false;
                 d.setCutSettings(s);
             },
             &ScenarioDocument::cutSettingsChanged},
            {"add stroke", withStrokeAndSweep,
             [](ScenarioDocument& d) { d.addStroke(sampleStroke("middle", 1), 1); },
             &ScenarioDocument::strokesChanged},
            {"remove stroke", withStrokeAndSweep,
             [](ScenarioDocument& d) { QVERIFY(d.removeStroke(0)); },
             &ScenarioDocument::strokesChanged},
            {"add sweep", withStrokeAndSweep,
             [](ScenarioDocument& d) { d.addSweep(sampleSweep("c"), 0); },
             &ScenarioDocument::sweepsChanged},
            {"remove sweep", withStrokeAndSweep,
             [](ScenarioDocument& d) { QVERIFY(d.removeSweep(1)); },
             &ScenarioDocument::sweepsChanged},
            {"effect on", nothing,
             [](ScenarioDocument& d) { QVERIFY(d.setEffectEnabled("gravity", true)); },
             &ScenarioDocument::effectsChanged},
            {"effect off", nothing,
             [](ScenarioDocument& d) { QVERIFY(d.toggleEffect("deformation")); },
             &ScenarioDocument::effectsChanged},
            {"title", nothing, [](ScenarioDocument& d) { d.setTitle("Another title"); },
             &ScenarioDocument::metadataChanged},
            {"effect parameters", nothing,
             [](ScenarioDocument& d) {
                 QVERIFY(d.setEffectParameters("damping", QJsonObject{{"coefficient", 5.0}}));
             },
             &ScenarioDocument::effectsChanged},
            {"add fixed region", nothing,
             [](ScenarioDocument& d) { QVERIFY(d.addFixedRegion(FixedRegion{Vec3(0, 0, 0), Vec3(1, 1, 1), {}})); },
             &ScenarioDocument::fixedRegionsChanged},
            {"change fixed region", nothing,
             [](ScenarioDocument& d) {
                 FixedRegion r = d.fixedRegions().front();
                 r.max.z() += 1;
                 QVERIFY(d.setFixedRegion(0, r));
             },
             &ScenarioDocument::fixedRegionsChanged},
            {"remove the last fixed region", nothing,
             [](ScenarioDocument& d) { QVERIFY(d.removeFixedRegion(0)); },
             &ScenarioDocument::fixedRegionsChanged},
        };
        for (const EditCase& c : cases) {
            auto doc = makeDocument();
            QVERIFY(doc->newFromSample("polyp"));
            c.prepare(*doc);
            doc->undoStack()->clear();
            const Scenario before = doc->scenario();

            QSignalSpy specific(doc.get(), c.signal);
            QSignalSpy changed(doc.get(), &ScenarioDocument::changed);
            c.edit(*doc);
            const Scenario after = doc->scenario();
            QVERIFY2(!(after == before), c.name);
            QVERIFY2(doc->undoStack()->count() >= 1, c.name);
            QVERIFY2(specific.count() >= 1 && changed.count() >= 1, c.name);
            const int signalsPerDo = specific.count();

            while (doc->undoStack()->canUndo())
                doc->undoStack()->undo();
            QVERIFY2(doc->scenario() == before, c.name);
            QCOMPARE(specific.count(), 2 * signalsPerDo);
            while (doc->undoStack()->canRedo())
                doc->undoStack()->redo();
            QVERIFY2(doc->scenario() == after, c.name);
            QCOMPARE(specific.count(), 3 * signalsPerDo);
        }
    }

    void editsKeepOrderAndContent() {
        auto doc = makeDocument();
        QVERIFY(doc->newFromSample("polyp"));
        doc->addStroke(sampleStroke("a", 0));
        doc->addStroke(sampleStroke("c", 2));
        doc->addStroke(sampleStroke("b", 1), 1);
        QCOMPARE(doc->scenario().strokes[1].name, std::string("b"));
        QVERIFY(!doc->removeStroke(3));
        QVERIFY(!doc->removeSweep(0));
        QVERIFY(!doc->setEffectEnabled("levitation", true));

        // Effects stay in the documented order; one switched back on keeps its parameters.
        // (A new sample has deformation, fixed and damping on.)
        QVERIFY(doc->setEffectEnabled("tool-contact", true));
        QVERIFY(doc->setEffectEnabled("gravity", true));
        const auto& effects = doc->scenario().effects;
        QCOMPARE(effects.size(), std::size_t(5));
        QCOMPARE(effects[1].name, std::string("gravity"));
        QCOMPARE(effects[3].name, std::string("tool-contact"));
        QCOMPARE(effects[3].number("radius", 0), ScenarioDocument::kDefaultToolContactRadius);
        const int steps = doc->undoStack()->count();
        QVERIFY(doc->setEffectEnabled("gravity", true)); // already on: nothing to do
        QCOMPARE(doc->undoStack()->count(), steps);
    }

    // Issue 19: a new scene from a sample behaves when simulated: its base is anchored by a
    // box around the bottom few percent of its height, and damping is on with a coefficient.
    void aNewSampleSceneHasItsBaseFixedAndDamping_data() {
        QTest::addColumn<QString>("name");
        QTest::newRow("polyp") << "polyp";
        QTest::newRow("myoma") << "myoma";
    }
    void aNewSampleSceneHasItsBaseFixedAndDamping() {
        QFETCH(QString, name);
        auto doc = makeDocument();
        QVERIFY(doc->newFromSample(name));
        const Scenario& s = doc->scenario();
        QVERIFY(doc->isEffectEnabled("deformation"));
        QVERIFY(doc->isEffectEnabled("fixed"));
        QVERIFY(doc->isEffectEnabled("damping"));
        QVERIFY(!doc->isEffectEnabled("gravity"));
        QCOMPARE(s.findEffect("damping")->number("coefficient", 0), kDefaultDampingCoefficient);
        QVERIFY(kDefaultDampingCoefficient > 0);
        QCOMPARE(doc->fixedRegions().size(), std::size_t(1));
        // The box: the sample's bottom kBaseRegionFraction of its height, wider than it.
        const TriangleSurface surface = sampleSurface(*sampleFromName(name.toStdString()));
        Vec3 lo = surface.positions.front(), hi = lo;
        for (const Vec3& p : surface.positions) {
            lo = lo.cwiseMin(p);
            hi = hi.cwiseMax(p);
        }
        const FixedRegion& box = doc->fixedRegions().front();
        QVERIFY(box.min.x() < lo.x() && box.min.y() < lo.y() && box.min.z() < lo.z());
        QVERIFY(box.max.x() > hi.x() && box.max.y() > hi.y());
        QVERIFY(std::abs(box.max.z() - (lo.z() + kBaseRegionFraction * (hi.z() - lo.z()))) < 1e-9 * (hi - lo).norm());
        ScenarioDiagnostics diag;
        const Status valid = validateScenario(s, diag);
        QVERIFY2(valid.ok(), valid.message().c_str());
        // An imported anatomy's base is unknown before it is loaded: damping only.
        auto anatomy = makeDocument();
        const QString file = path("tissue.obj");
        QVERIFY(writeAll(file, "v 0 0 0\n"));
        QVERIFY(anatomy->newFromAnatomy(file));
        QVERIFY(anatomy->isEffectEnabled("damping"));
        QVERIFY(!anatomy->isEffectEnabled("fixed"));
        QVERIFY(anatomy->fixedRegions().empty());
    }

    void effectsStartWithParametersThatRun() {
        // Every effect switched on for the first time has the parameters it needs (a new
        // anatomy scene: nothing on but deformation and damping).
        auto doc = makeDocument();
        const QString file = path("tissue.obj");
        QVERIFY(writeAll(file, "v 0 0 0\n"));
        QVERIFY(doc->newFromAnatomy(file));
        for (const char* name : {"gravity", "tool-contact"})
            QVERIFY(doc->setEffectEnabled(name, true));
        QCOMPARE(doc->scenario().findEffect("gravity")->vector("acceleration", Vec3::Zero()),
                 Vec3(0, 0, -kDefaultGravity));
        QCOMPARE(doc->scenario().findEffect("tool-contact")->number("radius", 0), kDefaultToolContactRadius);
        ScenarioDiagnostics diag;
        const Status valid = validateScenario(doc->scenario(), diag);
        QVERIFY2(valid.ok(), valid.message().c_str());
        // Switching damping off and on again keeps an edited coefficient.
        QVERIFY(doc->setEffectParameters("damping", QJsonObject{{"coefficient", 3.0}}));
        QVERIFY(doc->setEffectEnabled("damping", false));
        QVERIFY(!doc->setEffectParameters("damping", QJsonObject{{"coefficient", 4.0}})); // off
        QVERIFY(doc->setEffectEnabled("damping", true));
        QCOMPARE(doc->scenario().findEffect("damping")->number("coefficient", 0), 3.0);
    }

    void fixedRegionEditsAreUndoSteps() {
        auto doc = makeDocument();
        QVERIFY(doc->newFromSample("polyp"));
        const FixedRegion base = doc->fixedRegions().front();
        // Typing into one box's numbers is one undo step; another box starts another.
        FixedRegion r = base;
        for (double z : {1.5, 2.0, 2.5}) {
            r.max.z() = z;
            QVERIFY(doc->setFixedRegion(0, r));
        }
        QCOMPARE(doc->undoStack()->count(), 1);
        QVERIFY(doc->addFixedRegion(FixedRegion{Vec3(-1, -1, 5), Vec3(1, 1, 6), {}}));
        QCOMPARE(doc->undoStack()->count(), 2);
        QVERIFY(!doc->setFixedRegion(2, r));
        QVERIFY(!doc->removeFixedRegion(-1));
        doc->undoStack()->undo();
        doc->undoStack()->undo();
        QVERIFY(doc->fixedRegions() == std::vector<FixedRegion>{base});

        // Removing the last box switches the fixed effect off with it (one step); fixRegion
        // switches it on again with a box (one step).
        QVERIFY(doc->removeFixedRegion(0));
        QVERIFY(doc->fixedRegions().empty());
        QVERIFY(!doc->isEffectEnabled("fixed"));
        QCOMPARE(doc->undoStack()->index(), 1);
        QVERIFY(doc->fixRegion(base));
        QVERIFY(doc->isEffectEnabled("fixed"));
        QVERIFY(doc->fixedRegions() == std::vector<FixedRegion>{base});
        QCOMPARE(doc->undoStack()->index(), 2);
        doc->undoStack()->undo();
        QVERIFY(doc->fixedRegions().empty());
        QVERIFY(!doc->isEffectEnabled("fixed"));
        doc->undoStack()->undo();
        QVERIFY(doc->fixedRegions() == std::vector<FixedRegion>{base});
        QVERIFY(doc->isEffectEnabled("fixed"));
        ScenarioDiagnostics diag;
        QVERIFY(validateScenario(doc->scenario(), diag).ok());
    }

    void effectParameterEditsMerge() {
        auto doc = makeDocument();
        QVERIFY(doc->newFromSample("polyp"));
        for (double c : {21.0, 22.0, 30.0})
            QVERIFY(doc->setEffectParameters("damping", QJsonObject{{"coefficient", c}}));
        QCOMPARE(doc->undoStack()->count(), 1);
        QVERIFY(doc->setEffectEnabled("gravity", true));
        QVERIFY(doc->setEffectParameters("gravity", QJsonObject{{"acceleration", QJsonArray{0, 0, -1000}}}));
        QCOMPARE(doc->undoStack()->count(), 3);
        // Back to where it started: the merged step disappears.
        QVERIFY(doc->setEffectParameters("gravity", defaultEffectParameters("gravity")));
        QCOMPARE(doc->undoStack()->count(), 2);
        doc->undoStack()->undo();
        doc->undoStack()->undo();
        QCOMPARE(doc->scenario().findEffect("damping")->number("coefficient", 0), kDefaultDampingCoefficient);
    }

    void consecutiveNumericEditsMerge() {
        auto doc = makeDocument();
        QVERIFY(doc->newFromSample("polyp"));
        for (double d : {0.21, 0.25, 0.3, 0.35})
            doc->setD(d);
        QCOMPARE(doc->undoStack()->count(), 1);
        QCOMPARE(doc->scenario().cut.d, 0.35);
        doc->setRelaxSteps(4); // another setting: a new step
        doc->setRelaxSteps(5);
        QCOMPARE(doc->undoStack()->count(), 2);
        doc->setD(0.1); // d again, but not consecutive: a new step
        QCOMPARE(doc->undoStack()->count(), 3);
        doc->undoStack()->undo();
        doc->undoStack()->undo();
        QCOMPARE(doc->scenario().cut.relaxSteps, 10);
        QCOMPARE(doc->scenario().cut.d, 0.35);
        doc->undoStack()->undo();
        QCOMPARE(doc->scenario().cut.d, 0.2);

        // Method is not numeric: every change is a step.
        auto other = makeDocument();
        QVERIFY(other->newFromSample("polyp"));
        other->setTriangulation(FaceTriangulation::Standard);
        other->setTriangulation(FaceTriangulation::Enhanced);
        QCOMPARE(other->undoStack()->count(), 2);
        // Dragging d away and back leaves no step; so does setting the same value.
        other->setD(0.3);
        other->setD(0.2);
        other->setD(0.2);
        QCOMPARE(other->undoStack()->count(), 2);

        // The improvement's factors merge each with itself, not with one another; its switch
        // does not merge.
        auto improvement = makeDocument();
        QVERIFY(improvement->newFromSample("polyp"));
        improvement->setImproveQuality(1.5);
        improvement->setImproveQuality(2);
        improvement->setImproveShortEdge(1);
        improvement->setImproveShortEdge(1.25);
        improvement->setImproveCoarsen(0.25);
        improvement->setImproveCoarsen(0.3);
        QCOMPARE(improvement->undoStack()->count(), 3);
        improvement->setImprove(false);
        improvement->setImprove(true);
        QCOMPARE(improvement->undoStack()->count(), 5);
        improvement->undoStack()->setIndex(3);
        QCOMPARE(improvement->scenario().cut.improve, true);
        QCOMPARE(improvement->scenario().cut.improveQuality, 2.0);
        QCOMPARE(improvement->scenario().cut.improveCoarsen, 0.3);
        improvement->undoStack()->setIndex(0);
        QVERIFY(improvement->scenario().cut == CutSettings{});
    }

    void mergeStopsAtSave() {
        auto doc = makeDocument();
        QVERIFY(doc->newFromSample("polyp"));
        doc->setD(0.3);
        QString error;
        QVERIFY2(doc->saveAs(path("s.json"), &error), qPrintable(error));
        doc->setD(0.4);
        QCOMPARE(doc->undoStack()->count(), 2);
        doc->undoStack()->undo();
        QCOMPARE(doc->scenario().cut.d, 0.3);
        QVERIFY(!doc->isModified());
    }

    void modifiedFlagAndSignals() {
        auto doc = makeDocument();
        QVERIFY(doc->newFromSample("polyp"));
        QSignalSpy modified(doc.get(), &ScenarioDocument::modifiedChanged);
        QSignalSpy file(doc.get(), &ScenarioDocument::fileChanged);
        doc->setTitle("T");
        QVERIFY(doc->isModified());
        QCOMPARE(modified.count(), 1);
        QCOMPARE(modified.last().at(0).toBool(), true);
        doc->setTitle("Ti"); // merges: still one step, no new signal
        QCOMPARE(doc->undoStack()->count(), 1);
        QCOMPARE(modified.count(), 1);
        doc->undoStack()->undo();
        QVERIFY(!doc->isModified());
        QCOMPARE(modified.last().at(0).toBool(), false);
        doc->undoStack()->redo();
        QVERIFY(doc->isModified());

        const QString target = path("m.json");
        QVERIFY(doc->saveAs(target));
        QVERIFY(!doc->isModified());
        QCOMPARE(modified.last().at(0).toBool(), false);
        QCOMPARE(file.count(), 1);
        QCOMPARE(file.last().at(0).toString(), QFileInfo(target).absoluteFilePath());
        QCOMPARE(doc->filePath(), QFileInfo(target).absoluteFilePath());
        QCOMPARE(doc->displayName(), QString("m.json"));

        doc->undoStack()->undo(); // before the save: modified again
        QVERIFY(doc->isModified());
        doc->close();
        QVERIFY(!doc->isModified());
        QVERIFY(doc->filePath().isEmpty());
        QCOMPARE(doc->undoStack()->count(), 0);
    }

    void saveOpenRoundTrip() {
        auto doc = makeDocument();
        QVERIFY(doc->newFromSample("myoma"));
        doc->addStroke(sampleStroke("pull", 0));
        doc->addSweep(sampleSweep("slice"));
        doc->setEffectEnabled("gravity", true);
        doc->setD(0.15);
        doc->setTitle("Round trip");
        QString error;
        const QString target = path("sub/round.json");
        QVERIFY(QDir().mkpath(path("sub")));
        QVERIFY2(doc->saveAs(target, &error), qPrintable(error));

        auto reopened = makeDocument();
        QSignalSpy reset(reopened.get(), &ScenarioDocument::documentReset);
        QVERIFY2(reopened->open(target, &error), qPrintable(error));
        QCOMPARE(reset.count(), 1);
        QVERIFY(reopened->scenario() == doc->scenario());
        QVERIFY(!reopened->isModified());
        QCOMPARE(reopened->filePath(), QFileInfo(target).absoluteFilePath());

        // A bundled example survives open -> save as -> open unchanged.
        const QString example = QStringLiteral(RESECT_SOURCE_DIR) +
                                "/resources/scenarios/polyp-resection.json";
        QVERIFY2(doc->open(example, &error), qPrintable(error));
        QVERIFY2(doc->saveAs(path("copy.json"), &error), qPrintable(error));
        QVERIFY2(reopened->open(path("copy.json"), &error), qPrintable(error));
        QVERIFY(reopened->scenario() == doc->scenario());
    }

    void sweepFileKeepsNamingTheSameFileAcrossSaveAs() {
        auto doc = makeDocument();
        QVERIFY(doc->newFromSample("polyp"));
        QVERIFY(QDir().mkpath(path("a")));
        QVERIFY(QDir().mkpath(path("b")));
        QVERIFY(writeAll(path("a/cut.json"),
                         R"({"curves": [[[-10, 0, 5], [10, 0, 5]], [[-10, 0, 15], [10, 0, 15]]]})"));
        QString error;
        QVERIFY2(doc->saveAs(path("a/s.json"), &error), qPrintable(error));
        SweepSpec sweep;
        sweep.name = "from file";
        sweep.file = "cut.json";
        doc->addSweep(sweep);
        QVERIFY2(doc->saveAs(path("b/s.json"), &error), qPrintable(error));
        QCOMPARE(doc->scenario().sweeps[0].file, std::string("../a/cut.json"));
        doc->undoStack()->undo();
        doc->undoStack()->redo(); // re-added after the document moved to b/
        QCOMPARE(doc->scenario().sweeps[0].file, std::string("../a/cut.json"));
        QVERIFY2(doc->save(&error), qPrintable(error));
    }

    void openCorruptFile_data() {
        QTest::addColumn<QByteArray>("content");
        QTest::addColumn<QStringList>("mentions");
        QTest::newRow("malformed json") << QByteArray("{\"format\": \"resect-scenario\", ")
                                        << QStringList{"bad.json"};
        QTest::newRow("not a scenario")
            << QByteArray(R"({"format": "something-else", "version": 1})")
            << QStringList{"format"};
        QTest::newRow("several problems")
            << QByteArray(R"({"format": "resect-scenario", "version": 1,
                  "tissues": [{"name": "t", "surface": "sample:liver"}],
                  "cut_settings": {"d": 7}})")
            << QStringList{"tissues[0].surface", "cut_settings.d"};
        QTest::newRow("empty file") << QByteArray() << QStringList{"bad.json"};
        QTest::newRow("binary") << QByteArray("\x00\xff\xfe garbage", 12)
                                << QStringList{"bad.json"};
    }
    void openCorruptFile() {
        QFETCH(QByteArray, content);
        QFETCH(QStringList, mentions);
        auto doc = makeDocument();
        QString error;
        QVERIFY(doc->open(QStringLiteral(RESECT_SOURCE_DIR) +
                              "/resources/scenarios/myoma-enucleation.json",
                          &error));
        doc->setD(0.3);
        const Scenario before = doc->scenario();
        const QString file = doc->filePath();
        const int steps = doc->undoStack()->count();
        QSignalSpy changed(doc.get(), &ScenarioDocument::changed);

        const QString bad = path("bad.json");
        QVERIFY(writeAll(bad, content));
        QVERIFY(!doc->open(bad, &error));
        QVERIFY(!error.isEmpty());
        for (const QString& m : mentions)
            QVERIFY2(error.contains(m), qPrintable(error));
        QVERIFY(doc->scenario() == before);
        QCOMPARE(doc->filePath(), file);
        QVERIFY(doc->isModified());
        QCOMPARE(doc->undoStack()->count(), steps);
        QCOMPARE(changed.count(), 0);
        QVERIFY(!doc->recentFiles().contains(QFileInfo(bad).absoluteFilePath()));

        QVERIFY(!doc->open(path("missing.json"), &error));
        QVERIFY2(error.contains("missing.json"), qPrintable(error));
        QVERIFY(doc->scenario() == before);
    }

    void recentFiles() {
        auto doc = makeDocument();
        QSignalSpy spy(doc.get(), &ScenarioDocument::recentFilesChanged);
        QVERIFY(doc->recentFiles().isEmpty());
        QStringList added;
        for (int i = 0; i < 10; ++i) {
            added << QFileInfo(path(QString("f%1.json").arg(i))).absoluteFilePath();
            doc->addRecentFile(added.last());
        }
        QCOMPARE(spy.count(), 10);
        QStringList files = doc->recentFiles();
        QCOMPARE(files.size(), ScenarioDocument::kMaxRecentFiles);
        QCOMPARE(files.first(), added[9]);
        QCOMPARE(files.last(), added[2]);

        doc->addRecentFile(added[5]); // again: moves to the front, no duplicate
        files = doc->recentFiles();
        QCOMPARE(files.size(), ScenarioDocument::kMaxRecentFiles);
        QCOMPARE(files.first(), added[5]);
        QCOMPARE(files.count(added[5]), 1);
        QCOMPARE(files[1], added[9]);

        // Relative and unclean spellings of the same file are one entry.
        doc->addRecentFile(path("sub/../f9.json"));
        QCOMPARE(doc->recentFiles().first(), added[9]);
        QCOMPARE(doc->recentFiles().count(added[9]), 1);

        // Stored in the injected settings: another document sees them; save as adds.
        auto other = makeDocument();
        QCOMPARE(other->recentFiles().first(), added[9]);
        QVERIFY(other->newFromSample("polyp"));
        QVERIFY(other->saveAs(path("saved.json")));
        QCOMPARE(doc->recentFiles().first(), QFileInfo(path("saved.json")).absoluteFilePath());
        QVERIFY(other->open(path("saved.json"))); // opening adds it again: still once
        QCOMPARE(doc->recentFiles().count(QFileInfo(path("saved.json")).absoluteFilePath()), 1);

        doc->clearRecentFiles();
        QVERIFY(other->recentFiles().isEmpty());
    }

    void autosaveAndRecoveryAfterCrash() {
        const QString target = path("work.json");
        QString error;
        {
            auto doc = makeDocument();
            QVERIFY(doc->newFromSample("polyp"));
            QVERIFY(doc->saveAs(target));
            // Not modified: nothing to write.
            QVERIFY(doc->autosaveNow(&error));
            QVERIFY(!QFile::exists(doc->autosavePath()));
            doc->setD(0.3);
            doc->addStroke(sampleStroke("unsaved", 0));
            QVERIFY2(doc->autosaveNow(&error), qPrintable(error));
            QVERIFY(QFile::exists(doc->autosavePath()));
            // The "crash": the document goes away without close() or save.
        }
        auto doc = makeDocument();
        const QString autosave = doc->recoverableAutosave();
        QVERIFY(!autosave.isEmpty());
        QCOMPARE(doc->autosaveOriginalFile(), QFileInfo(target).absoluteFilePath());
        QSignalSpy modified(doc.get(), &ScenarioDocument::modifiedChanged);
        QVERIFY2(doc->recover(&error), qPrintable(error));
        QCOMPARE(doc->scenario().cut.d, 0.3);
        QCOMPARE(doc->scenario().strokes.size(), std::size_t(1));
        QVERIFY(doc->isModified());
        QCOMPARE(modified.count(), 1);
        QCOMPARE(doc->filePath(), QFileInfo(target).absoluteFilePath());
        // The saved file is still the older version until the user saves.
        auto saved = makeDocument();
        QVERIFY(saved->open(target));
        QCOMPARE(saved->scenario().cut.d, 0.2);

        QVERIFY2(doc->save(&error), qPrintable(error));
        QVERIFY(!QFile::exists(autosave));
        QVERIFY(doc->recoverableAutosave().isEmpty());
        QVERIFY(saved->open(target));
        QVERIFY(saved->scenario() == doc->scenario());
    }

    void autosaveOfUntitledDocumentAndClose() {
        auto doc = makeDocument();
        QVERIFY(doc->newFromSample("myoma"));
        doc->setTitle("never saved");
        QVERIFY(doc->autosaveNow());
        auto second = makeDocument();
        QVERIFY(!second->recoverableAutosave().isEmpty());
        QVERIFY(second->autosaveOriginalFile().isEmpty());
        QVERIFY(second->recover());
        QCOMPARE(second->scenario().metadata.title, std::string("never saved"));
        QVERIFY(second->filePath().isEmpty());
        QVERIFY(second->isModified());
        QString error;
        QVERIFY(!second->save(&error)); // no file name yet
        QVERIFY(!error.isEmpty());

        // A clean close removes the autosave; a fresh document does not touch it.
        QVERIFY(doc->autosaveNow());
        auto fresh = makeDocument();
        QVERIFY(fresh->newFromSample("polyp"));
        QVERIFY(!fresh->recoverableAutosave().isEmpty());
        doc->close();
        QVERIFY(fresh->recoverableAutosave().isEmpty());
    }

    void staleAutosaveIsNotOffered() {
        auto doc = makeDocument();
        QVERIFY(doc->newFromSample("polyp"));
        QVERIFY(doc->saveAs(path("old.json")));
        doc->setD(0.3);
        QVERIFY(doc->autosaveNow());
        // The file was saved later by someone else (or another studio).
        QFile original(path("old.json"));
        QVERIFY(original.open(QIODevice::ReadWrite));
        QVERIFY(original.setFileTime(QDateTime::currentDateTime().addSecs(60),
                                     QFileDevice::FileModificationTime));
        original.close();
        auto other = makeDocument();
        QVERIFY(other->recoverableAutosave().isEmpty());
        QString error;
        QVERIFY(!other->recover(&error));
        QVERIFY(!error.isEmpty());
        other->discardAutosave();
        QVERIFY(!QFile::exists(other->autosavePath()));
    }

    void failedSaveLeavesOldFile() {
        auto doc = makeDocument();
        QVERIFY(doc->newFromSample("polyp"));
        const QString target = path("keep.json");
        QVERIFY(doc->saveAs(target));
        const QByteArray old = readAll(target);
        QVERIFY(!old.isEmpty());

        doc->setD(0.9); // out of range [0, 0.5]: validation refuses to write
        QString error;
        QVERIFY(!doc->save(&error));
        QVERIFY2(error.contains("cut_settings.d"), qPrintable(error));
        QCOMPARE(readAll(target), old);
        QVERIFY(doc->isModified());
        QCOMPARE(doc->filePath(), QFileInfo(target).absoluteFilePath());
        // No temporary left behind.
        QCOMPARE(QDir(m_dir->path()).entryList({"keep*"}, QDir::Files),
                 QStringList{"keep.json"});

        // An unwritable destination: an error, the document keeps its file name.
        doc->setD(0.25);
        QVERIFY(!doc->saveAs(path("no/such/folder/x.json"), &error));
        QVERIFY(!error.isEmpty());
        QCOMPARE(doc->filePath(), QFileInfo(target).absoluteFilePath());
        QVERIFY(doc->isModified());
        QVERIFY(doc->save(&error));
        QVERIFY(readAll(target) != old);
    }

    // revertTo (TissueSession refuses an edit whose state does not derive): back to the
    // nearest earlier good state, the undone edits dropped, one announcement of what changed.
    void revertToUndoesAndDropsTheEdits() {
        auto doc = makeDocument();
        QVERIFY(doc->newFromSample("polyp"));
        doc->setD(0.3);
        doc->setTitle("kept?");
        doc->addStroke(sampleStroke("bad", 0));
        doc->setSnap(false);
        QCOMPARE(doc->undoStack()->count(), 4);
        QSignalSpy strokes(doc.get(), &ScenarioDocument::strokesChanged);
        QSignalSpy settings(doc.get(), &ScenarioDocument::cutSettingsChanged);
        QSignalSpy metadata(doc.get(), &ScenarioDocument::metadataChanged);
        QSignalSpy changed(doc.get(), &ScenarioDocument::changed);
        // Good: no stroke. The nearest such state is the one after the title edit.
        const auto good = [](const Scenario& s) { return s.strokes.empty(); };
        QVERIFY(doc->revertTo(good));
        QVERIFY(doc->scenario().strokes.empty());
        QCOMPARE(doc->scenario().cut.d, 0.3);
        QCOMPARE(doc->scenario().cut.snap, true);
        QCOMPARE(doc->scenario().metadata.title, std::string("kept?"));
        // The refused edits are gone: nothing to redo, two steps left to undo.
        QVERIFY(!doc->undoStack()->canRedo());
        QCOMPARE(doc->undoStack()->count(), 2);
        QCOMPARE(doc->undoStack()->index(), 2);
        // Announced once, for the parts that changed (strokes and cut settings), not the
        // metadata the search passed through.
        QCOMPARE(strokes.count(), 1);
        QCOMPARE(settings.count(), 1);
        QCOMPARE(metadata.count(), 0);
        QCOMPARE(changed.count(), 1);
        // Undo still works below.
        doc->undoStack()->undo();
        doc->undoStack()->undo();
        QCOMPARE(doc->scenario().cut.d, 0.2);
    }

    void revertToWithoutAGoodStateChangesNothing() {
        auto doc = makeDocument();
        QVERIFY(doc->newFromSample("polyp"));
        doc->addStroke(sampleStroke("bad", 0));
        doc->setD(0.3);
        const Scenario before = doc->scenario();
        QSignalSpy changed(doc.get(), &ScenarioDocument::changed);
        QVERIFY(!doc->revertTo([](const Scenario& s) { return s.cut.d == 0.45; }));
        QVERIFY(doc->scenario() == before);
        QCOMPARE(doc->undoStack()->index(), 2);
        QCOMPARE(doc->undoStack()->count(), 2);
        QCOMPARE(changed.count(), 0);
        QVERIFY(doc->isModified());
    }

    void revertingPastTheSavedStateMakesTheDocumentModified() {
        auto doc = makeDocument();
        QVERIFY(doc->newFromSample("polyp"));
        doc->setD(0.3);
        QVERIFY(doc->saveAs(path("saved.json")));
        QVERIFY(!doc->isModified());
        doc->setSnap(false);
        // Back to the saved state: clean again.
        QVERIFY(doc->revertTo([](const Scenario& s) { return s.cut.snap; }));
        QVERIFY(!doc->isModified());
        // Back beyond it: the saved state is dropped, the document is modified.
        doc->setSnap(false);
        QVERIFY(doc->revertTo([](const Scenario& s) { return s.cut.d == 0.2; }));
        QVERIFY(doc->isModified());
        QVERIFY(!doc->undoStack()->canRedo());
    }

    void theSaveCheckCanRefuseASave() {
        auto doc = makeDocument();
        QVERIFY(doc->newFromSample("polyp"));
        QString reason = QStringLiteral("still deriving");
        doc->setSaveCheck([&reason] { return reason; });
        QString error;
        QVERIFY(!doc->saveAs(path("refused.json"), &error));
        QCOMPARE(error, reason);
        QVERIFY(!QFileInfo::exists(path("refused.json")));
        QVERIFY(doc->filePath().isEmpty());
        reason.clear();
        QVERIFY2(doc->saveAs(path("accepted.json"), &error), qPrintable(error));
        QVERIFY(QFileInfo::exists(path("accepted.json")));
    }

    // The enhanced triangulation belongs to the hybrid method: the document never holds it
    // with subdivision, which would not load again.
    void subdivisionTakesTheStandardTriangulation() {
        auto doc = makeDocument();
        QVERIFY(doc->newFromSample("polyp"));
        QCOMPARE(doc->scenario().cut.triangulation, FaceTriangulation::Enhanced);
        doc->setMethod(CutMethod::Subdivision);
        QCOMPARE(doc->scenario().cut.triangulation, FaceTriangulation::Standard);
        ScenarioDiagnostics diag;
        QVERIFY(validateScenario(doc->scenario(), diag).ok());
        doc->setMethod(CutMethod::Hybrid);
        QCOMPARE(doc->scenario().cut.triangulation, FaceTriangulation::Enhanced);
        CutSettings s = doc->scenario().cut;
        s.method = CutMethod::Subdivision; // with the enhanced triangulation, as Adopt gives it
        doc->setCutSettings(s);
        QCOMPARE(doc->scenario().cut.method, CutMethod::Subdivision);
        QCOMPARE(doc->scenario().cut.triangulation, FaceTriangulation::Standard);
        QVERIFY(validateScenario(doc->scenario(), diag).ok());
    }

    void readStepsLeaveTheDocumentAlone() {
        auto doc = makeDocument();
        QVERIFY(doc->newFromSample("polyp"));
        doc->setD(0.3);
        QVERIFY(doc->saveAs(path("a.json")));
        doc->setSnap(false);
        const Scenario before = doc->scenario();
        Scenario read;
        QString error;
        QVERIFY(ScenarioDocument::readScenario(path("a.json"), read, &error));
        QCOMPARE(read.cut.d, 0.3);
        QVERIFY(ScenarioDocument::sampleScenario("myoma", read, &error));
        QCOMPARE(read.tissues.front().surface, std::string("sample:myoma"));
        QVERIFY(!ScenarioDocument::sampleScenario("liver", read, &error));
        QVERIFY(error.contains("liver"));
        QVERIFY(!ScenarioDocument::anatomyScenario(path("none.stl"), read, &error));
        QVERIFY(doc->scenario() == before);
        QCOMPARE(doc->undoStack()->count(), 2);
        // replace() is the second step.
        QVERIFY(ScenarioDocument::readScenario(path("a.json"), read, &error));
        doc->replace(read, path("a.json"));
        QCOMPARE(doc->filePath(), QFileInfo(path("a.json")).absoluteFilePath());
        QVERIFY(!doc->isModified());
        QCOMPARE(doc->undoStack()->count(), 0);
        QCOMPARE(doc->recentFiles().first(), QFileInfo(path("a.json")).absoluteFilePath());
    }
};

QTEST_MAIN(TestScenarioDocument)
#include "test_scenario_document.moc"
