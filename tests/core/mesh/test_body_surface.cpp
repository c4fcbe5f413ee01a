// Tests of BodySurface (issue 16: no node may leave the body's surface): its signed distance
// against the analytic distance to a box at three scales, its sign on a curved body, its slack
// (zero on flat patches and sharp edges, the chordal error on smooth ones) and its range.
#include "core/mesh/body_surface.h"
#include "core/mesh/box_mesh.h"
#include "core/mesh/predicates.h"

#include <QTest>

#include <cmath>
#include <limits>
#include <map>
#include <random>

using namespace resect;

namespace {

/// Signed distance to the box [lo, hi]: positive outside (Euclidean), negative inside.
double boxDistance(const Vec3& p, const Vec3& lo, const Vec3& hi) {
    const Vec3 below = (lo - p).cwiseMax(0), above = (p - hi).cwiseMax(0);
    const double outside = (below + above).norm();
    if (outside > 0)
        return outside;
    return -std::min((p - lo).minCoeff(), (hi - p).minCoeff());
}

/// A ball of radius r: an icosahedron subdivided `levels` times, projected onto the sphere, and
/// coned to the centre (boundary faces outward).
TetMesh ball(double r, int levels) {
    const double t = (1 + std::sqrt(5.0)) / 2;
    std::vector<Vec3> v = {{-1, t, 0}, {1, t, 0}, {-1, -t, 0}, {1, -t, 0}, {0, -1, t}, {0, 1, t},
                           {0, -1, -t}, {0, 1, -t}, {t, 0, -1}, {t, 0, 1}, {-t, 0, -1}, {-t, 0, 1}};
    std::vector<Tri> f = {{0, 11, 5}, {0, 5, 1},  {0, 1, 7},   {0, 7, 10}, {0, 10, 11}, {1, 5, 9}, {5, 11, 4},
                          {11, 10, 2}, {10, 7, 6}, {7, 1, 8},  {3, 9, 4},  {3, 4, 2},   {3, 2, 6}, {3, 6, 8},
                          {3, 8, 9},  {4, 9, 5},  {2, 4, 11}, {6, 2, 10}, {8, 6, 7},   {9, 8, 1}};
    for (Vec3& p : v)
        p.normalize();
    for (int l = 0; l < levels; ++l) {
        std::vector<Tri> next;
        std::map<std::pair<int, int>, int> mid;
        const auto midpoint = [&](int a, int b) {
            const auto key = std::minmax(a, b);
            if (const auto it = mid.find(key); it != mid.end())
                return it->second;
            v.push_back((v[a] + v[b]).normalized());
            return mid[key] = static_cast<int>(v.size()) - 1;
        };
        for (const Tri& q : f) {
            const int ab = midpoint(q[0], q[1]), bc = midpoint(q[1], q[2]), ca = midpoint(q[2], q[0]);
            next.push_back({q[0], ab, ca});
            next.push_back({q[1], bc, ab});
            next.push_back({q[2], ca, bc});
            next.push_back({ab, bc, ca});
        }
        f = next;
    }
    TetMesh mesh;
    for (const Vec3& p : v)
        mesh.addNode(r * p, r * p);
    const int centre = mesh.addNode(Vec3::Zero(), Vec3::Zero());
    for (const Tri& q : f)  // counter-clockwise from outside: (centre, q0, q1, q2) is positive
        mesh.addTet({centre, q[0], q[1], q[2]});
    return mesh;
}

} // namespace

