// The studio's main window, driven like an author would (offscreen platform): open the
// sample, draw a pending cut, tune d and watch the preview, apply, undo and redo, save and
// reopen, open a corrupt file, run the simulation and toggle effects.

#include "main_window.h"

#include "core/mesh/quality.h"
#include "core/mesher/procedural_surfaces.h"
#include "scenario/surface_io.h"
#include "scenario/accuracy_study.h"
#include "widgets/accuracy_chart.h"
#include "widgets/accuracy_panel.h"
#include "widgets/authoring_panel.h"
#include "widgets/camera_ray.h"
#include "widgets/cut_panel.h"
#include "widgets/cut_preview.h"
#include "widgets/fixed_region_editor.h"
#include "widgets/fixed_region_tool.h"
#include "widgets/language.h"
#include "widgets/mesh_files.h"
#include "scenario/mesh_io.h"
#include "widgets/quality_curve.h"
#include "widgets/quality_panel.h"
#include "widgets/quality_summary_table.h"
#include "widgets/scenario_document.h"
#include "widgets/shown_tissue.h"
#include "widgets/simulation_controller.h"
#include "widgets/simulation_panel.h"
#include "widgets/stroke_recorder.h"
#include "widgets/tet_inspector.h"
#include "widgets/tissue_session.h"
#include "widgets/vtk_viewport.h"

#include "tests/widgets/sweep_fixtures.h"
#include "tests/widgets/tissue_compare.h"
#include <QAbstractButton>
#include <QAction>
#include <QApplication>
#include <QCheckBox>
#include <QComboBox>
#include <QDoubleSpinBox>
#include <QFileDialog>
#include <QTimer>
#include <QLabel>
#include <QMenuBar>
#include <QMessageBox>
#include <QPushButton>
#include <QSettings>
#include <QStyle>
#include <QStyleOptionButton>
#include <vtkCamera.h>

#include "scenario/scenario_load.h"
#include "scenario/scene_defaults.h"
#include "scenario/scenario_run.h"
#include "scenario/scenario_save.h"

#include <QStatusBar>

#include <cmath>
#include <functional>
#include <random>

#include <QSignalSpy>
#include <QStandardPaths>
#include <QTemporaryDir>
#include "core/mesh/validity.h"
#include <QTest>

using namespace resect;
using resect::test::planeSweep;
using resect::test::tissueDifference;

namespace {

constexpr int kWaitMs = 180'000;


/// Where a click toggles a check box: its indicator (the widget may be wider than its text).
QPoint indicatorCentre(QCheckBox* box) {
    QStyleOptionButton option;
    option.initFrom(box);
    return box->style()->subElementRect(QStyle::SE_CheckBoxIndicator, &option, box).center();
}

/// A window on the sample polyp, loaded, with errors signalled instead of shown.
struct Studio {
    MainWindow window;
    Studio() {
        window.setErrorDialogsEnabled(false);
        window.resize(1200, 800);
        window.show();
    }
    bool load(Sample sample = Sample::Polyp) {
        QSignalSpy loaded(&window, &MainWindow::meshLoaded);
        window.openSample(sample);
        return loaded.wait(kWaitMs) && idle();
    }
    /// The session and the preview are idle.
    bool idle() { return window.cutPreview().waitForIdle(kWaitMs); }
    int tets() { return window.session().current()->mesh().tetCount(); }
    QAction* action(const char* name) { return window.findChild<QAction*>(QString::fromLatin1(name)); }
    /// Opens `path` and waits for it to be shown (true) or to fail.
    bool open(const QString& path) {
        QSignalSpy loaded(&window, &MainWindow::meshLoaded);
        QSignalSpy failed(&window, &MainWindow::loadFailed);
        window.openFile(path);
        if (failed.count() == 0 && loaded.count() == 0)
            (void)QTest::qWaitFor([&] { return loaded.count() + failed.count() > 0; }, kWaitMs);
        return loaded.count() == 1 && failed.count() == 0 && idle();
    }
};

/// Independently of the studio: whether `scenario` replays, i.e. it is valid as loading would
/// find it, and its tissue, made as replay makes it (scenario_run.h planTissue, makeTissue),
/// takes every cut in replay order. The cut tissue goes to `out` if given.
Status replays(const Scenario& scenario, Tissue* out = nullptr) {
    ScenarioDiagnostics diag;
    if (Status s = validateScenario(scenario, diag); !s.ok())
        return s;
    ReplayPlan plan;
    if (Status s = planTissue(scenario, scenario.tissues.front(), plan); !s.ok())
        return s;
    Tissue local;
    Tissue& tissue = out ? *out : local;
    if (Status s = makeTissue(plan, tissue); !s.ok())
        return s;
    for (const ReplayStroke& stroke : plan.strokes)
        if (Status s = tissue.cut(stroke.sweep, plan.cut); !s.ok())
            return Status::error(stroke.name + ": " + s.message());
    tissue.updateSurface();
    return Status::success();
}

/// A stroke whose tool never moves (two poses at one place): the scenario layer refuses it.
Stroke stillStroke() {
    Stroke s;
    s.name = "held still";
    for (int i = 0; i < 2; ++i) {
        ToolPose p;
        p.t = 0.1 * i;
        p.position = Vec3(0, 0, 5);
        s.poses.push_back(p);
    }
    return s;
}

/// A stroke pulled as the studio's Pull motion pulls it (pullPoses): the loop opening
/// upwards (+z), its tip `depth` of the loop's half width below the tissue's top, `lateral`
/// mm beside its centre, pulled horizontally along `heading` (radians about z).
Stroke pulledStroke(const ToolSpec& tool, const TetMesh& mesh, double heading, double depth,
                    double lateral) {
    Vec3 centre = Vec3::Zero();
    double top = -1e300;
    for (const Vec3& p : mesh.referencePositions()) {
        centre += p;
        top = std::max(top, p.z());
    }
    centre /= double(mesh.nodeCount());
    const Vec3 along(std::cos(heading), std::sin(heading), 0), across(-along.y(), along.x(), 0);
    const Vec3 tip(centre.x(), centre.y(), top - depth * 0.5 * loopWidth(tool));
    Ray ray;
    ray.direction = along;
    ray.origin = tip + lateral * across - 100 * along;
    Stroke s;
    s.name = "pulled";
    s.poses = pullPoses(tool, ray, Vec3::UnitZ(), mesh.referencePositions(),
                        StrokeRecorder::kPullMarginFraction * loopWidth(tool),
                        StrokeRecorder::kPullSpeed);
    return s;
}

/// Random edits as an author makes them, some failing on purpose. After each, once the
/// studio is idle: the document holds the edit if and only if its state replays (replays(),
/// independently), else it is back where it was with nothing to redo and a refusal said;
/// the session's error is empty and its current state has every cut of the document.
/// `failures` counts the edits refused.
void randomEdits(Studio& s, unsigned seed, int steps, int& failures) {
    std::mt19937 random(seed);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    ScenarioDocument& doc = s.window.document();
    TissueSession& session = s.window.session();
    QSignalSpy refused(&session, &TissueSession::editRefused);
    const TetMesh base = session.base()->mesh();
    for (int step = 0; step < steps; ++step) {
        const int kind = std::uniform_int_distribution<int>(0, 7)(random);
        const Scenario before = doc.scenario();
        const int refusalsBefore = refused.count();
        bool mustFail = false;
        QString name;
        switch (kind) {
        case 0:
            name = QStringLiteral("add sweep");
            doc.addSweep(planeSweep(base, 0.3 + 0.55 * unit(random), 0.3 * (unit(random) - 0.5)));
            break;
        case 1:
            name = QStringLiteral("add pulled stroke");
            doc.addStroke(pulledStroke(doc.scenario().tool, base, 2 * M_PI * unit(random),
                                       0.3 + 0.5 * unit(random), 4 * (unit(random) - 0.5)));
            break;
        case 2:
            name = QStringLiteral("add still stroke");
            doc.addStroke(stillStroke());
            mustFail = true;
            break;
        case 3: {
            name = QStringLiteral("add missing sweep file");
            SweepSpec missing;
            missing.file = "/nonexistent/sweep.json";
            doc.addSweep(missing);
            mustFail = true;
            break;
        }
        case 4: {
            static const double kDs[] = {0.05, 0.1, 0.2, 0.3, 0.45};
            name = QStringLiteral("set d");
            doc.setD(kDs[std::uniform_int_distribution<int>(0, 4)(random)]);
            break;
        }
        case 5:
            name = QStringLiteral("set rings out of range");
            doc.setRings(CutLimits::kMaxRelaxRings + 1);
            mustFail = true;
            break;
        case 6:
            name = QStringLiteral("undo");
            s.action("undo")->trigger();
            break;
        default:
            name = QStringLiteral("redo");
            s.action("redo")->trigger();
            break;
        }
        const QString what = QStringLiteral("seed %1 step %2: %3").arg(seed).arg(step).arg(name);
        const Scenario candidate = doc.scenario();
        const Status judged = candidate == before ? Status::success() : replays(candidate);
        if (mustFail)
            QVERIFY2(!judged.ok(), qPrintable(what));
        QVERIFY2(s.idle(), qPrintable(what));
        QVERIFY2(session.error().isEmpty(),
                 qPrintable(what + QStringLiteral(": ") + session.error()));
        if (judged.ok()) {
            QVERIFY2(doc.scenario() == candidate, qPrintable(what));
            QCOMPARE(refused.count(), refusalsBefore);
        } else {
            ++failures;
            QVERIFY2(
                doc.scenario() == before,
                qPrintable(what + QStringLiteral(": ") + QString::fromStdString(judged.message())));
            QVERIFY2(!doc.undoStack()->canRedo(), qPrintable(what));
            QCOMPARE(refused.count(), refusalsBefore + 1);
        }
        const auto current = session.current();
        QVERIFY(current);
        QCOMPARE(current->cuts(),
                 int(doc.scenario().strokes.size() + doc.scenario().sweeps.size()));
        QVERIFY(session.saveBlocker().isEmpty());
    }
}

} // namespace

class TestStudioMainWindow : public QObject {
    Q_OBJECT

