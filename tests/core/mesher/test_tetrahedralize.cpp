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
    void qualityIsEnforcedByRetrying();
    void impossibleQualityIsAnError();
    void rejectsBadQualityOptions();
    void featuresAreProtectedOnlyWhenAsked();
    void volumeMatchingMovesBoundaryNodesALittle();
    void progressNamesEveryStage();
    void lowerBoundDoesNotLoosenThePasses();
};

void TestTetrahedralize::meshesShapes_data() {
    QTest::addColumn<QString>("name");
    QTest::addColumn<double>("maxVolumeError"); // relative to the surface's volume
    QTest::addColumn<int>("minTets");
    QTest::addColumn<int>("maxTets");
    // Coarse meshes of the paper's kind (its polyp had 136 tets, its myoma 277); ours
    // have a few hundred to a few thousand. Volume matching gives the surface's volume.
    QTest::newRow("polyp") << "polyp" << 1e-9 << 300 << 3000;
    QTest::newRow("myoma") << "myoma" << 1e-9 << 300 << 3000;
    QTest::newRow("torus") << "torus" << 1e-9 << 300 << 3000;
    QTest::newRow("thin ellipsoid") << "thin ellipsoid" << 1e-9 << 300 << 5000;
    QTest::newRow("box") << "box" << 1e-9 << 300 << 3000;
    QTest::newRow("small sphere") << "small sphere" << 1e-9 << 300 << 3000;
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

    // Every node lies inside the surface's bounding box, up to how far volume matching may
    // move a boundary node out (within the facet distance, 0.1 h).
    const auto [lo, hi] = boundingBox(surface.positions);
    const double tol = 0.1 * defaultEdgeLength(surface);
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
    MeshingReport ra, rb;
    QVERIFY(tetrahedralize(surface, coarse, a, &ra).ok());
    QVERIFY(tetrahedralize(surface, fine, b, &rb).ok());
    // Tet count grows like h^-3 (about 8x here); the inscribed boundary's volume error
    // shrinks with h, and volume matching removes it at both.
    QVERIFY2(b.tetCount() > 4 * a.tetCount(),
             qPrintable(QString("%1 vs %2").arg(a.tetCount()).arg(b.tetCount())));
    const double v = enclosedVolume(surface);
    QVERIFY(std::abs(rb.inscribedVolume - v) < std::abs(ra.inscribedVolume - v));
    QVERIFY(std::abs(a.totalReferenceVolume() - v) <= 1e-9 * v);
    QVERIFY(std::abs(b.totalReferenceVolume() - v) <= 1e-9 * v);
    QCOMPARE(ra.volume, a.totalReferenceVolume());
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
    // Without volume matching, the inscribed boundary of a coarse mesh of a curved surface
    // loses a few percent of the volume: refused with a hint, unless the caller accepts it.
    const TriangleSurface surface = surfaceByName("myoma");
    MeshingOptions strict;
    strict.matchVolume = false;
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

void TestTetrahedralize::qualityIsEnforcedByRetrying() {
    // Two consecutive seeds whose meshes differ in their worst angle; asking for an angle
    // between them must re-mesh with the second seed and report so.
    const TriangleSurface surface = surfaceByName("polyp");
    const auto worstAt = [&](unsigned seed) {
        MeshingOptions o;
        o.seed = seed;
        o.attempts = 1;
        o.minDihedralDeg = 0;
        TetMesh m;
        MeshingReport r;
        if (!tetrahedralize(surface, o, m, &r).ok())
            return -1.0;
        return r.minDihedralDeg;
    };
    for (unsigned seed = 0; seed < 6; ++seed) {
        const double a = worstAt(seed), b = worstAt(seed + 1);
        QVERIFY(a > 0 && b > 0);
        if (!(b > a + 0.01))
            continue;
        MeshingOptions o;
        o.seed = seed;
        o.minDihedralDeg = 0.5 * (a + b);
        TetMesh mesh, direct;
        MeshingReport report;
        const Status s = tetrahedralize(surface, o, mesh, &report);
        QVERIFY2(s.ok(), s.message().c_str());
        QCOMPARE(report.attempts, 2);
        QCOMPARE(report.seed, seed + 1);
        QCOMPARE(report.minDihedralDeg, b);
        // The accepted mesh is the next seed's own mesh.
        MeshingOptions next;
        next.seed = seed + 1;
        next.minDihedralDeg = 0;
        QVERIFY(tetrahedralize(surface, next, direct).ok());
        QCOMPARE(mesh.tetCount(), direct.tetCount());
        for (int n = 0; n < mesh.nodeCount(); ++n)
            QCOMPARE(mesh.ref(n), direct.ref(n));
        verifyMeshContract(mesh);
        return;
    }
    QFAIL("no two consecutive seeds of 0..6 gave different worst angles");
}

void TestTetrahedralize::impossibleQualityIsAnError() {
    MeshingOptions o;
    o.minDihedralDeg = 30; // no Delaunay mesher reaches this on a curved body
    TetMesh mesh;
    MeshingReport report;
    const Status s = tetrahedralize(surfaceByName("myoma"), o, mesh, &report);
    QVERIFY(!s.ok());
    QVERIFY2(describe(s).startsWith("no mesh reached the smallest dihedral angle of 30 degrees in 4 attempts"),
             s.message().c_str());
    QVERIFY2(describe(s).contains("--min-dihedral"), s.message().c_str());
    QVERIFY(mesh.empty());
    QCOMPARE(report.attempts, 4);
    QVERIFY(report.minDihedralDeg > 10.0 && report.minDihedralDeg < 30.0);
}

void TestTetrahedralize::rejectsBadQualityOptions() {
    const TriangleSurface surface = surfaceByName("box");
    TetMesh mesh;
    for (const double angle : {-1.0, 36.0, std::numeric_limits<double>::quiet_NaN()}) {
        MeshingOptions o;
        o.minDihedralDeg = angle;
        const Status s = tetrahedralize(surface, o, mesh);
        QVERIFY(!s.ok());
        QVERIFY2(describe(s).startsWith("--min-dihedral must be between 0 and 35 degrees"), s.message().c_str());
    }
    for (const double angle : {0.0, 180.0, std::numeric_limits<double>::infinity()}) {
        MeshingOptions o;
        o.protectFeatures = true;
        o.featureAngleDeg = angle;
        const Status s = tetrahedralize(surface, o, mesh);
        QVERIFY(!s.ok());
        QVERIFY2(describe(s).startsWith("--feature-angle must be between 0 and 180 degrees"), s.message().c_str());
    }
    QVERIFY(mesh.empty());
}

void TestTetrahedralize::featuresAreProtectedOnlyWhenAsked() {
    // A box is CAD-like input: with protection its 12 edges are kept (every corner is a
    // node); without, they are not protected, and the noisy scan case (tests of the
    // corpus) is what the default is for.
    const TriangleSurface surface = surfaceByName("box");
    const auto [lo, hi] = boundingBox(surface.positions);
    const auto cornersPresent = [&](const TetMesh& mesh) {
        int found = 0;
        for (int c = 0; c < 8; ++c) {
            const Vec3 corner((c & 1) ? hi.x() : lo.x(), (c & 2) ? hi.y() : lo.y(), (c & 4) ? hi.z() : lo.z());
            for (const Vec3& p : mesh.referencePositions())
                if ((p - corner).norm() <= 1e-9 * (hi - lo).norm()) {
                    ++found;
                    break;
                }
        }
        return found;
    };
    MeshingOptions keep;
    keep.protectFeatures = true;
    TetMesh sharp, plain;
    MeshingReport rs, rp;
    QVERIFY(tetrahedralize(surface, keep, sharp, &rs).ok());
    QVERIFY(tetrahedralize(surface, MeshingOptions{}, plain, &rp).ok());
    verifyMeshContract(sharp);
    QVERIFY2(rs.featureEdges >= 12, qPrintable(QString::number(rs.featureEdges)));
    QCOMPARE(rp.featureEdges, 0);
    QCOMPARE(cornersPresent(sharp), 8);
    QVERIFY(rs.minDihedralDeg >= 10.0);
    QVERIFY(std::abs(sharp.totalReferenceVolume() - enclosedVolume(surface)) <= 1e-9 * enclosedVolume(surface));
}

void TestTetrahedralize::volumeMatchingMovesBoundaryNodesALittle() {
    // A sphere of radius 5 (a fine triangulation of it): the inscribed mesh loses a few
    // percent; matching restores the volume by moving boundary nodes outward by a fraction
    // of the facet distance, and no angle drops below the bound.
    const double radius = 5.0;
    const TriangleSurface surface = makeEllipsoid(Vec3::Constant(radius), 64, 128);
    const double v = enclosedVolume(surface);
    MeshingOptions inscribedOptions;
    inscribedOptions.matchVolume = false;
    TetMesh inscribed, matched;
    MeshingReport ri, rm;
    QVERIFY(tetrahedralize(surface, inscribedOptions, inscribed, &ri).ok());
    QVERIFY(tetrahedralize(surface, MeshingOptions{}, matched, &rm).ok());
    verifyMeshContract(matched);
    QVERIFY2(inscribed.totalReferenceVolume() < 0.99 * v, qPrintable(QString::number(inscribed.totalReferenceVolume() / v)));
    QCOMPARE(ri.volume, inscribed.totalReferenceVolume());
    QVERIFY(std::abs(matched.totalReferenceVolume() - v) <= 1e-9 * v);
    QCOMPARE(rm.inscribedVolume, inscribed.totalReferenceVolume());
    QVERIFY(rm.maxBoundaryOffset > 0.0);
    QVERIFY(rm.maxBoundaryOffset <= 0.1 * rm.edgeLength);
    QVERIFY(rm.minDihedralDeg >= 10.0);
    // Same nodes and tets; interior nodes unmoved, boundary nodes within the facet distance
    // of the sphere, now on both sides of it.
    QCOMPARE(matched.tetCount(), inscribed.tetCount());
    QCOMPARE(matched.nodeCount(), inscribed.nodeCount());
    for (int t = 0; t < matched.tetCount(); ++t)
        QCOMPARE(matched.tet(t), inscribed.tet(t));
    int outside = 0, moved = 0;
    for (int n = 0; n < matched.nodeCount(); ++n) {
        const double r = matched.ref(n).norm();
        if (matched.ref(n) != inscribed.ref(n)) {
            ++moved;
            QVERIFY2(std::abs(r - radius) <= 0.1 * rm.edgeLength, qPrintable(QString::number(r)));
            outside += r > radius ? 1 : 0;
        }
    }
    QVERIFY(moved > 0);
    QVERIFY(outside > moved / 2);
}

void TestTetrahedralize::progressNamesEveryStage() {
    std::vector<MeshingProgress> seen;
    MeshingOptions o;
    o.progress = [&seen](const MeshingProgress& p) { seen.push_back(p); };
    TetMesh mesh;
    QVERIFY(tetrahedralize(surfaceByName("myoma"), o, mesh).ok());
    const std::vector<MeshingStage> expected{MeshingStage::CheckingSurface, MeshingStage::Refining,
                                             MeshingStage::Perturbing,      MeshingStage::Exuding,
                                             MeshingStage::MatchingVolume,  MeshingStage::CheckingQuality};
    QCOMPARE(seen.size(), expected.size());
    for (std::size_t i = 0; i < seen.size(); ++i) {
        QCOMPARE(int(seen[i].stage), int(expected[i]));
        QCOMPARE(seen[i].attempt, 1);
        QCOMPARE(seen[i].attempts, 4);
        QVERIFY(seen[i].fraction >= 0.0 && seen[i].fraction < 1.0);
        if (i > 0)
            QVERIFY(seen[i].fraction >= seen[i - 1].fraction);
    }
    QVERIFY(seen.back().fraction > 0.5);
}

void TestTetrahedralize::lowerBoundDoesNotLoosenThePasses() {
    // --min-dihedral 0 accepts any mesh from CGAL, but the collapse and volume-matching
    // passes still protect the default bound: where the default's first attempt passes, the
    // two meshes are the same.
    const TriangleSurface surface = surfaceByName("torus");
    MeshingOptions any;
    any.minDihedralDeg = 0;
    TetMesh a, b;
    MeshingReport ra, rb;
    QVERIFY(tetrahedralize(surface, MeshingOptions{}, a, &ra).ok());
    QVERIFY(tetrahedralize(surface, any, b, &rb).ok());
    QCOMPARE(ra.attempts, 1);
    QCOMPARE(b.tetCount(), a.tetCount());
    for (int n = 0; n < a.nodeCount(); ++n)
        QCOMPARE(b.ref(n), a.ref(n));
    QCOMPARE(rb.minDihedralDeg, ra.minDihedralDeg);
}

QTEST_GUILESS_MAIN(TestTetrahedralize)
#include "test_tetrahedralize.moc"
