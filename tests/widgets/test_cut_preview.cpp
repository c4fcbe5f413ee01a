// CutPreview: the pending cut and its preview on the session's current state, computed on its
// own worker thread (latest request wins), refused when it fails, applied as one undo step.

#include "core/mesh/validity.h"
#include "widgets/cut_preview.h"
#include "widgets/scenario_document.h"
#include "widgets/tissue_session.h"

#include "tests/widgets/sweep_fixtures.h"
#include "tests/widgets/tissue_compare.h"

#include <QSignalSpy>
#include <QTemporaryDir>
#include <QTest>

#include <memory>

using namespace resect;
using resect::test::planeSweep;
using resect::test::tissueDifference;

namespace {

constexpr int kWaitMs = 120'000;

/// A document on a sample with its session idle.
struct Scene {
    ScenarioDocument doc;
    TissueSession session{doc};
    explicit Scene(const QString& dir, const QString& sample = QStringLiteral("polyp")) {
        doc.setAutosaveDirectory(dir);
        if (doc.newFromSample(sample))
            session.waitForIdle(kWaitMs);
    }
    const TetMesh& baseMesh() const { return session.base()->mesh(); }
};

SweepSurface surfaceOf(const SweepSpec& spec) {
    SweepSurface s;
    if (!SweepSurface::fromCurves(spec.curves, s).ok())
        qFatal("bad test sweep");
    return s;
}

} // namespace

class TestCutPreview : public QObject {
    Q_OBJECT

    QTemporaryDir m_dir;

private slots:
    void initTestCase() { QVERIFY(m_dir.isValid()); }

    void previewFollowsThePendingCutAndTheCurrentState() {
        Scene s(m_dir.path());
        QVERIFY(s.session.current());
        CutPreview preview(s.doc, s.session);
        const auto current = s.session.current();
        const int tets = current->mesh().tetCount();
        const double volume = current->quality.volume;

        // A pending cut previews on a copy of current without touching the document.
        const SweepSpec a = planeSweep(s.baseMesh(), 0.6, 1e-3);
        preview.setPendingSweep(a);
        QVERIFY(preview.hasPending());
        QVERIFY(!preview.isReady());
        QVERIFY(preview.waitForIdle(kWaitMs));
        QVERIFY2(preview.error().isEmpty(), qPrintable(preview.error()));
        QVERIFY(preview.isReady());
        const auto p1 = preview.preview();
        QVERIFY(p1);
        // A new sample's base is anchored: the head the plane cuts off is a resected chip.
        int chipTets = 0;
        for (const Chip& c : p1->tissue.chips())
            chipTets += c.mesh.tetCount();
        QCOMPARE(p1->tissue.chips().size(), std::size_t(1));
        QVERIFY(p1->mesh().tetCount() + chipTets > tets);
        QCOMPARE(p1->pieces, 2);
        QVERIFY(std::abs(p1->quality.volume + p1->tissue.resectedVolume() - volume) < 1e-9 * volume);
        QVERIFY(p1->cutStats.cutEdges + p1->cutStats.cutNodes > 0);
        QCOMPARE(p1->cuts(), 1);
        QVERIFY(sameSweep(p1->applied.sweeps.back(), surfaceOf(a)));
        QCOMPARE(appendedCuts(current->applied, p1->applied), 1);
        QVERIFY(checkValidity(p1->mesh()).empty());
        QVERIFY(s.doc.scenario().sweeps.empty());
        QCOMPARE(s.doc.undoStack()->count(), 0);
        QCOMPARE(s.session.current(), current);
        // The preview is current cut by the sweep, nothing else: the same as cutting a copy.
        Tissue direct(current->tissue);
        QVERIFY(direct.cut(surfaceOf(a), current->applied.options).ok());
        direct.updateSurface();
        QCOMPARE(tissueDifference(p1->tissue, direct), QString());

        // Another pending sweep replaces the first.
        const SweepSpec b = planeSweep(s.baseMesh(), 0.4, 1e-3);
        preview.setPendingSweep(b);
        QVERIFY(preview.waitForIdle(kWaitMs));
        QVERIFY(sameSweep(preview.preview()->applied.sweeps.back(), surfaceOf(b)));
        QVERIFY(tissueDifference(preview.preview()->tissue, p1->tissue) != QString());

        // Settings: the session publishes a new current and the preview follows with them.
        s.doc.setD(0.0);
        QVERIFY(preview.waitForIdle(kWaitMs));
        QCOMPARE(preview.preview()->applied.options.d, 0.0);
        const int tets0 = preview.preview()->mesh().tetCount();
        s.doc.setD(0.45);
        QVERIFY(preview.waitForIdle(kWaitMs));
        QCOMPARE(preview.preview()->applied.options.d, 0.45);
        const int tets45 = preview.preview()->mesh().tetCount();
        QVERIFY2(tets0 > tets45, qPrintable(QStringLiteral("%1 %2").arg(tets0).arg(tets45)));

        // A cut added to the document: the preview is made on the new current.
        s.doc.addSweep(a);
        QVERIFY(preview.waitForIdle(kWaitMs));
        QCOMPARE(s.session.current()->cuts(), 1);
        QCOMPARE(preview.preview()->cuts(), 2);
        QCOMPARE(appendedCuts(s.session.current()->applied, preview.preview()->applied), 1);
    }

