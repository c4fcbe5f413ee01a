// Tests of core/mesher/check_surface: every problem kind is detected and named on small
// hand-built surfaces with literal coordinates; hole filling and reorientation repair
// what they promise.

#include "core/mesher/check_surface.h"
#include "core/mesher/procedural_surfaces.h"

#include <QtTest>

#include <cmath>
#include <limits>
#include <numbers>
#include <string>

using namespace resect;

namespace {

/// Unit tetrahedron, outward oriented (volume 1/6).
TriangleSurface tetrahedron(const Vec3& offset = Vec3::Zero()) {
    TriangleSurface s;
    s.positions = {offset + Vec3(0, 0, 0), offset + Vec3(1, 0, 0), offset + Vec3(0, 1, 0),
                   offset + Vec3(0, 0, 1)};
    s.triangles = {{0, 2, 1}, {0, 1, 3}, {0, 3, 2}, {1, 2, 3}};
    return s;
}

/// Axis-aligned box [0,2] x [0,1] x [0,1] as literal triangles (outward).
TriangleSurface literalBox(const Vec3& lo = Vec3(0, 0, 0), const Vec3& hi = Vec3(2, 1, 1)) {
    TriangleSurface s;
    for (int k = 0; k < 8; ++k)
        s.positions.emplace_back((k & 1) ? hi.x() : lo.x(), (k & 2) ? hi.y() : lo.y(),
                                 (k & 4) ? hi.z() : lo.z());
    s.triangles = {{0, 2, 3}, {0, 3, 1},  // z = lo
                   {4, 5, 7}, {4, 7, 6},  // z = hi (the "top")
                   {0, 1, 5}, {0, 5, 4},  // y = lo
                   {2, 6, 7}, {2, 7, 3},  // y = hi
                   {0, 4, 6}, {0, 6, 2},  // x = lo
                   {1, 3, 7}, {1, 7, 5}}; // x = hi
    return s;
}

/// Appends b to a as a separate component.
TriangleSurface merged(TriangleSurface a, const TriangleSurface& b) {
    const int offset = a.vertexCount();
    a.positions.insert(a.positions.end(), b.positions.begin(), b.positions.end());
    for (Tri t : b.triangles) {
        for (int& i : t)
            i += offset;
        a.triangles.push_back(t);
    }
    return a;
}

/// Builds the named surface for data-driven tests.
TriangleSurface surfaceByName(const QString& name) {
    const double nan = std::numeric_limits<double>::quiet_NaN();
    const double inf = std::numeric_limits<double>::infinity();
    if (name == "tetrahedron")
        return tetrahedron();
    if (name == "box")
        return literalBox();
    if (name == "two disjoint boxes")
        return merged(literalBox(), literalBox(Vec3(3, 0, 0), Vec3(4, 1, 1)));
    if (name == "empty")
        return {};
    if (name == "vertices only") {
        TriangleSurface s = tetrahedron();
        s.triangles.clear();
        return s;
    }
    if (name == "open box (top missing)") {
        TriangleSurface s = literalBox();
        s.triangles.erase(s.triangles.begin() + 2, s.triangles.begin() + 4);
        return s;
    }
    if (name == "three triangles on an edge") {
        // A closed tetrahedron plus a fin: a third triangle on edge 0-1.
        TriangleSurface s = tetrahedron();
        s.positions.emplace_back(0.5, -1.0, -1.0);
        s.triangles.push_back({0, 1, 4});
        return s;
    }
    if (name == "two tetrahedra touching at a vertex") {
        TriangleSurface s = tetrahedron();
        TriangleSurface t = tetrahedron(Vec3(1, 0, 0)); // its vertex 0 is our vertex 1
        // Share the vertex instead of duplicating it.
        const int offset = s.vertexCount();
        for (int k = 1; k < 4; ++k)
            s.positions.push_back(t.positions[k]);
        for (Tri tri : t.triangles) {
            for (int& i : tri)
                i = (i == 0) ? 1 : i - 1 + offset;
            s.triangles.push_back(tri);
        }
        return s;
    }
    if (name == "one flipped triangle") {
        TriangleSurface s = tetrahedron();
        std::swap(s.triangles[3][1], s.triangles[3][2]);
        return s;
    }
    if (name == "NaN vertex") {
        TriangleSurface s = tetrahedron();
        s.positions[2].y() = nan;
        return s;
    }
    if (name == "infinite vertices") {
        TriangleSurface s = tetrahedron();
        s.positions[1].x() = inf;
        s.positions[3].z() = -inf;
        return s;
    }
    if (name == "bad indices") {
        TriangleSurface s = tetrahedron();
        s.triangles.push_back({0, 1, 7});  // out of range
        s.triangles.push_back({2, 2, 3});  // repeated
        s.triangles.push_back({-1, 1, 2}); // negative
        return s;
    }
    if (name == "zero-area triangle") {
        // A tetrahedron whose fourth corner lies on edge 0-1: face (0, 1, 3) is a
        // segment, and the surface encloses no volume.
        TriangleSurface s = tetrahedron();
        s.positions[3] = Vec3(0.5, 0, 0);
        return s;
    }
    if (name == "two interpenetrating boxes")
        return merged(literalBox(Vec3(0, 0, 0), Vec3(2, 2, 2)),
                      literalBox(Vec3(1, 1, 1), Vec3(3, 3, 3)));
    if (name == "inside out") {
        TriangleSurface s = literalBox();
        for (Tri& t : s.triangles)
            std::swap(t[1], t[2]);
        return s;
    }
    return {};
}

} // namespace

