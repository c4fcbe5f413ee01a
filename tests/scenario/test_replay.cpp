// Replay of strokes, cuts and simulation (scenario/replay.h) on a box: a stroke through the
// middle cuts off the upper part, which falls while the anchored lower part stays; the outcome
// counts pieces and the resected volume; two runs give the same state; progress can cancel;
// plans needing too many steps are refused.
#include "scenario/replay.h"
#include "scenario/scenario_run.h"

#include "scenario/scenario_document.h"

#include "core/mesh/box_mesh.h"
#include "core/mesh/masses.h"

#include "core/cut/improve_mesh.h"

#include <QJsonArray>
#include <QJsonObject>
#include <QTest>

using namespace resect;

namespace {

/// The box [0, 4]^3 mm (4 cells a side), anchored at the bottom, cut at z = height by a
/// stroke of a straight 2-point tool moved along x (poses every 10 ms over 50 ms).
ReplayPlan boxPlan(bool withTool, double height = 2.3) {
    ReplayPlan plan;
    plan.mesh = makeBoxTetMesh(Vec3::Zero(), Vec3::Constant(4), 4, 4, 4);
    computeLumpedMasses(plan.mesh, plan.material.density);
    ReplayStroke stroke;
    stroke.name = "strokes[0]";
    for (int i = 0; i <= 5; ++i) {
        const double x = -1 + 6.0 * i / 5;
        stroke.times.push_back(0.01 * i);
        stroke.tool.push_back({Vec3(x, -1, height + 0.01 * x), Vec3(x, 5, height + 0.01 * x)});
    }
    if (!SweepSurface::fromCurves(stroke.tool, stroke.sweep).ok())
        qFatal("bad sweep");
    plan.strokes.push_back(stroke);
    plan.effects = {"deformation", "gravity", "fixed"};
    if (withTool) {
        // The tool pushes surface nodes by projection, which can crush the small elements next
        // to the cut within one step: explicit steps then diverge (the simulator says so),
        // the implicit integrator copes.
        plan.effects.push_back("tool-contact");
        plan.effectSettings.tool.radius = 0.2;
        plan.simulation.integrator = Integrator::BackwardEuler;
        plan.simulation.dt = 2e-4;  // s, about ten times the stable explicit step
    }
    plan.anchors.box = std::array<Vec3, 2>{Vec3::Constant(-1), Vec3(5, 5, 0.001)};
    plan.duration = 0.02;
    return plan;
}

} // namespace

class TestReplay : public QObject {
    Q_OBJECT
private slots:
    void strokesCutAndTheFreedPartFalls() {
        // The freed part stays in the tissue, deformable (resected pieces kept).
        ReplayPlan plan = boxPlan(true);
        plan.resected = ResectedPieces::Keep;
        ReplayOutcome out;
        const Status s = replay(std::move(plan), out);
        QVERIFY2(s.ok(), s.message().c_str());
        QVERIFY2(out.failure.empty(), out.failure.c_str());
        QVERIFY(out.finite);
        QCOMPARE(out.pieces, 2);
        QCOMPARE(out.inverted, 0);
        QVERIFY(out.mesh.tetCount() > out.tetsBefore);
        // The upper part (z > 2.3 + 0.01 x, on average 2.32) is resected: (4 - 2.32) / 4.
        QVERIFY2(std::abs(out.resectedVolumeFraction - (4 - 2.32) / 4) < 0.01,
                 qPrintable(QString::number(out.resectedVolumeFraction)));
        QVERIFY(out.steps > 0);
        QVERIFY(out.dt > 0 && out.stableDt > 0);
        // Effect times are reported for exactly the effects asked for.
        QStringList names;
        for (const EffectTime& e : out.effectTimes)
            names << QString::fromStdString(e.name);
        names.sort();
        QCOMPARE(names, (QStringList{"deformation", "fixed", "gravity", "tool-contact"}));
        // The freed part fell: its nodes are lower than where they were cut.
        double lowest = 1e9;
        for (int n = 0; n < out.mesh.nodeCount(); ++n)
            if (out.mesh.ref(n).z() > 3.9)
                lowest = std::min(lowest, out.mesh.pos(n).z() - out.mesh.ref(n).z());
        QVERIFY(lowest < -0.5);  // g t^2 / 2 over 70 ms is 24 mm
    }