    QTemporaryDir m_dir;

private slots:
    void exportMeshAsEveryFormat() {
        // Issue 21: File > Export mesh as... writes the mesh on show in every format, and
        // the studio opens what it wrote.
        Studio s;
        QVERIFY(s.load());
        const TetMesh* shown = s.window.shownTissue().mesh();
        QVERIFY(shown);
        const int tets = shown->tetCount();
        for (const MeshFormatInfo& f : meshFormats()) {
            const QString key = QString::fromUtf8(f.key.data(), f.key.size());
            const QString path = withMeshExtension(m_dir.filePath(QStringLiteral("shown-") + key), f.format);
            QSignalSpy exported(&s.window, &MainWindow::meshExported);
            QVERIFY2(s.window.exportMesh(path, f.format), qPrintable(key));
            QVERIFY(exported.wait(kWaitMs));
            QVERIFY2(exported.first().at(0).toBool(), qPrintable(exported.first().at(1).toString()));
            TetMesh back;
            QVERIFY2(readTetMesh(QFile::encodeName(path).toStdString(), back).ok(), qPrintable(path));
            QCOMPARE(back.tetCount(), tets);
        }
        // A path that does not fit the format is refused with an error, nothing written.
        QSignalSpy errors(&s.window, &MainWindow::errorReported);
        QVERIFY(!s.window.exportMesh(m_dir.filePath(QStringLiteral("wrong.vtu")), MeshFormat::Msh22));
        QCOMPARE(errors.count(), 1);
        QVERIFY(!QFile::exists(m_dir.filePath(QStringLiteral("wrong.vtu"))));
        // The studio opens a Gmsh file it wrote.
        Studio other;
        QVERIFY(other.open(m_dir.filePath(QStringLiteral("shown-msh22-binary.msh"))));
        QCOMPARE(other.tets(), tets);
        s.window.setUnsavedChangesAnswer(QMessageBox::Discard);
        other.window.setUnsavedChangesAnswer(QMessageBox::Discard);
    }

    void openingAMixedFileSaysWhatWasDropped() {
        // Issue 21: a file with triangles beside its tets opens with its tets, and the status
        // bar says what was left out.
        const QString path = m_dir.filePath(QStringLiteral("mixed.msh"));
        QFile f(path);
        QVERIFY(f.open(QIODevice::WriteOnly));
        f.write("$MeshFormat\n2.2 0 8\n$EndMeshFormat\n$Nodes\n5\n1 0 0 0\n2 1 0 0\n3 0 1 0\n4 0 0 1\n"
                "5 1 1 1\n$EndNodes\n$Elements\n3\n1 2 2 7 1 1 2 3\n2 4 2 7 1 1 2 3 4\n3 4 2 7 1 2 3 4 5\n"
                "$EndElements\n");
        f.close();
        Studio s;
        QVERIFY(s.open(path));
        QCOMPARE(s.tets(), 2);
        const QString message = s.window.statusBar()->currentMessage();
        QVERIFY2(message.contains(QStringLiteral("dropped 1 element")) && message.contains(QStringLiteral("triangle")),
                 qPrintable(message));
        s.window.setUnsavedChangesAnswer(QMessageBox::Discard);
    }

    void exportMeshDialogChoosesTheFormatByName() {
        // Driven as a user does: File > Export mesh as..., pick "Gmsh 2.2 binary", type a
        // name without extension, accept.
        Studio s;
        QVERIFY(s.load());
        QAction* action = s.action("exportMesh");
        QVERIFY(action);
        const QString base = m_dir.filePath(QStringLiteral("dialog-liver"));
        bool sawDialog = false;
        QStringList filters;
        QTimer::singleShot(0, &s.window, [&] {
            auto* dialog = s.window.findChild<QFileDialog*>(QStringLiteral("exportMeshDialog"));
            if (!dialog)
                return;
            sawDialog = true;
            filters = dialog->nameFilters();
            dialog->selectNameFilter(QStringLiteral("Gmsh 2.2 binary (*.msh)"));
            dialog->selectFile(base);
            static_cast<QDialog*>(dialog)->accept(); // QFileDialog's own accept, as OK does
        });
        QSignalSpy exported(&s.window, &MainWindow::meshExported);
        action->trigger();
        QVERIFY(sawDialog);
        QCOMPARE(filters, tetMeshSaveFilters());
        QVERIFY(filters.contains(QStringLiteral("Medit (*.mesh)")));
        QVERIFY(exported.wait(kWaitMs));
        QVERIFY2(exported.first().at(0).toBool(), qPrintable(exported.first().at(1).toString()));
        QFile written(base + QStringLiteral(".msh"));
        QVERIFY(written.open(QIODevice::ReadOnly));
        QVERIFY(written.read(24).startsWith("$MeshFormat\n2.2 1 8"));
        // Open and Import list every readable extension.
        for (const char* ext : {"*.vtu", "*.msh", "*.vtk", "*.mesh", "*.node", "*.ele"})
            QVERIFY2(tetMeshOpenFilter().contains(QLatin1String(ext)), ext);
        const QStringList open = tetMeshOpenFilters().split(QStringLiteral(";;"));
        QCOMPARE(open.size(), 6);
        QVERIFY(open.contains(QStringLiteral("Gmsh 2.2 and 4.1, ASCII and binary (*.msh)")));
        QVERIFY(open.contains(QStringLiteral("TetGen (*.node *.ele)")));
        s.window.setUnsavedChangesAnswer(QMessageBox::Discard);
    }

    void initTestCase() {
        QVERIFY(m_dir.isValid());
        // Settings and autosaves go to the test's folder, never the user's.
        QStandardPaths::setTestModeEnabled(true);
        QSettings().clear();
    }

    void opensTheSample() {
        Studio s;
        QVERIFY(s.load());
        QVERIFY(s.tets() > 100);
        QVERIFY(s.window.windowTitle().contains(QStringLiteral("polyp")));
        auto* status = s.window.findChild<QLabel*>(QStringLiteral("statusSummary"));
        QVERIFY(status);
        QVERIFY(status->text().contains(QString::number(s.tets())));
        // The view shows the tissue (VTK data, also without OpenGL).
        QVERIFY(!s.window.viewport()->tetMeshActor().empty());
        QVERIFY(validBounds(s.window.viewport()->sceneBounds()));
    }

    void dChangesThePreviewApplyUndoRedo() {
        Studio s;
        QVERIFY(s.load());
        const int tets = s.tets();
        CutPanel* panel = s.window.cutPanel();
        QCOMPARE(panel->previewValue(QStringLiteral("tets")), QString());

        s.window.cutPreview().setPendingSweep(planeSweep(s.window.session().base()->mesh(), 0.6));
        QVERIFY(s.idle());
        const QString at02 = panel->previewValue(QStringLiteral("added_tets"));
        QVERIFY(!at02.isEmpty());

        // Change d in the panel as an author would: type into the spin box.
        auto* d = panel->findChild<QDoubleSpinBox*>(QStringLiteral("d"));
        QVERIFY(d);
        d->selectAll();
        QTest::keyClicks(d, QStringLiteral("0.01"));
        QTest::keyClick(d, Qt::Key_Enter);
        QVERIFY(s.idle());
        QCOMPARE(s.window.document().scenario().cut.d, 0.01);
        const QString at001 = panel->previewValue(QStringLiteral("added_tets"));
        QVERIFY2(at001 != at02, qPrintable(at001 + QStringLiteral(" vs ") + at02));
        QVERIFY(at001.toInt() > at02.toInt()); // fewer cut nodes, more split edges
        QCOMPARE(s.tets(), tets);              // the preview is not applied

        // Apply with the panel's button: the tet count grows.
        auto* apply = panel->findChild<QPushButton*>(QStringLiteral("applyCut"));
        QVERIFY(apply && apply->isEnabled());
        QTest::mouseClick(apply, Qt::LeftButton);
        QVERIFY(s.idle());
        const int cut = s.tets();
        QCOMPARE(cut, tets + at001.toInt());
        QCOMPARE(s.window.session().current()->pieces, 2);
        QVERIFY(s.window.document().isModified());
        QVERIFY(s.window.isWindowModified());

        // Undo the cut, then the d change; redo both.
        QAction* undo = s.action("undo");
        QAction* redo = s.action("redo");
        QVERIFY(undo && redo);
        undo->trigger();
        QVERIFY(s.idle());
        QCOMPARE(s.tets(), tets);
        undo->trigger();
        QCOMPARE(s.window.document().scenario().cut.d, 0.2);
        QCOMPARE(d->value(), 0.2); // the panel follows the document
        redo->trigger();
        redo->trigger();
        QVERIFY(s.idle());
        QCOMPARE(s.tets(), cut);
        s.window.setUnsavedChangesAnswer(QMessageBox::Discard);
    }

    void recordAStrokeAndApplyIt() {
        Studio s;
        QVERIFY(s.load());
        const int tets = s.tets();
        AuthoringPanel* panel = s.window.authoringPanel();
        QVERIFY(panel);
        double now = 0;
        panel->strokeRecorder().setClock([&now] { return now; });
        auto* record = panel->findChild<QPushButton*>(QStringLiteral("recordStrokeButton"));
        QVERIFY(record);
        record->click();
        QVERIFY(panel->strokeRecorder().isRecording());

        // Drag the electrode across the middle of the view, left to right.
        VtkViewport* view = s.window.viewport();
        double before[3];
        view->camera()->GetPosition(before);
        const int y = view->height() / 2;
        const int x0 = view->width() / 5, x1 = 4 * view->width() / 5;
        QTest::mousePress(view, Qt::LeftButton, {}, QPoint(x0, y));
        for (int i = 1; i <= 12; ++i) {
            now += 0.05;
            QTest::mouseMove(view, QPoint(x0 + (x1 - x0) * i / 12, y + i));
        }
        QTest::mouseRelease(view, Qt::LeftButton, {}, QPoint(x1, y + 12));
        double after[3];
        view->camera()->GetPosition(after);
        QCOMPARE(after[0], before[0]); // recording does not move the camera
        QVERIFY(!panel->strokeRecorder().isRecording());

        // The stroke is the pending cut: its sweep is previewed, then applied.
        QVERIFY(s.window.cutPreview().hasPending());
        QVERIFY(s.idle());
        QVERIFY2(s.window.cutPreview().error().isEmpty(), qPrintable(s.window.cutPreview().error()));
        QVERIFY(s.window.cutPreview().preview());
        const int previewTets = s.window.cutPreview().preview()->mesh().tetCount();
        QVERIFY(previewTets > tets);
        QCOMPARE(panel->lastStroke().poses.size(), std::size_t(13));
        QVERIFY(panel->lastStroke().poses.back().t > panel->lastStroke().poses.front().t);
        QTest::mouseClick(s.window.cutPanel()->findChild<QPushButton*>(QStringLiteral("applyCut")), Qt::LeftButton);
        QVERIFY(s.idle());
        QCOMPARE(int(s.window.document().scenario().strokes.size()), 1);
        QCOMPARE(s.tets(), previewTets);
        s.window.setUnsavedChangesAnswer(QMessageBox::Discard);
    }

