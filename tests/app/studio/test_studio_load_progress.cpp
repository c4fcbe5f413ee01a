// Issue 18: while the studio meshes anatomy, its load dialog ("loadProgress") shows the
// mesher's stages and the work done (MeshingProgress, forwarded by TissueSession), and its
// Cancel stops the load, leaving the open document and the tissue on show as they were.
// Driven through the real main window under the offscreen platform.

#include "main_window.h"

#include "core/mesher/samples.h"
#include "scenario/scenario_save.h"
#include "scenario/surface_io.h"
#include "widgets/scenario_document.h"
#include "widgets/tissue_session.h"

#include <QProgressDialog>
#include <QPushButton>
#include <QSettings>
#include <QSignalSpy>
#include <QStandardPaths>
#include <QStatusBar>
#include <QTemporaryDir>
#include <QTest>

#include <vector>

using namespace resect;

namespace {

constexpr int kWaitMs = 180'000;
/// An edge length that makes the polyp take several seconds to mesh (about 130 000 tets;
/// its default, about 1.9, gives about 900 tets in a fraction of a second).
constexpr double kFineEdgeLength = 0.3;

const QString kRefining = QStringLiteral("Meshing (Delaunay refinement)");
/// Every stage's text, in the mesher's order (TissueSession::stageText).
const QStringList kStages{QStringLiteral("Checking the surface"),
                          kRefining,
                          QStringLiteral("Removing slivers (perturbation)"),
                          QStringLiteral("Removing slivers (exudation)"),
                          QStringLiteral("Matching the volume"),
                          QStringLiteral("Checking element quality")};

/// What the load dialog showed when the session reported a stage.
struct Shown {
    QString label;
    int value = -1, minimum = -1, maximum = -1;
};

/// A main window whose load dialog is recorded each time the session reports progress. The
/// recorder is connected after the window's own connection, so the dialog has taken the
/// report when it is read: without forwarding nothing is recorded, and a dialog that ignored
/// the report would show the wrong label or range.
struct Studio {
    MainWindow window;
    std::vector<Shown> shown;
    Studio() {
        window.setErrorDialogsEnabled(false);
        window.resize(1200, 800);
        window.show();
        QObject::connect(&window.session(), &TissueSession::loadProgress, &window, [this] {
            auto* dialog = window.findChild<QProgressDialog*>(QStringLiteral("loadProgress"));
            Shown s;
            if (dialog != nullptr)
                s = {dialog->labelText(), dialog->value(), dialog->minimum(), dialog->maximum()};
            shown.push_back(s);
        });
    }
    bool loadSample() {
        QSignalSpy loaded(&window, &MainWindow::meshLoaded);
        window.openSample(Sample::Polyp);
        return loaded.wait(kWaitMs) && window.session().waitForIdle(kWaitMs);
    }
    QProgressDialog* dialog() {
        return window.findChild<QProgressDialog*>(QStringLiteral("loadProgress"));
    }
    QStringList labels() const {
        QStringList out;
        for (const Shown& s : shown)
            if (!out.contains(s.label))
                out.append(s.label);
        return out;
    }
};

} // namespace

class TestStudioLoadProgress : public QObject {
    Q_OBJECT

    QTemporaryDir m_dir;

private slots:
    void initTestCase() {
        QVERIFY(m_dir.isValid());
        QStandardPaths::setTestModeEnabled(true);
        QSettings().clear();
    }

