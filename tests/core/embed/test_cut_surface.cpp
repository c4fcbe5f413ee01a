// Cutting the high-resolution surface and closing it (section 5): after any complete cut the
// surface is closed and manifold, splits into pieces whose volumes add up to the original,
// and every new vertex lies on the sweep; a partial cut keeps one closed component.
#include "core/embed/cut_surface.h"
#include "core/mesher/procedural_surfaces.h"
#include "core/mesher/samples.h"

#include <QTest>

#include <algorithm>
#include <map>
#include <numeric>

using namespace resect;
Q_DECLARE_METATYPE(resect::Vec3)

namespace {

/// Empty if every directed edge appears once and its reverse once (closed, oriented, manifold).
QString closedManifoldProblem(const TriangleSurface& s) {
    std::map<std::pair<int, int>, int> directed;
    for (const Tri& t : s.triangles)
        for (int e = 0; e < 3; ++e)
            ++directed[{t[e], t[(e + 1) % 3]}];
    for (const auto& [edge, count] : directed) {
        if (count != 1)
            return QString("edge %1-%2 used %3 times in one direction").arg(edge.first).arg(edge.second).arg(count);
        if (!directed.count({edge.second, edge.first}))
            return QString("edge %1-%2 has no opposite").arg(edge.first).arg(edge.second);
    }
    return {};
}

std::vector<TriangleSurface> components(const TriangleSurface& s) {
    std::vector<int> parent(s.vertexCount());
    std::iota(parent.begin(), parent.end(), 0);
    const auto find = [&](int x) {
        while (parent[x] != x)
            x = parent[x] = parent[parent[x]];
        return x;
    };
    for (const Tri& t : s.triangles) {
        parent[find(t[1])] = find(t[0]);
        parent[find(t[2])] = find(t[0]);
    }
    std::map<int, TriangleSurface> byRoot;
    for (const Tri& t : s.triangles) {
        TriangleSurface& c = byRoot[find(t[0])];
        c.positions = s.positions;  // enclosedVolume only reads the referenced vertices
        c.triangles.push_back(t);
    }
    std::vector<TriangleSurface> result;
    for (auto& [root, c] : byRoot)
        result.push_back(std::move(c));
    return result;
}

SweepSurface sweepFrom(const std::vector<std::vector<Vec3>>& curves) {
    SweepSurface s;
    const Status st = SweepSurface::fromCurves(curves, s);
    if (!st.ok())
        qFatal("%s", st.message().c_str());
    return s;
}

/// A sweep through the plane {p : (p - c) . n = 0}, optionally bent and with m poses; `reach`
/// is its half size along w (the direction the tool moves); partial: it stops at c.
SweepSurface planeSweep(const Vec3& c, const Vec3& normal, double size, double bend, int poses, bool partial) {
    const Vec3 n = normal.normalized(), u = n.unitOrthogonal(), w = n.cross(u);
    std::vector<std::vector<Vec3>> curves(poses);
    for (int i = 0; i < poses; ++i) {
        const double r = -size + (partial ? size : 2 * size) * i / (poses - 1);
        for (int j = 0; j <= 24; ++j) {
            const double s = -size + 2 * size * j / 24;
            curves[i].push_back(c + s * u + r * w + bend * size * std::sin(2.0 * s / size + 0.3 * r / size) * n);
        }
    }
    return sweepFrom(curves);
}

} // namespace

