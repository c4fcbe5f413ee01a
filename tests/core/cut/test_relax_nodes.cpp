// Relaxation (section 4.6). Step 7 alone on a literal octahedron around a displaced centre
// node: a node on the cut moves within the sweep, an interior node freely, copies together,
// fixed and boundary nodes not at all, a node in equilibrium stays; the volume is kept and
// the smallest radius ratio never drops. Through the cutter: the same on random cuts, and
// masses follow Eq. 3 after any sequence of cuts (the rest state alone is tested in
// test_update_rest_state).
#include "cut_checks.h"
#include "step_fixtures.h"

#include "core/cut/relax_nodes.h"
#include "core/mesh/predicates.h"

#include "core/mesh/box_mesh.h"
#include "core/mesh/masses.h"
#include "core/mesh/quality.h"
#include "core/mesher/samples.h"
#include "core/mesher/tetrahedralize.h"

#include <QTest>

#include <random>

using namespace resect;
using resect::testing::cutViolations;
using resect::testing::planeZ0;

namespace {

TetMesh jitteredBoxWithMasses(double scale, unsigned seed) {
    TetMesh m = resect::testing::jitteredBox(scale, seed, 0.04);
    computeLumpedMasses(m, Material{}.density);
    return m;
}

SweepSurface tiltedPlane(double scale, unsigned seed) {
    std::mt19937 rng(seed);
    std::uniform_real_distribution<double> sym(-1, 1);
    const Vec3 c = Vec3(0.5, 0.5, 0.5) * scale + 0.1 * scale * Vec3(sym(rng), sym(rng), sym(rng));
    const Vec3 n = Vec3(0.3 * sym(rng), 0.3 * sym(rng), 1).normalized();
    const Vec3 u = n.unitOrthogonal(), w = n.cross(u);
    const double R = 2 * scale;
    std::vector<Vec3> a, b;
    for (int j = 0; j <= 4; ++j) {
        const double s = -R + 2 * R * j / 4;
        a.push_back(c - R * w + s * u + 0.05 * scale * std::sin(3 * s / scale) * n);
        b.push_back(c + R * w + s * u + 0.05 * scale * std::sin(3 * s / scale) * n);
    }
    SweepSurface sweep;
    if (!SweepSurface::fromStartEnd(a, b, sweep).ok())
        qFatal("bad sweep");
    return sweep;
}

/// The octahedron with corners at distance 1 on the axes (nodes 0-5: -z, +z, +x, +y, -x,
/// -y) split into eight tets around a centre node 6 at `centre`; with `copy`, the four tets
/// below z = 0 use node 7 instead, a copy of the centre (as separation leaves a cut node).
TetMesh octahedron(const Vec3& centre, bool copy) {
    std::vector<Vec3> nodes{Vec3(0, 0, -1), Vec3(0, 0, 1), Vec3(1, 0, 0), Vec3(0, 1, 0), Vec3(-1, 0, 0), Vec3(0, -1, 0),
                            centre};
    const int c = copy ? 7 : 6;
    if (copy)
        nodes.push_back(centre);
    return TetMesh::fromArrays(nodes, {{6, 2, 3, 1}, {6, 3, 4, 1}, {6, 4, 5, 1}, {6, 5, 2, 1},
                                       {c, 3, 2, 0}, {c, 4, 3, 0}, {c, 5, 4, 0}, {c, 2, 5, 0}});
}

/// Counts of a RelaxResult: movable (interior) nodes, nodes on the sweep, fixed nodes.
using Counts = std::array<int, 3>;

} // namespace

Q_DECLARE_METATYPE(resect::Vec3)
Q_DECLARE_METATYPE(Counts)

