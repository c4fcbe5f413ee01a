// Node snapping (section 4.5). Step 6 alone on literal tets: a cut node is projected onto
// the sweep and its reference position follows from barycentric coordinates (also when the
// configurations differ), its copies move with it, and a snap is refused and counted when
// the node is on the surface, when a tet would go flat, or when a tet would drop below the
// quality floor. Through the cutter: snapped cut nodes lie on the sweep, a planar complete
// cut then leaves no edge crossing the sweep, and spoiling snaps are refused and counted.
#include "cut_checks.h"
#include "step_fixtures.h"

#include "core/cut/snap_nodes.h"
#include "core/mesh/predicates.h"

#include "core/mesh/box_mesh.h"

#include <QTest>

#include <cstring>
#include <random>
#include <unordered_set>

using namespace resect;
using resect::testing::cutViolations;
using resect::testing::jitteredBox;
using resect::testing::planeZ0;

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

/// Literal meshes for snapping node 0 onto the plane z = 0 (the sweep below):
///  0: one tet, node 0 at height 1/16 under the face (1, 2, 3) at z = 1;
///  1: the same above the plane and its mirror image below, attached to node 4, a copy of
///     node 0 (as separation leaves them);
///  2: node 0 above the face (1, 2, 3) lying in z = 0: the snap would flatten the tet;
///  3: node 0 at height 0.05 over a face at z = -0.3: the snap lowers the radius ratio from
///     0.516 to 0.434 (above the default floor 0.05).
TetMesh snapMesh(int id) {
    switch (id) {
    case 0: return TetMesh::fromArrays({Vec3(0.25, 0.25, 0.0625), Vec3(1, 0, 1), Vec3(0, 1, 1), Vec3(0, 0, 1)}, {{0, 1, 2, 3}});
    case 1:
        return TetMesh::fromArrays({Vec3(0.25, 0.25, 0.0625), Vec3(1, 0, 1), Vec3(0, 1, 1), Vec3(0, 0, 1),
                                    Vec3(0.25, 0.25, 0.0625), Vec3(1, 0, -1), Vec3(0, 1, -1), Vec3(0, 0, -1)},
                                   {{0, 1, 2, 3}, {4, 6, 5, 7}});
    case 2: return TetMesh::fromArrays({Vec3(0.25, 0.25, 0.0625), Vec3(1, 0, 0), Vec3(0, 1, 0), Vec3(0, 0, 0)}, {{0, 2, 1, 3}});
    default:
        return TetMesh::fromArrays({Vec3(0.25, 0.25, 0.05), Vec3(1, 0, -0.3), Vec3(0, 1, -0.3), Vec3(0, 0, -0.3)},
                                   {{0, 2, 1, 3}});
    }
}

} // namespace

class TestSnapNodes : public QObject {
    Q_OBJECT
private slots:
    void snapOneCutNode_data() {
        QTest::addColumn<int>("mesh");
        QTest::addColumn<bool>("onSurface");
        QTest::addColumn<double>("qualityFloor");
        QTest::addColumn<bool>("snapped");
        QTest::newRow("projected onto the sweep") << 0 << false << 0.05 << true;
        QTest::newRow("copies move together") << 1 << false << 0.05 << true;
        QTest::newRow("on the surface: stays") << 0 << true << 0.05 << false;
        QTest::newRow("would flatten a tet: refused") << 2 << false << 0.05 << false;
        QTest::newRow("worse but above the floor: snapped") << 3 << false << 0.05 << true;
        QTest::newRow("worse and the floor forbids it: refused") << 3 << false << 1.0 << false;
    }
    void snapOneCutNode() {
        QFETCH(int, mesh);
        QFETCH(bool, onSurface);
        QFETCH(double, qualityFloor);
        QFETCH(bool, snapped);
        TetMesh m = snapMesh(mesh);
        for (int t = 0; t < m.tetCount(); ++t)
            QVERIFY(m.referenceVolume(t) > 0);
        const SweepSurface sweep = planeZ0(-5, 5, -5, 5);
        CutChanges changes;
        changes.cutNodes = {0};
        if (mesh == 1)
            changes.duplicatedNodes = {{0, 4}};
        const std::vector<Vec3> refBefore(m.referencePositions().begin(), m.referencePositions().end());
        const double height = m.pos(0).z();
        SnapOptions options;
        options.qualityFloor = qualityFloor;
        const SnapResult r = snapNodes(m, sweep, changes, onSurface ? std::vector<int>{0} : std::vector<int>{}, options);
        QCOMPARE(r.snapped, snapped ? 1 : 0);
        QCOMPARE(r.refused, snapped ? 0 : 1);
        // Refused snaps leave the node where it was, at its distance from the sweep.
        QCOMPARE(r.maxDistanceAfter, snapped ? 0.0 : height);
        const Vec3 expected = snapped ? Vec3(0.25, 0.25, 0) : refBefore[0];
        QVERIFY((m.pos(0) - expected).norm() <= 1e-15);
        QVERIFY((m.ref(0) - expected).norm() <= 1e-15);  // current = reference here
        for (int v = 1; v < m.nodeCount(); ++v)
            if (!(mesh == 1 && v == 4))
                QCOMPARE(m.ref(v), refBefore[v]);
        if (mesh == 1) {
            QCOMPARE(m.pos(4), m.pos(0));
            QCOMPARE(m.ref(4), m.ref(0));
        }
        for (int t = 0; t < m.tetCount(); ++t) {
            const Tet& q = m.tet(t);
            QVERIFY(orient3d(m.ref(q[0]), m.ref(q[1]), m.ref(q[2]), m.ref(q[3])) > 0);
        }
    }