    void theFreedPartLeavesAsARigidChip() {
        // By default a piece off the anchors is resected as a rigid chip: it leaves the tet
        // mesh, the counts and the mass say so, and the tissue simulates on without it.
        ReplayOutcome out;
        const Status s = replay(boxPlan(true), out);
        QVERIFY2(s.ok(), s.message().c_str());
        QVERIFY2(out.failure.empty(), out.failure.c_str());
        QCOMPARE(out.resectedPieces, 1);
        QCOMPARE(out.pieces, 2);  // the tissue and the chip
        QVERIFY(out.resectedMass > 0);
        QVERIFY2(std::abs(out.resectedVolumeFraction - (4 - 2.32) / 4) < 0.01,
                 qPrintable(QString::number(out.resectedVolumeFraction)));
        double top = -1e9;
        for (int n = 0; n < out.mesh.nodeCount(); ++n)
            top = std::max(top, out.mesh.ref(n).z());
        // Nothing above the cut is left in the tissue (z = 2.3 + 0.01 x <= 2.34), but for the
        // mesh improvement's bounded deviation off a curved or creased boundary (maxDeviation
        // times the local boundary edge, at most the face diagonal sqrt 2 here).
        const double slack = ImproveOptions{}.maxDeviation * std::sqrt(2.0);
        QVERIFY2(top <= 2.34 + slack, qPrintable(QString::number(top)));
        QCOMPARE(out.inverted, 0);
    }

    void oneFixedRegionIsTheAnchorsBox() {
        // A scenario's one fixed region anchors like `resect cut --fix-box`: the nodes in it,
        // and it is the anchors' box. Several regions give their nodes and no box.
        const TetMesh mesh = makeBoxTetMesh(Vec3::Zero(), Vec3::Constant(4), 4, 4, 4);
        TissueSpec spec;
        spec.fixedRegions = {FixedRegion{Vec3::Constant(-1), Vec3(5, 5, 1.1), {}}};
        const FixedSelection one = regionAnchors(spec, mesh);
        QCOMPARE(one.nodes.size(), std::size_t(50));  // the layers z = 0 and z = 1, 5 x 5 each
        QVERIFY(one.box);
        QCOMPARE((*one.box)[0], Vec3::Constant(-1));
        QCOMPARE((*one.box)[1], Vec3(5, 5, 1.1));
        spec.fixedRegions.push_back(FixedRegion{Vec3(-1, -1, 3.9), Vec3(5, 5, 5), {}});
        const FixedSelection two = regionAnchors(spec, mesh);
        QCOMPARE(two.nodes.size(), std::size_t(75));
        QVERIFY(!two.box);
    }

    void aCutThroughTheFixedRegionAddsAnchoredNodes() {
        // A stroke through the fixed region (z = 0.55, between the node layers z = 0 and 1 that
        // it holds) splits the edges it crosses there. The new nodes lie in the region, so the
        // fixed effect holds them, as it holds the old ones: under gravity, every node in the
        // region stays where it is. With the region's nodes only (no box, as scenarios anchored
        // before), the new nodes were free and sagged.
        ReplayPlan plan = boxPlan(false, 0.55);
        TissueSpec spec;
        spec.fixedRegions = {FixedRegion{Vec3::Constant(-1), Vec3(5, 5, 1.1), {}}};
        plan.anchors = regionAnchors(spec, plan.mesh);
        const int inRegionBefore = static_cast<int>(plan.anchors.nodes.size());
        plan.resected = ResectedPieces::Keep;
        ReplayOutcome out;
        const Status s = replay(std::move(plan), out);
        QVERIFY2(s.ok(), s.message().c_str());
        QVERIFY2(out.cutFailure.empty(), out.cutFailure.c_str());
        QVERIFY(out.finite);
        QVERIFY(out.steps > 0);
        int inRegion = 0;
        double moved = 0, movedAbove = 0;
        for (int n = 0; n < out.mesh.nodeCount(); ++n) {
            const double d = (out.mesh.pos(n) - out.mesh.ref(n)).norm();
            if (spec.fixedRegions.front().contains(out.mesh.ref(n))) {
                ++inRegion;
                moved = std::max(moved, d);
            } else {
                movedAbove = std::max(movedAbove, d);
            }
        }
        QVERIFY2(inRegion > inRegionBefore, qPrintable(QString("%1 nodes in the region, %2 before").arg(inRegion).arg(inRegionBefore)));
        QCOMPARE(moved, 0.0);
        QVERIFY2(movedAbove > 1e-6, qPrintable(QString::number(movedAbove)));  // (gravity acts on the rest)
    }

