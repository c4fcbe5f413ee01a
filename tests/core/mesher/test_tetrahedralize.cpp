// Tests of core/mesher/tetrahedralize: valid, positively oriented coarse tet meshes of the
// samples and of procedural shapes, with the surface's volume and a tet count of the
// paper's kind; reproducible from the seed; clear errors for unfit surfaces and absurd
// options.

#include "core/mesh/quality.h"
#include "core/mesh/validity.h"
#include "core/mesher/check_surface.h"
#include "core/mesher/procedural_surfaces.h"
#include "core/mesher/samples.h"
#include "core/mesher/tetrahedralize.h"

#include <QtTest>

#include <atomic>
#include <chrono>
#include <cmath>
#include <limits>
#include <thread>

using namespace resect;

namespace {

TriangleSurface surfaceByName(const QString& name) {
    if (name == "polyp")
        return sampleSurface(Sample::Polyp, 0.1);
    if (name == "myoma")
        return sampleSurface(Sample::Myoma, 0.1);
    if (name == "torus")
        return makeTorus(8.0, 3.0, 64, 32);
    if (name == "thin ellipsoid")
        return makeEllipsoid(Vec3(10.0, 10.0, 1.5), 32, 64);
    if (name == "box")
        return makeBox(Vec3(-5.0, 0.0, 1.0), Vec3(15.0, 10.0, 6.0));
    if (name == "small sphere") // millimetre-sized: the default adapts to the scale
        return makeEllipsoid(Vec3(0.01, 0.01, 0.01), 16, 32);
    return {};
}

QString describe(const Status& s) {
    return QString::fromStdString(s.message());
}

/// Asserts the mesh contract of tetrahedralize() (see tetrahedralize.h).
void verifyMeshContract(const TetMesh& mesh) {
    QVERIFY(!mesh.empty());
    const std::vector<MeshProblem> problems = checkValidity(mesh);
    QVERIFY2(problems.empty(),
             problems.empty() ? "" : problems.front().message.c_str()); // incl. unused nodes
    for (int t = 0; t < mesh.tetCount(); ++t)
        QVERIFY(mesh.referenceVolume(t) > 0.0);
    for (int n = 0; n < mesh.nodeCount(); ++n) {
        QCOMPARE(mesh.pos(n), mesh.ref(n));
        QCOMPARE(mesh.masses()[n], 0.0);
        QVERIFY(mesh.ref(n).allFinite());
    }
}

} // namespace

class TestTetrahedralize : public QObject {
    Q_OBJECT

private slots:
    void meshesShapes_data();
    void meshesShapes();
    void deterministic();
    void seedChangesMeshButNotValidity();
    void smallerEdgeLengthGivesMoreTets();
    void zeroEdgeLengthMeansDefault();
    void defaultEdgeLengthScalesWithSize();
    void rejectsUnfitSurfaces_data();
    void rejectsUnfitSurfaces();
    void meshesInsideOutSurface();
    void rejectsBadEdgeLengths_data();
    void rejectsBadEdgeLengths();
    void rejectsBadCriteria();
    void volumeGuard();
    void cancelBeforeStart();
    void cancelDuringRefinement();
};

void TestTetrahedralize::meshesShapes_data() {
    QTest::addColumn<QString>("name");
    QTest::addColumn<double>("maxVolumeError"); // relative to the surface's volume
    QTest::addColumn<int>("minTets");
    QTest::addColumn<int>("maxTets");
    // Coarse meshes of the paper's kind (its polyp had 136 tets, its myoma 277); ours
    // have a few hundred to a few thousand. The boundary is inscribed in curved surfaces
    // (volume a few percent low); the box's sharp edges are kept, so its volume is exact.
    QTest::newRow("polyp") << "polyp" << 0.06 << 300 << 3000;
    QTest::newRow("myoma") << "myoma" << 0.06 << 300 << 3000;
    QTest::newRow("torus") << "torus" << 0.06 << 300 << 3000;
    QTest::newRow("thin ellipsoid") << "thin ellipsoid" << 0.04 << 300 << 5000;
    QTest::newRow("box") << "box" << 1e-9 << 300 << 3000;
    QTest::newRow("small sphere") << "small sphere" << 0.06 << 300 << 3000;
}

