// Tests of core/mesher/procedural_surfaces and core/mesher/samples: closed, manifold,
// outward-oriented surfaces free of self-intersections, with texture coordinates, whose
// volumes converge to the smooth formulas; and samples of the promised shape and size.

#include "core/mesher/check_surface.h"
#include "core/mesher/procedural_surfaces.h"
#include "core/mesher/samples.h"

#include <QtTest>

#include <algorithm>
#include <cmath>
#include <numbers>

using namespace resect;

namespace {

constexpr double kPi = std::numbers::pi;

/// Surfaces by name, for data-driven tests.
TriangleSurface surfaceByName(const QString& name) {
    if (name == "torus")
        return makeTorus(8.0, 3.0, 48, 24);
    if (name == "torus-minimal")
        return makeTorus(2.0, 1.0, 3, 3);
    if (name == "ellipsoid")
        return makeEllipsoid(Vec3(3.0, 2.0, 1.0), 16, 32);
    if (name == "ellipsoid-minimal")
        return makeEllipsoid(Vec3(1.0, 1.0, 1.0), 2, 3);
    if (name == "thin-ellipsoid")
        return makeEllipsoid(Vec3(10.0, 10.0, 1.5), 32, 64);
    if (name == "box")
        return makeBox(Vec3(-1.0, 0.0, 2.0), Vec3(3.0, 0.5, 7.0));
    if (name == "box-reversed-corners") // lo and hi swapped on one axis
        return makeBox(Vec3(3.0, 0.0, 2.0), Vec3(-1.0, 0.5, 7.0));
    if (name == "polar-clockwise") // a mapping of the opposite handedness: still outward
        return makePolarGridSurface(
            [](double s, double phi) {
                const double t = kPi * s;
                return Vec3(std::sin(t) * std::cos(-phi), std::sin(t) * std::sin(-phi),
                            -std::cos(t));
            },
            8, 12);
    if (name == "polyp-1")
        return sampleSurface(Sample::Polyp, 1.0);
    if (name == "polyp-0.25")
        return sampleSurface(Sample::Polyp, 0.25);
    if (name == "polyp-0.02")
        return sampleSurface(Sample::Polyp, 0.02);
    if (name == "myoma-1")
        return sampleSurface(Sample::Myoma, 1.0);
    if (name == "myoma-0.25")
        return sampleSurface(Sample::Myoma, 0.25);
    if (name == "myoma-0.02")
        return sampleSurface(Sample::Myoma, 0.02);
    return {};
}

double relativeError(double value, double exact) {
    return std::abs(value - exact) / exact;
}

/// Radius of the polyp's horizontal slice nearest to height z: the mean distance of the
/// ring's vertices from the ring's centroid, and the per-vertex distances in ring order.
struct Slice {
    double meanRadius = 0;
    std::vector<double> radii;
};
Slice polypSlice(const TriangleSurface& s, double z) {
    // Rings are stored one after another between the two poles; find the ring whose
    // height is nearest to z (all vertices of a ring share one height).
    double best = 1e300, ringZ = 0;
    for (const Vec3& p : s.positions)
        if (std::abs(p.z() - z) < best) {
            best = std::abs(p.z() - z);
            ringZ = p.z();
        }
    std::vector<Vec3> ring;
    for (const Vec3& p : s.positions)
        if (p.z() == ringZ)
            ring.push_back(p);
    Vec3 c = Vec3::Zero();
    for (const Vec3& p : ring)
        c += p;
    c /= static_cast<double>(ring.size());
    Slice slice;
    for (const Vec3& p : ring) {
        slice.radii.push_back((p - c).head<2>().norm());
        slice.meanRadius += slice.radii.back();
    }
    slice.meanRadius /= static_cast<double>(ring.size());
    return slice;
}

} // namespace

class TestProceduralSurfaces : public QObject {
    Q_OBJECT

private slots:
    void closedManifoldOriented_data();
    void closedManifoldOriented();
    void torusCounts();
    void polarGridCountsAndPoles();
    void polarGridUvs();
    void ellipsoidVolumeConverges();
    void torusVolumeConverges();
    void boxIsExact();
    void samplesNames();
    void sampleTriangleCounts_data();
    void sampleTriangleCounts();
    void samplesDeterministic();
    void samplesOddDetailStillValid_data();
    void samplesOddDetailStillValid();
    void polypShape();
    void myomaShape();
};

