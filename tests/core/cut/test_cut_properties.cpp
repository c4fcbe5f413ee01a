// Property tests of the cut on many seeded random sweeps (planar, curved, multi-pose,
// complete and partial), every method, at scales 1e-3, 1 and 1e3: volume conserved, no
// inverted or flat tet, conforming topology, no edge crossing the sweep away from the cut
// surface, complete cuts leave exactly two pieces (the sweeps are height fields reaching
// past the body on every side), partial cuts leave one.
#include "cut_checks.h"

#include "core/mesh/box_mesh.h"
#include "core/mesh/quality.h"
#include "core/mesher/samples.h"
#include "core/mesher/tetrahedralize.h"

#include <QTest>

#include <algorithm>
#include <array>
#include <random>

using namespace resect;
using resect::testing::cutViolations;
using resect::testing::jitteredBox;

namespace {

enum class SweepKind { PlanarComplete, PlanarPartial, CurvedComplete, MultiPoseComplete, CurvedPartial };


/// A random sweep through the unit box scaled by `scale`: a height field over the (s, r)
/// plane of a random frame, so it never intersects itself.
SweepSurface randomSweep(SweepKind kind, double scale, std::mt19937& rng) {
    std::uniform_real_distribution<double> u01(0, 1), sym(-1, 1);
    Vec3 n(sym(rng), sym(rng), sym(rng));
    n.normalize();
    const Vec3 u = n.unitOrthogonal();
    const Vec3 w = n.cross(u);
    const Vec3 c = Vec3(0.5 + 0.2 * sym(rng), 0.5 + 0.2 * sym(rng), 0.5 + 0.2 * sym(rng)) * scale;
    const double R = 2.0 * scale;
    const bool partial = kind == SweepKind::PlanarPartial || kind == SweepKind::CurvedPartial;
    const int m = kind == SweepKind::MultiPoseComplete ? 6 : (kind == SweepKind::CurvedPartial ? 4 : 2);
    const int segments = kind == SweepKind::PlanarComplete || kind == SweepKind::PlanarPartial ? 3 : 12;
    const double bend = (kind == SweepKind::CurvedComplete || kind == SweepKind::CurvedPartial) ? 0.15 : 0.0;
    const double twist = kind == SweepKind::MultiPoseComplete ? 0.25 : 0.0;
    const double phase = 6.28 * u01(rng);
    std::vector<std::vector<Vec3>> curves(m);
    for (int i = 0; i < m; ++i) {
        const double r = -R + (partial ? R : 2 * R) * i / (m - 1);  // partial: stops at the centre
        for (int j = 0; j <= segments; ++j) {
            const double s = -R + 2 * R * j / segments;
            const double h = bend * scale * std::sin(3.0 * s / scale + phase) + twist * s * r / scale;
            curves[i].push_back(c + s * u + r * w + h * n);
        }
    }
    SweepSurface sweep;
    const Status st = SweepSurface::fromCurves(curves, sweep);
    if (!st.ok())
        qFatal("%s", st.message().c_str());
    return sweep;
}

} // namespace

Q_DECLARE_METATYPE(SweepKind)
Q_DECLARE_METATYPE(resect::CutMethod)
Q_DECLARE_METATYPE(resect::FaceTriangulation)