void TestTetrahedralize::meshesShapes() {
    QFETCH(QString, name);
    QFETCH(double, maxVolumeError);
    QFETCH(int, minTets);
    QFETCH(int, maxTets);
    const TriangleSurface surface = surfaceByName(name);
    TetMesh mesh;
    const Status status = tetrahedralize(surface, MeshingOptions{}, mesh);
    QVERIFY2(status.ok(), status.message().c_str());
    verifyMeshContract(mesh);

    const double surfaceVolume = enclosedVolume(surface);
    const double error = std::abs(mesh.totalReferenceVolume() - surfaceVolume) / surfaceVolume;
    QVERIFY2(error <= maxVolumeError, qPrintable(QString("volume error %1").arg(error)));
    QVERIFY2(mesh.tetCount() >= minTets && mesh.tetCount() <= maxTets,
             qPrintable(QString("%1 tets").arg(mesh.tetCount())));

    // Every node lies inside the surface's bounding box (up to rounding).
    const auto [lo, hi] = boundingBox(surface.positions);
    const double tol = 1e-9 * (hi - lo).norm();
    for (const Vec3& p : mesh.referencePositions())
        QVERIFY((p.array() >= lo.array() - tol).all() && (p.array() <= hi.array() + tol).all());

    // Sliver removal leaves no flat tets: radius ratio (1 for a regular tet) well above 0.
    const QualitySummary q = summarizeQuality(mesh);
    QVERIFY2(q.minRadiusRatio > 0.05, qPrintable(QString::number(q.minRadiusRatio)));
    QVERIFY2(q.meanRadiusRatio > 0.5, qPrintable(QString::number(q.meanRadiusRatio)));
    qInfo("%s: %d tets, %d nodes, volume error %.2f %%, min radius ratio %.3f, mean %.3f",
          qPrintable(name), mesh.tetCount(), mesh.nodeCount(), 100.0 * error, q.minRadiusRatio,
          q.meanRadiusRatio);
}

void TestTetrahedralize::deterministic() {
    const TriangleSurface surface = surfaceByName("myoma");
    MeshingOptions options;
    options.seed = 7;
    TetMesh a, b;
    QVERIFY(tetrahedralize(surface, options, a).ok());
    QVERIFY(tetrahedralize(surface, options, b).ok());
    QCOMPARE(a.nodeCount(), b.nodeCount());
    QCOMPARE(a.tetCount(), b.tetCount());
    QVERIFY(a.tets() == b.tets());
    for (int n = 0; n < a.nodeCount(); ++n)
        QCOMPARE(a.ref(n), b.ref(n));
}

void TestTetrahedralize::seedChangesMeshButNotValidity() {
    const TriangleSurface surface = surfaceByName("torus");
    for (unsigned seed : {1u, 2u, 3u}) {
        MeshingOptions options;
        options.seed = seed;
        TetMesh mesh;
        const Status status = tetrahedralize(surface, options, mesh);
        QVERIFY2(status.ok(), status.message().c_str());
        verifyMeshContract(mesh);
    }
}

void TestTetrahedralize::smallerEdgeLengthGivesMoreTets() {
    const TriangleSurface surface = surfaceByName("myoma");
    const double h = defaultEdgeLength(surface);
    MeshingOptions coarse, fine;
    coarse.edgeLength = 1.5 * h;
    fine.edgeLength = 0.75 * h;
    TetMesh a, b;
    QVERIFY(tetrahedralize(surface, coarse, a).ok());
    QVERIFY(tetrahedralize(surface, fine, b).ok());
    // Tet count grows like h^-3 (about 8x here); the volume error shrinks with h.
    QVERIFY2(b.tetCount() > 4 * a.tetCount(),
             qPrintable(QString("%1 vs %2").arg(a.tetCount()).arg(b.tetCount())));
    const double v = enclosedVolume(surface);
    QVERIFY(std::abs(b.totalReferenceVolume() - v) < std::abs(a.totalReferenceVolume() - v));
    QVERIFY(meanEdgeLength(b) < meanEdgeLength(a));
}

void TestTetrahedralize::zeroEdgeLengthMeansDefault() {
    const TriangleSurface surface = surfaceByName("box");
    MeshingOptions zero, explicitDefault;
    explicitDefault.edgeLength = defaultEdgeLength(surface);
    TetMesh a, b;
    QVERIFY(tetrahedralize(surface, zero, a).ok());
    QVERIFY(tetrahedralize(surface, explicitDefault, b).ok());
    QCOMPARE(a.tetCount(), b.tetCount());
    QVERIFY(a.tets() == b.tets());
}

