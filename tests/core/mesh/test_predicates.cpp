// Tests of orient3d's floating-point filter (core/mesh/predicates.h) against the exact
// predicate: wherever the filter decides, its sign must be the exact one, on random points,
// on points made nearly coplanar by rounding (where the rounded determinant is of the order
// of its error bound, so a bound too small gives wrong signs here), at huge and tiny scales
// (overflow and underflow), and on exactly coplanar points (which it must never decide).
#include "core/mesh/predicates.h"

#include <QTest>

#include <cmath>
#include <limits>
#include <random>

using namespace resect;

namespace {

enum class Kind { Random, RoundedCoplanar, RoundedCollinear, ExactlyCoplanar };

struct Points {
    Vec3 a, b, c, d;
};

/// Points of the given kind with coordinates of size about `scale`, the whole set shifted by
/// `offset` (in units of scale).
Points makePoints(Kind kind, double scale, double offset, std::mt19937_64& rng) {
    std::uniform_real_distribution<double> u(-1.0, 1.0);
    const auto random = [&] { return Vec3(u(rng), u(rng), u(rng)); };
    const Vec3 shift = Vec3::Constant(offset);
    Points p;
    switch (kind) {
    case Kind::Random:
        p = {random() + shift, random() + shift, random() + shift, random() + shift};
        break;
    case Kind::RoundedCoplanar: {
        // d = a + s (b - a) + t (c - a) lies on the plane before rounding; rounding puts it a
        // few ulps off, on either side or (rarely) on it.
        p.a = random() + shift;
        p.b = random() + shift;
        p.c = random() + shift;
        const double s = u(rng), t = u(rng);
        p.d = p.a + s * (p.b - p.a) + t * (p.c - p.a);
        break;
    }
    case Kind::RoundedCollinear: {
        // a, b, c nearly on a line: the plane itself is barely defined.
        p.a = random() + shift;
        p.b = random() + shift;
        p.c = p.a + u(rng) * (p.b - p.a);
        p.d = random() + shift;
        break;
    }
    case Kind::ExactlyCoplanar: {
        // Multiples of 2^-8 in a small range, and d an integer combination: every sum and
        // product is exact, so d lies exactly on the plane of a, b, c.
        std::uniform_int_distribution<int> k(-64, 64), m(-3, 3);
        const auto grid = [&] {
            const double x = k(rng), y = k(rng), z = k(rng);
            return Vec3(x, y, z) / 256.0;
        };
        p.a = grid() + shift;
        p.b = grid() + shift;
        p.c = grid() + shift;
        const double i = m(rng), j = m(rng);
        p.d = p.a + i * (p.b - p.a) + j * (p.c - p.a);
        break;
    }
    }
    // Scales are powers of two, so scaling is exact and keeps every exact sign.
    p.a *= scale;
    p.b *= scale;
    p.c *= scale;
    p.d *= scale;
    return p;
}

QString describe(const Points& p) {
    const auto v = [](const Vec3& x) {
        return QString("(%1, %2, %3)")
            .arg(x.x(), 0, 'g', 17)
            .arg(x.y(), 0, 'g', 17)
            .arg(x.z(), 0, 'g', 17);
    };
    return v(p.a) + " " + v(p.b) + " " + v(p.c) + " " + v(p.d);
}

} // namespace

Q_DECLARE_METATYPE(Kind)

