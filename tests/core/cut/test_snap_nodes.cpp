// Node snapping (section 4.5): snapped cut nodes lie on the sweep, their copies stay
// together, a planar complete cut then leaves no edge crossing the sweep, and snaps that
// would spoil a tet are refused and counted.
#include "cut_checks.h"

#include "core/mesh/box_mesh.h"

#include <QTest>

#include <random>
#include <unordered_set>

using namespace resect;
using resect::testing::cutViolations;
using resect::testing::jitteredBox;

namespace {


SweepSurface plane(const Vec3& c, const Vec3& normal, double R) {
    const Vec3 n = normal.normalized(), u = n.unitOrthogonal(), w = n.cross(u);
    SweepSurface s;
    const Status st = SweepSurface::fromStartEnd({c - R * w - R * u, c - R * w + R * u},
                                                 {c + R * w - R * u, c + R * w + R * u}, s);
    if (!st.ok())
        qFatal("%s", st.message().c_str());
    return s;
}

} // namespace

class TestSnapNodes : public QObject {
    Q_OBJECT
private slots:
    void planarCutLeavesNoCrossingEdge_data() {
        QTest::addColumn<double>("scale");
        QTest::addColumn<unsigned>("seed");
        for (double scale : {1e-3, 1.0, 1e3})
            for (unsigned seed : {1u, 2u, 3u, 4u, 5u})
                QTest::addRow("scale %g, seed %u", scale, seed) << scale << seed;
    }
    void planarCutLeavesNoCrossingEdge() {
        QFETCH(double, scale);
        QFETCH(unsigned, seed);
        TetMesh mesh = jitteredBox(scale, seed, 0.03);
        std::mt19937 rng(seed);
        std::uniform_real_distribution<double> sym(-1, 1);
        const SweepSurface sweep = plane(Vec3(0.5, 0.5, 0.5) * scale + 0.1 * scale * Vec3(sym(rng), sym(rng), sym(rng)),
                                         Vec3(sym(rng), sym(rng), sym(rng)), 2 * scale);
        const double volume = mesh.totalReferenceVolume();
        HybridCutter cutter(mesh);
        CutOptions options;
        options.snap = true;
        options.d = 0.3;
        CutResult r;
        QVERIFY(cutter.cut(sweep, options, r).ok());
        const QString v = cutViolations(mesh, sweep, volume, r);
        QVERIFY2(v.isEmpty(), qPrintable(v));
        QVERIFY(r.stats.cutNodes > 0);
        QCOMPARE(r.stats.snappedNodes + r.stats.refusedSnaps, r.stats.cutNodes);
        QVERIFY(r.stats.snappedNodes > 0);
        // Snapped nodes (and their copies) are on the sweep, to rounding.
        int onSweep = 0;
        for (int n : r.changes.cutNodes) {
            const double dist = sweep.closestPoint(mesh.pos(n)).distance;
            if (dist <= 1e-12 * scale)
                ++onSweep;
        }
        QCOMPARE(onSweep, r.stats.snappedNodes);
        for (const auto& [orig, copy] : r.changes.duplicatedNodes) {
            QCOMPARE(mesh.pos(orig), mesh.pos(copy));
            QCOMPARE(mesh.ref(orig), mesh.ref(copy));
        }
        // No edge crosses the sweep, except at cut nodes that were not snapped (those on the
        // outer surface keep their place): the snapped cut nodes bring the cut onto the sweep.
        std::unordered_set<int> unsnapped;
        for (int n : r.changes.cutNodes)
            if (sweep.closestPoint(mesh.pos(n)).distance > 1e-12 * scale)
                unsnapped.insert(n);
        for (const auto& [orig, copy] : r.changes.duplicatedNodes)
            if (unsnapped.count(orig))
                unsnapped.insert(copy);
        QCOMPARE(int(unsnapped.size()) > 0, r.stats.refusedSnaps > 0);
        SegmentQuery q;
        std::vector<int> scratch;
        int checked = 0;
        const auto onSweepNow = [&](int n) { return sweep.closestPoint(mesh.pos(n)).distance <= 1e-12 * scale; };
        for (const auto& e : uniqueEdges(mesh)) {
            if (unsnapped.count(e[0]) || unsnapped.count(e[1]))
                continue;
            if (onSweepNow(e[0]) && onSweepNow(e[1]))
                continue;  // an edge lying in the sweep (between two snapped nodes)
            ++checked;
            intersectSegment(sweep, mesh.pos(e[0]), mesh.pos(e[1]), q, scratch);
            // A snapped node lies on the sweep to rounding: a crossing within 1e-9 of the edge
            // length from it is the edge touching the sweep there, not crossing it.
            int crossings = 0;
            for (const SegmentHit& h : q.hits)
                if (h.t > 1e-9 && h.t < 1 - 1e-9)
                    ++crossings;
            QVERIFY2(crossings % 2 == 0, qPrintable(QString("edge %1-%2").arg(e[0]).arg(e[1])));
        }
        QVERIFY(checked > mesh.tetCount());
    }

    void spoilingSnapsAreRefusedAndCounted() {
        TetMesh mesh = jitteredBox(1.0, 9, 0.03);
        const SweepSurface sweep = plane(Vec3(0.5, 0.5, 0.52), Vec3(0.1, 0.2, 1), 2);
        HybridCutter cutter(mesh);
        CutOptions options;
        options.snap = true;
        options.d = 0.3;
        options.snapQualityFloor = 1.0;  // no tet may get any worse: nearly every snap refused
        CutResult r;
        QVERIFY(cutter.cut(sweep, options, r).ok());
        QVERIFY(r.stats.refusedSnaps > 0);
        QCOMPARE(r.stats.snappedNodes + r.stats.refusedSnaps, r.stats.cutNodes);
        QVERIFY(r.stats.maxCutNodeDistance > 0);
        QVERIFY(checkValidity(mesh).empty());
    }
};

QTEST_GUILESS_MAIN(TestSnapNodes)
#include "test_snap_nodes.moc"