class TestRelaxNodes : public QObject {
    Q_OBJECT
private slots:
    void relaxTheCentreOfAnOctahedron_data() {
        QTest::addColumn<Vec3>("centre");
        QTest::addColumn<bool>("copy");
        QTest::addColumn<std::vector<int>>("cutSurface");
        QTest::addColumn<std::vector<int>>("fixedNodes");
        QTest::addColumn<int>("steps");
        QTest::addColumn<bool>("moves");
        QTest::addColumn<Counts>("counts");  ///< movable, on the sweep, fixed
        const Vec3 inPlane(0.3, 0.1, 0), offPlane(0.3, 0.1, 0.2);
        QTest::newRow("on the cut: moves within the sweep")
            << inPlane << false << std::vector<int>{6} << std::vector<int>{} << 10 << true << Counts{0, 1, 6};
        // The cut touches the surface at node 2 (fixed, as the cutter fixes cut nodes on the
        // surface); the centre is interior and not on the cut.
        QTest::newRow("interior: moves freely")
            << offPlane << false << std::vector<int>{2} << std::vector<int>{2} << 10 << true << Counts{1, 0, 6};
        QTest::newRow("copies move together")
            << inPlane << true << std::vector<int>{6, 7} << std::vector<int>{} << 10 << true << Counts{0, 1, 6};
        QTest::newRow("fixed: stays")
            << inPlane << false << std::vector<int>{6} << std::vector<int>{6} << 10 << false << Counts{0, 0, 7};
        QTest::newRow("in equilibrium: stays")
            << Vec3(0, 0, 0) << false << std::vector<int>{6} << std::vector<int>{} << 10 << false << Counts{0, 1, 6};
        QTest::newRow("no steps") << inPlane << false << std::vector<int>{6} << std::vector<int>{} << 0 << false
                                  << Counts{0, 0, 0};
    }
    void relaxTheCentreOfAnOctahedron() {
        QFETCH(Vec3, centre);
        QFETCH(bool, copy);
        QFETCH(std::vector<int>, cutSurface);
        QFETCH(std::vector<int>, fixedNodes);
        QFETCH(int, steps);
        QFETCH(bool, moves);
        QFETCH(Counts, counts);
        TetMesh mesh = octahedron(centre, copy);
        for (int t = 0; t < mesh.tetCount(); ++t)
            QVERIFY(mesh.referenceVolume(t) > 0);
        const TetMesh before = mesh;
        const SweepSurface sweep = planeZ0(-5, 5, -5, 5);
        CutChanges changes;
        changes.cutSurfaceNodes = cutSurface;
        if (copy)
            changes.duplicatedNodes = {{6, 7}};
        RelaxOptions options;
        options.steps = steps;
        const RelaxResult r = relaxNodes(mesh, sweep, changes, fixedNodes, options);

        QCOMPARE(r.movable, counts[0]);
        QCOMPARE(r.onSweep, counts[1]);
        QCOMPARE(r.fixed, counts[2]);
        QCOMPARE(r.acceptedMoves > 0, moves);
        const std::vector<int> movedNodes = !moves ? std::vector<int>{} : copy ? std::vector<int>{6, 7} : std::vector<int>{6};
        QCOMPARE(r.movedNodes, movedNodes);
        // The corners are on the boundary: they never move.
        for (int v = 0; v < 6; ++v) {
            QCOMPARE(mesh.pos(v), before.pos(v));
            QCOMPARE(mesh.ref(v), before.ref(v));
        }
        const Vec3 moved = mesh.pos(6);
        if (!moves) {
            QCOMPARE(moved, centre);
        } else {
            // Towards the symmetric position (the equilibrium of equal springs), the reference
            // position following (the configurations coincide here).
            QVERIFY2(moved.norm() < centre.norm(), qPrintable(QString("%1 -> %2").arg(centre.norm()).arg(moved.norm())));
            QVERIFY((mesh.ref(6) - moved).norm() <= 1e-15);
            if (counts[1] > 0)  // projected onto the plane z = 0: exactly in it
                QVERIFY2(moved.z() == 0, qPrintable(QString::number(moved.z(), 'g', 17)));
            else
                QVERIFY(moved.z() != centre.z());  // free to leave its plane
        }
        if (copy) {
            QCOMPARE(mesh.pos(7), mesh.pos(6));
            QCOMPARE(mesh.ref(7), mesh.ref(6));
        }
        // Volume kept; every tet positive; the smallest radius ratio does not drop.
        QVERIFY(std::abs(mesh.totalReferenceVolume() - 4.0 / 3.0) <= 1e-15);
        for (int t = 0; t < mesh.tetCount(); ++t) {
            const Tet& q = mesh.tet(t);
            QVERIFY(orient3d(mesh.ref(q[0]), mesh.ref(q[1]), mesh.ref(q[2]), mesh.ref(q[3])) > 0);
        }
        QVERIFY(summarizeQuality(mesh).minRadiusRatio >= summarizeQuality(before).minRadiusRatio);
    }