class TestBodySurface : public QObject {
    Q_OBJECT
private slots:
    void boxDistancesAreExact_data() {
        QTest::addColumn<double>("scale");
        QTest::newRow("1e-3") << 1e-3;
        QTest::newRow("1") << 1.0;
        QTest::newRow("1e3") << 1e3;
    }
    void boxDistancesAreExact() {
        // Points inside, outside and on the box (faces, edges, corners, across its diagonals):
        // the signed distance is the analytic one, and the slack is zero (flat faces, sharp
        // edges and corners).
        QFETCH(double, scale);
        const Vec3 lo = Vec3(-1, 2, 0.5) * scale, hi = Vec3(3, 5, 2.5) * scale;
        const auto body = BodySurface::fromBoundary(makeBoxTetMesh(lo, hi, 4, 3, 2));
        QVERIFY(!body->empty());
        QCOMPARE(body->triangleCount(), 2 * (4 * 3 + 3 * 2 + 4 * 2) * 2);
        std::mt19937 rng(7);
        std::uniform_real_distribution<double> u(-0.3, 1.3);
        const double range = 10 * scale;
        for (int i = 0; i < 2000; ++i) {
            Vec3 p = lo + (hi - lo).cwiseProduct(Vec3(u(rng), u(rng), u(rng)));
            if (i % 4 == 0)  // onto a face plane
                p[i % 3] = (i % 8 == 0) ? lo[i % 3] : hi[i % 3];
            const BodySurface::Side s = body->side(p, range);
            const double expected = boxDistance(p, lo, hi);
            QVERIFY2(std::abs(s.distance - expected) <= 1e-12 * scale,
                     qPrintable(QString("at (%1 %2 %3): %4, expected %5").arg(p.x()).arg(p.y()).arg(p.z()).arg(s.distance).arg(expected)));
            QCOMPARE(s.slack, 0.0);
        }
        // Corners and edge points are on it.
        QCOMPARE(body->side(lo, scale).distance, 0.0);
        QCOMPARE(body->side(Vec3(hi.x(), lo.y(), 0.5 * (lo.z() + hi.z())), scale).distance, 0.0);
    }

    void rangeIsTheSearchRadius() {
        // With no triangle within range, the answer is -range ("inside"): a caller that moved
        // a point by less than range from inside the body passed the surface on its way out.
        const auto body = BodySurface::fromBoundary(makeBoxTetMesh(Vec3::Zero(), Vec3::Constant(6), 6, 6, 6));
        QCOMPARE(body->side(Vec3(3, 3, 3), 1.0).distance, -1.0);
        QCOMPARE(body->side(Vec3(3, 3, 3), 4.0).distance, -3.0);
        QCOMPARE(body->side(Vec3(3, 3, 20), 1.0).distance, -1.0);
        QCOMPARE(body->side(Vec3(3, 3, 20), 15.0).distance, 14.0);
        const double nan = std::numeric_limits<double>::quiet_NaN();
        QCOMPARE(body->side(Vec3(nan, 0, 0), 1.0).distance, -1.0);
        QCOMPARE(body->side(Vec3(3, 3, 7), 0.0).distance, -0.0);
    }

    void emptyMeshHasNoSurface() {
        const auto body = BodySurface::fromBoundary(TetMesh{});
        QVERIFY(body->empty());
        QCOMPARE(body->side(Vec3::Zero(), 2.0).distance, -2.0);
    }

    void curvedBodySignAndSlack_data() {
        QTest::addColumn<double>("radius");
        QTest::newRow("1e-3") << 1e-3;
        QTest::newRow("1") << 1.0;
        QTest::newRow("1e3") << 1e3;
    }
    void curvedBodySignAndSlack() {
        // A ball of 320 faces: points just outside and inside along random directions get the
        // right sign (the pseudo-normals at edges and corners included); the slack of its
        // smooth patches is positive and no larger than an edge times its bend over 4; the
        // coarse icosahedron's edges are sharp (bend 0.73 rad): no slack.
        QFETCH(double, radius);
        const auto smooth = BodySurface::fromBoundary(ball(radius, 2));
        const auto coarse = BodySurface::fromBoundary(ball(radius, 0));
        QCOMPARE(smooth->triangleCount(), 320);
        const TetMesh check = ball(radius, 2);
        for (const Tet& q : check.tets())
            QVERIFY(orient3d(check.ref(q[0]), check.ref(q[1]), check.ref(q[2]), check.ref(q[3])) > 0);
        std::mt19937 rng(11);
        std::normal_distribution<double> g;
        const double edge = 0.32 * radius;  // about the subdivided edge
        for (int i = 0; i < 1000; ++i) {
            const Vec3 dir = Vec3(g(rng), g(rng), g(rng)).normalized();
            const BodySurface::Side out = smooth->side(1.05 * radius * dir, radius);
            const BodySurface::Side in = smooth->side(0.9 * radius * dir, radius);
            QVERIFY2(out.distance > 0 && in.distance < 0, qPrintable(QString("direction %1").arg(i)));
            QVERIFY(out.slack > 0 && out.slack <= edge * 0.5 / 4);
            QCOMPARE(coarse->side(1.05 * radius * dir, radius).slack, 0.0);
        }
        // On a vertex of the surface: distance zero.
        QCOMPARE(smooth->side(Vec3(0, 1, (1 + std::sqrt(5.0)) / 2).normalized() * radius, radius).distance, 0.0);
    }
};

QTEST_GUILESS_MAIN(TestBodySurface)
#include "test_body_surface.moc"