void TestProceduralSurfaces::closedManifoldOriented_data() {
    QTest::addColumn<QString>("name");
    for (const char* n :
         {"torus", "torus-minimal", "ellipsoid", "ellipsoid-minimal", "thin-ellipsoid", "box",
          "box-reversed-corners", "polar-clockwise", "polyp-1", "polyp-0.25", "polyp-0.02",
          "myoma-1", "myoma-0.25", "myoma-0.02"})
        QTest::newRow(n) << QString(n);
}

void TestProceduralSurfaces::closedManifoldOriented() {
    QFETCH(QString, name);
    const TriangleSurface s = surfaceByName(name);
    const SurfaceCheck c = checkSurface(s);
    QVERIFY(c.triangles > 0);
    QCOMPARE(c.nonFiniteVertices, 0);
    QCOMPARE(c.badIndexTriangles, 0);
    QCOMPARE(c.degenerateTriangles, 0);
    QCOMPARE(c.borderEdges, 0);
    QCOMPARE(c.nonManifoldEdges, 0);
    QCOMPARE(c.nonManifoldVertices, 0);
    QCOMPARE(c.orientationErrors, 0);
    QVERIFY(!c.selfIntersecting);
    QVERIFY2(c.enclosedVolume > 0.0, "outward orientation gives a positive volume");
    const Status problem = surfaceProblem(c);
    QVERIFY2(problem.ok(), problem.message().c_str());
    // Closed triangle surface: every edge in two triangles, so 3 F = 2 E.
    // Euler characteristic V - E + F is 0 for the torus, 2 for the spheres.
    const int edges = 3 * c.triangles / 2;
    const int euler = c.vertices - edges + c.triangles;
    QCOMPARE(euler, name.startsWith("torus") ? 0 : 2);
    // Texture coordinates: one per vertex, inside the unit square.
    QCOMPARE(static_cast<int>(s.uvs.size()), s.vertexCount());
    for (const Eigen::Vector2d& uv : s.uvs) {
        QVERIFY(uv.allFinite());
        QVERIFY(uv.x() >= 0.0 && uv.x() <= 1.0 && uv.y() >= 0.0 && uv.y() <= 1.0);
    }
}

void TestProceduralSurfaces::torusCounts() {
    const TriangleSurface s = makeTorus(5.0, 1.0, 20, 10);
    QCOMPARE(s.vertexCount(), 200);
    QCOMPARE(s.triangleCount(), 400);
    // Segment counts below 3 are raised to 3.
    const TriangleSurface tiny = makeTorus(5.0, 1.0, 1, 0);
    QCOMPARE(tiny.vertexCount(), 9);
    QVERIFY(surfaceProblem(checkSurface(tiny)).ok());
}

void TestProceduralSurfaces::polarGridCountsAndPoles() {
    const int rings = 7, segments = 11;
    const Vec3 bottom(0.0, 0.0, -2.0), top(0.0, 0.0, 3.0);
    const TriangleSurface s = makePolarGridSurface(
        [&](double t, double phi) {
            const double r = std::sin(kPi * t);
            const double z = bottom.z() + (top.z() - bottom.z()) * t;
            return Vec3(r * std::cos(phi), r * std::sin(phi), z);
        },
        rings, segments);
    QCOMPARE(s.vertexCount(), (rings - 1) * segments + 2);
    QCOMPARE(s.triangleCount(), 2 * segments * (rings - 1));
    // Each pole is one vertex, shared by `segments` triangles.
    int bottomCount = 0, topCount = 0, bottomIndex = -1;
    for (int i = 0; i < s.vertexCount(); ++i) {
        if ((s.positions[i] - bottom).norm() < 1e-12) {
            ++bottomCount;
            bottomIndex = i;
        }
        if ((s.positions[i] - top).norm() < 1e-12)
            ++topCount;
    }
    QCOMPARE(bottomCount, 1);
    QCOMPARE(topCount, 1);
    int fan = 0;
    for (const Tri& t : s.triangles)
        fan += std::count(t.begin(), t.end(), bottomIndex) > 0 ? 1 : 0;
    QCOMPARE(fan, segments);
    // No two vertices coincide: the seam at phi = 2 pi reuses the phi = 0 vertices.
    for (int i = 0; i < s.vertexCount(); ++i)
        for (int j = i + 1; j < s.vertexCount(); ++j)
            QVERIFY((s.positions[i] - s.positions[j]).norm() > 1e-9);
}