    void aFailingPreviewRefusesToApply_data() {
        QTest::addColumn<QString>("kind");
        QTest::newRow("curves of different lengths") << "curves";
        QTest::newRow("missing sweep file") << "file";
        QTest::newRow("stroke without two distinct poses") << "stroke";
    }
    void aFailingPreviewRefusesToApply() {
        QFETCH(QString, kind);
        Scene s(m_dir.path());
        CutPreview preview(s.doc, s.session);
        if (kind == QLatin1String("stroke")) {
            Stroke still;
            ToolPose pose;
            pose.position = Vec3(0, 0, 5);
            still.poses = {pose, pose};
            still.poses[1].t = 1;
            preview.setPendingStroke(still);
        } else {
            SweepSpec bad;
            if (kind == QLatin1String("curves"))
                bad.curves = {{Vec3(0, 0, 0), Vec3(1, 0, 0)}, {Vec3(0, 1, 0)}};
            else
                bad.file = m_dir.filePath(QStringLiteral("no-such-sweep.json")).toStdString();
            preview.setPendingSweep(bad);
        }
        QVERIFY(preview.waitForIdle(kWaitMs));
        QVERIFY(!preview.preview());
        QVERIFY(!preview.error().isEmpty());
        QVERIFY(preview.hasPending());

        const int undoSteps = s.doc.undoStack()->count();
        QString error;
        QVERIFY(!preview.apply(&error));
        QVERIFY2(error.contains(preview.error()), qPrintable(error));
        QCOMPARE(s.doc.undoStack()->count(), undoSteps);
        QVERIFY(s.doc.scenario().sweeps.empty());
        QVERIFY(s.doc.scenario().strokes.empty());
        QVERIFY(!s.doc.isModified());
        QVERIFY(preview.hasPending()); // still there to be fixed or discarded
    }

