// TissueSession: base and current derived from the document on a worker thread (load, cuts,
// undo and redo, settings), on the samples and the example polyp scenario. Current must be
// bit-identical to a Tissue made and cut directly as replay does it.

#include "core/mesh/validity.h"
#include "scenario/replay.h"
#include "scenario/scenario_run.h"
#include "widgets/scenario_document.h"
#include "widgets/tissue_session.h"

#include "tests/widgets/sweep_fixtures.h"
#include "tests/widgets/tissue_compare.h"

#include <QSignalSpy>
#include <QTemporaryDir>
#include <QTest>

#include <cstdint>
#include <cstring>
#include <functional>
#include <limits>
#include <span>

using namespace resect;
using resect::test::planeSweep;
using resect::test::tissueDifference;

namespace {

/// Tets of the tissue and of the chips resected from it (a cut adds to their sum).
int allTets(const Tissue& t) {
    int n = t.mesh().tetCount();
    for (const Chip& c : t.chips())
        n += c.mesh.tetCount();
    return n;
}


constexpr int kWaitMs = 120'000;

const QString kPolypScenario =
    QStringLiteral(RESECT_SOURCE_DIR "/resources/scenarios/polyp-resection.json");

/// The first tissue of `scenario` made as replay makes it (planTissue, makeTissue) and cut by
/// every cut of the scenario in replay order with the scenario's cut settings.
Status cutDirectly(const Scenario& scenario, Tissue& out) {
    ReplayPlan plan;
    if (Status s = planTissue(scenario, scenario.tissues.front(), plan); !s.ok())
        return s;
    if (Status s = makeTissue(plan, out); !s.ok())
        return s;
    for (const ReplayStroke& stroke : plan.strokes)
        if (Status s = out.cut(stroke.sweep, plan.cut); !s.ok())
            return Status::error(stroke.name + ": " + s.message());
    out.updateSurface();
    return Status::success();
}

/// A stroke whose tool never moves: two poses at the same place. Its sweep has fewer than
/// two distinct curves, which the scenario layer refuses.
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
        QSignalSpy current(&session, &TissueSession::currentChanged);
        QVERIFY(doc.newFromSample(QStringLiteral("polyp")));
        // The request runs on the worker: the call returns before the tissue is there.
        QVERIFY(session.isBusy());
        QVERIFY(!session.base());
        QVERIFY(session.waitForIdle(kWaitMs));
        QCOMPARE(base.count(), 1);
        QCOMPARE(current.count(), 1);
        QVERIFY(session.error().isEmpty());
        const auto b = session.base();
        QVERIFY(b && b->mesh().tetCount() > 100);
        QVERIFY(!b->surface().empty());
        QCOMPARE(b->pieces, 1);
        QVERIFY(b->stableDt > 0);
        QCOMPARE(b->cuts(), 0);
        QCOMPARE(b->tissue.cutCount(), 0);
        QVERIFY(b->applied.baseId != 0);
        QCOMPARE(b->tissueName, QStringLiteral("polyp"));
        for (Scheme s : b->tissue.schemes())
            QCOMPARE(s, Scheme::None);
        // No cuts: current is a copy of base, not base itself, from the same base.
        const auto c = session.current();
        QVERIFY(c && c != b);
        QCOMPARE(c->applied.baseId, b->applied.baseId);
        QCOMPARE(c->cuts(), 0);
        QCOMPARE(tissueDifference(c->tissue, b->tissue), QString());
    }

    // The example scenario: three strokes, snapping and relaxation, an anchored stalk.
    void currentIsTheDocumentsCutsAppliedLikeReplay() {
        ScenarioDocument doc;
        doc.setAutosaveDirectory(m_dir.path());
        TissueSession session(doc);
        QString error;
        QVERIFY2(doc.open(kPolypScenario, &error), qPrintable(error));
        QVERIFY(session.waitForIdle(kWaitMs));
        QVERIFY2(session.error().isEmpty(), qPrintable(session.error()));
        const Scenario& scenario = doc.scenario();
        QCOMPARE(int(scenario.strokes.size()), 3);

        // Base: the loaded tissue with the fixed region's nodes anchored, as replay makes it.
        ReplayPlan plan;
        QVERIFY(planTissue(scenario, scenario.tissues.front(), plan).ok());
        const auto base = session.base();
        QVERIFY(!plan.anchors.nodes.empty());
        QCOMPARE(base->tissue.anchors().nodes(), plan.anchors.nodes);
        // (and the one fixed region is the anchors' box: nodes cuts put in it are anchored)
        QVERIFY(plan.anchors.box && base->tissue.anchors().box() == plan.anchors.box);
        QCOMPARE(base->mesh().tetCount(), plan.mesh.tetCount());

        // Current: the three strokes cut in order, bit-identical to cutting directly.
        Tissue direct;
        QVERIFY(cutDirectly(scenario, direct).ok());
        auto current = session.current();
        QCOMPARE(current->cuts(), 3);
        QCOMPARE(current->tissue.cutCount(), 3);
        QCOMPARE(tissueDifference(current->tissue, direct), QString());
        QVERIFY(allTets(current->tissue) > base->mesh().tetCount());
        QCOMPARE(current->pieces, direct.pieces().count + static_cast<int>(direct.chips().size()));
        QVERIFY(current->pieces >= 2); // the head is off (the scenario expects it)
        QVERIFY(current->surfaceCapTriangles > 0);
        QVERIFY(current->cutStats.cutEdges + current->cutStats.cutNodes > 0);
        QVERIFY(checkValidity(current->mesh()).empty());
        // Every tet the cuts added was produced by a scheme (Figure 4).
        QCOMPARE(int(current->tissue.schemes().size()), current->mesh().tetCount());
        for (int t = base->mesh().tetCount(); t < current->mesh().tetCount(); ++t)
            QVERIFY2(current->tissue.schemes()[t] != Scheme::None, qPrintable(QString::number(t)));

        // An added sweep is cut on a copy of current: still bit-identical to cutting directly.
        doc.addSweep(planeSweep(base->mesh(), 0.3, 1e-3));
        QVERIFY(session.waitForIdle(kWaitMs));
        QVERIFY2(session.error().isEmpty(), qPrintable(session.error()));
        direct = Tissue();
        QVERIFY(cutDirectly(doc.scenario(), direct).ok());
        current = session.current();
        QCOMPARE(current->cuts(), 4);
        QCOMPARE(tissueDifference(current->tissue, direct), QString());

        // Other settings re-apply every cut on a copy of base.
        doc.setD(0.3);
        QVERIFY(session.waitForIdle(kWaitMs));
        direct = Tissue();
        QVERIFY(cutDirectly(doc.scenario(), direct).ok());
        const auto at03 = session.current();
        QCOMPARE(at03->applied.options.d, 0.3);
        QCOMPARE(tissueDifference(at03->tissue, direct), QString());
        // (A different tissue, not only a different tet count: the counts can coincide.)
        QVERIFY(!tissueDifference(at03->tissue, current->tissue).isEmpty());

        // Undo: back to d = 0.2, the same tissue as before the settings changed.
        doc.undoStack()->undo();
        QVERIFY(session.waitForIdle(kWaitMs));
        QCOMPARE(session.current()->applied.options.d, 0.2);
        QCOMPARE(tissueDifference(session.current()->tissue, current->tissue), QString());

        // And through replay itself (`resect run`), with nothing simulated between the cuts:
        // the same mesh and surface, bit for bit.
        Scenario still = doc.scenario();
        still.effects.clear();
        still.simulation.duration = 0;
        ReplayPlan stillPlan;
        QVERIFY(planTissue(still, still.tissues.front(), stillPlan).ok());
        ReplayOutcome out;
        const Status replayed = replay(std::move(stillPlan), out);
        QVERIFY2(replayed.ok(), replayed.message().c_str());
        const TetMesh& studio = session.current()->mesh();
        const auto same = [](auto a, auto b) {
            return a.size() == b.size() && std::memcmp(a.data(), b.data(), a.size() * sizeof(a[0])) == 0;
        };
        QCOMPARE(out.mesh.tetCount(), studio.tetCount());
        QVERIFY(same(out.mesh.positions(), studio.positions()));
        QVERIFY(same(out.mesh.referencePositions(), studio.referencePositions()));
        QVERIFY(same(out.mesh.masses(), studio.masses()));
        QVERIFY(out.mesh.tets() == studio.tets());
        const TriangleSurface& surface = session.current()->tissue.surface().surface();
        QVERIFY(same(std::span<const Vec3>(out.surface.positions), std::span<const Vec3>(surface.positions)));
        QVERIFY(out.surface.triangles == surface.triangles);
    }

    void addUndoRedoACut() {
        ScenarioDocument doc;
        doc.setAutosaveDirectory(m_dir.path());
        TissueSession session(doc);
        QVERIFY(doc.newFromSample(QStringLiteral("polyp")));
        QVERIFY(session.waitForIdle(kWaitMs));
        const auto uncut = session.current();
        const int tets = uncut->mesh().tetCount();
        const double volume = uncut->quality.volume;

        doc.addSweep(planeSweep(session.base()->mesh(), 0.6, 1e-3));
        QVERIFY(session.waitForIdle(kWaitMs));
        const auto cut = session.current();
        // A new sample's base is anchored: the head the plane cuts off is a resected chip.
        QVERIFY(allTets(cut->tissue) > tets);
        QCOMPARE(cut->cuts(), 1);
        QCOMPARE(cut->pieces, 2);
        QCOMPARE(cut->tissue.chips().size(), std::size_t(1));
        const double total = cut->quality.volume + cut->tissue.resectedVolume();
        QVERIFY(std::abs(total - volume) < 1e-9 * volume);
        QVERIFY(cut->surfaceCapTriangles > 0);
        QVERIFY(checkValidity(cut->mesh()).empty());
        QCOMPARE(appendedCuts(uncut->applied, cut->applied), 1);

        doc.undoStack()->undo();
        QVERIFY(session.waitForIdle(kWaitMs));
        QCOMPARE(session.current()->cuts(), 0);
        QCOMPARE(session.current()->mesh().tetCount(), tets);
        QCOMPARE(appendedCuts(cut->applied, session.current()->applied), -1);
        doc.undoStack()->redo();
        QVERIFY(session.waitForIdle(kWaitMs));
        QCOMPARE(tissueDifference(session.current()->tissue, cut->tissue), QString());
    }

    // Issue 19: editing a fixed region re-anchors the loaded tissue (no re-meshing, no new
    // base announced, so the views keep their framing) and applies the cuts again: what a
    // cut resects follows the anchors, exactly as replay derives it.
    void fixedRegionEditsReanchorWithoutReloading() {
        ScenarioDocument doc;
        doc.setAutosaveDirectory(m_dir.path());
        TissueSession session(doc);
        QVERIFY(doc.newFromSample(QStringLiteral("polyp")));
        QVERIFY(session.waitForIdle(kWaitMs));
        const auto loaded = session.base();
        const std::vector<int> baseAnchors = loaded->tissue.anchors().nodes();
        QVERIFY(!baseAnchors.empty());
        doc.addSweep(planeSweep(loaded->mesh(), 0.6, 1e-3));
        QVERIFY(session.waitForIdle(kWaitMs));
        QCOMPARE(session.current()->tissue.chips().size(), std::size_t(1)); // the head

        // Move the box up to hold the head instead: the stalk is now what comes off.
        QSignalSpy base(&session, &TissueSession::baseChanged);
        QSignalSpy current(&session, &TissueSession::currentChanged);
        FixedRegion head = doc.fixedRegions().front();
        const FixedRegion original = head;
        head.min.z() = 17;
        head.max.z() = 30;
        QVERIFY(doc.setFixedRegion(0, head));
        QVERIFY(session.waitForIdle(kWaitMs));
        QVERIFY2(session.error().isEmpty(), qPrintable(session.error()));
        QCOMPARE(base.count(), 0);
        QCOMPARE(current.count(), 1);
        // The same mesh (not meshed again), other anchors under a new base id.
        QVERIFY(&session.base()->mesh() != &loaded->mesh());
        const auto same = [](std::span<const Vec3> a, std::span<const Vec3> b) {
            return std::equal(a.begin(), a.end(), b.begin(), b.end());
        };
        QVERIFY(same(session.base()->mesh().referencePositions(), loaded->mesh().referencePositions()));
        QVERIFY(session.base()->applied.baseId != loaded->applied.baseId);
        const std::vector<int> headAnchors = session.base()->tissue.anchors().nodes();
        QVERIFY(!headAnchors.empty() && headAnchors != baseAnchors);
        for (int n : headAnchors)
            QVERIFY(head.contains(loaded->mesh().ref(n)));
        QVERIFY(session.base()->tissue.anchors().box() == (std::array<Vec3, 2>{head.min, head.max}));
        Tissue direct;
        QVERIFY(cutDirectly(doc.scenario(), direct).ok());
        QCOMPARE(tissueDifference(session.current()->tissue, direct), QString());
        // The chip is the stalk now: it reaches down to the base.
        QCOMPARE(session.current()->tissue.chips().size(), std::size_t(1));
        double chipBottom = std::numeric_limits<double>::infinity();
        for (const Vec3& p : session.current()->tissue.chips().front().mesh.referencePositions())
            chipBottom = std::min(chipBottom, p.z());
        QVERIFY2(chipBottom < 1, qPrintable(QString::number(chipBottom)));

        // A region grown where there are no nodes holds the same nodes, but it is another box
        // (nodes a cut puts in the new part are anchored): the base is anchored again. (The
        // two edits of the region are one step to undo.)
        FixedRegion wider = head;
        wider.max.z() = 1e3;
        QVERIFY(doc.setFixedRegion(0, wider));
        QVERIFY(session.waitForIdle(kWaitMs));
        QCOMPARE(session.base()->tissue.anchors().nodes(), headAnchors);
        QVERIFY(session.base()->tissue.anchors().box() == (std::array<Vec3, 2>{wider.min, wider.max}));

        // Undo: back to the base's anchors, bit-identical to the state before.
        doc.undoStack()->undo();
        QVERIFY(session.waitForIdle(kWaitMs));
        QCOMPARE(session.base()->tissue.anchors().nodes(), baseAnchors);
        QVERIFY(session.base()->tissue.anchors().box() == (std::array<Vec3, 2>{original.min, original.max}));
        direct = Tissue();
        QVERIFY(cutDirectly(doc.scenario(), direct).ok());
        QCOMPARE(tissueDifference(session.current()->tissue, direct), QString());
        QCOMPARE(base.count(), 0);
    }

    void badTissuesAreReportedNotFatal() {
        ScenarioDocument doc;
        doc.setAutosaveDirectory(m_dir.path());
        TissueSession session(doc);
        QVERIFY(doc.newFromSample(QStringLiteral("polyp")));
        QVERIFY(session.waitForIdle(kWaitMs));
        QVERIFY(session.base());

        // A surface that is not a closed surface: loading fails with a message, no crash,
        // and nothing of the previous tissue stays.
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
        QCOMPARE(session.error(), failed.first().first().toString());
        QVERIFY(!session.base());
        QVERIFY(!session.current());
    }

    void aNewerDocumentSupersedesALoadingOne() {
        ScenarioDocument doc;
        doc.setAutosaveDirectory(m_dir.path());
        TissueSession session(doc);
        QSignalSpy base(&session, &TissueSession::baseChanged);
        QVERIFY(doc.newFromSample(QStringLiteral("polyp")));
        QVERIFY(doc.newFromSample(QStringLiteral("myoma")));
        QVERIFY(session.waitForIdle(kWaitMs));
        QCOMPARE(session.base()->tissueName, QStringLiteral("myoma"));
        QCOMPARE(session.current()->tissueName, QStringLiteral("myoma"));
        QCOMPARE(base.count(), 1); // the polyp was never published
        QVERIFY(session.error().isEmpty());
    }

    void aNewDocumentOnTheSameTissueReusesTheBase() {
        ScenarioDocument doc;
        doc.setAutosaveDirectory(m_dir.path());
        TissueSession session(doc);
        QVERIFY(doc.newFromSample(QStringLiteral("myoma")));
        QVERIFY(session.waitForIdle(kWaitMs));
        const auto first = session.base();
        QSignalSpy base(&session, &TissueSession::baseChanged);
        QVERIFY(doc.newFromSample(QStringLiteral("myoma")));
        QVERIFY(session.waitForIdle(kWaitMs));
        QCOMPARE(session.base(), first); // not meshed again
        QCOMPARE(base.count(), 1);       // but the views reframe
    }

    // The document never keeps a state that does not derive: each failing edit (a stroke
    // the tool cannot sweep, a sweep file that is not there, a setting out of range, an
    // effect the tissue cannot have) is undone and dropped, and editRefused says why.
    void failingEditsAreUndoneAndSayWhy() {
        ScenarioDocument doc;
        doc.setAutosaveDirectory(m_dir.path());
        TissueSession session(doc);
        QVERIFY(doc.newFromSample(QStringLiteral("polyp")));
        QVERIFY(session.waitForIdle(kWaitMs));
        doc.addSweep(planeSweep(session.base()->mesh(), 0.6, 1e-3));
        QVERIFY(session.waitForIdle(kWaitMs));
        QVERIFY(session.error().isEmpty());
        const auto cut = session.current();
        QCOMPARE(cut->cuts(), 1);
        const Scenario good = doc.scenario();

        SweepSpec missing;
        missing.name = "missing";
        missing.file = m_dir.filePath(QStringLiteral("no-such-sweep.json")).toStdString();
        struct Case {
            const char* name;
            std::function<void()> edit;
            const char* mentions;
        };
        const std::vector<Case> cases{
            {"still stroke", [&] { doc.addStroke(stillStroke()); }, "strokes[0]"},
            {"missing sweep file", [&] { doc.addSweep(missing); }, "no-such-sweep.json"},
            {"rings out of range", [&] { doc.setRings(CutLimits::kMaxRelaxRings + 1); }, "rings"},
            {"fixed region holding no node",
             [&] {
                 FixedRegion away;
                 away.min = Vec3(100, 100, 100);
                 away.max = Vec3(101, 101, 101);
                 doc.setFixedRegion(0, away);
             },
             "holds no node"},
            {"damping without a coefficient",
             [&] { doc.setEffectParameters(QStringLiteral("damping"), QJsonObject{{"coefficient", 0}}); },
             "coefficient"},
        };
        for (const Case& c : cases) {
            QSignalSpy refused(&session, &TissueSession::editRefused);
            QSignalSpy failed(&session, &TissueSession::failed);
            c.edit();
            QVERIFY2(!(doc.scenario() == good), c.name);
            QVERIFY2(session.waitForIdle(kWaitMs), c.name);
            QVERIFY2(refused.count() == 1, c.name);
            const QString reason = refused.first().first().toString();
            QVERIFY2(reason.contains(QLatin1String(c.mentions)), qPrintable(reason));
            QCOMPARE(failed.count(), 0);
            QVERIFY2(doc.scenario() == good, c.name);
            QCOMPARE(doc.undoStack()->count(), 1); // the sweep; the refused edit is gone
            QVERIFY(!doc.undoStack()->canRedo());
            QVERIFY2(session.error().isEmpty(), qPrintable(session.error()));
            QCOMPARE(session.current()->cuts(), 1);
            QCOMPARE(tissueDifference(session.current()->tissue, cut->tissue), QString());
            QVERIFY(session.saveBlocker().isEmpty());
        }
    }

    // A failing edit made while an earlier one is still being derived: both end up undone
    // back to the last state that derived.
    void editsMadeInARowAreUndoneToTheLastGoodState() {
        ScenarioDocument doc;
        doc.setAutosaveDirectory(m_dir.path());
        TissueSession session(doc);
        QVERIFY(doc.newFromSample(QStringLiteral("polyp")));
        QVERIFY(session.waitForIdle(kWaitMs));
        QSignalSpy refused(&session, &TissueSession::editRefused);
        doc.setD(0.3);
        doc.addStroke(stillStroke());
        doc.setSnap(false);
        QVERIFY(!session.saveBlocker().isEmpty()); // not derived yet
        QVERIFY(session.waitForIdle(kWaitMs));
        QCOMPARE(refused.count(), 1);
        QVERIFY(doc.scenario().strokes.empty());
        QCOMPARE(doc.scenario().cut.d, 0.2); // 0.3 alone was never derived
        QVERIFY(doc.scenario().cut.snap);
        QCOMPARE(doc.undoStack()->count(), 0);
        QVERIFY(session.error().isEmpty());
        QVERIFY(session.saveBlocker().isEmpty());

        // A state whose derivation was cancelled is not saved either, until it derives.
        doc.setD(0.3);
        session.cancel();
        QVERIFY(session.waitForIdle(kWaitMs));
        QVERIFY(!session.saveBlocker().isEmpty());
        doc.setD(0.25);
        QVERIFY(session.waitForIdle(kWaitMs));
        QVERIFY2(session.saveBlocker().isEmpty(), qPrintable(session.saveBlocker()));
    }

    // A trial derives a scenario that is not the document's; the document takes its states
    // when it is replaced by it, without deriving them again. A failed trial changes nothing.
    void trialsDeriveWithoutTouchingTheDocument() {
        ScenarioDocument doc;
        doc.setAutosaveDirectory(m_dir.path());
        TissueSession session(doc);
        QVERIFY(doc.newFromSample(QStringLiteral("polyp")));
        QVERIFY(session.waitForIdle(kWaitMs));
        const auto base = session.base();
        const auto current = session.current();
        const Scenario before = doc.scenario();

        Scenario other;
        QVERIFY(ScenarioDocument::sampleScenario(QStringLiteral("myoma"), other));
        other.sweeps.push_back(planeSweep(current->mesh(), 0.5, 1e-3)); // where the polyp is
        QSignalSpy finished(&session, &TissueSession::trialFinished);
        QSignalSpy changed(&session, &TissueSession::currentChanged);
        const std::uint64_t id = session.trial(other);
        QVERIFY(session.isBusy());
        QVERIFY(session.waitForIdle(kWaitMs));
        QCOMPARE(finished.count(), 1);
        QCOMPARE(finished.first().at(0).value<std::uint64_t>(), id);
        QVERIFY2(finished.first().at(1).toBool(), qPrintable(finished.first().at(2).toString()));
        QCOMPARE(changed.count(), 0);
        QVERIFY(doc.scenario() == before);
        QCOMPARE(session.base(), base);
        QCOMPARE(session.current(), current);

        doc.replace(other);
        QVERIFY(!session.isBusy()); // published, not derived again
        QCOMPARE(session.current()->tissueName, QStringLiteral("myoma"));
        QCOMPARE(session.current()->cuts(), 1);
        QVERIFY(session.saveBlocker().isEmpty());
        Tissue direct;
        QVERIFY(cutDirectly(other, direct).ok());
        QCOMPARE(tissueDifference(session.current()->tissue, direct), QString());

        // A trial whose tissue cannot be loaded: nothing changes.
        const QString path = m_dir.filePath(QStringLiteral("open-trial.obj"));
        QFile f(path);
        QVERIFY(f.open(QIODevice::WriteOnly));
        f.write("v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n");
        f.close();
        Scenario broken;
        QVERIFY(ScenarioDocument::anatomyScenario(path, broken));
        const auto shown = session.current();
        const Scenario now = doc.scenario();
        finished.clear();
        session.trial(broken);
        QVERIFY(session.waitForIdle(kWaitMs));
        QCOMPARE(finished.count(), 1);
        QVERIFY(!finished.first().at(1).toBool());
        QVERIFY(finished.first().at(2).toString().contains(QStringLiteral("open-trial")));
        QVERIFY(doc.scenario() == now);
        QCOMPARE(session.current(), shown);
        QVERIFY(session.error().isEmpty());
    }
};

QTEST_MAIN(TestTissueSession)
#include "test_tissue_session.moc"
