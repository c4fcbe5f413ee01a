// TissueSession: the tissue derived from the document on a worker thread (load, cuts,
// preview, apply, undo and redo), on the sample polyp.

#include "core/mesh/validity.h"
#include "widgets/scenario_document.h"
#include "widgets/tissue_session.h"

#include "tests/widgets/sweep_fixtures.h"

#include <QSignalSpy>
#include <QTemporaryDir>
#include <QTest>

using namespace resect;
using resect::test::planeSweep;

namespace {

constexpr int kWaitMs = 120'000;


} // namespace

class TestTissueSession : public QObject {
    Q_OBJECT

    QTemporaryDir m_dir;

private slots:
    void initTestCase() { QVERIFY(m_dir.isValid()); }

    void loadsTheSampleOffTheGuiThread() {
        ScenarioDocument doc;
        doc.setAutosaveDirectory(m_dir.path());
        TissueSession session(doc);
        QSignalSpy base(&session, &TissueSession::baseChanged);
        QVERIFY(doc.newFromSample(QStringLiteral("polyp")));
        // The request runs on the worker: the call returns before the tissue is there.
        QVERIFY(session.isBusy());
        QVERIFY(!session.base());
        QVERIFY(session.waitForIdle(kWaitMs));
        QCOMPARE(base.count(), 1);
        QVERIFY(session.error().isEmpty());
        const auto b = session.base();
        QVERIFY(b && b->mesh.tetCount() > 100);
        QVERIFY(!b->surface.empty());
        QCOMPARE(b->pieces, 1);
        QVERIFY(b->stableDt > 0);
        QCOMPARE(session.current()->mesh.tetCount(), b->mesh.tetCount());
        QVERIFY(!session.preview());
    }

    void previewFollowsSettingsApplyUndoRedo() {
        ScenarioDocument doc;
        doc.setAutosaveDirectory(m_dir.path());
        TissueSession session(doc);
        QVERIFY(doc.newFromSample(QStringLiteral("polyp")));
        QVERIFY(session.waitForIdle(kWaitMs));
        const int tets = session.current()->mesh.tetCount();
        const double volume = session.current()->quality.volume;

        // A pending cut previews without touching the document.
        session.setPendingSweep(planeSweep(session.base()->mesh, 0.6, 1e-3));
        QVERIFY(session.hasPending());
        QVERIFY(session.waitForIdle(kWaitMs));
        QVERIFY2(session.previewError().isEmpty(), qPrintable(session.previewError()));
        const auto p1 = session.preview();
        QVERIFY(p1);
        QVERIFY(p1->mesh.tetCount() > tets);
        QCOMPARE(p1->pieces, 2);
        QVERIFY(std::abs(p1->quality.volume - volume) < 1e-9 * volume);
        QVERIFY(p1->cutStats.cutEdges + p1->cutStats.cutNodes > 0);
        QVERIFY(doc.scenario().sweeps.empty());
        QVERIFY(!doc.isModified());
        QCOMPARE(session.current()->mesh.tetCount(), tets);
        // Schemes: every new tet was produced by one.
        for (int t = tets; t < p1->mesh.tetCount(); ++t)
            QVERIFY(p1->schemes[t] != Scheme::None);

        // d = 0 (every crossed edge split) and d = 0.45 (many cut nodes) give other counts.
        doc.setD(0.0);
        QVERIFY(session.waitForIdle(kWaitMs));
        const int tets0 = session.preview()->mesh.tetCount();
        doc.setD(0.45);
        QVERIFY(session.waitForIdle(kWaitMs));
        const int tets45 = session.preview()->mesh.tetCount();
        QVERIFY2(tets0 > tets45, qPrintable(QStringLiteral("%1 %2").arg(tets0).arg(tets45)));
        QCOMPARE(session.preview()->cutStats.cutNodes > 0, true);

        // Apply: the cut enters the document (one undo step) and the current state.
        QVERIFY(session.applyPending());
        QVERIFY(!session.hasPending());
        QCOMPARE(int(doc.scenario().sweeps.size()), 1);
        QVERIFY(session.waitForIdle(kWaitMs));
        const int cutTets = session.current()->mesh.tetCount();
        QCOMPARE(cutTets, tets45);
        QCOMPARE(session.current()->cuts, 1);
        QCOMPARE(session.current()->pieces, 2);
        QVERIFY(session.current()->surfaceCapTriangles > 0);
        QVERIFY(checkValidity(session.current()->mesh).empty());

        doc.undoStack()->undo(); // the sweep
        QVERIFY(session.waitForIdle(kWaitMs));
        QCOMPARE(session.current()->cuts, 0);
        QCOMPARE(session.current()->mesh.tetCount(), tets);
        doc.undoStack()->redo();
        QVERIFY(session.waitForIdle(kWaitMs));
        QCOMPARE(session.current()->mesh.tetCount(), cutTets);

        // Nothing pending: apply refuses with a reason.
        QString error;
        QVERIFY(!session.applyPending(&error));
        QVERIFY(!error.isEmpty());
    }