class TestCutProperties : public QObject {
    Q_OBJECT
private slots:
    void randomSweeps_data() {
        QTest::addColumn<double>("scale");
        QTest::addColumn<CutMethod>("method");
        QTest::addColumn<FaceTriangulation>("triangulation");
        QTest::addColumn<SweepKind>("kind");
        QTest::addColumn<double>("advantage");
        const std::pair<const char*, SweepKind> kinds[] = {
            {"planar", SweepKind::PlanarComplete},      {"planar partial", SweepKind::PlanarPartial},
            {"curved", SweepKind::CurvedComplete},      {"multi-pose", SweepKind::MultiPoseComplete},
            {"curved partial", SweepKind::CurvedPartial}};
        for (double scale : {1e-3, 1.0, 1e3})
            for (const auto& [kname, kind] : kinds) {
                QTest::addRow("%s, subdivision, %g", kname, scale)
                    << scale << CutMethod::Subdivision << FaceTriangulation::Standard << kind << 1.5;
                QTest::addRow("%s, hybrid standard, %g", kname, scale)
                    << scale << CutMethod::Hybrid << FaceTriangulation::Standard << kind << 1.5;
                QTest::addRow("%s, hybrid enhanced, %g", kname, scale)
                    << scale << CutMethod::Hybrid << FaceTriangulation::Enhanced << kind << 1.5;
                QTest::addRow("%s, hybrid plain symmetric, %g", kname, scale)
                    << scale << CutMethod::Hybrid << FaceTriangulation::Enhanced << kind << 0.0;
            }
    }
    void randomSweeps() {
        QFETCH(double, scale);
        QFETCH(CutMethod, method);
        QFETCH(FaceTriangulation, triangulation);
        QFETCH(SweepKind, kind);
        QFETCH(double, advantage);
        const bool partial = kind == SweepKind::PlanarPartial || kind == SweepKind::CurvedPartial;
        for (unsigned seed = 1; seed <= 8; ++seed) {
            TetMesh mesh = jitteredBox(scale, seed, 0.2 / 6);
            std::mt19937 rng(seed * 7919u + static_cast<unsigned>(kind));
            const SweepSurface sweep = randomSweep(kind, scale, rng);
            const double volume = mesh.totalReferenceVolume();
            HybridCutter cutter(mesh);
            CutOptions options;
            options.method = method;
            options.triangulation = triangulation;
            options.faceNodeAdvantage = advantage;
            CutResult result;
            const Status st = cutter.cut(sweep, options, result);
            QVERIFY2(st.ok(), qPrintable(QString("seed %1: %2").arg(seed).arg(st.message().c_str())));
            const QString v = cutViolations(mesh, sweep, volume, result);
            QVERIFY2(v.isEmpty(), qPrintable(QString("seed %1: %2").arg(seed).arg(v)));
            const int pieces = connectedComponents(mesh).count;
            QVERIFY2(pieces == (partial ? 1 : 2), qPrintable(QString("seed %1: %2 pieces").arg(seed).arg(pieces)));
            QVERIFY(result.stats.crossedEdges > 0);
            QVERIFY(summarizeQuality(mesh).minRadiusRatio > 0);
        }
    }

    void randomSweepsOnTheSamples_data() {
        QTest::addColumn<int>("sample");
        QTest::addColumn<double>("scale");
        for (int sample : {0, 1})
            for (double scale : {1e-3, 1.0, 1e3})
                QTest::addRow("%s, %g", sample ? "myoma" : "polyp", scale) << sample << scale;
    }
    void randomSweepsOnTheSamples() {
        // The meshed anatomy (CGAL), scaled, cut by random planar, curved and multi-pose
        // sweeps through its middle with every method.
        QFETCH(int, sample);
        QFETCH(double, scale);
        TriangleSurface surface = sampleSurface(sample ? Sample::Myoma : Sample::Polyp, 0.25);
        for (Vec3& p : surface.positions)
            p *= scale;
        TetMesh base;
        QVERIFY(tetrahedralize(surface, MeshingOptions{}, base).ok());
        const auto [lo, hi] = boundingBox(base.positions());
        const double size = (hi - lo).maxCoeff();
        for (unsigned seed = 1; seed <= 6; ++seed) {
            std::mt19937 rng(seed);
            const SweepKind kind = seed % 3 == 0 ? SweepKind::MultiPoseComplete
                                                 : (seed % 3 == 1 ? SweepKind::PlanarComplete : SweepKind::CurvedComplete);
            // randomSweep works in the unit box: map it onto the mesh's bounding box.
            SweepSurface unit = randomSweep(kind, 1.0, rng);
            std::vector<std::vector<Vec3>> curves = unit.curves();
            for (auto& c : curves)
                for (Vec3& p : c)
                    p = lo + p * size;
            SweepSurface sweep;
            QVERIFY(SweepSurface::fromCurves(curves, sweep).ok());
            for (CutMethod method : {CutMethod::Subdivision, CutMethod::Hybrid}) {
                TetMesh mesh = base;
                const double volume = mesh.totalReferenceVolume();
                HybridCutter cutter(mesh);
                CutOptions options;
                options.method = method;
                options.triangulation = method == CutMethod::Hybrid ? FaceTriangulation::Enhanced : FaceTriangulation::Standard;
                CutResult result;
                const Status st = cutter.cut(sweep, options, result);
                QVERIFY2(st.ok(), st.message().c_str());
                const QString v = cutViolations(mesh, sweep, volume, result);
                QVERIFY2(v.isEmpty(), qPrintable(QString("seed %1: %2").arg(seed).arg(v)));
                // Every sweep passes through the middle of the body and reaches past its
                // bounding box: a complete cut, in two pieces, by every method.
                QVERIFY(result.stats.crossedEdges > 0);
                const int pieces = connectedComponents(mesh).count;
                QVERIFY2(pieces == 2, qPrintable(QString("seed %1: %2 pieces").arg(seed).arg(pieces)));
            }
        }
    }