class TestPredicates : public QObject {
    Q_OBJECT
private slots:
    void filterNeverContradictsExact_data() {
        QTest::addColumn<Kind>("kind");
        QTest::addColumn<double>("scale");
        QTest::addColumn<double>("offset");
        QTest::addColumn<double>("minDecided"); // fraction the filter must decide
        QTest::newRow("random") << Kind::Random << 1.0 << 0.0 << 0.99;
        QTest::newRow("random far from origin") << Kind::Random << 1.0 << 1e6 << 0.99;
        QTest::newRow("rounded coplanar") << Kind::RoundedCoplanar << 1.0 << 0.0 << 0.0;
        QTest::newRow("rounded coplanar far from origin")
            << Kind::RoundedCoplanar << 1.0 << 1e3 << 0.0;
        QTest::newRow("rounded coplanar at 2^-60")
            << Kind::RoundedCoplanar << 0x1p-60 << 0.0 << 0.0;
        QTest::newRow("rounded collinear") << Kind::RoundedCollinear << 1.0 << 0.0 << 0.0;
        QTest::newRow("random at 2^300") << Kind::Random << 0x1p300 << 0.0 << 0.99;
        QTest::newRow("random at 2^400 (products overflow)")
            << Kind::Random << 0x1p400 << 0.0 << 0.0;
        QTest::newRow("random at 2^-300") << Kind::Random << 0x1p-300 << 0.0 << 0.99;
        QTest::newRow("random at 2^-360 (products underflow)")
            << Kind::Random << 0x1p-360 << 0.0 << 0.0;
        QTest::newRow("rounded coplanar at 2^-350 (products underflow)")
            << Kind::RoundedCoplanar << 0x1p-350 << 0.0 << 0.0;
        QTest::newRow("random at 2^-1000 (coordinates subnormal)")
            << Kind::Random << 0x1p-1000 << 0.0 << 0.0;
        QTest::newRow("exactly coplanar") << Kind::ExactlyCoplanar << 1.0 << 0.0 << 0.0;
        QTest::newRow("exactly coplanar far from origin")
            << Kind::ExactlyCoplanar << 1.0 << 4096.0 << 0.0;
        QTest::newRow("exactly coplanar at 2^-500")
            << Kind::ExactlyCoplanar << 0x1p-500 << 0.0 << 0.0;
    }
    void filterNeverContradictsExact() {
        QFETCH(Kind, kind);
        QFETCH(double, scale);
        QFETCH(double, offset);
        QFETCH(double, minDecided);
        std::mt19937_64 rng(20061);
        constexpr int kSamples = 200000;
        int decided = 0, nonzero = 0;
        for (int i = 0; i < kSamples; ++i) {
            const Points p = makePoints(kind, scale, offset, rng);
            const int exact = orient3dExact(p.a, p.b, p.c, p.d);
            const int filtered = orient3dFilter(p.a, p.b, p.c, p.d);
            if (filtered != 0 && filtered != exact)
                QFAIL(qPrintable(QString("filter says %1, exact %2 for %3")
                                     .arg(filtered)
                                     .arg(exact)
                                     .arg(describe(p))));
            if (orient3d(p.a, p.b, p.c, p.d) != exact)
                QFAIL(qPrintable("orient3d differs from the exact sign for " + describe(p)));
            decided += filtered != 0;
            nonzero += exact != 0;
        }
        if (kind == Kind::ExactlyCoplanar)
            QCOMPARE(nonzero, 0); // the construction is exact
        QVERIFY2(
            decided >= minDecided * kSamples,
            qPrintable(QString("the filter decided only %1 of %2").arg(decided).arg(kSamples)));
    }

    /// The rounded nearly coplanar points must exercise the filter near its bound: it decides
    /// some of them (else the rows above would pass with any bound) and leaves others.
    void roundedCoplanarPointsReachTheBound() {
        std::mt19937_64 rng(7);
        int decided = 0, undecided = 0, positive = 0, negative = 0;
        for (int i = 0; i < 200000; ++i) {
            const Points p = makePoints(Kind::RoundedCoplanar, 1.0, 0.0, rng);
            const int filtered = orient3dFilter(p.a, p.b, p.c, p.d);
            (filtered != 0 ? decided : undecided) += 1;
            const int exact = orient3dExact(p.a, p.b, p.c, p.d);
            positive += exact > 0;
            negative += exact < 0;
        }
        QVERIFY2(decided > 1000 && undecided > 1000,
                 qPrintable(QString("decided %1, undecided %2").arg(decided).arg(undecided)));
        QVERIFY(positive > 1000 && negative > 1000);
    }

    /// Non-finite input is never decided by the filter (orient3d then behaves as before it).
    void nonFiniteIsUndecided() {
        const double inf = std::numeric_limits<double>::infinity();
        const double nan = std::numeric_limits<double>::quiet_NaN();
        const Vec3 o(0, 0, 0), x(1, 0, 0), y(0, 1, 0);
        QCOMPARE(orient3dFilter(o, x, y, Vec3(0, 0, inf)), 0);
        QCOMPARE(orient3dFilter(o, x, y, Vec3(0, 0, nan)), 0);
        QCOMPARE(orient3dFilter(Vec3(1e308, 0, 0), Vec3(-1e308, 0, 0), y, Vec3(0, 0, 1)), 0);
    }

    void literalSigns() {
        const Vec3 o(0, 0, 0), x(1, 0, 0), y(0, 1, 0), z(0, 0, 1);
        QCOMPARE(orient3d(o, x, y, z), 1);
        QCOMPARE(orient3d(o, y, x, z), -1);
        QCOMPARE(orient3d(o, x, y, Vec3(0.25, 0.5, 0)), 0);
        QCOMPARE(orient3dFilter(o, x, y, z), 1);
        QCOMPARE(orient3dFilter(o, x, y, Vec3(0.25, 0.5, 0)), 0);
    }
};

QTEST_GUILESS_MAIN(TestPredicates)
#include "test_predicates.moc"