class TestCutSurface : public QObject {
    Q_OBJECT
private slots:
    void cutsCloseTheSurface_data() {
        QTest::addColumn<int>("shape");    // 0 polyp, 1 myoma, 2 torus
        QTest::addColumn<Vec3>("normal");
        QTest::addColumn<double>("bend");
        QTest::addColumn<int>("poses");
        QTest::addColumn<bool>("partial");
        QTest::addColumn<int>("minPieces");
        QTest::newRow("polyp, planar") << 0 << Vec3(0.1, 0.2, 1) << 0.0 << 2 << false << 2;
        QTest::newRow("myoma, curved") << 1 << Vec3(0.3, -0.2, 1) << 0.08 << 2 << false << 2;
        QTest::newRow("myoma, multi-pose") << 1 << Vec3(-0.2, 0.3, 1) << 0.05 << 6 << false << 2;
        QTest::newRow("torus across its axis: annulus caps") << 2 << Vec3(0.05, 0.02, 1) << 0.0 << 2 << false << 2;
        QTest::newRow("torus through its axis: two loops a side") << 2 << Vec3(1, 0.1, 0.05) << 0.0 << 2 << false << 2;
        QTest::newRow("myoma, partial") << 1 << Vec3(0.2, 0.1, 1) << 0.0 << 2 << true << 1;
        QTest::newRow("polyp, curved partial") << 0 << Vec3(0.1, 0.1, 1) << 0.05 << 4 << true << 1;
    }
    void cutsCloseTheSurface() {
        QFETCH(int, shape);
        QFETCH(Vec3, normal);
        QFETCH(double, bend);
        QFETCH(int, poses);
        QFETCH(bool, partial);
        QFETCH(int, minPieces);
        TriangleSurface s = shape == 2 ? makeTorus(10, 3, 96, 48)
                                       : sampleSurface(shape == 0 ? Sample::Polyp : Sample::Myoma, 0.25);
        const auto [lo, hi] = boundingBox(s.positions);
        const Vec3 centre = 0.5 * (lo + hi) + Vec3(0.013, 0.021, shape == 0 ? 0.2 * (hi.z() - lo.z()) : 0.017);
        const double size = (hi - lo).norm();
        const SweepSurface sweep = planeSweep(centre, normal, size, bend, poses, partial);
        const double volume = enclosedVolume(s);
        std::vector<Vec3> rest = s.positions;
        const std::vector<Tri> trianglesBefore = s.triangles;
        SurfaceCut cut;
        const Status st = cutSurface(s, &rest, sweep, cut);
        QVERIFY2(st.ok(), st.message().c_str());
        QVERIFY(cut.splitEdges > 0);
        QVERIFY(cut.capTriangles > 0);
        QCOMPARE(partial, cut.faceVertices > 0);
        const QString problem = closedManifoldProblem(s);
        QVERIFY2(problem.isEmpty(), qPrintable(problem));
        const auto pieces = components(s);
        if (partial)
            QCOMPARE(int(pieces.size()), 1);
        else
            QVERIFY(int(pieces.size()) >= minPieces);
        double sum = 0;
        for (const auto& p : pieces) {
            const double v = enclosedVolume(p);
            QVERIFY(v > 0);
            sum += v;
        }
        QVERIFY2(std::abs(sum - volume) <= 1e-6 * volume, qPrintable(QString("%1 vs %2").arg(sum).arg(volume)));
        // New vertices lie on the sweep; every vertex has texture coordinates and a rest position.
        for (int v = cut.firstNewVertex; v < s.vertexCount(); ++v)
            QVERIFY(sweep.closestPoint(s.positions[v]).distance <= 1e-9 * size);
        QCOMPARE(int(s.uvs.size()), s.vertexCount());
        QCOMPARE(int(rest.size()), s.vertexCount());
        if (shape == 2 && normal.z() > 0.5)
            QVERIFY(cut.loops >= 4);  // two circles a side: annulus caps
        // In place: only crossed triangles (all among the candidates) changed, at their index.
        int changed = 0;
        for (std::size_t t = 0; t < trianglesBefore.size(); ++t)
            changed += s.triangles[t] != trianglesBefore[t] ? 1 : 0;
        QVERIFY(changed > 0);
        QVERIFY(changed <= cut.candidateTriangles);
        // Cut faces are flagged, and their texture coordinates are the sweep's (u, v).
        QCOMPARE(int(s.cutFaces.size()), s.triangleCount());
        QCOMPARE(int(s.cutUvs.size()), s.vertexCount());
        QCOMPARE(int(std::count(s.cutFaces.begin(), s.cutFaces.end(), 1)), cut.capTriangles);
        for (int f = 0; f < s.triangleCount(); ++f)
            if (s.isCutFace(f))
                for (int v : s.triangles[f]) {
                    QVERIFY(v >= cut.firstNewVertex);
                    QVERIFY(s.cutUvs[v].allFinite());
                    QVERIFY((sweep.pointAt(s.cutUvs[v]) - s.positions[v]).norm() <= 1e-9 * size);
                }
        for (int v = 0; v < cut.firstNewVertex; ++v)
            QVERIFY(!s.cutUvs[v].allFinite());
    }

