// Tests of the sweep surface: construction errors, (u, v) parameterisation, closest points,
// and exact segment crossings including degenerate contact.
#include "core/sweep/intersect_segment.h"
#include "core/sweep/sweep_surface.h"

#include <QTest>

#include <cmath>
#include <limits>
#include <random>

using namespace resect;
Q_DECLARE_METATYPE(resect::Vec3)

namespace {

/// Planar square sweep in z = 0 over [-1, 1]^2 with n segments per curve and m curves.
SweepSurface square(int n = 4, int m = 2) {
    std::vector<std::vector<Vec3>> curves(m);
    for (int i = 0; i < m; ++i)
        for (int j = 0; j <= n; ++j)
            curves[i].push_back(Vec3(-1 + 2.0 * j / n, -1 + 2.0 * i / (m - 1), 0));
    SweepSurface s;
    const Status st = SweepSurface::fromCurves(curves, s);
    if (!st.ok())
        qFatal("%s", st.message().c_str());
    return s;
}

} // namespace

class TestSweepSurface : public QObject {
    Q_OBJECT
private slots:
    void rejectsBadSweeps_data() {
        QTest::addColumn<int>("kind");
        QTest::addColumn<QString>("message");
        QTest::newRow("one curve") << 0 << "at least two curves";
        QTest::newRow("different lengths") << 1 << "same number";
        QTest::newRow("NaN point") << 2 << "not finite";
        QTest::newRow("zero area") << 3 << "zero area";
        QTest::newRow("self-intersecting") << 4 << "intersects itself";
        QTest::newRow("single-point curves") << 5 << "at least two";
    }
    void rejectsBadSweeps() {
        QFETCH(int, kind);
        QFETCH(QString, message);
        std::vector<std::vector<Vec3>> c;
        switch (kind) {
        case 0: c = {{Vec3(0, 0, 0), Vec3(1, 0, 0)}}; break;
        case 1: c = {{Vec3(0, 0, 0), Vec3(1, 0, 0)}, {Vec3(0, 1, 0), Vec3(1, 1, 0), Vec3(2, 1, 0)}}; break;
        case 2: c = {{Vec3(0, 0, 0), Vec3(1, 0, 0)}, {Vec3(0, 1, 0), Vec3(1, std::nan(""), 0)}}; break;
        case 3: c = {{Vec3(0, 0, 0), Vec3(1, 0, 0)}, {Vec3(2, 0, 0), Vec3(3, 0, 0)}}; break;
        case 4:
            // A stroke that comes back through itself: the third pose crosses the first quad.
            c = {{Vec3(0, 0, 0), Vec3(2, 0, 0)}, {Vec3(0, 2, 0), Vec3(2, 2, 0)},
                 {Vec3(0, 2, 2), Vec3(2, 2, 2)}, {Vec3(1, 1, -1), Vec3(1.5, 1, -1)}};
            break;
        case 5: c = {{Vec3(0, 0, 0)}, {Vec3(1, 0, 0)}}; break;
        }
        SweepSurface s;
        const Status st = SweepSurface::fromCurves(c, s);
        QVERIFY(!st.ok());
        QVERIFY2(QString::fromStdString(st.message()).contains(message), st.message().c_str());
    }

    void topologyAndArea() {
        const SweepSurface s = square(4, 3);
        QCOMPARE(s.curveCount(), 3);
        QCOMPARE(s.pointsPerCurve(), 5);
        QCOMPARE(int(s.triangles().size()), 2 * 4 * 2);  // 2n triangles per pair of curves
        QVERIFY(std::abs(s.area() - 4.0) < 1e-12);
        QCOMPARE(int(s.borderEdges().size()), 2 * 4 + 2 * 2);
        QCOMPARE(s.curves()[1][2], Vec3(0, 0, 0));
    }

    void parameterisationRoundTrip() {
        // A curved, multi-pose sweep: points mapped to (u, v) and back land on themselves.
        std::vector<std::vector<Vec3>> curves(4);
        for (int i = 0; i < 4; ++i)
            for (int j = 0; j <= 6; ++j)
                curves[i].push_back(Vec3(j * 0.3, i * 0.5, 0.2 * std::sin(j * 0.7 + i)));
        SweepSurface s;
        QVERIFY(SweepSurface::fromCurves(curves, s).ok());
        std::mt19937 rng(3);
        std::uniform_real_distribution<double> u01(0, 1);
        for (int k = 0; k < 200; ++k) {
            const int t = std::uniform_int_distribution<int>(0, int(s.triangles().size()) - 1)(rng);
            double a = u01(rng), b = u01(rng);
            if (a + b > 1) {
                a = 1 - a;
                b = 1 - b;
            }
            const Vec3 bary(1 - a - b, a, b);
            const Tri& q = s.triangles()[t];
            const Vec3 p = bary[0] * s.vertices()[q[0]] + bary[1] * s.vertices()[q[1]] + bary[2] * s.vertices()[q[2]];
            const Vec2 uv = s.uvAt(t, bary);
            QVERIFY(uv.minCoeff() >= -1e-15 && uv.maxCoeff() <= 1 + 1e-15);
            QVERIFY2((s.pointAt(uv) - p).norm() < 1e-12, qPrintable(QString::number((s.pointAt(uv) - p).norm())));
            // And the closest point of p is p itself, with the same (u, v).
            const auto c = s.closestPoint(p);
            QVERIFY(c.distance < 1e-12);
            QVERIFY((c.uv - uv).norm() < 1e-9);
        }
        QCOMPARE(s.vertexUv(0), Vec2(0, 0));
        QCOMPARE(s.vertexUv(27), Vec2(1, 1));
    }

