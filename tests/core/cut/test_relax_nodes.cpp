// Relaxation (section 4.6) and the rest-state update (section 4.7): relaxation never lowers
// the minimum radius ratio, conserves the rest volume, keeps nodes on the sweep on it and
// fixed nodes in place; masses follow Eq. 3 after any sequence of cuts; stiffnesses Eq. 4.
#include "cut_checks.h"

#include "core/cut/update_rest_state.h"
#include "core/mesh/box_mesh.h"
#include "core/mesh/masses.h"
#include "core/mesh/quality.h"
#include "core/mesher/samples.h"
#include "core/mesher/tetrahedralize.h"

#include <QTest>

#include <random>

using namespace resect;
using resect::testing::cutViolations;

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

} // namespace

class TestRelaxNodes : public QObject {
    Q_OBJECT
private slots:
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

    void stiffnessesFollowEq4() {
        TetMesh m = TetMesh::fromArrays({Vec3(0, 0, 0), Vec3(2, 0, 0), Vec3(0, 1, 0), Vec3(0, 0, 1)}, {{0, 1, 2, 3}});
        computeLumpedMasses(m, 3.0);  // V0 = 1/3, each node 3 * (1/3) / 4 = 0.25
        Material mat;
        mat.stiffness = 5.0;
        QVERIFY(std::abs(springStiffness(m, 0, 1, mat) - 5.0 * 0.5 / 4.0) < 1e-12);    // l0 = 2
        QVERIFY(std::abs(volumeStiffness(m, 0, mat) - 5.0 * 1.0 / (1.0 / 9.0)) < 1e-9);  // V0 = 1/3
    }
};

QTEST_GUILESS_MAIN(TestRelaxNodes)
#include "test_relax_nodes.moc"