    void applyAddsExactlyOneUndoStep() {
        Scene s(m_dir.path());
        CutPreview preview(s.doc, s.session);

        // Nothing pending: refused with a reason.
        QString error;
        QVERIFY(!preview.apply(&error));
        QVERIFY(!error.isEmpty());
        QCOMPARE(s.doc.undoStack()->count(), 0);

        const SweepSpec sweep = planeSweep(s.baseMesh(), 0.6, 1e-3);
        preview.setPendingSweep(sweep);
        // Not computed yet (the worker starts from the event loop): refused as well.
        error.clear();
        QVERIFY(!preview.apply(&error));
        QVERIFY(!error.isEmpty());
        QCOMPARE(s.doc.undoStack()->count(), 0);

        QVERIFY(preview.waitForIdle(kWaitMs));
        const auto previewed = preview.preview();
        QVERIFY(previewed);
        QSignalSpy changed(&preview, &CutPreview::changed);
        QVERIFY(preview.apply(&error));
        QCOMPARE(s.doc.undoStack()->count(), 1);
        QCOMPARE(int(s.doc.scenario().sweeps.size()), 1);
        QCOMPARE(s.doc.scenario().sweeps.front(), sweep);
        QVERIFY(!preview.hasPending());
        QVERIFY(!preview.preview());
        QCOMPARE(changed.count(), 1);

        // The session derives the new current from the document: what was previewed.
        QVERIFY(preview.waitForIdle(kWaitMs));
        QCOMPARE(s.session.current()->cuts(), 1);
        QCOMPARE(tissueDifference(s.session.current()->tissue, previewed->tissue), QString());
        QVERIFY(!preview.preview()); // nothing pending, nothing previewed

        s.doc.undoStack()->undo();
        QVERIFY(s.doc.scenario().sweeps.empty());
    }

    void theLatestRequestWins() {
        Scene s(m_dir.path());
        CutPreview preview(s.doc, s.session);
        const SweepSpec a = planeSweep(s.baseMesh(), 0.6, 1e-3);
        const SweepSpec b = planeSweep(s.baseMesh(), 0.35, 2e-3);
        bool showedA = false;
        connect(&preview, &CutPreview::changed, &preview, [&] {
            if (const auto p = preview.preview())
                showedA = showedA || sameSweep(p->applied.sweeps.back(), surfaceOf(a));
        });
        preview.setPendingSweep(a);
        QCoreApplication::processEvents(); // the worker starts on a
        QVERIFY(preview.isBusy());
        preview.setPendingSweep(b);
        QVERIFY(preview.waitForIdle(kWaitMs));
        QVERIFY(!showedA);
        QVERIFY(preview.isReady());
        QVERIFY(sameSweep(preview.preview()->applied.sweeps.back(), surfaceOf(b)));
    }

    void discardAndANewDocumentDropThePendingCut() {
        Scene s(m_dir.path(), QStringLiteral("myoma"));
        CutPreview preview(s.doc, s.session);
        preview.setPendingSweep(planeSweep(s.baseMesh(), 0.5, 1e-3));
        QVERIFY(preview.waitForIdle(kWaitMs));
        QVERIFY(preview.preview());
        QSignalSpy changed(&preview, &CutPreview::changed);
        preview.discard();
        QCOMPARE(changed.count(), 1);
        QVERIFY(!preview.preview());
        QVERIFY(!preview.hasPending());
        QVERIFY(!s.doc.isModified());

        preview.setPendingSweep(planeSweep(s.baseMesh(), 0.5, 1e-3));
        QVERIFY(preview.waitForIdle(kWaitMs));
        QVERIFY(preview.preview());
        QVERIFY(s.doc.newFromSample(QStringLiteral("polyp")));
        QVERIFY(!preview.hasPending());
        QVERIFY(!preview.preview());
        QVERIFY(preview.waitForIdle(kWaitMs));
        QVERIFY(!preview.preview()); // the new current brings no preview back
    }

    void destroyingItWhileTheWorkerRunsIsSafe() {
        Scene s(m_dir.path());
        auto preview = std::make_unique<CutPreview>(s.doc, s.session);
        preview->setPendingSweep(planeSweep(s.baseMesh(), 0.6, 1e-3));
        QCoreApplication::processEvents(); // the worker starts
        QVERIFY(preview->isBusy());
        preview.reset();
        // The session and the document go on; a new preview works.
        s.doc.setD(0.3);
        QVERIFY(s.session.waitForIdle(kWaitMs));
        CutPreview again(s.doc, s.session);
        again.setPendingSweep(planeSweep(s.baseMesh(), 0.6, 1e-3));
        QVERIFY(again.waitForIdle(kWaitMs));
        QVERIFY(again.preview());
    }
};

QTEST_MAIN(TestCutPreview)
#include "test_cut_preview.moc"