void TestProceduralSurfaces::polarGridUvs() {
    const int rings = 4, segments = 8;
    const TriangleSurface s = makeEllipsoid(Vec3(1.0, 1.0, 1.0), rings, segments);
    // Vertex 1 is (s = 1/rings, phi = 0): uv (0, 1/4); vertex 2 is phi = 2 pi / 8.
    QCOMPARE(s.uvs[0], Eigen::Vector2d(0.0, 0.0));
    QCOMPARE(s.uvs[1], Eigen::Vector2d(0.0, 0.25));
    QCOMPARE(s.uvs[2], Eigen::Vector2d(0.125, 0.25));
    QCOMPARE(s.uvs.back(), Eigen::Vector2d(0.0, 1.0));
    // Bottom pole at -z, top at +z.
    QVERIFY(s.positions.front().isApprox(Vec3(0.0, 0.0, -1.0)));
    QVERIFY(s.positions.back().isApprox(Vec3(0.0, 0.0, 1.0)));
}

void TestProceduralSurfaces::ellipsoidVolumeConverges() {
    const Vec3 radii(3.0, 2.0, 1.5);
    const double exact = 4.0 / 3.0 * kPi * radii.x() * radii.y() * radii.z();
    double previous = 1.0;
    for (int n : {8, 16, 32, 64}) {
        const double v = enclosedVolume(makeEllipsoid(radii, n, 2 * n));
        const double err = relativeError(v, exact);
        QVERIFY2(v < exact, "the polyhedron is inscribed");
        // Second-order convergence: halving the spacing divides the error by about 4.
        QVERIFY2(err < previous / 3.0, qPrintable(QString("n=%1 err=%2").arg(n).arg(err)));
        previous = err;
    }
    QVERIFY(previous < 0.002);
}

void TestProceduralSurfaces::torusVolumeConverges() {
    const double R = 8.0, r = 3.0;
    const double exact = 2.0 * kPi * kPi * R * r * r; // Pappus
    double previous = 1.0;
    for (int n : {8, 16, 32, 64}) {
        const double err = relativeError(enclosedVolume(makeTorus(R, r, 2 * n, n)), exact);
        QVERIFY2(err < previous / 3.0, qPrintable(QString("n=%1 err=%2").arg(n).arg(err)));
        previous = err;
    }
    // Cross-section and path polygons each lose about (2 pi / n)^2 / 6.
    QVERIFY2(previous < 0.003, qPrintable(QString::number(previous)));
}

void TestProceduralSurfaces::boxIsExact() {
    const TriangleSurface s = makeBox(Vec3(-1.0, 0.0, 2.0), Vec3(3.0, 0.5, 7.0));
    QCOMPARE(s.vertexCount(), 8);
    QCOMPARE(s.triangleCount(), 12);
    QVERIFY(std::abs(enclosedVolume(s) - 4.0 * 0.5 * 5.0) < 1e-12);
    const auto [lo, hi] = boundingBox(s.positions);
    QCOMPARE(lo, Vec3(-1.0, 0.0, 2.0));
    QCOMPARE(hi, Vec3(3.0, 0.5, 7.0));
}

void TestProceduralSurfaces::samplesNames() {
    QCOMPARE(sampleNames(), (std::vector<std::string>{"polyp", "myoma"}));
    for (const std::string& n : sampleNames()) {
        const auto s = sampleFromName(n);
        QVERIFY(s.has_value());
        QCOMPARE(sampleName(*s), n);
    }
    QVERIFY(!sampleFromName("Polyp").has_value());
    QVERIFY(!sampleFromName("").has_value());
    QVERIFY(!sampleFromName("uterus").has_value());
}

void TestProceduralSurfaces::sampleTriangleCounts_data() {
    QTest::addColumn<int>("sample");
    QTest::newRow("polyp") << static_cast<int>(Sample::Polyp);
    QTest::newRow("myoma") << static_cast<int>(Sample::Myoma);
}

void TestProceduralSurfaces::sampleTriangleCounts() {
    QFETCH(int, sample);
    const auto smp = static_cast<Sample>(sample);
    const int full = sampleSurface(smp).triangleCount();
    QVERIFY2(full >= 30000 && full <= 60000, qPrintable(QString::number(full)));
    // Detail scales the triangle count about linearly.
    const int quarter = sampleSurface(smp, 0.25).triangleCount();
    QVERIFY(std::abs(quarter - full / 4) < full / 20);
    QVERIFY(sampleSurface(smp, 0.02).triangleCount() < quarter);
}

