// The studio's main window, driven like an author would (offscreen platform): open the
// sample, draw a pending cut, tune d and watch the preview, apply, undo and redo, save and
// reopen, open a corrupt file, run the simulation and toggle effects.

#include "main_window.h"

#include "widgets/accuracy_panel.h"
#include "widgets/authoring_panel.h"
#include "widgets/language.h"
#include "widgets/quality_panel.h"
#include "scenario/accuracy_study.h"
#include "widgets/cut_panel.h"
#include "widgets/cut_preview.h"
#include "widgets/stroke_recorder.h"
#include "widgets/scenario_document.h"
#include "widgets/simulation_controller.h"
#include "widgets/simulation_panel.h"
#include "widgets/shown_tissue.h"
#include "widgets/tissue_session.h"
#include "widgets/vtk_viewport.h"

#include <QAction>
#include <vtkCamera.h>
#include <QCheckBox>
#include <QComboBox>
#include <QMenuBar>
#include <QDoubleSpinBox>
#include <QLabel>
#include <QPushButton>
#include <QSettings>
#include "tests/widgets/sweep_fixtures.h"

#include <QSignalSpy>
#include <QStandardPaths>
#include <QTemporaryDir>
#include <QTest>

using namespace resect;
using resect::test::planeSweep;

namespace {

constexpr int kWaitMs = 180'000;


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
};

} // namespace

class TestStudioMainWindow : public QObject {
    Q_OBJECT

    QTemporaryDir m_dir;

private slots:
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
        QVERIFY(s.window.simulation().effectNames().size() == 2);

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

        // Undoing the effect edit rebuilds the simulation without gravity, at time 0.
        s.action("undo")->trigger();
        QVERIFY(!s.window.document().isEffectEnabled(QStringLiteral("gravity")));
        QVERIFY(!gravity->isChecked());
        QCOMPARE(s.window.simulation().steps(), 0LL);
        QCOMPARE(s.window.simulation().effectNames().size(), std::size_t(1));
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
        QVERIFY(s.window.simulation().mesh().tetCount() > tets);
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
};

QTEST_MAIN(TestStudioMainWindow)
#include "test_studio_main_window.moc"