    void closestPointMatchesBruteForce() {
        std::vector<std::vector<Vec3>> curves(5);
        for (int i = 0; i < 5; ++i)
            for (int j = 0; j <= 8; ++j)
                curves[i].push_back(Vec3(j * 0.25, i * 0.4, 0.3 * std::cos(j * 0.5) * std::sin(i * 0.8)));
        SweepSurface s;
        QVERIFY(SweepSurface::fromCurves(curves, s).ok());
        std::mt19937 rng(5);
        std::uniform_real_distribution<double> u(-1, 3);
        for (int k = 0; k < 300; ++k) {
            const Vec3 p(u(rng), u(rng), u(rng) - 1);
            double best = std::numeric_limits<double>::infinity();
            for (const Tri& q : s.triangles()) {
                const Vec3 b = closestPointBarycentric(p, s.vertices()[q[0]], s.vertices()[q[1]], s.vertices()[q[2]]);
                const Vec3 x = b[0] * s.vertices()[q[0]] + b[1] * s.vertices()[q[1]] + b[2] * s.vertices()[q[2]];
                best = std::min(best, (x - p).norm());
            }
            QVERIFY(std::abs(s.closestPoint(p).distance - best) < 1e-12);
        }
    }

    void sideOfIsExactAndSigned() {
        const SweepSurface s = square();
        QCOMPARE(s.sideOf(Vec3(0.3, 0.2, 1e-300)), 1);
        QCOMPARE(s.sideOf(Vec3(0.3, 0.2, -1e-300)), -1);
        QCOMPARE(s.sideOf(Vec3(0.3, 0.2, 0)), 0);
    }

    void segmentCrossings_data() {
        QTest::addColumn<Vec3>("p");
        QTest::addColumn<Vec3>("q");
        QTest::addColumn<int>("hits");
        QTest::addColumn<bool>("pOn");
        QTest::addColumn<bool>("qOn");
        QTest::addColumn<double>("t");
        QTest::newRow("through interior") << Vec3(0.1, 0.3, -1) << Vec3(0.1, 0.3, 3) << 1 << false << false << 0.25;
        QTest::newRow("through a shared sweep edge (once)") << Vec3(0.5, 0.5, -1) << Vec3(0.5, 0.5, 1) << 1 << false << false << 0.5;
        QTest::newRow("through a sweep vertex (once)") << Vec3(0, 0, -2) << Vec3(0, 0, 2) << 1 << false << false << 0.5;
        QTest::newRow("through the border") << Vec3(1, 0.2, -1) << Vec3(1, 0.2, 1) << 1 << false << false << 0.5;
        QTest::newRow("misses outside") << Vec3(1.0000001, 0.2, -1) << Vec3(1.0000001, 0.2, 1) << 0 << false << false << 0.0;
        QTest::newRow("parallel above") << Vec3(-2, 0, 1e-12) << Vec3(2, 0, 1e-12) << 0 << false << false << 0.0;
        QTest::newRow("endpoint on the sweep") << Vec3(0.2, 0.2, 0) << Vec3(0.2, 0.2, 1) << 0 << true << false << 0.0;
        QTest::newRow("endpoint on the border line outside") << Vec3(1.5, 0.2, 0) << Vec3(0.2, 0.2, 1) << 0 << false << false << 0.0;
        QTest::newRow("segment inside the sweep") << Vec3(-0.5, 0.1, 0) << Vec3(0.5, 0.1, 0) << 0 << true << true << 0.0;
        QTest::newRow("tiny crossing near q") << Vec3(0.3, 0.3, -1) << Vec3(0.3, 0.3, 1e-300) << 1 << false << false << 1.0;
    }
    void segmentCrossings() {
        QFETCH(Vec3, p);
        QFETCH(Vec3, q);
        QFETCH(int, hits);
        QFETCH(bool, pOn);
        QFETCH(bool, qOn);
        QFETCH(double, t);
        const SweepSurface s = square();
        SegmentQuery query;
        std::vector<int> scratch;
        intersectSegment(s, p, q, query, scratch);
        QCOMPARE(int(query.hits.size()), hits);
        QCOMPARE(query.pOnSweep, pOn);
        QCOMPARE(query.qOnSweep, qOn);
        if (hits == 1) {
            QVERIFY(std::abs(query.hits[0].t - t) < 1e-12);
            QCOMPARE(query.hits[0].sideP, -1);
            QVERIFY(std::abs(query.hits[0].point.z()) < 1e-12);
            const Vec2 uv = query.hits[0].uv;
            QVERIFY((s.pointAt(uv) - query.hits[0].point).norm() < 1e-9);
        }
    }

    void curvedSweepCrossedTwice() {
        // A V-shaped stroke (three poses): a segment across both arms crosses twice.
        std::vector<std::vector<Vec3>> c = {{Vec3(0, 0.3, 1.5), Vec3(1, 0.3, 1.5)},
                                            {Vec3(0, 0.5, 0.3), Vec3(1, 0.5, 0.3)},
                                            {Vec3(0, 0.7, 1.5), Vec3(1, 0.7, 1.5)}};
        SweepSurface s;
        QVERIFY(SweepSurface::fromCurves(c, s).ok());
        SegmentQuery query;
        std::vector<int> scratch;
        intersectSegment(s, Vec3(0.5, 0.25, 0.5), Vec3(0.5, 0.75, 0.5), query, scratch);
        QCOMPARE(int(query.hits.size()), 2);
        QVERIFY(query.hits[0].t < query.hits[1].t);
        QCOMPARE(query.hits[0].sideP, -query.hits[1].sideP);
    }
};

QTEST_GUILESS_MAIN(TestSweepSurface)
#include "test_sweep_surface.moc"