    void sameResultTwice() {
        ReplayOutcome a, b;
        QVERIFY(replay(boxPlan(false), a).ok());
        QVERIFY(replay(boxPlan(false), b).ok());
        QCOMPARE(a.mesh.nodeCount(), b.mesh.nodeCount());
        QCOMPARE(a.mesh.tets(), b.mesh.tets());
        for (int n = 0; n < a.mesh.nodeCount(); ++n)
            QCOMPARE(a.mesh.pos(n), b.mesh.pos(n));
        QCOMPARE(a.steps, b.steps);
        QCOMPARE(a.resectedVolumeFraction, b.resectedVolumeFraction);
    }

    void progressCanCancel() {
        ReplayOutcome out;
        double last = -1;
        int calls = 0;
        bool monotone = true;
        const Status s = replay(boxPlan(false), out, [&](double p) -> bool {
            monotone = monotone && p >= last;
            last = p;
            return ++calls < 3;
        });
        QVERIFY(monotone);
        QVERIFY(!s.ok());
        QVERIFY2(s.message().find("cancelled") != std::string::npos, s.message().c_str());
    }

    void aFailedCutIsReportedAndTheReplayStops() {
        // A cut that fails (here refused: d far out of range) ends the replay at that stroke,
        // with the tissue as it was: the outcome is kept and says which stroke and why, so
        // that `resect run` still writes its report (and exits 1), and the run has not passed.
        ReplayPlan plan = boxPlan(false);
        plan.strokes.push_back(plan.strokes.front());
        plan.strokes.back().name = "strokes[1]";
        plan.cut.d = 1e9;
        const int tets = plan.mesh.tetCount();
        TissueRun t;
        t.name = "box";
        const Status s = replay(std::move(plan), t.outcome);
        QVERIFY2(s.ok(), s.message().c_str());
        const ReplayOutcome& out = t.outcome;
        QVERIFY2(out.cutFailure.rfind("strokes[0]: ", 0) == 0, out.cutFailure.c_str());
        QVERIFY2(out.cutFailure.find("d (a fraction of the mean edge length)") != std::string::npos, out.cutFailure.c_str());
        QCOMPARE(out.mesh.tetCount(), tets);
        QCOMPARE(out.steps, 0LL);  // (no simulation after the failed cut, nor the plan's duration)
        QCOMPARE(out.pieces, 1);
        QVERIFY(out.failure.empty());
        ScenarioRun run;
        run.tissues.push_back(std::move(t));
        QVERIFY(!run.cutsSucceeded());
        QVERIFY(!run.allPassed());
        const QJsonObject json = scenarioRunJson(run);
        QCOMPARE(json["passed"].toBool(), false);
        QVERIFY(json["tissues"].toArray()[0].toObject()["cut_failure"].toString().startsWith("strokes[0]: "));
        // And a replay whose cuts all succeed has none.
        ReplayOutcome ok;
        QVERIFY(replay(boxPlan(false), ok).ok());
        QVERIFY(ok.cutFailure.empty());
    }

    void tooManyStepsAreRefused() {
        ReplayPlan plan = boxPlan(false);
        plan.duration = 1000;  // s: millions of steps at the stable step
        ReplayOutcome out;
        const Status s = replay(std::move(plan), out);
        QVERIFY(!s.ok());
        QVERIFY2(s.message().find("simulation steps") != std::string::npos, s.message().c_str());
    }
};

QTEST_GUILESS_MAIN(TestReplay)
#include "test_replay.moc"