    void relaxationProperties_data() {
        QTest::addColumn<double>("scale");
        QTest::addColumn<unsigned>("seed");
        QTest::addColumn<bool>("snap");
        for (double scale : {1e-3, 1.0, 1e3})
            for (unsigned seed : {1u, 2u, 3u})
                for (bool snap : {false, true})
                    QTest::addRow("scale %g, seed %u, %s", scale, seed, snap ? "snapped" : "not snapped")
                        << scale << seed << snap;
    }
    void relaxationProperties() {
        QFETCH(double, scale);
        QFETCH(unsigned, seed);
        QFETCH(bool, snap);
        const TetMesh input = jitteredBoxWithMasses(scale, seed);
        std::vector<char> wasBoundary(input.nodeCount());
        for (int n = 0; n < input.nodeCount(); ++n)
            wasBoundary[n] = isBoundaryNode(input, n);
        const SweepSurface sweep = tiltedPlane(scale, seed);
        CutOptions options;
        options.snap = snap;
        TetMesh plain = input, relaxed = input;
        CutResult rPlain, rRelaxed;
        {
            HybridCutter cutter(plain);
            QVERIFY(cutter.cut(sweep, options, rPlain).ok());
        }
        options.relaxSteps = 10;
        {
            HybridCutter cutter(relaxed);
            QVERIFY(cutter.cut(sweep, options, rRelaxed).ok());
        }
        QVERIFY(rRelaxed.stats.relaxedMoves > 0);
        QCOMPARE(relaxed.tetCount(), plain.tetCount());
        const QString v = cutViolations(relaxed, sweep, input.totalReferenceVolume(), rRelaxed);
        QVERIFY2(v.isEmpty(), qPrintable(v));
        // Never lowers the minimum radius ratio.
        const double before = summarizeQuality(plain).minRadiusRatio;
        const double after = summarizeQuality(relaxed).minRadiusRatio;
        QVERIFY2(after >= before, qPrintable(QString("%1 -> %2").arg(before).arg(after)));
        // Nodes on the sweep stay on it; nodes that were on the boundary stay in place.
        for (int n : rPlain.changes.cutSurfaceNodes)
            if (sweep.closestPoint(plain.pos(n)).distance <= 1e-12 * scale)
                QVERIFY2(sweep.closestPoint(relaxed.pos(n)).distance <= 1e-12 * scale, qPrintable(QString::number(n)));
        for (int n = 0; n < input.nodeCount(); ++n)
            if (wasBoundary[n]) {
                QCOMPARE(relaxed.pos(n), plain.pos(n));
                QCOMPARE(relaxed.ref(n), plain.ref(n));
            }
    }

    void massesFollowEq3AfterManyCuts_data() {
        QTest::addColumn<double>("scale");
        QTest::newRow("1e-3") << 1e-3;
        QTest::newRow("1") << 1.0;
        QTest::newRow("1e3") << 1e3;
    }
    void massesFollowEq3AfterManyCuts() {
        QFETCH(double, scale);
        TetMesh mesh = jitteredBoxWithMasses(scale, 11);
        double total = 0;
        for (double m : mesh.masses())
            total += m;
        HybridCutter cutter(mesh);
        for (unsigned k = 0; k < 4; ++k) {
            CutOptions options;
            options.snap = k % 2 == 0;
            options.relaxSteps = k < 2 ? 10 : 0;
            options.method = k == 3 ? CutMethod::Subdivision : CutMethod::Hybrid;
            CutResult r;
            QVERIFY(cutter.cut(tiltedPlane(scale, 20 + k), options, r).ok());
        }
        double after = 0;
        for (double m : mesh.masses())
            after += m;
        QVERIFY2(std::abs(after - total) <= 1e-9 * total, qPrintable(QString("%1 vs %2").arg(after).arg(total)));
        TetMesh reference = mesh;
        computeLumpedMasses(reference, Material{}.density);
        for (int n = 0; n < mesh.nodeCount(); ++n)
            QVERIFY(std::abs(mesh.masses()[n] - reference.masses()[n]) <= 1e-12 * total);
    }
};

QTEST_GUILESS_MAIN(TestRelaxNodes)
#include "test_relax_nodes.moc"