    void discardDropsThePreview() {
        ScenarioDocument doc;
        doc.setAutosaveDirectory(m_dir.path());
        TissueSession session(doc);
        QVERIFY(doc.newFromSample(QStringLiteral("myoma")));
        QVERIFY(session.waitForIdle(kWaitMs));
        session.setPendingSweep(planeSweep(session.base()->mesh, 0.5, 1e-3));
        QVERIFY(session.waitForIdle(kWaitMs));
        QVERIFY(session.preview());
        QSignalSpy changed(&session, &TissueSession::previewChanged);
        session.discardPending();
        QCOMPARE(changed.count(), 1);
        QVERIFY(!session.preview());
        QVERIFY(!session.hasPending());
        QVERIFY(!doc.isModified());
    }

    void badCutsAndTissuesAreReportedNotFatal() {
        ScenarioDocument doc;
        doc.setAutosaveDirectory(m_dir.path());
        TissueSession session(doc);
        QVERIFY(doc.newFromSample(QStringLiteral("polyp")));
        QVERIFY(session.waitForIdle(kWaitMs));
        // A sweep whose curves have different point counts: the preview fails with a reason.
        SweepSpec bad;
        bad.curves = {{Vec3(0, 0, 0), Vec3(1, 0, 0)}, {Vec3(0, 1, 0)}};
        session.setPendingSweep(bad);
        QVERIFY(session.waitForIdle(kWaitMs));
        QVERIFY(!session.preview());
        QVERIFY(!session.previewError().isEmpty());
        QString error;
        QVERIFY(!session.applyPending(&error));
        QVERIFY(error.contains(session.previewError().left(10)) || !error.isEmpty());
        QVERIFY(doc.scenario().sweeps.empty());

        // A surface that is not a closed surface: loading fails with a message, no crash.
        const QString path = m_dir.filePath(QStringLiteral("open.obj"));
        QFile f(path);
        QVERIFY(f.open(QIODevice::WriteOnly));
        f.write("v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n");
        f.close();
        QSignalSpy failed(&session, &TissueSession::failed);
        QVERIFY(doc.newFromAnatomy(path));
        QVERIFY(session.waitForIdle(kWaitMs));
        QCOMPARE(failed.count(), 1);
        QVERIFY(failed.first().first().toString().contains(QStringLiteral("open")));
    }

    void aNewerDocumentSupersedesALoadingOne() {
        ScenarioDocument doc;
        doc.setAutosaveDirectory(m_dir.path());
        TissueSession session(doc);
        QVERIFY(doc.newFromSample(QStringLiteral("polyp")));
        QVERIFY(doc.newFromSample(QStringLiteral("myoma")));
        QVERIFY(session.waitForIdle(kWaitMs));
        QCOMPARE(session.base()->tissueName, QStringLiteral("myoma"));
        QVERIFY(session.error().isEmpty());
    }
};

QTEST_MAIN(TestTissueSession)
#include "test_tissue_session.moc"