    /// A surface with a hole (not closed): the cut boundary runs into the hole, the cut is
    /// refused and the surface, its texture coordinates and rest positions are untouched.
    void failedCutLeavesTheSurfaceUntouched() {
        TriangleSurface s = makeEllipsoid(Vec3(10, 8, 6), 24, 32);
        // Remove the triangles around the equator on the +x side.
        std::vector<Tri> kept;
        for (const Tri& t : s.triangles) {
            const Vec3 c = (s.positions[t[0]] + s.positions[t[1]] + s.positions[t[2]]) / 3;
            if (!(c.x() > 8 && std::abs(c.z()) < 1.5))
                kept.push_back(t);
        }
        QVERIFY(kept.size() < s.triangles.size());
        s.triangles = kept;
        s.uvs.assign(s.positions.size(), Vec2(0.25, 0.5));
        std::vector<Vec3> rest = s.positions;
        const TriangleSurface before = s;
        SurfaceCut cut;
        const Status st = cutSurface(s, &rest, planeSweep(Vec3(0.01, 0.02, 0.03), Vec3(0, 0.05, 1), 30, 0, 2, false), cut);
        QVERIFY(!st.ok());
        QVERIFY2(st.message().find("open") != std::string::npos, st.message().c_str());
        QCOMPARE(s.positions, before.positions);
        QCOMPARE(s.triangles, before.triangles);
        QCOMPARE(s.uvs, before.uvs);
        QCOMPARE(s.cutUvs.size(), before.cutUvs.size());
        QCOMPARE(s.cutFaces.size(), before.cutFaces.size());
        QCOMPARE(rest, before.positions);
    }

    void repeatedIntersectingCuts() {
        TriangleSurface s = sampleSurface(Sample::Myoma, 0.25);
        const double volume = enclosedVolume(s);
        const auto [lo, hi] = boundingBox(s.positions);
        const double size = (hi - lo).norm();
        const Vec3 c = 0.5 * (lo + hi);
        for (const Vec3& n : {Vec3(0.1, 0.05, 1), Vec3(1, 0.1, 0.07), Vec3(0.07, 1, 0.1)}) {
            SurfaceCut cut;
            const Status st = cutSurface(s, nullptr, planeSweep(c + Vec3(0.011, 0.013, 0.017), n, size, 0.02, 3, false), cut);
            QVERIFY2(st.ok(), st.message().c_str());
            const QString problem = closedManifoldProblem(s);
            QVERIFY2(problem.isEmpty(), qPrintable(problem));
        }
        const auto pieces = components(s);
        QCOMPARE(int(pieces.size()), 8);  // three cutting planes through the middle
        double sum = 0;
        for (const auto& p : pieces)
            sum += enclosedVolume(p);
        QVERIFY(std::abs(sum - volume) <= 1e-6 * volume);
    }

    void sweepMissingTheSurfaceChangesNothing() {
        TriangleSurface s = sampleSurface(Sample::Myoma, 0.1);
        const TriangleSurface before = s;
        SurfaceCut cut;
        QVERIFY(cutSurface(s, nullptr, planeSweep(Vec3(100, 100, 100), Vec3(0, 0, 1), 5, 0, 2, false), cut).ok());
        QCOMPARE(s.triangleCount(), before.triangleCount());
        QCOMPARE(cut.splitEdges, 0);
    }
};

QTEST_GUILESS_MAIN(TestCutSurface)
#include "test_cut_surface.moc"