class TestCheckSurface : public QObject {
    Q_OBJECT

private slots:
    void detectsProblems_data();
    void detectsProblems();
    void selfIntersectionTestCanBeSkipped();
    void flatPillowEnclosesNoVolume();
    void countsDisjointBorderAndOrientation();
    void fillHolesClosesOpenBox();
    void fillHolesClosesHolesInSphere();
    void fillHolesLeavesClosedSurfaceAlone();
    void fillHolesRefusesBrokenSurface();
    void orientOutwardFlipsInsideOut();
    void orientOutwardIgnoresBadIndices();
};

void TestCheckSurface::detectsProblems_data() {
    QTest::addColumn<QString>("name");
    QTest::addColumn<int>("nonFinite");
    QTest::addColumn<int>("badIndex");
    QTest::addColumn<int>("degenerate");
    QTest::addColumn<int>("border");
    QTest::addColumn<int>("nonManifoldEdges");
    QTest::addColumn<int>("nonManifoldVertices");
    QTest::addColumn<int>("orientation");
    QTest::addColumn<bool>("selfIntersecting");
    QTest::addColumn<QString>("message"); // the exact sentence, empty if fit for meshing

    auto row = [](const char* name, int nf, int bi, int dg, int be, int nme, int nmv, int oe,
                  bool si, const char* message) {
        QTest::newRow(name) << QString(name) << nf << bi << dg << be << nme << nmv << oe << si
                            << QString(message);
    };
    row("tetrahedron", 0, 0, 0, 0, 0, 0, 0, false, "");
    row("box", 0, 0, 0, 0, 0, 0, 0, false, "");
    row("two disjoint boxes", 0, 0, 0, 0, 0, 0, 0, false, "");
    row("empty", 0, 0, 0, 0, 0, 0, 0, false, "surface has no triangles");
    row("vertices only", 0, 0, 0, 0, 0, 0, 0, false, "surface has no triangles");
    row("open box (top missing)", 0, 0, 0, 4, 0, 0, 0, false,
        "open surface: 4 border edges (try --repair to fill holes)");
    row("three triangles on an edge", 0, 0, 0, 2, 1, 0, 0, false,
        "non-manifold surface: 1 edge shared by more than two triangles");
    row("two tetrahedra touching at a vertex", 0, 0, 0, 0, 0, 1, 0, false,
        "non-manifold surface: 1 vertex joins separate sheets of triangles (surfaces "
        "touching at a point)");
    row("one flipped triangle", 0, 0, 0, 0, 0, 0, 3, false,
        "inconsistent triangle orientation: 3 edges are traversed in the same direction by "
        "both of its triangles");
    row("NaN vertex", 1, 0, 0, 0, 0, 0, 0, false,
        "1 vertex has non-finite coordinates (NaN or infinite)");
    row("infinite vertices", 2, 0, 0, 0, 0, 0, 0, false,
        "2 vertices have non-finite coordinates (NaN or infinite)");
    // The three bad triangles are left out of the edge counts, and the tetrahedron's
    // edges stay closed.
    row("bad indices", 0, 3, 0, 0, 0, 0, 0, false,
        "3 triangles have an out-of-range or repeated vertex index");
    // CGAL reports a degenerate face as intersecting itself.
    row("zero-area triangle", 0, 0, 1, 0, 0, 0, 0, true,
        "degenerate surface: 1 triangle has zero area (collinear corners)");
    row("two interpenetrating boxes", 0, 0, 0, 0, 0, 0, 0, true,
        "self-intersecting surface: some triangles cross each other");
    // Inside out is fit for meshing (ray parity); orientOutward() turns it around.
    row("inside out", 0, 0, 0, 0, 0, 0, 0, false, "");
}

