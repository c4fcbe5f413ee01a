// After a real HybridCutter cut, Simulator::applyCut updates only what changed, and the
// result equals a simulator built from scratch on the cut mesh: the same terms, the same
// forces at the same state, the same anchored and surface nodes, and the same motion after.
#include "sim_test_mesh.h"

#include "core/cut/hybrid_cutter.h"
#include "core/mesh/topology.h"
#include "core/sim/deformation_effect.h"
#include "core/sim/simulator.h"

#include <QTest>

#include <algorithm>
#include <cmath>

using namespace resect;
using resect::testing::countInvertedTets;
using resect::testing::quad;
using resect::testing::simBox;

namespace {

/// Sweeps of a scene: a complete, slightly tilted cut across the box, then a partial cut
/// ending inside it that crosses the first, then a cut through existing node planes.
std::vector<SweepSurface> sweeps() {
    return {quad(Vec3(-1, -1, 3.37), Vec3(7, -1, 3.61), Vec3(-1, 7, 3.52), Vec3(7, 7, 3.76)),
            quad(Vec3(2.63, -1, -1), Vec3(2.71, 3.4, -1), Vec3(2.58, -1, 7), Vec3(2.66, 3.4, 7)),
            quad(Vec3(-1, 4, -1), Vec3(7, 4, -1), Vec3(-1, 4, 7), Vec3(7, 4, 7))};
}

EffectSettings sceneSettings() {
    EffectSettings s;
    s.fixed.box = std::array<Vec3, 2>{Vec3(-1, -1, -1), Vec3(7, 7, 0.1)};
    s.tool = Tool{{Vec3(1, 1, 6.8), Vec3(5, 5, 6.8)}, 1.0};
    return s;
}

std::unique_ptr<Simulator> scene(TetMesh& m, int threads) {
    SimulatorOptions o;
    o.threads = threads;
    o.grain = 1; // threaded even on this small mesh: the thread windows must follow the cut
    auto sim = std::make_unique<Simulator>(m, Material{}, o);
    for (const char* name : {"deformation", "gravity", "fixed", "tool-contact"})
        if (Status st = sim->addEffect(name, sceneSettings()); !st.ok())
            qFatal("%s", st.message().c_str());
    return sim;
}

std::vector<int> sorted(std::vector<int> v) {
    std::sort(v.begin(), v.end());
    return v;
}

} // namespace