    // Importing a surface (File > Import anatomy... opens it as openFile does): the dialog takes
    // every stage in order with a percentage.
    void importedSurfaceShowsEveryStage() {
        const QString path = m_dir.filePath(QStringLiteral("polyp.obj"));
        const Status written = writeSurface(path.toStdString(), sampleSurface(Sample::Polyp));
        QVERIFY2(written.ok(), written.message().c_str());
        Studio s;
        QSignalSpy loaded(&s.window, &MainWindow::meshLoaded);
        s.window.openFile(path);
        QVERIFY(loaded.wait(kWaitMs));
        QVERIFY(s.window.session().waitForIdle(kWaitMs));

        QVERIFY2(s.shown.size() >= std::size_t(kStages.size()),
                 "the session forwarded too few stages");
        QCOMPARE(s.labels(), kStages); // one attempt reaches the quality bound for the polyp
        double last = -1;
        for (const Shown& shown : s.shown) {
            QCOMPARE(shown.minimum, 0);
            QCOMPARE(shown.maximum, 100);
            QVERIFY(shown.value >= 0 && shown.value <= 100);
            QVERIFY2(shown.value >= last, "the work done went backwards within one attempt");
            last = shown.value;
        }
        QVERIFY(s.shown.back().value > 0);
    }

    // A slow meshing (a scenario on the polyp with a fine edge length): the dialog goes from
    // busy to the stages, and its Cancel stops the load; the previous document and tissue stay.
    void cancelStopsASlowMeshing() {
        Studio s;
        QVERIFY(s.loadSample());
        QVERIFY(s.shown.size() >= 2); // the sample is meshed too
        s.shown.clear();
        const auto previous = s.window.session().current();
        const Scenario before = s.window.document().scenario();

        Scenario fine = before;
        fine.tissues.front().meshing.edgeLength = kFineEdgeLength;
        const QString path = m_dir.filePath(QStringLiteral("fine.json"));
        const Status saved = saveScenario(path.toStdString(), fine);
        QVERIFY2(saved.ok(), saved.message().c_str());

        QSignalSpy loaded(&s.window, &MainWindow::meshLoaded);
        QSignalSpy errors(&s.window, &MainWindow::errorReported);
        s.window.openFile(path);
        // The dialog appears (after its minimum duration) and has shown the refinement.
        QVERIFY(QTest::qWaitFor(
            [&] {
                QProgressDialog* d = s.dialog();
                return (d != nullptr && d->isVisible() && s.labels().contains(kRefining)) ||
                       !s.window.session().isBusy();
            },
            kWaitMs));
        QVERIFY2(s.window.session().isBusy(), "the meshing ended before it could be cancelled");
        QCOMPARE(s.labels().value(0), kStages.front());
        QVERIFY(s.labels().size() >= 2);
        for (const Shown& shown : s.shown) {
            QCOMPARE(shown.minimum, 0);
            QCOMPARE(shown.maximum, 100);
            QVERIFY(shown.value >= 0 && shown.value <= 100);
        }
        QProgressDialog* dialog = s.dialog();
        QVERIFY(kStages.contains(dialog->labelText()));
        auto* cancel = dialog->findChild<QPushButton*>();
        QVERIFY(cancel);
        QTest::mouseClick(cancel, Qt::LeftButton);
        // The dialog hides at once; until the mesher has stopped, the status bar says why.
        QCOMPARE(s.window.statusBar()->currentMessage(), QStringLiteral("Cancelling..."));

        QVERIFY(QTest::qWaitFor([&] { return errors.count() > 0; }, kWaitMs));
        QVERIFY(s.window.session().waitForIdle(kWaitMs));
        QVERIFY2(
            errors.first().first().toString().contains(QStringLiteral("Opening was cancelled.")),
            qPrintable(errors.first().first().toString()));
        QVERIFY2(s.window.statusBar()->currentMessage().contains(QStringLiteral("fine.json")),
                 qPrintable(s.window.statusBar()->currentMessage()));
        QCOMPARE(loaded.count(), 0);
        QVERIFY(s.window.document().scenario() == before);
        QCOMPARE(s.window.session().current(), previous);
        QVERIFY(s.window.session().error().isEmpty());
        QVERIFY(s.dialog() == nullptr || !s.dialog()->isVisible());
    }
};

QTEST_MAIN(TestStudioLoadProgress)
#include "test_studio_load_progress.moc"