void TestCheckSurface::detectsProblems() {
    QFETCH(QString, name);
    QFETCH(int, nonFinite);
    QFETCH(int, badIndex);
    QFETCH(int, degenerate);
    QFETCH(int, border);
    QFETCH(int, nonManifoldEdges);
    QFETCH(int, nonManifoldVertices);
    QFETCH(int, orientation);
    QFETCH(bool, selfIntersecting);
    QFETCH(QString, message);

    const TriangleSurface s = surfaceByName(name);
    const SurfaceCheck c = checkSurface(s);
    QCOMPARE(c.vertices, s.vertexCount());
    QCOMPARE(c.triangles, s.triangleCount());
    QCOMPARE(c.nonFiniteVertices, nonFinite);
    QCOMPARE(c.badIndexTriangles, badIndex);
    QCOMPARE(c.degenerateTriangles, degenerate);
    QCOMPARE(c.borderEdges, border);
    QCOMPARE(c.nonManifoldEdges, nonManifoldEdges);
    QCOMPARE(c.nonManifoldVertices, nonManifoldVertices);
    QCOMPARE(c.orientationErrors, orientation);
    QCOMPARE(c.selfIntersecting, selfIntersecting);
    const Status status = surfaceProblem(c);
    QCOMPARE(QString::fromStdString(status.message()), message);
    QCOMPARE(status.ok(), message.isEmpty());
}

void TestCheckSurface::selfIntersectionTestCanBeSkipped() {
    const TriangleSurface s = surfaceByName("two interpenetrating boxes");
    SurfaceCheckOptions options;
    options.testSelfIntersection = false;
    const SurfaceCheck c = checkSurface(s, options);
    QVERIFY(!c.selfIntersecting);
    QVERIFY(surfaceProblem(c).ok());
    // The enclosed volume is computed in either case: 8 + 8 for two 2x2x2 boxes.
    QVERIFY(std::abs(c.enclosedVolume - 16.0) < 1e-12);
}

void TestCheckSurface::flatPillowEnclosesNoVolume() {
    // One triangle seen from both sides: closed, manifold, consistently oriented, but flat.
    TriangleSurface s;
    s.positions = {Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0)};
    s.triangles = {{0, 1, 2}, {0, 2, 1}};
    SurfaceCheckOptions noSelfIntersection;
    noSelfIntersection.testSelfIntersection = false;
    const SurfaceCheck c = checkSurface(s, noSelfIntersection);
    QCOMPARE(c.borderEdges, 0);
    QCOMPARE(c.orientationErrors, 0);
    QCOMPARE(c.nonManifoldVertices, 0);
    QCOMPARE(c.enclosedVolume, 0.0);
    QCOMPARE(surfaceProblem(c).message(), std::string("surface encloses no volume"));
    // With the exact test, the two coincident triangles are found to overlap.
    QVERIFY(!surfaceProblem(checkSurface(s)).ok());
}

void TestCheckSurface::countsDisjointBorderAndOrientation() {
    // Two open boxes and one flipped tetrahedron triangle: counts add up over components,
    // and the first problem in order (orientation before open) is named.
    TriangleSurface s =
        merged(surfaceByName("open box (top missing)"), surfaceByName("open box (top missing)"));
    s = merged(s, surfaceByName("one flipped triangle"));
    const SurfaceCheck c = checkSurface(s);
    QCOMPARE(c.borderEdges, 8);
    QCOMPARE(c.orientationErrors, 3);
    QVERIFY(QString::fromStdString(surfaceProblem(c).message())
                .startsWith("inconsistent triangle orientation: 3 edges"));
}