    void referencePositionFromTheDeformedConfiguration() {
        // Current positions are twice the reference ones, shifted by (3, 0, 0): node 0 is
        // snapped onto z = 0 in the current configuration, at (3.5, 0.5, 0); its barycentric
        // coordinates there give the reference position (0.25, 0.25, 0).
        TetMesh m = snapMesh(0);
        for (int v = 0; v < 4; ++v)
            m.positions()[v] = 2 * m.ref(v) + Vec3(3, 0, 0);
        CutChanges changes;
        changes.cutNodes = {0};
        const SnapResult r = snapNodes(m, planeZ0(-5, 10, -5, 5), changes, {}, SnapOptions{});
        QCOMPARE(r.snapped, 1);
        QVERIFY((m.pos(0) - Vec3(3.5, 0.5, 0)).norm() <= 1e-15);
        QVERIFY((m.ref(0) - Vec3(0.25, 0.25, 0)).norm() <= 1e-15);
    }

    void tetCoordinates() {
        // In the unit tet the coordinates (l1, l2, l3) are the point's own; a flat tet gives
        // non-finite coordinates.
        const Vec3 o(0, 0, 0), x(1, 0, 0), y(0, 1, 0), z(0, 0, 1);
        QCOMPARE(resect::tetCoordinates(Vec3(0.25, 0.5, 0.125), o, x, y, z), Vec3(0.25, 0.5, 0.125));
        QCOMPARE(resect::tetCoordinates(Vec3(2, 4, 6), Vec3(1, 1, 1), Vec3(3, 1, 1), Vec3(1, 3, 1), Vec3(1, 1, 3)),
                 Vec3(0.5, 1.5, 2.5));
        QVERIFY(!resect::tetCoordinates(Vec3(0.1, 0.1, 0), o, x, y, Vec3(1, 1, 0)).allFinite());
    }

    /// referenceFromDeformedIn (given the incident tets; two tets at a time) must give
    /// referenceFromDeformed's position bit for bit, ties between tets included, on a deformed
    /// jittered box, for targets near every node and far outside the mesh.
    void referenceFromIncidentTetsIsBitIdentical() {
        TetMesh m = jitteredBox(1.0, 5, 0.1, 4);
        std::mt19937 rng(11);
        std::uniform_real_distribution<double> u(-1, 1);
        for (int n = 0; n < m.nodeCount(); ++n)
            m.positions()[n] = m.ref(n) + 0.05 * Vec3(u(rng), u(rng), u(rng)) + Vec3(0.3 * m.ref(n).z(), 0, 0);
        int compared = 0;
        for (int n = 0; n < m.nodeCount(); ++n)
            for (const double reach : {0.01, 0.2, 5.0}) {
                const Vec3 target = m.pos(n) + reach * Vec3(u(rng), u(rng), u(rng));
                const Vec3 expected = referenceFromDeformed(m, {n}, target);
                const Vec3 got = referenceFromDeformedIn(m, m.nodeTets(n), target);
                QVERIFY2(std::memcmp(&expected, &got, sizeof got) == 0, qPrintable(QString::number(n)));
                ++compared;
            }
        // A vertex of the box mesh has one to 24 tets: odd and even counts both occur.
        QVERIFY(compared > 300);
    }

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