    void repeatedIntersectingCuts() {
        // Ten scoops through the same region, one after another, with every method.
        for (CutMethod method : {CutMethod::Hybrid, CutMethod::Subdivision}) {
            TetMesh mesh = jitteredBox(1.0, 99, 0.2 / 6);
            const double volume = mesh.totalReferenceVolume();
            HybridCutter cutter(mesh);
            std::mt19937 rng(12345);
            for (int k = 0; k < 10; ++k) {
                const SweepSurface sweep = randomSweep(k % 2 ? SweepKind::CurvedComplete : SweepKind::PlanarComplete, 1.0, rng);
                CutOptions options;
                options.method = method;
                options.triangulation = method == CutMethod::Hybrid ? FaceTriangulation::Enhanced : FaceTriangulation::Standard;
                CutResult result;
                const Status st = cutter.cut(sweep, options, result);
                QVERIFY2(st.ok(), qPrintable(QString("cut %1: %2").arg(k).arg(st.message().c_str())));
                const QString v = cutViolations(mesh, sweep, volume, result);
                QVERIFY2(v.isEmpty(), qPrintable(QString("cut %1: %2").arg(k).arg(v)));
            }
            QVERIFY(connectedComponents(mesh).count >= 3);
        }
    }

    void changeListDescribesTheEdit() {
        TetMesh mesh = jitteredBox(1.0, 5, 0.2 / 6);
        const int nodes = mesh.nodeCount(), tets = mesh.tetCount();
        const std::vector<Tet> before = mesh.tets();
        HybridCutter cutter(mesh);
        std::mt19937 rng(77);
        const SweepSurface sweep = randomSweep(SweepKind::PlanarComplete, 1.0, rng);
        CutResult r;
        QVERIFY(cutter.cut(sweep, CutOptions{}, r).ok());
        const CutChanges& c = r.changes;
        QCOMPARE(c.firstNewNode, nodes);
        QCOMPARE(c.firstNewTet, tets);
        QCOMPARE(int(c.parentOfNewTet.size()), mesh.tetCount() - tets);
        // Every old tet that changed is listed; no unchanged one is.
        std::vector<int> changed;
        for (int t = 0; t < tets; ++t)
            if (mesh.tet(t) != before[t])
                changed.push_back(t);
        QCOMPARE(c.modifiedTets, changed);
        for (const auto& [orig, copy] : c.duplicatedNodes) {
            QVERIFY(copy >= nodes);
            QVERIFY((mesh.ref(orig) - mesh.ref(copy)).norm() == 0);
        }
        // The per-tet schemes agree with the scheme counts, and every decomposed tet and every
        // parent of a new tet has one.
        std::array<int, 10> counted{};
        for (const auto& [t, scheme] : c.tetScheme) {
            QVERIFY(t >= 0 && t < tets);
            QCOMPARE(c.schemeOf(t), scheme);
            ++counted[static_cast<int>(scheme)];
        }
        QVERIFY(counted == r.stats.schemeCount);
        QVERIFY(std::is_sorted(c.tetScheme.begin(), c.tetScheme.end()));
        for (int parent : c.parentOfNewTet)
            QVERIFY(c.schemeOf(parent) != Scheme::None);
        QCOMPARE(c.schemeOf(-1), Scheme::None);
        // The counts agree with the change list and the mesh.
        QCOMPARE(r.stats.addedTets, mesh.tetCount() - tets);
        QCOMPARE(r.stats.addedNodes, mesh.nodeCount() - nodes);
        QCOMPARE(r.stats.duplicatedNodes, int(c.duplicatedNodes.size()));
        QCOMPARE(r.stats.cutNodes, int(c.cutNodes.size()));
        QVERIFY(r.stats.cutNodes + r.stats.cutEdges > 0);
        // The stages are timed one after another inside the total.
        const auto& ms = r.stats.timeMs;
        QVERIFY(ms.total > 0);
        QVERIFY2(ms.total >= ms.intersect + ms.select + ms.decompose + ms.snap + ms.relax + ms.update,
                 qPrintable(QString("total %1 ms < sum of the stages").arg(ms.total)));
    }
};

QTEST_GUILESS_MAIN(TestCutProperties)
#include "test_cut_properties.moc"