    void saveReopenCompare() {
        const QString path = m_dir.filePath(QStringLiteral("saved.json"));
        Scenario saved;
        {
            Studio s;
            QVERIFY(s.load());
            s.window.cutPreview().setPendingSweep(planeSweep(s.window.session().base()->mesh(), 0.55));
            QVERIFY(s.idle());
            QVERIFY(s.window.cutPreview().apply());
            s.window.document().toggleEffect(QStringLiteral("gravity"));
            QVERIFY(s.idle());
            QVERIFY(s.window.saveAs(path));
            QVERIFY(!s.window.document().isModified());
            saved = s.window.document().scenario();
        }
        Studio s;
        QSignalSpy loaded(&s.window, &MainWindow::meshLoaded);
        s.window.openFile(path);
        QVERIFY(loaded.wait(kWaitMs));
        QVERIFY(s.idle());
        Scenario reopened = s.window.document().scenario();
        QCOMPARE(reopened.sweeps, saved.sweeps);
        QCOMPARE(reopened.effects, saved.effects);
        QCOMPARE(reopened.cut, saved.cut);
        QCOMPARE(reopened.tissues, saved.tissues);
        QCOMPARE(s.window.session().current()->cuts(), 1);
        QVERIFY(s.window.document().recentFiles().contains(QFileInfo(path).absoluteFilePath()));
    }

    void corruptFileGivesAMessage_data() {
        QTest::addColumn<QByteArray>("content");
        QTest::addColumn<QString>("name");
        QTest::newRow("not json") << QByteArray("{\"format\": \"resect-scenario\", \"vers") << "broken.json";
        QTest::newRow("wrong types") << QByteArray("{\"format\": \"resect-scenario\", \"version\": 1, \"tissues\": 3}")
                                     << "types.json";
        QTest::newRow("binary mesh") << QByteArray("\x00\x01\x02garbage", 10) << "mesh.vtu";
        QTest::newRow("bad surface") << QByteArray("solid x\nfacet normal nan nan nan\nendsolid\n") << "bad.stl";
    }
    void corruptFileGivesAMessage() {
        QFETCH(QByteArray, content);
        QFETCH(QString, name);
        Studio s;
        QVERIFY(s.load());
        const int tets = s.tets();
        const QString path = m_dir.filePath(name);
        QFile f(path);
        QVERIFY(f.open(QIODevice::WriteOnly));
        f.write(content);
        f.close();
        QSignalSpy errors(&s.window, &MainWindow::errorReported);
        s.window.openFile(path);
        QVERIFY(s.idle());
        QTRY_VERIFY_WITH_TIMEOUT(errors.count() >= 1, kWaitMs);
        const QString message = errors.first().first().toString();
        QVERIFY2(!message.isEmpty(), "empty message");
        // A bad scenario leaves the open document as it was.
        if (name.endsWith(QLatin1String(".json")))
            QCOMPARE(s.tets(), tets);
        QFile again(path);
        QVERIFY(again.open(QIODevice::ReadOnly));
        QCOMPARE(again.readAll(), content); // the input is untouched
        s.window.setUnsavedChangesAnswer(QMessageBox::Discard);
    }

