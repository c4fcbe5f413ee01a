// Tests of the quality measures (Table 1 of the paper) against hand-computed values.
#include "core/mesh/box_mesh.h"
#include "core/mesh/quality.h"

#include <QTest>

#include <array>
#include <cmath>
#include <cstring>
#include <limits>
#include <numbers>
#include <random>

using namespace resect;

namespace {
constexpr double kDeg = 180.0 / std::numbers::pi;
const Vec3 kRegular[4] = {Vec3(1, 1, 1), Vec3(1, -1, -1), Vec3(-1, 1, -1), Vec3(-1, -1, 1)};
} // namespace

class TestQuality : public QObject {
    Q_OBJECT
private slots:
    void regularTetIsOne_data() {
        QTest::addColumn<double>("scale");
        QTest::addColumn<double>("offset");
        QTest::newRow("unit") << 1.0 << 0.0;
        QTest::newRow("1e-6") << 1e-6 << 0.0;
        QTest::newRow("1e6") << 1e6 << 0.0;
        QTest::newRow("1e-6 far from origin") << 1e-6 << 1e-3;
        QTest::newRow("1e6 offset") << 1e6 << 1e7;
    }
    void regularTetIsOne() {
        QFETCH(double, scale);
        QFETCH(double, offset);
        Vec3 p[4];
        for (int i = 0; i < 4; ++i)
            p[i] = kRegular[i] * scale + Vec3::Constant(offset);
        // kRegular is negatively oriented as listed; swap to make it positive.
        const TetQuality q = tetQuality(p[0], p[2], p[1], p[3]);
        QVERIFY(q.volume > 0);
        QVERIFY2(std::abs(q.radiusRatio - 1.0) < 1e-9, qPrintable(QString::number(q.radiusRatio, 'g', 17)));
        const double dihedral = std::acos(1.0 / 3.0);  // 70.5288 degrees
        QVERIFY(std::abs(q.minDihedral - dihedral) < 1e-9);
        QVERIFY(std::abs(q.maxDihedral - dihedral) < 1e-9);
        QVERIFY(std::abs(q.maxEdge / q.minEdge - 1.0) < 1e-9);
    }

    void cornerTetHandComputed_data() {
        QTest::addColumn<double>("scale");
        QTest::newRow("1") << 1.0;
        QTest::newRow("1e-6") << 1e-6;
        QTest::newRow("1e6") << 1e6;
    }
    void cornerTetHandComputed() {
        QFETCH(double, scale);
        // r_in = 1 / (3 + sqrt 3), R = sqrt(3) / 2, so 3 r_in / R = sqrt(3) - 1.
        const TetQuality q = tetQuality(Vec3(0, 0, 0), Vec3(scale, 0, 0), Vec3(0, scale, 0),
                                        Vec3(0, 0, scale));
        QVERIFY(std::abs(q.radiusRatio - (std::sqrt(3.0) - 1.0)) < 1e-12);
        QVERIFY(std::abs(q.volume - scale * scale * scale / 6.0) <= 1e-14 * scale * scale * scale);
        QVERIFY(std::abs(q.minDihedral * kDeg - std::acos(1.0 / std::sqrt(3.0)) * kDeg) < 1e-9);
        QVERIFY(std::abs(q.maxDihedral * kDeg - 90.0) < 1e-9);
    }