void TestProceduralSurfaces::samplesDeterministic() {
    for (Sample smp : {Sample::Polyp, Sample::Myoma}) {
        const TriangleSurface a = sampleSurface(smp, 0.1);
        const TriangleSurface b = sampleSurface(smp, 0.1);
        QVERIFY(a.positions == b.positions);
        QVERIFY(a.triangles == b.triangles);
        QVERIFY(a.uvs == b.uvs);
    }
}

void TestProceduralSurfaces::samplesOddDetailStillValid_data() {
    QTest::addColumn<double>("detail");
    QTest::newRow("zero") << 0.0;
    QTest::newRow("negative") << -3.0;
    QTest::newRow("nan") << std::nan("");
    QTest::newRow("tiny") << 1e-9;
}

void TestProceduralSurfaces::samplesOddDetailStillValid() {
    QFETCH(double, detail);
    for (Sample smp : {Sample::Polyp, Sample::Myoma}) {
        const TriangleSurface s = sampleSurface(smp, detail);
        const Status problem = surfaceProblem(checkSurface(s));
        QVERIFY2(problem.ok(), problem.message().c_str());
    }
}

void TestProceduralSurfaces::polypShape() {
    const TriangleSurface s = sampleSurface(Sample::Polyp, 1.0);
    const auto [lo, hi] = boundingBox(s.positions);
    // About 20 mm tall, base at z = 0, narrower than tall.
    QVERIFY(std::abs(lo.z()) < 1e-12);
    QVERIFY(std::abs(hi.z() - 20.0) < 1e-9);
    QVERIFY(hi.x() - lo.x() < 16.0 && hi.y() - lo.y() < 16.0);
    QVERIFY(hi.x() - lo.x() > 8.0 && hi.y() - lo.y() > 8.0);
    // A narrower stalk on a slightly flared base under a wide head.
    const double base = polypSlice(s, 1.0).meanRadius;
    const double stalk = polypSlice(s, 6.0).meanRadius;
    const double head = polypSlice(s, 14.5).meanRadius;
    QVERIFY2(stalk < 0.5 * head, qPrintable(QString("stalk %1 head %2").arg(stalk).arg(head)));
    QVERIFY2(base > 1.5 * stalk, qPrintable(QString("base %1 stalk %2").arg(base).arg(stalk)));
    QVERIFY(stalk > 1.0);
    // 3 to 5 soft lobes: local maxima of the radius around the head.
    const std::vector<double> r = polypSlice(s, 14.5).radii;
    const int n = static_cast<int>(r.size());
    QVERIFY(n >= 12);
    int lobes = 0;
    for (int j = 0; j < n; ++j)
        if (r[j] > r[(j + n - 1) % n] && r[j] >= r[(j + 1) % n])
            ++lobes;
    QVERIFY2(lobes >= 3 && lobes <= 5, qPrintable(QString("%1 lobes").arg(lobes)));
    const auto [minIt, maxIt] = std::minmax_element(r.begin(), r.end());
    QVERIFY2(*maxIt > 1.15 * *minIt, "lobes stand out from the clefts");
}

void TestProceduralSurfaces::myomaShape() {
    const TriangleSurface s = sampleSurface(Sample::Myoma, 1.0);
    const auto [lo, hi] = boundingBox(s.positions);
    for (int k = 0; k < 3; ++k) {
        const double extent = hi[k] - lo[k];
        QVERIFY2(extent > 17.0 && extent < 23.0, qPrintable(QString::number(extent)));
    }
    // Roughly spherical but irregular: distances from the centroid vary by a few percent
    // to about 10 % around their mean, smoothly.
    Vec3 c = Vec3::Zero();
    for (const Vec3& p : s.positions)
        c += p;
    c /= s.vertexCount();
    double rmin = 1e300, rmax = 0, mean = 0;
    for (const Vec3& p : s.positions) {
        const double r = (p - c).norm();
        rmin = std::min(rmin, r);
        rmax = std::max(rmax, r);
        mean += r;
    }
    mean /= s.vertexCount();
    QVERIFY2((rmax - rmin) / mean > 0.06, "not a perfect sphere");
    QVERIFY2((rmax - rmin) / mean < 0.35, "no more than a mild irregularity");
    // Its volume is that of a sphere of the mean radius, give or take the irregularity.
    const double volume = enclosedVolume(s);
    const double sphere = 4.0 / 3.0 * kPi * mean * mean * mean;
    QVERIFY(relativeError(volume, sphere) < 0.1);
}

QTEST_GUILESS_MAIN(TestProceduralSurfaces)
#include "test_procedural_surfaces.moc"