void TestTetrahedralize::defaultEdgeLengthScalesWithSize() {
    const TriangleSurface unit = makeEllipsoid(Vec3(1.0, 1.0, 1.0), 8, 16);
    TriangleSurface big = unit;
    for (Vec3& p : big.positions)
        p = 1000.0 * p + Vec3(5e4, -3e4, 1e4);
    const double h = defaultEdgeLength(unit);
    QVERIFY(h > 0.0 && h < 1.0);
    QVERIFY(std::abs(defaultEdgeLength(big) - 1000.0 * h) < 1e-9 * 1000.0 * h + 1e-6);
    // Thin shapes get a few layers: at most a 2.5th of the smallest extent.
    const TriangleSurface thin = makeEllipsoid(Vec3(10.0, 10.0, 0.5), 16, 32);
    QVERIFY(defaultEdgeLength(thin) <= 1.0 / 2.5 + 1e-12);
    // Degenerate input still gives a positive length.
    QVERIFY(defaultEdgeLength(TriangleSurface{}) > 0.0);
}

void TestTetrahedralize::rejectsUnfitSurfaces_data() {
    QTest::addColumn<int>("kind");
    QTest::addColumn<QString>("expected"); // start of the error message
    QTest::newRow("empty") << 0 << "surface has no triangles";
    QTest::newRow("open") << 1 << "open surface: 3 border edges";
    QTest::newRow("NaN") << 2 << "1 vertex has non-finite coordinates";
    QTest::newRow("non-manifold edge") << 3 << "non-manifold surface: 1 edge";
    QTest::newRow("self-intersecting") << 4 << "self-intersecting surface";
    QTest::newRow("non-manifold vertex") << 5 << "non-manifold surface: 1 vertex";
}

void TestTetrahedralize::rejectsUnfitSurfaces() {
    QFETCH(int, kind);
    QFETCH(QString, expected);
    const TriangleSurface box = makeBox(Vec3(0, 0, 0), Vec3(2, 2, 2));
    TriangleSurface s;
    switch (kind) {
    case 0:
        break;
    case 1: // one triangle missing: a triangular hole
        s = box;
        s.triangles.erase(s.triangles.begin());
        break;
    case 2:
        s = box;
        s.positions[5].x() = std::numeric_limits<double>::quiet_NaN();
        break;
    case 3:
        s = box;
        s.positions.emplace_back(-1.0, -1.0, -1.0);
        s.triangles.push_back({s.triangles[0][0], s.triangles[0][1], 8});
        break;
    case 4: {
        s = box;
        const TriangleSurface other = makeBox(Vec3(1, 1, 1), Vec3(3, 3, 3));
        for (const Vec3& p : other.positions)
            s.positions.push_back(p);
        for (Tri t : other.triangles) {
            for (int& i : t)
                i += 8;
            s.triangles.push_back(t);
        }
        break;
    }
    case 5: {
        // Two boxes sharing one corner: (2,2,2) of the first is (2,2,2) of the second.
        s = box;
        const TriangleSurface other = makeBox(Vec3(2, 2, 2), Vec3(4, 4, 4));
        for (int k = 1; k < 8; ++k)
            s.positions.push_back(other.positions[k]);
        for (Tri t : other.triangles) {
            for (int& i : t)
                i = (i == 0) ? 7 : i - 1 + 8;
            s.triangles.push_back(t);
        }
        break;
    }
    }
    TetMesh mesh = TetMesh::fromArrays({Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0), Vec3(0, 0, 1)},
                                       {Tet{0, 1, 2, 3}});
    const Status status = tetrahedralize(s, MeshingOptions{}, mesh);
    QVERIFY(!status.ok());
    QVERIFY2(describe(status).startsWith(expected), status.message().c_str());
    QVERIFY2(mesh.empty() && mesh.nodeCount() == 0, "the output is cleared on error");
    // The same sentence as surfaceProblem gives.
    QCOMPARE(status.message(), surfaceProblem(checkSurface(s)).message());
}

void TestTetrahedralize::meshesInsideOutSurface() {
    // Inside and outside come from ray parity: the reversed surface gives the same mesh.
    const TriangleSurface surface = surfaceByName("myoma");
    TriangleSurface reversed = surface;
    for (Tri& t : reversed.triangles)
        std::swap(t[1], t[2]);
    QVERIFY(enclosedVolume(reversed) < 0.0);
    TetMesh a, b;
    QVERIFY(tetrahedralize(surface, MeshingOptions{}, a).ok());
    const Status status = tetrahedralize(reversed, MeshingOptions{}, b);
    QVERIFY2(status.ok(), status.message().c_str());
    verifyMeshContract(b);
    QCOMPARE(b.tetCount(), a.tetCount());
    QVERIFY(std::abs(b.totalReferenceVolume() - a.totalReferenceVolume()) <
            1e-9 * a.totalReferenceVolume());
}