class TestSimApplyCut : public QObject {
    Q_OBJECT
private slots:
    void incrementalEqualsRebuild_data() {
        QTest::addColumn<bool>("snapAndRelax");
        QTest::addColumn<int>("threads");
        QTest::newRow("plain cut, 1 thread") << false << 1;
        QTest::newRow("plain cut, 2 threads") << false << 2;
        QTest::newRow("snap and relax, 1 thread") << true << 1;
    }
    void incrementalEqualsRebuild() {
        QFETCH(bool, snapAndRelax);
        QFETCH(int, threads);
        TetMesh m = simBox(6, 6, 6, 0.2, 12);
        auto sim = scene(m, threads);
        HybridCutter cutter(m);
        CutOptions options;
        options.snap = snapAndRelax;
        options.relaxSteps = snapAndRelax ? 10 : 0;
        int cuts = 0;
        for (const SweepSurface& sweep : sweeps()) {
            for (int s = 0; s < 10; ++s)
                QVERIFY(sim->step().ok());
            // The model on its own, to see how much an update touches.
            DeformationModel alone(m, Material{}, DeformationTerms{});
            cutter.refreshSpatialIndex();
            CutResult result;
            const Status st = cutter.cut(sweep, options, result);
            QVERIFY2(st.ok(), st.message().c_str());
            QVERIFY(result.stats.addedTets > 0 || result.stats.separatedTets > 0);
            ++cuts;
            sim->applyCut(result.changes);
            const DeformationChanges changed = alone.applyCut(m, result.changes);
            // Proportional to the change: a few slots per touched node (a Kuhn mesh's nodes
            // have 14 edges), whatever the mesh size.
            const auto touched = static_cast<int>(result.changes.touchedNodes.size());
            QVERIFY2(static_cast<int>(changed.edgeSlots.size()) <= 8 * touched &&
                         static_cast<int>(changed.triangleSlots.size()) <= 12 * touched &&
                         static_cast<int>(changed.tets.size()) <= 24 * touched,
                     qPrintable(QString("%1 edge slots for %2 touched nodes")
                                    .arg(changed.edgeSlots.size())
                                    .arg(touched)));

            TetMesh copy = m;
            auto fresh = scene(copy, threads);
            // Same terms.
            const auto* inc = static_cast<DeformationEffect*>(sim->findEffect("deformation"));
            const auto* full = static_cast<DeformationEffect*>(fresh->findEffect("deformation"));
            QCOMPARE(inc->model().liveEdges(), full->model().liveEdges());
            QCOMPARE(inc->model().liveTriangles(), full->model().liveTriangles());
            QCOMPARE(alone.liveEdges(), full->model().liveEdges());
            QCOMPARE(inc->model().tetRestVolume6().size(), std::size_t(m.tetCount()));
            for (int t = 0; t < m.tetCount(); ++t) {
                QCOMPARE(inc->model().tetRestVolume6()[t], full->model().tetRestVolume6()[t]);
                QCOMPARE(inc->model().tetStiffness36()[t], full->model().tetStiffness36()[t]);
            }
            // Same forces at the same state (summation order differs: rounding only).
            std::vector<Vec3> fi(m.nodeCount()), ff(m.nodeCount());
            const double ei = sim->computeForces(fi);
            const double ef = fresh->computeForces(ff);
            double scale = 0, worst = 0;
            for (int i = 0; i < m.nodeCount(); ++i) {
                scale = std::max(scale, ff[i].norm());
                worst = std::max(worst, (fi[i] - ff[i]).norm());
            }
            QVERIFY2(
                worst <= 1e-12 * scale,
                qPrintable(
                    QString("cut %1: force difference %2 of %3").arg(cuts).arg(worst).arg(scale)));
            QVERIFY(std::abs(ei - ef) <= 1e-12 * std::abs(ef) + 1e-12);
            // Same anchors and surface nodes.
            QCOMPARE(static_cast<FixedNodesEffect*>(sim->findEffect("fixed"))->nodes(),
                     static_cast<FixedNodesEffect*>(fresh->findEffect("fixed"))->nodes());
            QCOMPARE(sorted(static_cast<ToolContactEffect*>(sim->findEffect("tool-contact"))
                                ->surfaceNodes()),
                     sorted(static_cast<ToolContactEffect*>(fresh->findEffect("tool-contact"))
                                ->surfaceNodes()));
            // Same motion afterwards.
            for (int s = 0; s < 10; ++s) {
                QVERIFY(sim->step().ok());
                QVERIFY(fresh->step().ok());
            }
            double motion = 0, gap = 0;
            for (int i = 0; i < m.nodeCount(); ++i) {
                motion = std::max(motion, (m.pos(i) - m.ref(i)).norm());
                gap = std::max(gap, (m.pos(i) - copy.pos(i)).norm());
            }
            QVERIFY(motion > 0);
            QVERIFY2(gap <= 1e-9 * motion, qPrintable(QString("%1 vs %2").arg(gap).arg(motion)));
        }
        QCOMPARE(cuts, 3);
        QVERIFY(connectedComponents(m).count >= 2);
        QCOMPARE(countInvertedTets(m), 0);
    }

    void piecesFallApartAfterACompleteCut() {
        // Cut the top off a box anchored at its bottom: the top falls, the bottom stays.
        TetMesh m = simBox(4, 4, 4, 0.2, 13);
        SimulatorOptions o;
        auto sim = std::make_unique<Simulator>(m, Material{}, o);
        EffectSettings s;
        s.fixed.box = std::array<Vec3, 2>{Vec3(-1, -1, -1), Vec3(5, 5, 0)};
        for (const char* name : {"deformation", "gravity", "fixed"})
            QVERIFY(sim->addEffect(name, s).ok());
        HybridCutter cutter(m);
        CutResult result;
        QVERIFY(cutter
                    .cut(quad(Vec3(-1, -1, 2.43), Vec3(5, -1, 2.51), Vec3(-1, 5, 2.47),
                              Vec3(5, 5, 2.55)),
                         CutOptions{}, result)
                    .ok());
        sim->applyCut(result.changes);
        QCOMPARE(connectedComponents(m).count, 2);
        const double dt = sim->stableTimeStep();
        while (sim->time() < 0.02)
            QVERIFY(sim->step(dt).ok());
        double top = 1e9, bottom = -1e9;
        for (int i = 0; i < m.nodeCount(); ++i) {
            if (m.ref(i).z() > 3.5)
                top = std::min(top, m.ref(i).z() - m.pos(i).z());
            if (m.ref(i).z() < 1)
                bottom = std::max(bottom, m.ref(i).z() - m.pos(i).z());
        }
        // Free fall for 20 ms: 1/2 g t^2 = 1.96 mm; the anchored part sags by far less.
        QVERIFY2(top > 1.8, qPrintable(QString::number(top)));
        QVERIFY2(bottom < 0.1, qPrintable(QString::number(bottom)));
        QCOMPARE(countInvertedTets(m), 0);
    }
};

QTEST_GUILESS_MAIN(TestSimApplyCut)
#include "test_sim_apply_cut.moc"