void TestCheckSurface::fillHolesClosesOpenBox() {
    TriangleSurface s = surfaceByName("open box (top missing)");
    s.uvs.assign(s.positions.size(), Eigen::Vector2d(0.5, 0.25));
    int filled = -1;
    const Status status = fillHoles(s, &filled);
    QVERIFY2(status.ok(), status.message().c_str());
    QCOMPARE(filled, 1);
    const SurfaceCheck c = checkSurface(s);
    const Status problem = surfaceProblem(c);
    QVERIFY2(problem.ok(), problem.message().c_str());
    QCOMPARE(c.borderEdges, 0);
    // The original eight corners keep their indices and positions.
    const TriangleSurface box = literalBox();
    for (int k = 0; k < 8; ++k)
        QCOMPARE(s.positions[k], box.positions[k]);
    // The patch spans the missing 2 x 1 top; fairing may bow it a little.
    QVERIFY2(std::abs(c.enclosedVolume - 2.0) < 0.3, qPrintable(QString::number(c.enclosedVolume)));
    QCOMPARE(s.uvs.size(), s.positions.size());
    for (const Eigen::Vector2d& uv : s.uvs)
        QCOMPARE(uv, Eigen::Vector2d(0.5, 0.25));
}

void TestCheckSurface::fillHolesClosesHolesInSphere() {
    // A sphere with two caps cut away (the pole fans): two holes, filled smoothly.
    const TriangleSurface sphere = makeEllipsoid(Vec3(1.0, 1.0, 1.0), 16, 24);
    TriangleSurface s = sphere;
    const int top = s.vertexCount() - 1;
    std::erase_if(s.triangles, [&](const Tri& t) {
        for (int i : t)
            if (i == 0 || i == top)
                return true;
        return false;
    });
    QCOMPARE(checkSurface(s).borderEdges, 48);
    int filled = 0;
    const Status status = fillHoles(s, &filled);
    QVERIFY2(status.ok(), status.message().c_str());
    QCOMPARE(filled, 2);
    const SurfaceCheck c = checkSurface(s);
    const Status problem = surfaceProblem(c);
    QVERIFY2(problem.ok(), problem.message().c_str());
    const double v = enclosedVolume(sphere);
    QVERIFY2(std::abs(c.enclosedVolume - v) < 0.02 * v,
             qPrintable(QString("%1 vs %2").arg(c.enclosedVolume).arg(v)));
    QCOMPARE(s.uvs.size(), s.positions.size());
}

void TestCheckSurface::fillHolesLeavesClosedSurfaceAlone() {
    TriangleSurface s = literalBox();
    const TriangleSurface before = s;
    int filled = -1;
    QVERIFY(fillHoles(s, &filled).ok());
    QCOMPARE(filled, 0);
    QVERIFY(s.positions == before.positions);
    QVERIFY(s.triangles == before.triangles);
}

void TestCheckSurface::fillHolesRefusesBrokenSurface() {
    for (const char* name : {"three triangles on an edge", "NaN vertex", "bad indices"}) {
        TriangleSurface s = surfaceByName(name);
        // Give the closed NaN and bad-index tetrahedra a hole too, so that there is
        // something to fill (the fin already has two border edges).
        if (QString(name) != "three triangles on an edge")
            s.triangles.erase(s.triangles.begin());
        QVERIFY(checkSurface(s).borderEdges > 0);
        const TriangleSurface before = s;
        const Status status = fillHoles(s);
        QVERIFY2(!status.ok(), name);
        QVERIFY2(QString::fromStdString(status.message()).startsWith("cannot fill holes: "),
                 status.message().c_str());
        QVERIFY(s.triangles == before.triangles); // untouched on failure
    }
}

void TestCheckSurface::orientOutwardFlipsInsideOut() {
    TriangleSurface s = surfaceByName("inside out");
    QVERIFY(checkSurface(s).enclosedVolume < 0);
    orientOutward(s);
    QVERIFY(std::abs(enclosedVolume(s) - 2.0) < 1e-12);
    QVERIFY(surfaceProblem(checkSurface(s)).ok());
    QVERIFY(checkSurface(s).enclosedVolume > 0.0);
    // Already outward: unchanged.
    const TriangleSurface before = s;
    orientOutward(s);
    QVERIFY(s.triangles == before.triangles);
}

void TestCheckSurface::orientOutwardIgnoresBadIndices() {
    TriangleSurface s = surfaceByName("bad indices");
    const TriangleSurface before = s;
    orientOutward(s); // must not read out of range
    QVERIFY(s.triangles == before.triangles);
}

QTEST_GUILESS_MAIN(TestCheckSurface)
#include "test_check_surface.moc"