void TestTetrahedralize::rejectsBadEdgeLengths_data() {
    QTest::addColumn<double>("fractionOfBox"); // edge length over the box diagonal
    QTest::addColumn<QString>("expected");
    QTest::newRow("negative") << -0.1 << "--edge-length must be a positive finite number";
    QTest::newRow("NaN") << std::numeric_limits<double>::quiet_NaN()
                         << "--edge-length must be a positive finite number";
    QTest::newRow("infinite") << std::numeric_limits<double>::infinity()
                              << "--edge-length must be a positive finite number";
    QTest::newRow("1e-9 of the box") << 1e-9 << "--edge-length";
    QTest::newRow("1e-4 of the box") << 1e-4 << "--edge-length";
    QTest::newRow("smallest positive double")
        << std::numeric_limits<double>::denorm_min() << "--edge-length";
}

void TestTetrahedralize::rejectsBadEdgeLengths() {
    QFETCH(double, fractionOfBox);
    QFETCH(QString, expected);
    const TriangleSurface surface = surfaceByName("myoma");
    const auto [lo, hi] = boundingBox(surface.positions);
    MeshingOptions options;
    options.edgeLength = fractionOfBox * (hi - lo).norm();
    TetMesh mesh;
    const Status status = tetrahedralize(surface, options, mesh);
    QVERIFY(!status.ok());
    QVERIFY2(describe(status).startsWith(expected), status.message().c_str());
    if (std::isfinite(fractionOfBox) && fractionOfBox > 0.0)
        QVERIFY2(describe(status).contains("too small"), status.message().c_str());
    QVERIFY(mesh.empty());
}

void TestTetrahedralize::rejectsBadCriteria() {
    const TriangleSurface surface = surfaceByName("box");
    TetMesh mesh;
    MeshingOptions ratio;
    ratio.cellRadiusEdgeRatio = 1.5; // Mesh_3 need not terminate below 2
    Status status = tetrahedralize(surface, ratio, mesh);
    QVERIFY(!status.ok());
    QVERIFY2(describe(status).startsWith("cell radius-edge ratio must be at least 2"),
             status.message().c_str());
    MeshingOptions distance;
    distance.facetDistanceFraction = 0.0;
    status = tetrahedralize(surface, distance, mesh);
    QVERIFY(!status.ok());
    QVERIFY2(describe(status).startsWith("facet distance fraction"), status.message().c_str());
}

void TestTetrahedralize::volumeGuard() {
    // A very coarse edge length on a curved surface loses much of the volume: refused
    // with a hint, unless the caller accepts it.
    const TriangleSurface surface = surfaceByName("myoma");
    MeshingOptions strict;
    strict.maxVolumeError = 1e-4;
    TetMesh mesh;
    const Status status = tetrahedralize(surface, strict, mesh);
    QVERIFY(!status.ok());
    QVERIFY2(describe(status).startsWith("the tet mesh volume"), status.message().c_str());
    QVERIFY2(describe(status).contains("--edge-length"), status.message().c_str());
    QVERIFY(mesh.empty());
}

void TestTetrahedralize::cancelBeforeStart() {
    const std::atomic<bool> cancel{true};
    MeshingOptions options;
    options.cancel = &cancel;
    TetMesh mesh;
    const Status status = tetrahedralize(surfaceByName("myoma"), options, mesh);
    QVERIFY(!status.ok());
    QCOMPARE(status.message(), std::string("meshing cancelled"));
    QVERIFY(mesh.empty());
    // Not cancelled: the same call succeeds.
    const std::atomic<bool> go{false};
    options.cancel = &go;
    QVERIFY(tetrahedralize(surfaceByName("myoma"), options, mesh).ok());
}

void TestTetrahedralize::cancelDuringRefinement() {
    // A fine mesh (some 10^5 tets, many seconds) cancelled from another thread shortly
    // after it started: CGAL polls the flag during refinement and stops.
    const TriangleSurface surface = surfaceByName("myoma");
    std::atomic<bool> cancel{false};
    MeshingOptions options;
    options.edgeLength = defaultEdgeLength(surface) / 5.0;
    options.cancel = &cancel;
    TetMesh mesh;
    std::thread canceller([&cancel] {
        std::this_thread::sleep_for(std::chrono::milliseconds(50));
        cancel = true;
    });
    const Status status = tetrahedralize(surface, options, mesh);
    canceller.join();
    QCOMPARE(status.message(), std::string("meshing cancelled"));
    QVERIFY(mesh.empty());
}

QTEST_GUILESS_MAIN(TestTetrahedralize)
#include "test_tetrahedralize.moc"