    void simulationStepsAndEffectsToggle() {
        Studio s;
        QVERIFY(s.load(Sample::Myoma));
        SimulationPanel* panel = s.window.simulationPanel();
        QCheckBox* gravity = panel->effectBox("gravity");
        QVERIFY(gravity && !gravity->isChecked());
        gravity->click(); // the dock is tabbed behind the cut panel: not clickable with the mouse
        QVERIFY(s.window.document().isEffectEnabled(QStringLiteral("gravity")));
        QVERIFY(s.window.simulation().isReady());
        // A new sample scene has deformation, fixed and damping on (scene_defaults.h).
        QCOMPARE(s.window.simulation().effectNames().size(), std::size_t(4));

        auto* step = panel->findChild<QPushButton*>(QStringLiteral("simStep"));
        QVERIFY(step);
        step->click();
        step->click();
        QCOMPARE(s.window.simulation().steps(), 2LL);
        QVERIFY(s.window.simulation().time() > 0);
        // Falling under gravity: a node moved downwards from its rest position.
        const TetMesh& mesh = s.window.simulation().mesh();
        double dz = 0;
        for (int n = 0; n < mesh.nodeCount(); ++n)
            dz = std::min(dz, mesh.pos(n).z() - mesh.ref(n).z());
        QVERIFY(dz < 0);

        auto* play = panel->findChild<QPushButton*>(QStringLiteral("simPlay"));
        play->click();
        QVERIFY(s.window.simulation().isPlaying());
        QTRY_VERIFY_WITH_TIMEOUT(s.window.simulation().steps() > 10, 30'000);
        play->click();
        QVERIFY(!s.window.simulation().isPlaying());
        // A new scene simulates with the implicit integrator at 1 ms, and the dock says how
        // fast that runs against real time.
        QCOMPARE(s.window.simulation().timeStep(), 0.001);
        auto* realTime = panel->findChild<QLabel*>(QStringLiteral("simRealtime"));
        QVERIFY(realTime);
        QVERIFY2(realTime->text().contains(QStringLiteral("x real time")), qPrintable(realTime->text()));
        QVERIFY2(realTime->text().contains(QStringLiteral("implicit, 5 iterations")), qPrintable(realTime->text()));
        auto* cost = panel->findChild<QLabel*>(QStringLiteral("simCost"));
        QVERIFY2(cost && cost->text().contains(QStringLiteral("integrator: ")), qPrintable(cost->text()));

        // Undoing the effect edit rebuilds the simulation without gravity, at time 0.
        s.action("undo")->trigger();
        QVERIFY(!s.window.document().isEffectEnabled(QStringLiteral("gravity")));
        QVERIFY(!gravity->isChecked());
        QCOMPARE(s.window.simulation().steps(), 0LL);
        QCOMPARE(s.window.simulation().effectNames().size(), std::size_t(3));
        s.window.setUnsavedChangesAnswer(QMessageBox::Discard);
    }

    // What is shown: the preview while a cut is pending, else the simulated tissue once it
    // moved; a cut applied while simulating is followed by the simulation and shown at once.
    void aCutAppliedWhileSimulatingIsShownInTheSimulation() {
        Studio s;
        QVERIFY(s.load(Sample::Myoma));
        ShownTissue& shown = s.window.shownTissue();
        TetMeshActor& actor = s.window.viewport()->tetMeshActor();
        QCOMPARE(shown.source(), ShownTissue::Source::Current);
        QCOMPARE(shown.mesh(), &s.window.session().current()->mesh());

        auto* step = s.window.simulationPanel()->findChild<QPushButton*>(QStringLiteral("simStep"));
        QVERIFY(step);
        step->click();
        step->click();
        QCOMPARE(shown.source(), ShownTissue::Source::Simulation);
        QCOMPARE(shown.mesh(), &s.window.simulation().mesh());
        const double time = s.window.simulation().time();
        const int tets = s.tets();

        s.window.cutPreview().setPendingSweep(planeSweep(s.window.session().base()->mesh(), 0.6));
        QVERIFY(s.idle());
        QCOMPARE(shown.source(), ShownTissue::Source::Preview);
        QCOMPARE(shown.mesh(), &s.window.cutPreview().preview()->mesh());
        QCOMPARE(actor.tetCount(), s.window.cutPreview().preview()->mesh().tetCount());

        QTest::mouseClick(s.window.cutPanel()->findChild<QPushButton*>(QStringLiteral("applyCut")), Qt::LeftButton);
        QVERIFY(s.idle());
        QCOMPARE(s.window.session().current()->cuts(), 1);
        QCOMPARE(s.window.simulation().time(), time); // followed, not rebuilt
        QCOMPARE(shown.source(), ShownTissue::Source::Simulation);
        // The cut added tets (the part the plane took off a new sample's anchored base is a
        // resected chip now).
        int chipTets = 0;
        for (const Chip& c : s.window.simulation().tissue().chips())
            chipTets += c.mesh.tetCount();
        QVERIFY(s.window.simulation().mesh().tetCount() + chipTets > tets);
        QCOMPARE(actor.tetCount(), s.window.simulation().mesh().tetCount());
        QCOMPARE(actor.tetScheme(actor.tetCount() - 1), s.window.simulation().tissue().schemes().back());
        s.window.setUnsavedChangesAnswer(QMessageBox::Discard);
    }

    void exportWritesThePackage() {
        Studio s;
        QVERIFY(s.load(Sample::Myoma));
        // A short scenario: the export replays it.
        s.window.cutPreview().setPendingSweep(planeSweep(s.window.session().base()->mesh(), 0.7));
        QVERIFY(s.idle());
        QVERIFY(s.window.cutPreview().apply());
        QVERIFY(s.idle());
        const QString out = m_dir.filePath(QStringLiteral("package"));
        QSignalSpy finished(&s.window, &MainWindow::exportFinished);
        QVERIFY(s.window.exportPackage(out));
        QVERIFY(finished.wait(kWaitMs));
        QVERIFY2(finished.first().at(0).toBool(), qPrintable(finished.first().at(1).toString()));
        const QStringList files = finished.first().at(2).toStringList();
        QVERIFY(files.size() >= 4);
        for (const QString& f : files)
            QVERIFY2(QFileInfo::exists(f), qPrintable(f));
        QVERIFY(QFileInfo::exists(out + QStringLiteral("/manifest.json")));
        QVERIFY(QFileInfo::exists(out + QStringLiteral("/scenario.json")));
        // A second export into the now non-empty folder is refused, and says so.
        finished.clear();
        QSignalSpy errors(&s.window, &MainWindow::errorReported);
        QVERIFY(s.window.exportPackage(out));
        QVERIFY(finished.wait(kWaitMs));
        QVERIFY(!finished.first().at(0).toBool());
        QCOMPARE(errors.count(), 1);
        s.window.setUnsavedChangesAnswer(QMessageBox::Discard);
    }

    void aPendingCutHoldsTheSimulation() {
        // Issue 19: a simulation kept running hidden behind a static cut preview.
        Studio s;
        QVERIFY(s.load(Sample::Myoma));
        SimulationPanel* panel = s.window.simulationPanel();
        QCheckBox* gravity = panel->effectBox("gravity");
        QVERIFY(gravity);
        if (!gravity->isChecked())
            gravity->click();
        QVERIFY(s.window.simulation().isReady());
        s.window.simulation().play();
        QVERIFY(s.window.simulation().isPlaying());
        s.window.cutPreview().setPendingSweep(planeSweep(s.window.session().base()->mesh(), 0.5));
        QVERIFY(!s.window.simulation().isPlaying());
        QVERIFY2(s.window.statusBar()->currentMessage().contains(QStringLiteral("paused")),
                 qPrintable(s.window.statusBar()->currentMessage()));
        // Playing again waits for the cut.
        s.window.simulation().play();
        QVERIFY(!s.window.simulation().isPlaying());
        QVERIFY(s.idle());
        s.window.cutPreview().discard();
        s.window.simulation().play();
        QVERIFY(s.window.simulation().isPlaying());
        s.window.simulation().pause();
        s.window.setUnsavedChangesAnswer(QMessageBox::Discard);
    }

    void exportIsConfirmed() {
        // Issue 19: after an export nothing but a brief status message said it had worked.
        Studio s;
        QVERIFY(s.load(Sample::Myoma));
        s.window.setErrorDialogsEnabled(true);
        const QString out = m_dir.filePath(QStringLiteral("confirmed-package"));
        QSignalSpy finished(&s.window, &MainWindow::exportFinished);
        QVERIFY(s.window.exportPackage(out));
        QVERIFY(finished.wait(kWaitMs));
        QVERIFY2(finished.first().at(0).toBool(), qPrintable(finished.first().at(1).toString()));
        auto* box = s.window.findChild<QMessageBox*>(QStringLiteral("exportConfirmation"));
        QVERIFY(box);
        QVERIFY(QTest::qWaitFor([box] { return box->isVisible(); }, 5000));
        QVERIFY2(box->text().contains(out), qPrintable(box->text()));
        bool openFolder = false;
        for (QAbstractButton* b : box->buttons())
            openFolder = openFolder || b->text().contains(QStringLiteral("folder"), Qt::CaseInsensitive);
        QVERIFY(openFolder);
        box->accept();
        s.window.setErrorDialogsEnabled(false);
        s.window.setUnsavedChangesAnswer(QMessageBox::Discard);
    }

    void smallThings() {
        Studio s;
        QVERIFY(s.load());
        // One piece is "1 piece".
        const QString summary = s.window.findChild<QLabel*>(QStringLiteral("statusSummary"))->text();
        QVERIFY2(summary.contains(QStringLiteral("1 piece,")) && !summary.contains(QStringLiteral("pieces")),
                 qPrintable(summary));
        // Ctrl+O works from every window of the studio (floating docks too).
        QAction* open = s.action("openFile");
        QVERIFY(open);
        QCOMPARE(open->shortcut(), QKeySequence(QKeySequence::Open));
        QCOMPARE(open->shortcutContext(), Qt::ApplicationShortcut);
        // View > Reset camera restores the starting view after the view was turned.
        VtkViewport* view = s.window.viewport();
        double start[3], turned[3], reset[3];
        view->camera()->GetDirectionOfProjection(start);
        const int y = view->height() / 2;
        QTest::mousePress(view, Qt::LeftButton, {}, QPoint(view->width() / 3, y));
        for (int i = 1; i <= 8; ++i)
            QTest::mouseMove(view, QPoint(view->width() / 3 + 20 * i, y + 5 * i));
        QTest::mouseRelease(view, Qt::LeftButton, {}, QPoint(view->width() / 3 + 160, y + 40));
        view->camera()->GetDirectionOfProjection(turned);
        QVERIFY(std::abs(turned[0] - start[0]) + std::abs(turned[1] - start[1]) + std::abs(turned[2] - start[2]) > 0.1);
        s.action("resetCamera")->trigger();
        view->camera()->GetDirectionOfProjection(reset);
        for (int i = 0; i < 3; ++i)
            QVERIFY2(std::abs(reset[i] - start[i]) < 1e-9, qPrintable(QString("%1 vs %2").arg(reset[i]).arg(start[i])));
    }

    void overlayAndQualityFilterSwitch() {
        Studio s;
        QVERIFY(s.load());
        QualityPanel* panel = s.window.qualityPanel();
        TetMeshActor& actor = s.window.viewport()->tetMeshActor();
        const int tets = s.tets();
        QCOMPARE(int(actor.displayedTets().size()), tets);
        QCOMPARE(actor.overlayMeasure(), QualityMeasure::RadiusRatio);

        auto* measure = panel->findChild<QComboBox*>(QStringLiteral("overlayMeasure"));
        QVERIFY(measure);
        const int dihedral = static_cast<int>(QualityMeasure::MinDihedral); // items in enum order
        QCOMPARE(measure->itemText(dihedral), qualityMeasureTitle(QualityMeasure::MinDihedral));
        measure->setCurrentIndex(dihedral);
        QCOMPARE(actor.overlayMeasure(), QualityMeasure::MinDihedral);

        // Only the tets below a threshold remain: count them independently.
        auto* filter = panel->findChild<QCheckBox*>(QStringLiteral("filterEnabled"));
        auto* threshold = panel->findChild<QDoubleSpinBox*>(QStringLiteral("filterThreshold"));
        QVERIFY(filter && threshold);
        threshold->setValue(30.0);
        filter->click();
        QVERIFY(actor.qualityFilterEnabled());
        const auto qualities = tetQualities(s.window.session().current()->mesh());
        int below = 0;
        for (const TetQuality& q : qualities)
            below += q.minDihedral * 180.0 / M_PI < 30.0;
        QCOMPARE(int(actor.displayedTets().size()), below);
        QVERIFY(below < tets);
        filter->click();
        QCOMPARE(int(actor.displayedTets().size()), tets);
        s.window.setUnsavedChangesAnswer(QMessageBox::Discard);
    }

    void accuracyStudyAdoptsAPoint() {
        Studio s;
        QVERIFY(s.load(Sample::Myoma));
        AccuracyPanel* panel = s.window.accuracyPanel();
        QVERIFY(panel->hasTissue());
        StudyConfig config = tinyConfig();
        config.dValues = {0.1, 0.3};
        config.repeats = 1;
        panel->setCustomConfig(config);
        QSignalSpy finished(panel, &AccuracyPanel::studyFinished);
        panel->run();
        QVERIFY(finished.wait(kWaitMs));
        QVERIFY2(finished.first().first().toBool(), qPrintable(finished.first().at(1).toString()));
        QVERIFY(!panel->rows().empty());
        // Pick a hybrid row at d = 0.3 and adopt it: the document's settings follow (undoable).
        int row = -1;
        for (int i = 0; i < int(panel->rows().size()); ++i)
            if (panel->rows()[i].method != "subdivision" && panel->rows()[i].d == 0.3)
                row = i;
        QVERIFY(row >= 0);
        panel->selectRow(row);
        panel->adoptSelected();
        QCOMPARE(s.window.document().scenario().cut.d, 0.3);
        s.action("undo")->trigger();
        QCOMPARE(s.window.document().scenario().cut.d, 0.2);
        s.window.setUnsavedChangesAnswer(QMessageBox::Discard);
    }

    void germanInterface() {
        QVERIFY(installTranslations(*QCoreApplication::instance(), QStringLiteral("de")));
        {
            Studio s;
            QStringList menus;
            for (QAction* a : s.window.menuBar()->actions())
                menus << a->text();
            QVERIFY2(menus.contains(QStringLiteral("&Datei")), qPrintable(menus.join(QLatin1Char(','))));
            QCOMPARE(s.window.cutPanel()->findChild<QPushButton*>(QStringLiteral("applyCut"))->text(),
                     QCoreApplication::translate("resect::CutPanel", "&Apply cut"));
            QVERIFY(s.window.cutPanel()->findChild<QPushButton*>(QStringLiteral("applyCut"))->text() !=
                    QStringLiteral("&Apply cut"));
        }
        QVERIFY(installTranslations(*QCoreApplication::instance(), QStringLiteral("en")));
    }

    void unsavedChangesAreAskedAbout() {
        Studio s;
        QVERIFY(s.load());
        s.window.document().setD(0.3);
        s.window.setUnsavedChangesAnswer(QMessageBox::Cancel);
        QVERIFY(!s.window.close());
        QVERIFY(s.window.isVisible());
        // Opening another document is refused as well: the edit is still there.
        s.window.openSample(Sample::Myoma);
        QCOMPARE(s.window.document().scenario().cut.d, 0.3);
        s.window.setUnsavedChangesAnswer(QMessageBox::Discard);
        QVERIFY(s.window.close());
    }

    // Issue 15: a preview that fails cannot be applied; Apply is disabled and the reason is
    // shown in the cut panel, with no dialog. Nor while the preview is still computing.
    void aFailingPreviewCannotBeApplied_data() {
        QTest::addColumn<bool>("stroke");
        QTest::newRow("a stroke held still") << true;
        QTest::newRow("a sweep file that is not there") << false;
    }
    void aFailingPreviewCannotBeApplied() {
        QFETCH(bool, stroke);
        Studio s;
        s.window.setErrorDialogsEnabled(true); // a dialog would be a failure here
        QVERIFY(s.load());
        CutPanel* panel = s.window.cutPanel();
        auto* apply = panel->findChild<QPushButton*>(QStringLiteral("applyCut"));
        auto* status = panel->findChild<QLabel*>(QStringLiteral("previewStatus"));
        QAction* menuApply = s.action("applyPendingCut");
        QVERIFY(apply && status && menuApply);
        const int tets = s.tets();

        // A good cut: not applicable while it is computed, then applicable.
        s.window.cutPreview().setPendingSweep(planeSweep(s.window.session().base()->mesh(), 0.6));
        QVERIFY(!apply->isEnabled());
        QVERIFY(!menuApply->isEnabled());
        QVERIFY(s.idle());
        QVERIFY(apply->isEnabled());
        QVERIFY(menuApply->isEnabled());

        QSignalSpy errors(&s.window, &MainWindow::errorReported);
        if (stroke) {
            s.window.cutPreview().setPendingStroke(stillStroke());
        } else {
            SweepSpec missing;
            missing.file = m_dir.filePath(QStringLiteral("missing-sweep.json")).toStdString();
            s.window.cutPreview().setPendingSweep(missing);
        }
        QVERIFY(s.idle());
        const QString reason = s.window.cutPreview().error();
        QVERIFY(!reason.isEmpty());
        QVERIFY(!apply->isEnabled());
        QVERIFY(!menuApply->isEnabled());
        QVERIFY2(status->text().contains(reason), qPrintable(status->text()));
        QVERIFY(status->isVisibleTo(panel));
        // Clicking, the shortcut's action or the call itself apply nothing.
        QTest::mouseClick(apply, Qt::LeftButton);
        menuApply->trigger();
        QString error;
        QVERIFY(!s.window.cutPreview().apply(&error));
        QVERIFY(error.contains(reason));
        QVERIFY(s.idle());
        QCOMPARE(s.window.document().undoStack()->count(), 0);
        QCOMPARE(s.tets(), tets);
        QCOMPARE(errors.count(), 0);
        QVERIFY(s.window.findChildren<QMessageBox*>().isEmpty());
        s.window.setUnsavedChangesAnswer(QMessageBox::Discard);
    }

    // Issue 15: no sequence of edits produces a document whose state does not derive.
    void randomEditsNeverLeaveAFailingDocument_data() {
        QTest::addColumn<unsigned>("seed");
        for (unsigned seed : {11u, 12u, 13u})
            QTest::addRow("seed %u", seed) << seed;
    }
    void randomEditsNeverLeaveAFailingDocument() {
        QFETCH(unsigned, seed);
        Studio s;
        QVERIFY(s.load());
        int failures = 0;
        randomEdits(s, seed, 16, failures);
        if (QTest::currentTestFailed())
            return;
        QVERIFY(failures >= 1); // the sequence did try failing edits
        // The state on show is the one replay makes, bit for bit.
        Tissue direct;
        QVERIFY(replays(s.window.document().scenario(), &direct).ok());
        QCOMPARE(tissueDifference(s.window.session().current()->tissue, direct), QString());
        s.window.setUnsavedChangesAnswer(QMessageBox::Discard);
    }

    // Issue 15: a saved scenario reopens in a fresh studio with the same tissue and replays
    // through `resect run`'s runScenario.
    void saveReopenReplayRoundTrips_data() {
        QTest::addColumn<unsigned>("seed");
        for (unsigned seed : {21u, 22u})
            QTest::addRow("seed %u", seed) << seed;
    }
    void saveReopenReplayRoundTrips() {
        QFETCH(unsigned, seed);
        const QString path = m_dir.filePath(QStringLiteral("round-trip-%1.json").arg(seed));
        Studio s;
        QVERIFY(s.load());
        int failures = 0;
        randomEdits(s, seed, 12, failures);
        if (QTest::currentTestFailed())
            return;
        QVERIFY(s.window.saveAs(path));
        const Scenario saved = s.window.document().scenario();
        const auto shown = s.window.session().current();

        Studio fresh;
        QVERIFY(fresh.open(path));
        QVERIFY(fresh.window.document().scenario() == saved);
        QCOMPARE(tissueDifference(fresh.window.session().current()->tissue, shown->tissue),
                 QString());

        Scenario loaded;
        ScenarioDiagnostics diag;
        QVERIFY(loadScenario(path.toStdString(), loaded, diag).ok());
        ScenarioRun run;
        const Status replayed = runScenario(loaded, run);
        QVERIFY2(replayed.ok(), replayed.message().c_str());
        QCOMPARE(run.tissues.size(), std::size_t(1));
        QCOMPARE(run.tissues.front().outcome.mesh.tetCount(), shown->mesh().tetCount());
        QCOMPARE(run.tissues.front().outcome.pieces, shown->pieces);
        s.window.setUnsavedChangesAnswer(QMessageBox::Discard);
    }

    // Issue 15: opening something that fails (to read, to load its tissue) leaves the open
    // document, its undo stack, its title and the tissue on show exactly as they were.
    void aFailedOpenLeavesEverythingUnchanged_data() {
        QTest::addColumn<QString>("kind");
        QTest::newRow("corrupt scenario") << "corrupt";
        QTest::newRow("scenario on a broken tet mesh") << "broken mesh";
        QTest::newRow("scenario on an open surface") << "open surface";
        QTest::newRow("broken tet mesh") << "mesh file";
    }
    void aFailedOpenLeavesEverythingUnchanged() {
        QFETCH(QString, kind);
        QTemporaryDir dir;
        QVERIFY(dir.isValid());
        Studio s;
        QVERIFY(s.load());
        // An open document with a file, edits, undo history and a cut on show.
        QVERIFY(s.window.saveAs(dir.filePath(QStringLiteral("previous.json"))));
        s.window.document().addSweep(planeSweep(s.window.session().base()->mesh(), 0.6));
        s.window.document().setD(0.3);
        QVERIFY(s.idle());
        QCOMPARE(s.window.session().current()->cuts(), 1);

        const auto write = [&](const QString& name, const QByteArray& bytes) {
            QFile f(dir.filePath(name));
            QVERIFY(f.open(QIODevice::WriteOnly));
            f.write(bytes);
        };
        QString path;
        if (kind == QLatin1String("corrupt")) {
            path = dir.filePath(QStringLiteral("corrupt.json"));
            write(QStringLiteral("corrupt.json"), "{\"format\": \"resect-scenario\", \"vers");
        } else if (kind == QLatin1String("mesh file")) {
            path = dir.filePath(QStringLiteral("garbage.vtu"));
            write(QStringLiteral("garbage.vtu"),
                  "<VTKFile type=\"UnstructuredGrid\"> this is not a mesh");
        } else {
            Scenario bad = s.window.document().scenario();
            TissueSpec& tissue = bad.tissues.front();
            tissue.surface.clear();
            if (kind == QLatin1String("broken mesh")) {
                write(QStringLiteral("garbage.vtu"),
                      "<VTKFile type=\"UnstructuredGrid\"> this is not a mesh");
                tissue.mesh = dir.filePath(QStringLiteral("garbage.vtu")).toStdString();
            } else {
                write(QStringLiteral("open.obj"), "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n");
                tissue.surface = dir.filePath(QStringLiteral("open.obj")).toStdString();
            }
            path = dir.filePath(QStringLiteral("bad.json"));
            const Status saved = saveScenario(path.toStdString(), bad);
            QVERIFY2(saved.ok(), saved.message().c_str());
        }

        const QString title = s.window.windowTitle();
        const Scenario scenario = s.window.document().scenario();
        const QString file = s.window.document().filePath();
        const int undoCount = s.window.document().undoStack()->count();
        const int undoIndex = s.window.document().undoStack()->index();
        const auto current = s.window.session().current();
        const TetMesh* shown = s.window.shownTissue().mesh();
        const int actorTets = s.window.viewport()->tetMeshActor().tetCount();
        QSignalSpy errors(&s.window, &MainWindow::errorReported);
        QSignalSpy loaded(&s.window, &MainWindow::meshLoaded);

        s.window.setUnsavedChangesAnswer(QMessageBox::Discard); // go ahead without saving
        QVERIFY(!s.open(path));
        QVERIFY(s.idle());
        QCOMPARE(errors.count(), 1);
        const QString message = errors.first().first().toString();
        QVERIFY2(message.contains(QFileInfo(path).fileName()) ||
                     message.contains(QStringLiteral("garbage.vtu")) ||
                     message.contains(QStringLiteral("open.obj")),
                 qPrintable(message));
        QCOMPARE(loaded.count(), 0);
        QCOMPARE(s.window.windowTitle(), title);
        QVERIFY(s.window.document().scenario() == scenario);
        QCOMPARE(s.window.document().filePath(), file);
        QVERIFY(s.window.document().isModified());
        QCOMPARE(s.window.document().undoStack()->count(), undoCount);
        QCOMPARE(s.window.document().undoStack()->index(), undoIndex);
        QCOMPARE(s.window.session().current(), current);
        QVERIFY(s.window.session().error().isEmpty());
        QCOMPARE(s.window.shownTissue().mesh(), shown);
        QCOMPARE(s.window.viewport()->tetMeshActor().tetCount(), actorTets);
        // The document goes on as before: undo still undoes its own edits.
        s.action("undo")->trigger();
        QCOMPARE(s.window.document().scenario().cut.d, 0.2);
    }

    // Issue 15: a successful open resets every view: the pending cut, what was drawn or
    // recorded, the picked tet, the study and its chart, the quality comparison, messages.
    void aSmallAnatomyAfterALargeOneIsFramed() {
        // Issue 18, found importing CGAL's femur (0.3 long) after the polyp (20 mm): the view
        // framed the new tet mesh together with the old surface, and the femur was a dot.
        Studio s;
        QVERIFY(s.load());
        const double radius = 0.15;
        const QString file = m_dir.filePath(QStringLiteral("small-body.obj"));
        QVERIFY(writeSurface(file.toStdString(), makeEllipsoid(Vec3(radius, 0.8 * radius, 0.6 * radius), 16, 32)).ok());
        QVERIFY(s.open(file));
        QVERIFY(s.tets() > 0);
        // Framed: the camera looks at the body's centre from a distance of a few radii (the
        // polyp's framing left it 600 of them away).
        vtkCamera* camera = s.window.viewport()->camera();
        double focal[3], position[3];
        camera->GetFocalPoint(focal);
        camera->GetPosition(position);
        const double distance = (Vec3(position[0], position[1], position[2]) - Vec3(focal[0], focal[1], focal[2])).norm();
        QVERIFY2(distance > radius && distance < 20.0 * radius, qPrintable(QString::number(distance)));
        QVERIFY(Vec3(focal[0], focal[1], focal[2]).norm() < 0.5 * radius);
    }

    void aSuccessfulOpenResetsEveryView() {
        const QString target = m_dir.filePath(QStringLiteral("reset-target.json"));
        Studio s;
        QVERIFY(s.load());
        s.window.document().addSweep(planeSweep(s.window.session().base()->mesh(), 0.5));
        QVERIFY(s.idle());
        QVERIFY(s.window.saveAs(target));
        const int targetTets = s.tets();
        const int baseTets = s.window.session().base()->mesh().tetCount();

        // The study on this tissue.
        AccuracyPanel* accuracy = s.window.accuracyPanel();
        StudyConfig config = tinyConfig();
        config.dValues = {0.2};
        config.repeats = 1;
        accuracy->setCustomConfig(config);
        QSignalSpy studied(accuracy, &AccuracyPanel::studyFinished);
        accuracy->run();
        QVERIFY(studied.wait(kWaitMs));
        QVERIFY(!accuracy->rows().empty());
        accuracy->selectRow(0);
        // A refused edit's notice, a picked tet, a message.
        s.window.document().setRings(CutLimits::kMaxRelaxRings + 1);
        QVERIFY(s.idle());
        QVERIFY(!s.window.cutPanel()->notice().isEmpty());
        s.window.qualityPanel()->inspectTet(s.window.session().current()->mesh(), 3, Scheme::None);
        QCOMPARE(s.window.qualityPanel()->inspector()->tet(), 3);
        // A recorded stroke, pending, previewed.
        AuthoringPanel* authoring = s.window.authoringPanel();
        double now = 0;
        authoring->strokeRecorder().setClock([&now] { return now; });
        authoring->findChild<QPushButton*>(QStringLiteral("recordStrokeButton"))->click();
        VtkViewport* view = s.window.viewport();
        const int y = view->height() / 2;
        QTest::mousePress(view, Qt::LeftButton, {}, QPoint(view->width() / 5, y));
        for (int i = 1; i <= 6; ++i) {
            now += 0.05;
            QTest::mouseMove(view, QPoint(view->width() / 5 + i * view->width() / 10, y));
        }
        QTest::mouseRelease(view, Qt::LeftButton, {},
                            QPoint(view->width() / 5 + 6 * view->width() / 10, y));
        QVERIFY(s.idle());
        QVERIFY(s.window.cutPreview().preview());
        QVERIFY(!authoring->lastStroke().poses.empty());
        authoring->findChild<QPushButton*>(QStringLiteral("drawSweepButton"))->click();
        s.window.statusBar()->showMessage(QStringLiteral("an old message"));
        QCOMPARE(s.window.qualityPanel()->summaryTable()->value(QualitySummaryTable::Tets,
                                                                QualitySummaryTable::After),
                 QString::number(s.window.cutPreview().preview()->mesh().tetCount()));
        // The overlap row: the preview's, as deepestOverlap measures it (issue 16's defect).
        QCOMPARE(s.window.qualityPanel()->summaryTable()->value(QualitySummaryTable::Overlap,
                                                                QualitySummaryTable::After),
                 QString::number(deepestOverlap(s.window.cutPreview().preview()->mesh()).depth, 'g', 6));
        QCOMPARE(s.window.qualityPanel()->summaryTable()->value(QualitySummaryTable::Overlap,
                                                                QualitySummaryTable::Before),
                 QString::number(deepestOverlap(s.window.session().current()->mesh()).depth, 'g', 6));

        s.window.setUnsavedChangesAnswer(QMessageBox::Discard);
        QVERIFY(s.open(target));
        QVERIFY(!s.window.cutPreview().hasPending());
        QVERIFY(!s.window.cutPreview().preview());
        QCOMPARE(s.window.shownTissue().source(), ShownTissue::Source::Current);
        QVERIFY(authoring->lastStroke().poses.empty());
        QVERIFY(authoring->strokeRecorder().poses().empty());
        QVERIFY(!authoring->strokeRecorder().toolActor().isVisible());
        QVERIFY(
            !authoring->findChild<QPushButton*>(QStringLiteral("drawSweepButton"))->isChecked());
        QVERIFY(
            !authoring->findChild<QPushButton*>(QStringLiteral("playStrokeButton"))->isEnabled());
        QVERIFY(accuracy->rows().empty());
        QVERIFY(accuracy->chart()->rows().empty());
        QCOMPARE(accuracy->selectedRow(), -1);
        QCOMPARE(s.window.qualityPanel()->inspector()->tet(), -1);
        QVERIFY(s.window.cutPanel()->notice().isEmpty());
        QCOMPARE(s.window.statusBar()->currentMessage(), QString());
        QCOMPARE(s.window.qualityPanel()->summaryTable()->value(QualitySummaryTable::Tets,
                                                                QualitySummaryTable::Before),
                 QString::number(baseTets));
        QCOMPARE(s.window.qualityPanel()->summaryTable()->value(QualitySummaryTable::Tets,
                                                                QualitySummaryTable::After),
                 QString::number(targetTets));
        QCOMPARE(s.tets(), targetTets);
    }

    // Issue 16: the quality dock draws the remaining tissue's worst radius ratio, relative to
    // the input's, after every cut of the open scenario; cuts applied through the cut panel
    // add their points (the pending one's shown apart first), undo takes them away.
    void qualityDockCurveFollowsTheAppliedCuts() {
        Studio s;
        QVERIFY(s.load());
        QualityCurve* curve = s.window.qualityPanel()->cutCurve();
        QVERIFY(curve);
        QCOMPARE(curve->points(), std::vector<QPointF>{QPointF(0, 1)}); // the input alone
        QVERIFY(!curve->pendingPoint());

        // Without the improvement, and with a small d, the cuts leave worse tets than the
        // input's worst (with it the curve of these cuts stays at 1).
        auto* improve = s.window.cutPanel()->findChild<QCheckBox*>(QStringLiteral("improve"));
        QTest::mouseClick(improve, Qt::LeftButton, {}, indicatorCentre(improve));
        s.window.cutPanel()->findChild<QDoubleSpinBox*>(QStringLiteral("d"))->setValue(0.05);
        QVERIFY(s.idle());
        QCOMPARE(s.window.document().scenario().cut.improve, false);
        QCOMPARE(curve->points().size(), std::size_t(1));

        const TetMesh& base = s.window.session().base()->mesh();
        auto* apply = s.window.cutPanel()->findChild<QPushButton*>(QStringLiteral("applyCut"));
        for (const SweepSpec& sweep : {planeSweep(base, 0.6, 1e-3), planeSweep(base, 0.4, 2e-3)}) {
            s.window.cutPreview().setPendingSweep(sweep);
            QVERIFY(s.idle());
            const auto pending = curve->pendingPoint();
            QVERIFY(pending);
            QCOMPARE(pending->x(), double(curve->points().size()));
            QVERIFY(apply->isEnabled());
            QTest::mouseClick(apply, Qt::LeftButton);
            QVERIFY(s.idle());
            QVERIFY(!curve->pendingPoint());
        }
        QCOMPARE(int(s.window.document().scenario().sweeps.size()), 2);

        // Independently of the studio: the scenario replayed with its first cut, then both.
        Scenario first = s.window.document().scenario();
        first.sweeps.resize(1);
        Tissue once, twice;
        QVERIFY(replays(first, &once).ok());
        QVERIFY(replays(s.window.document().scenario(), &twice).ok());
        const double input = once.inputWorstRatio();
        QVERIFY(input > 0);
        QCOMPARE(curve->inputRatio(), input);
        const std::vector<QPointF> points = curve->points();
        QCOMPARE(points.size(), std::size_t(3));
        QCOMPARE(points[0], QPointF(0, 1));
        QCOMPARE(points[1], QPointF(1, summarizeQuality(once.mesh()).minRadiusRatio / input));
        QCOMPARE(points[2], QPointF(2, summarizeQuality(twice.mesh()).minRadiusRatio / input));
        QCOMPARE(points[2].y() * input, s.window.session().current()->quality.minRadiusRatio);
        // (The second cut need not worsen the worst tet: a new sample's base is anchored, and
        // what the cuts take off, worst tets included, leaves the tissue as a chip.)
        QVERIFY2(points[1].y() < 1 && points[2].y() < 1,
                 qPrintable(QStringLiteral("%1 %2").arg(points[1].y()).arg(points[2].y())));
        for (const QPointF& p : points)
            QVERIFY(curve->plotRect().adjusted(-1, -1, 1, 1).contains(curve->pixelOf(p)));
        QVERIFY(!curve->pointToolTip(2).isEmpty());

        // Undo the second cut: its point goes.
        s.action("undo")->trigger();
        QVERIFY(s.idle());
        QCOMPARE(curve->points().size(), std::size_t(2));
        QCOMPARE(curve->points()[1], points[1]);
        s.window.setUnsavedChangesAnswer(QMessageBox::Discard);
    }

    // Issue 15, the paper's loop motion: "Pull loop", one click near the top of the polyp's
    // head, pulls the loop from behind the tissue towards the camera and takes off a chip.
    void aPulledLoopTakesOffAChip() {
        Studio s;
        QVERIFY(s.load());
        QCOMPARE(s.window.session().current()->pieces, 1);
        AuthoringPanel* authoring = s.window.authoringPanel();
        auto* pull = authoring->findChild<QPushButton*>(QStringLiteral("pullLoopButton"));
        QVERIFY(pull);
        pull->click();
        QVERIFY(authoring->strokeRecorder().isRecording());
        QCOMPARE(authoring->strokeRecorder().motion(), StrokeRecorder::Motion::Pull);

        // Where to click: on the head's centre line, 40 % of the loop's depth (half its
        // width) below the top of the tissue as seen.
        VtkViewport* view = s.window.viewport();
        vtkCamera* camera = view->camera();
        double upArray[3];
        camera->GetViewUp(upArray);
        const Vec3 up(upArray[0], upArray[1], upArray[2]);
        const TetMesh& mesh = s.window.session().current()->mesh();
        Vec3 centre = Vec3::Zero();
        double top = -1e300;
        for (const Vec3& p : mesh.positions()) {
            centre += p;
            top = std::max(top, p.dot(up));
        }
        centre /= double(mesh.nodeCount());
        const double depth = 0.4 * 0.5 * loopWidth(s.window.document().scenario().tool);
        const Vec3 tip = centre + (top - depth - centre.dot(up)) * up;
        const auto pixel = worldToPixel(camera, view->size(), tip);
        QVERIFY(pixel.has_value());
        QTest::mousePress(view, Qt::LeftButton, {}, pixel->toPoint());
        QTest::mouseRelease(view, Qt::LeftButton, {}, pixel->toPoint());
        QVERIFY(!authoring->strokeRecorder().isRecording());
        QCOMPARE(authoring->lastStroke().poses.size(), std::size_t(2));
        // The loop goes from behind the tissue to in front of it, towards the camera, along
        // the ray through the click.
        const Vec3 toward = pixelRay(camera, view->size(), pixel->toPoint()).direction;
        const Vec3 start = authoring->lastStroke().poses.front().position;
        const Vec3 end = authoring->lastStroke().poses.back().position;
        QVERIFY((end - start).dot(toward) < 0);
        for (const Vec3& p : mesh.positions()) {
            QVERIFY((start - p).dot(toward) > 0);
            QVERIFY((end - p).dot(toward) < 0);
        }

        QVERIFY(s.window.cutPreview().hasPending());
        QVERIFY(s.idle());
        QVERIFY2(s.window.cutPreview().error().isEmpty(),
                 qPrintable(s.window.cutPreview().error()));
        QCOMPARE(s.window.cutPreview().preview()->pieces, 2);
        auto* apply = s.window.cutPanel()->findChild<QPushButton*>(QStringLiteral("applyCut"));
        QVERIFY(apply->isEnabled());
        QTest::mouseClick(apply, Qt::LeftButton);
        QVERIFY(s.idle());
        QCOMPARE(int(s.window.document().scenario().strokes.size()), 1);
        QCOMPARE(s.window.session().current()->pieces, 2); // a chip came off
        QVERIFY(s.window.session().error().isEmpty());
        s.window.setUnsavedChangesAnswer(QMessageBox::Discard);
    }

    // Issue 19 item 3: a new scene from a sample has its base anchored and damping on; the
    // fixed-region editor anchors nodes (an undoable edit typed into its numbers), and with
    // gravity the base stays where it is and the body in view. Without the anchors the same
    // simulation drops the body far below where it was.
    void aNewSampleSceneStaysInPlaceUnderGravity() {
        Studio s;
        QVERIFY(s.load());
        QSignalSpy errors(&s.window, &MainWindow::errorReported);
        SimulationPanel* panel = s.window.simulationPanel();
        QVERIFY(panel->effectBox("fixed")->isChecked());
        QVERIFY(panel->effectBox("damping")->isChecked());
        QVERIFY(!panel->effectBox("gravity")->isChecked());
        auto* coefficient = panel->findChild<QDoubleSpinBox*>(QStringLiteral("dampingCoefficient"));
        QVERIFY(coefficient && coefficient->isEnabled());
        QCOMPARE(coefficient->value(), kDefaultDampingCoefficient);
        FixedRegionEditor* editor = panel->fixedRegionEditor();
        QCOMPARE(editor->regionCount(), 1);

        // The base: anchored nodes, all in the bottom few percent of the height.
        const TetMesh& uncut = s.window.session().base()->mesh();
        double zmin = uncut.ref(0).z(), zmax = zmin;
        for (const Vec3& p : uncut.referencePositions()) {
            zmin = std::min(zmin, p.z());
            zmax = std::max(zmax, p.z());
        }
        const double height = zmax - zmin;
        const std::vector<int> base = s.window.session().current()->tissue.anchors().nodes();
        QVERIFY(base.size() >= 10);
        QCOMPARE(editor->anchoredNodes(), int(base.size()));
        auto* anchoredLabel = panel->findChild<QLabel*>(QStringLiteral("anchoredNodes"));
        QVERIFY2(anchoredLabel->text().contains(QString::number(base.size())), qPrintable(anchoredLabel->text()));
        for (int n : base)
            QVERIFY(uncut.ref(n).z() <= zmin + 1.01 * kBaseRegionFraction * height);

        // Typing a higher top into the box anchors more nodes; undo takes it back.
        QDoubleSpinBox* top = editor->coordinateBox(0, true, 2);
        QVERIFY(top && top == panel->findChild<QDoubleSpinBox*>(QStringLiteral("region0MaxZ")));
        top->setFocus();
        top->selectAll();
        QTest::keyClicks(top, QString::number(zmin + 0.25 * height, 'f', 2));
        QTest::keyClick(top, Qt::Key_Return);
        QVERIFY(s.idle());
        QCOMPARE(s.window.document().fixedRegions().front().max.z(), std::round((zmin + 0.25 * height) * 100) / 100);
        QVERIFY(s.window.session().current()->tissue.anchors().nodes().size() > base.size() + 10);
        QCOMPARE(editor->anchoredNodes(), int(s.window.session().current()->tissue.anchors().nodes().size()));
        s.action("undo")->trigger();
        QVERIFY(s.idle());
        QCOMPARE(s.window.session().current()->tissue.anchors().nodes(), base);
        QCOMPARE(editor->anchoredNodes(), int(base.size()));

        // Gravity on, a third of a second simulated.
        panel->effectBox("gravity")->click();
        QVERIFY(s.idle());
        QVERIFY(s.window.simulation().isReady());
        const auto simulate = [&s] {
            for (int i = 0; i < 300; ++i)
                if (!s.window.simulation().step())
                    return false;
            return true;
        };
        QVERIFY2(simulate(), qPrintable(s.window.simulation().error()));
        const TetMesh& mesh = s.window.simulation().mesh();
        for (int n : base)
            QCOMPARE(mesh.pos(n), mesh.ref(n)); // held exactly
        // The body sags but stays where it was: every node within a body height of its bounds.
        double lowest = mesh.pos(0).z(), meanDrop = 0;
        for (int n = 0; n < mesh.nodeCount(); ++n) {
            lowest = std::min(lowest, mesh.pos(n).z());
            meanDrop += (mesh.ref(n).z() - mesh.pos(n).z()) / mesh.nodeCount();
        }
        QVERIFY2(lowest > zmin - 0.5 * height, qPrintable(QString::number(lowest)));
        QVERIFY(meanDrop > 0); // it does sag
        QVERIFY2(meanDrop < 0.5 * height, qPrintable(QString::number(meanDrop)));
        // And it is in view: the simulated tissue is on show and every node projects into the
        // viewport (the camera as framed for the new scene).
        QVERIFY(s.window.shownTissue().source() == ShownTissue::Source::Simulation);
        VtkViewport* view = s.window.viewport();
        for (int n = 0; n < mesh.nodeCount(); ++n) {
            const auto pixel = worldToPixel(view->camera(), view->size(), mesh.pos(n));
            QVERIFY(pixel);
            QVERIFY2(QRectF(QPointF(0, 0), QSizeF(view->size())).contains(*pixel),
                     qPrintable(QString("node %1 at (%2, %3)").arg(n).arg(pixel->x()).arg(pixel->y())));
        }

        // Without the anchors (the fixed effect off) the same simulation drops the body.
        panel->effectBox("fixed")->click();
        QVERIFY(s.idle());
        QVERIFY(!s.window.document().isEffectEnabled(QStringLiteral("fixed")));
        QVERIFY2(simulate(), qPrintable(s.window.simulation().error()));
        const TetMesh& free = s.window.simulation().mesh(); // a new simulation (the old `mesh` is gone)
        double freeDrop = 0;
        for (int n = 0; n < free.nodeCount(); ++n)
            freeDrop += (free.ref(n).z() - free.pos(n).z()) / free.nodeCount();
        QVERIFY2(freeDrop > 2 * height, qPrintable(QString::number(freeDrop)));
        QCOMPARE(errors.count(), 0);
        s.window.setUnsavedChangesAnswer(QMessageBox::Discard);
    }

    // A second new scene on the same sample reuses the loaded tissue (not meshed again) with
    // its anchors, and the fixed regions go on working.
    void aNewSceneOnTheSameSampleKeepsItsAnchors() {
        Studio s;
        QVERIFY(s.load());
        const auto first = s.window.session().base();
        const std::vector<int> anchors = first->tissue.anchors().nodes();
        s.window.setUnsavedChangesAnswer(QMessageBox::Discard);
        QVERIFY(s.load());
        QVERIFY(s.window.session().base());
        QCOMPARE(s.window.session().base()->tissue.anchors().nodes(), anchors);
        QCOMPARE(s.window.session().current()->tissue.anchors().nodes(), anchors);
        QVERIFY(s.window.simulationPanel()->fixedRegionEditor()->baseRegionOfTissue());
        QCOMPARE(s.window.simulationPanel()->fixedRegionEditor()->anchoredNodes(), int(anchors.size()));
        QVERIFY(s.window.simulation().isReady());
    }

    // Toggling effects never opens a dialog: with error dialogs on, every effect switched on
    // and off (also quickly, while the last edit is still derived) leaves no message box and
    // reports no error; the fixed effect without a box anchors the tissue's base again.
    void togglingEffectsOpensNoDialog() {
        Studio s;
        s.window.setErrorDialogsEnabled(true);
        QVERIFY(s.load());
        QSignalSpy errors(&s.window, &MainWindow::errorReported);
        SimulationPanel* panel = s.window.simulationPanel();
        const auto messageBoxes = [] {
            int n = 0;
            for (QWidget* w : QApplication::topLevelWidgets())
                n += qobject_cast<QMessageBox*>(w) != nullptr && w->isVisible() ? 1 : 0;
            return n;
        };
        const Scenario before = s.window.document().scenario();
        for (int round = 0; round < 2; ++round)
            for (const std::string& name : knownEffectNames()) {
                QCheckBox* box = panel->effectBox(name);
                box->click();
                if (round == 1)
                    QVERIFY(s.idle()); // the first round does not wait for the session
                box->click();
                QVERIFY(s.idle());
                QCOMPARE(messageBoxes(), 0);
                QVERIFY2(panel->notice().isEmpty(), qPrintable(panel->notice()));
                QVERIFY2(s.window.simulation().error().isEmpty(), qPrintable(s.window.simulation().error()));
            }
        QVERIFY(s.window.document().scenario() == before);
        // Every effect on at once: the simulation runs.
        for (const std::string& name : knownEffectNames())
            if (!panel->effectBox(name)->isChecked())
                panel->effectBox(name)->click();
        QVERIFY(s.idle());
        for (const std::string& name : knownEffectNames())
            QVERIFY2(s.window.document().isEffectEnabled(QString::fromStdString(name)), name.c_str());
        QVERIFY(s.window.simulation().step());

        // The last box removed switches the fixed effect off; ticking it anchors the base again.
        auto* remove = panel->findChild<QPushButton*>(QStringLiteral("region0Remove"));
        QVERIFY(remove);
        remove->click();
        QVERIFY(s.idle());
        QVERIFY(!panel->effectBox("fixed")->isChecked());
        QVERIFY(s.window.document().fixedRegions().empty());
        QVERIFY(s.window.session().current()->tissue.anchors().empty());
        panel->effectBox("fixed")->click();
        QVERIFY(s.idle());
        QVERIFY(s.window.document().isEffectEnabled(QStringLiteral("fixed")));
        QCOMPARE(s.window.document().fixedRegions().size(), std::size_t(1));
        QVERIFY(!s.window.session().current()->tissue.anchors().empty());

        // A parameter typed that the effect cannot take is undone in place, not in a dialog.
        auto* coefficient = panel->findChild<QDoubleSpinBox*>(QStringLiteral("dampingCoefficient"));
        QVERIFY(coefficient->minimum() > 0); // the editor cannot even make it 0
        QCOMPARE(messageBoxes(), 0);
        QCOMPARE(errors.count(), 0);
        s.window.setUnsavedChangesAnswer(QMessageBox::Discard);
    }

    // The boxes placed in the view: "Place in view" draws each with a handle per face; dragging
    // the top face's handle up moves that face (one undoable edit), the numbers follow, and
    // more nodes are anchored. A drag away from the handles turns the view instead.
    void aFixedRegionIsPlacedByDraggingItsHandle() {
        Studio s;
        QVERIFY(s.load());
        auto* tool = s.window.findChild<FixedRegionTool*>();
        QVERIFY(tool && !tool->isActive());
        auto* inView = s.window.simulationPanel()->findChild<QPushButton*>(QStringLiteral("editRegionsInView"));
        QVERIFY(inView && inView->isCheckable());
        inView->click();
        QVERIFY(tool->isActive());
        QCOMPARE(s.window.viewport()->tool(), static_cast<ViewportTool*>(tool));
        QCOMPARE(tool->handleCount(), 6);

        VtkViewport* view = s.window.viewport();
        const FixedRegion before = s.window.document().fixedRegions().front();
        const std::size_t anchored = s.window.session().current()->tissue.anchors().nodes().size();
        const FixedRegionTool::Face top{0, 2, true};
        const auto pixel = worldToPixel(view->camera(), view->size(), tool->faceCentre(top));
        QVERIFY(pixel);
        QCOMPARE(tool->faceAt(*pixel), std::optional<FixedRegionTool::Face>(top));
        const int steps = s.window.document().undoStack()->count();
        const QPoint from = pixel->toPoint();
        QTest::mousePress(view, Qt::LeftButton, {}, from);
        for (int i = 1; i <= 10; ++i)
            QTest::mouseMove(view, from - QPoint(0, 8 * i));
        QTest::mouseRelease(view, Qt::LeftButton, {}, from - QPoint(0, 80));
        QVERIFY(s.idle());
        const FixedRegion after = s.window.document().fixedRegions().front();
        QVERIFY2(after.max.z() > before.max.z() + 1, qPrintable(QString::number(after.max.z())));
        QCOMPARE(after.min, before.min); // only that face moved
        QCOMPARE(after.max.x(), before.max.x());
        QCOMPARE(s.window.document().undoStack()->count(), steps + 1); // one edit for the drag
        QCOMPARE(s.window.simulationPanel()->fixedRegionEditor()->coordinateBox(0, true, 2)->value(),
                 std::round(after.max.z() * 100) / 100);
        QVERIFY(s.window.session().current()->tissue.anchors().nodes().size() > anchored);
        QCOMPARE(tool->regions().front().max.z(), after.max.z());

        // Away from the handles the press is the camera's: the box stays.
        const Vec3 eye(view->camera()->GetPosition());
        QTest::mousePress(view, Qt::LeftButton, {}, QPoint(10, 10));
        QTest::mouseMove(view, QPoint(60, 20));
        QTest::mouseRelease(view, Qt::LeftButton, {}, QPoint(60, 20));
        QVERIFY(!(Vec3(view->camera()->GetPosition()) == eye));
        QCOMPARE(s.window.document().fixedRegions().front().max.z(), after.max.z());

        s.action("undo")->trigger();
        QVERIFY(s.idle());
        QCOMPARE(s.window.document().fixedRegions().front().max.z(), before.max.z());
        QCOMPARE(tool->regions().front().max.z(), before.max.z());
        // Another tool (drawing a sweep) takes the view: the boxes go, the button says so.
        view->setTool(nullptr);
        QVERIFY(!tool->isActive());
        QVERIFY(!inView->isChecked());
        QCOMPARE(tool->handleCount(), 0);
        s.window.setUnsavedChangesAnswer(QMessageBox::Discard);
    }

    // A box moved off the tissue while the fixed effect is on would anchor nothing: the edit is
    // undone and the simulation dock says why, in place.
    void aBoxThatHoldsNoNodeIsUndoneInPlace() {
        Studio s;
        QVERIFY(s.load());
        QSignalSpy errors(&s.window, &MainWindow::errorReported);
        SimulationPanel* panel = s.window.simulationPanel();
        const FixedRegion base = s.window.document().fixedRegions().front();
        QDoubleSpinBox* bottom = panel->fixedRegionEditor()->coordinateBox(0, false, 2);
        QDoubleSpinBox* top = panel->fixedRegionEditor()->coordinateBox(0, true, 2);
        top->setValue(200);
        QVERIFY(s.idle());
        bottom->setValue(150); // above the polyp: the box holds no node
        QVERIFY(s.idle());
        QVERIFY2(panel->notice().contains(QStringLiteral("holds no node")), qPrintable(panel->notice()));
        QCOMPARE(s.window.document().fixedRegions().front().min.z(), base.min.z());
        QCOMPARE(bottom->value(), base.min.z());
        QVERIFY(!s.window.session().current()->tissue.anchors().empty());
        QCOMPARE(errors.count(), 0);
        s.window.setUnsavedChangesAnswer(QMessageBox::Discard);
    }

    // Issue 19 item 4: a preview that divides the stable step by more than ten warns in the
    // cut dock, and its button shows the worst tet in the quality dock's tet inspector.
    void aCutThatWrecksTheStepWarnsWithItsWorstTet() {
        Studio s;
        QVERIFY(s.load());
        CutPanel* cut = s.window.cutPanel();
        auto* method = cut->findChild<QComboBox*>(QStringLiteral("method"));
        method->setCurrentIndex(method->findData(int(CutMethod::Subdivision)));
        cut->findChild<QCheckBox*>(QStringLiteral("improve"))->click();
        QVERIFY(s.idle());
        QCOMPARE(s.window.document().scenario().cut.method, CutMethod::Subdivision);
        QVERIFY(!s.window.document().scenario().cut.improve);
        QVERIFY(cut->warning().isEmpty());
        s.window.cutPreview().setPendingSweep(planeSweep(s.window.session().base()->mesh(), 0.7));
        QVERIFY(s.idle());
        const auto preview = s.window.cutPreview().preview();
        QVERIFY(preview);
        QVERIFY(s.window.session().current()->stableDt > CutPreview::kStepDropWarning * preview->stableDt);
        QVERIFY2(cut->warning().contains(QStringLiteral("times smaller")), qPrintable(cut->warning()));
        auto* inspect = cut->findChild<QPushButton*>(QStringLiteral("inspectWorstTet"));
        QVERIFY(inspect && inspect->isEnabled());
        // (click(), not a synthetic mouse click at the button's centre: with the machine loaded,
        // about one run of this file in six left the inspector at -1 after the mouse click; the
        // cause was not found, six instrumented runs did not repeat it. What is tested here is
        // what the button's click does.)
        inspect->click();
        TetInspector* inspector = s.window.qualityPanel()->inspector();
        QCOMPARE(inspector->tet(), preview->stepLimitingTets.front());
        QVERIFY(inspector->isVisible()); // its tab and the quality dock are raised
        // The inspected tet is the preview's (the mesh on show): its measures are there.
        auto* ratio = inspector->findChild<QLabel*>(QStringLiteral("radiusRatio"));
        const Tet& q = preview->mesh().tet(inspector->tet());
        const double expected = radiusRatio(preview->mesh().ref(q[0]), preview->mesh().ref(q[1]),
                                            preview->mesh().ref(q[2]), preview->mesh().ref(q[3]));
        QCOMPARE(ratio->text(), QString::number(expected, 'g', 6));
        s.window.setUnsavedChangesAnswer(QMessageBox::Discard);
    }
};

QTEST_MAIN(TestStudioMainWindow)
#include "test_studio_main_window.moc"