    void sliverNearZero_data() {
        QTest::addColumn<double>("height");
        QTest::addColumn<double>("maxRatio");
        QTest::newRow("1e-2") << 1e-2 << 0.05;
        QTest::newRow("1e-4") << 1e-4 << 5e-4;
        QTest::newRow("1e-8") << 1e-8 << 5e-8;
    }
    void sliverNearZero() {
        QFETCH(double, height);
        QFETCH(double, maxRatio);
        // A square lifted at one corner: all four points nearly coplanar, well-separated
        // (the classic sliver: edges fine, volume vanishing).
        const TetQuality q = tetQuality(Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0), Vec3(1, 1, height));
        QVERIFY(std::abs(q.radiusRatio) > 0);
        QVERIFY2(std::abs(q.radiusRatio) < maxRatio, qPrintable(QString::number(q.radiusRatio)));
        QVERIFY(q.maxDihedral * kDeg > 179.0 || q.minDihedral * kDeg < 1.0);
    }

    void radiusRatioAloneMatchesTetQuality() {
        std::mt19937 rng(4);
        std::uniform_real_distribution<double> u(-1, 1);
        for (int k = 0; k < 500; ++k) {
            const Vec3 p[4] = {Vec3(u(rng), u(rng), u(rng)), Vec3(u(rng), u(rng), u(rng)),
                               Vec3(u(rng), u(rng), u(rng)), Vec3(u(rng), u(rng), u(rng))};
            const double full = tetQuality(p[0], p[1], p[2], p[3]).radiusRatio;
            QVERIFY(std::abs(radiusRatio(p[0], p[1], p[2], p[3]) - full) <= 1e-12 * std::max(1.0, std::abs(full)));
        }
        QCOMPARE(radiusRatio(Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0), Vec3(1, 1, 0)), 0.0);
    }

    void degenerateAndInverted() {
        const TetQuality flat = tetQuality(Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0), Vec3(1, 1, 0));
        QCOMPARE(flat.radiusRatio, 0.0);
        QCOMPARE(flat.volume, 0.0);
        const TetQuality point = tetQuality(Vec3(1, 1, 1), Vec3(1, 1, 1), Vec3(1, 1, 1), Vec3(1, 1, 1));
        QCOMPARE(point.radiusRatio, 0.0);
        const TetQuality inv = tetQuality(Vec3(0, 0, 0), Vec3(0, 1, 0), Vec3(1, 0, 0), Vec3(0, 0, 1));
        QVERIFY(std::abs(inv.radiusRatio + (std::sqrt(3.0) - 1.0)) < 1e-12);
        QVERIFY(inv.volume < 0);
    }

    void summaryOfBoxMesh_data() {
        QTest::addColumn<double>("scale");
        QTest::newRow("1") << 1.0;
        QTest::newRow("1e-6") << 1e-6;
        QTest::newRow("1e6") << 1e6;
    }
    void summaryOfBoxMesh() {
        QFETCH(double, scale);
        const TetMesh m = makeBoxTetMesh(Vec3::Zero(), Vec3::Constant(2 * scale), 2, 2, 2);
        const QualitySummary s = summarizeQuality(m);
        QCOMPARE(s.tets, 48);
        QCOMPARE(s.nodes, 27);
        QCOMPARE(s.edges, 98);
        QVERIFY(std::abs(s.volume - 8 * scale * scale * scale) <= 1e-12 * 8 * scale * scale * scale);
        QVERIFY(std::abs(s.volumeRatio - 1.0) < 1e-9);       // all Kuhn tets are congruent
        QVERIFY(std::abs(s.edgeRatio - std::sqrt(3.0)) < 1e-9);  // cube diagonal / cube edge
        // Kuhn tet (path tet in a unit cube): hand-computed radius ratio.
        const TetQuality k = tetQuality(Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(1, 1, 0), Vec3(1, 1, 1));
        QVERIFY(std::abs(s.minRadiusRatio - std::abs(k.radiusRatio)) < 1e-9);
        QVERIFY(std::abs(s.minAspectRatioPaper - s.minRadiusRatio / 3.0) < 1e-15);
        QVERIFY(std::abs(s.minDihedralDeg - 45.0) < 1e-9);
        QVERIFY(std::abs(s.maxDihedralDeg - 90.0) < 1e-9);
        // Mean edge of the Kuhn mesh: (54 * 1 + 36 * sqrt 2 + 8 * sqrt 3) / 98 cube edges.
        const double mean = (54 + 36 * std::sqrt(2.0) + 8 * std::sqrt(3.0)) / 98 * scale;
        QVERIFY(std::abs(s.meanEdge - mean) <= 1e-12 * mean);
        QVERIFY(std::abs(meanEdgeLength(m) - mean) <= 1e-12 * mean);
    }

    /// radiusRatioPair promises radiusRatio's values bit for bit (relaxation relies on it: its
    /// trial moves must decide exactly as before), on all kinds of tets in either lane.
    void radiusRatioPairIsBitIdentical_data() {
        QTest::addColumn<int>("kind"); // 0 random, 1 nearly flat, 2 flat or collapsed, 3 slivers
        QTest::addColumn<double>("scale");
        QTest::newRow("random") << 0 << 1.0;
        QTest::newRow("random 1e-150") << 0 << 1e-150;
        QTest::newRow("random 1e150") << 0 << 1e150;
        QTest::newRow("nearly flat") << 1 << 1.0;
        QTest::newRow("nearly flat 1e-6") << 1 << 1e-6;
        QTest::newRow("flat or collapsed") << 2 << 1.0;
        QTest::newRow("slivers") << 3 << 1.0;
    }
    void radiusRatioPairIsBitIdentical() {
        QFETCH(int, kind);
        QFETCH(double, scale);
        std::mt19937_64 rng(kind * 7919 + 1);
        std::uniform_real_distribution<double> u(-1, 1);
        const auto random = [&] {
            const double x = u(rng), y = u(rng), z = u(rng);
            return Vec3(x, y, z);
        };
        const auto makeTet = [&] {
            std::array<Vec3, 4> p{random(), random(), random(), random()};
            if (kind == 1)
                p[3] = p[0] + u(rng) * (p[1] - p[0]) + u(rng) * (p[2] - p[0]) + 1e-9 * random();
            if (kind == 2) {
                const int collapse = static_cast<int>(rng() % 3);
                p[3] = collapse == 0   ? p[0]
                       : collapse == 1 ? Vec3(p[0] + 0.5 * (p[1] - p[0]))
                                       : p[2];
                if (rng() % 4 == 0)
                    p = {p[0], p[0], p[0], p[0]};
            }
            if (kind == 3) {
                // Four points near the corners of a square: a flat, fat-looking sliver.
                p = {Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(1, 1, 0), Vec3(0, 1, 0)};
                for (auto& x : p)
                    x += 1e-3 * random();
            }
            for (auto& x : p)
                x *= scale;
            return p;
        };
        const auto same = [](double a, double b) { return std::memcmp(&a, &b, sizeof a) == 0; };
        for (int i = 0; i < 50000; ++i) {
            const std::array<Vec3, 4> s = makeTet(), t = makeTet();
            const auto [rs, rt] = radiusRatioPair(s, t);
            const double es = radiusRatio(s[0], s[1], s[2], s[3]),
                         et = radiusRatio(t[0], t[1], t[2], t[3]);
            if (!same(rs, es) || !same(rt, et))
                QFAIL(qPrintable(QString("pair (%1, %2), alone (%3, %4)")
                                     .arg(rs, 0, 'g', 17)
                                     .arg(rt, 0, 'g', 17)
                                     .arg(es, 0, 'g', 17)
                                     .arg(et, 0, 'g', 17)));
        }
        // Non-finite corners: both give the same (0 for an infinite edge, NaN passes through).
        const double inf = std::numeric_limits<double>::infinity();
        const std::array<Vec3, 4> bad{Vec3(0, 0, 0), Vec3(inf, 0, 0), Vec3(0, 1, 0), Vec3(0, 0, 1)};
        const std::array<Vec3, 4> good{Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0), Vec3(0, 0, 1)};
        const auto [rb, rg] = radiusRatioPair(bad, good);
        QVERIFY(same(rb, radiusRatio(bad[0], bad[1], bad[2], bad[3])));
        QVERIFY(same(rg, radiusRatio(good[0], good[1], good[2], good[3])));
    }
};

QTEST_GUILESS_MAIN(TestQuality)
#include "test_quality.moc"
