// SurfaceIndex (where a cut finds the triangles near its sweep) gives exactly the candidates of
// their definition (triangles whose corners are not all strictly beyond one face of the box) for
// boxes of every size, after the vertices moved, and after cuts that appended and replaced
// triangles; and cutting through the index and a reused workspace gives the same surface, bit
// for bit, as the plain pass over the surface with fresh scratch.
#include "core/embed/cut_surface.h"
#include "core/embed/surface_index.h"
#include "core/mesher/samples.h"

#include <QTest>

#include <cstring>
#include <random>

using namespace resect;

namespace {

std::vector<int> candidatesByDefinition(const TriangleSurface& s, const Box3& box) {
    const Vec3 lo = box.min(), hi = box.max();
    const auto code = [&](const Vec3& p) {
        return (p.x() < lo.x() ? 1 : 0) | (p.x() > hi.x() ? 2 : 0) | (p.y() < lo.y() ? 4 : 0) |
               (p.y() > hi.y() ? 8 : 0) | (p.z() < lo.z() ? 16 : 0) | (p.z() > hi.z() ? 32 : 0);
    };
    std::vector<int> out;
    for (int t = 0; t < s.triangleCount(); ++t) {
        const Tri& q = s.triangles[t];
        if ((code(s.positions[q[0]]) & code(s.positions[q[1]]) & code(s.positions[q[2]])) == 0)
            out.push_back(t);
    }
    return out;
}

/// Random boxes from a point of the surface's box, of sizes from a hundredth to all of it.
QString compareOnRandomBoxes(SurfaceIndex& index, const TriangleSurface& s, std::mt19937& rng) {
    const auto [lo, hi] = boundingBox(s.positions);
    std::uniform_real_distribution<double> u(0, 1), scale(-2, 0);
    std::vector<int> got;
    for (int k = 0; k < 40; ++k) {
        const Vec3 centre = lo + (hi - lo).cwiseProduct(Vec3(u(rng), u(rng), u(rng)));
        const Vec3 half = 0.5 * std::pow(10.0, scale(rng)) * (hi - lo).cwiseProduct(Vec3(u(rng), u(rng), u(rng)));
        const Box3 box(centre - half, centre + half);
        index.candidates(s, box, got);
        const std::vector<int> expected = candidatesByDefinition(s, box);
        if (got != expected)
            return QString("box %1: %2 candidates, %3 by definition").arg(k).arg(got.size()).arg(expected.size());
    }
    return {};
}

bool planeSweep(const Vec3& p, const Vec3& n, double size, SweepSurface& out) {
    const Vec3 a = n.unitOrthogonal(), b = n.normalized().cross(a);
    return SweepSurface::fromStartEnd({p - size * a - size * b, p + size * a - size * b},
                                      {p - size * a + size * b, p + size * a + size * b}, out)
        .ok();
}

QString sameSurface(const TriangleSurface& a, const TriangleSurface& b) {
    if (a.triangles != b.triangles)
        return "triangles differ";
    if (a.positions.size() != b.positions.size() ||
        std::memcmp(a.positions.data(), b.positions.data(), a.positions.size() * sizeof(Vec3)) != 0)
        return "positions differ";
    if (a.cutFaces != b.cutFaces)
        return "cut faces differ";
    for (std::size_t v = 0; v < a.cutUvs.size(); ++v)
        if (std::memcmp(a.cutUvs[v].data(), b.cutUvs[v].data(), sizeof(Vec2)) != 0)
            return QString("cut (u, v) of vertex %1 differs").arg(v);
    return {};
}

} // namespace

class TestSurfaceIndex : public QObject {
    Q_OBJECT
private slots:
    void candidatesAreTheDefinition() {
        TriangleSurface s = sampleSurface(Sample::Polyp, 0.5);
        SurfaceIndex index;
        index.build(s);
        std::mt19937 rng(5);
        QString problem = compareOnRandomBoxes(index, s, rng);
        QVERIFY2(problem.isEmpty(), qPrintable(problem));
        // The vertices move (an affine map and a jitter): the boxes follow once told.
        Eigen::Matrix3d A;
        A << 1.2, 0.1, 0, -0.2, 0.8, 0.3, 0.1, 0, 1.1;
        std::normal_distribution<double> jitter(0, 0.05);
        for (Vec3& p : s.positions)
            p = A * p + Vec3(jitter(rng), jitter(rng), jitter(rng));
        index.positionsChanged();
        problem = compareOnRandomBoxes(index, s, rng);
        QVERIFY2(problem.isEmpty(), qPrintable(problem));
    }

    /// Cuts through the index with a kept workspace equal the plain cut, and the index follows
    /// what the cuts appended and replaced (also across a motion between cuts).
    void cutsThroughTheIndex() {
        TriangleSurface indexed = sampleSurface(Sample::Myoma, 0.5);
        TriangleSurface plain = indexed;
        SurfaceIndex index;
        index.build(indexed);
        SurfaceCutWorkspace workspace;
        const auto [lo, hi] = boundingBox(indexed.positions);
        std::mt19937 rng(11);
        std::uniform_real_distribution<double> u(0, 1), n(-1, 1);
        int cuts = 0;
        for (int k = 0; k < 8; ++k) {
            if (k == 4) {  // the surface moves between cuts
                for (TriangleSurface* s : {&indexed, &plain})
                    for (Vec3& p : s->positions)
                        p = Vec3(1.05 * p.x(), p.y() + 0.02 * p.z(), p.z());
                index.positionsChanged();
            }
            const Vec3 p = lo + (hi - lo).cwiseProduct(Vec3(0.2 + 0.6 * u(rng), 0.2 + 0.6 * u(rng), 0.2 + 0.6 * u(rng)));
            SweepSurface sweep;
            QVERIFY(planeSweep(p, Vec3(n(rng), n(rng), 1.0 + u(rng)), (hi - lo).norm() * (k % 3 == 2 ? 0.3 : 2), sweep));
            SurfaceCut a, b;
            const Status sa = cutSurface(indexed, nullptr, sweep, a, &index, &workspace);
            const Status sb = cutSurface(plain, nullptr, sweep, b);
            QCOMPARE(sa.ok(), sb.ok());
            QCOMPARE(a.candidateTriangles, b.candidateTriangles);
            QCOMPARE(a.capTriangles, b.capTriangles);
            QCOMPARE(a.side, b.side);
            QCOMPARE(a.sourceEdge, b.sourceEdge);
            const QString same = sameSurface(indexed, plain);
            QVERIFY2(same.isEmpty(), qPrintable(QString("cut %1: %2").arg(k).arg(same)));
            cuts += sa.ok() && a.capTriangles > 0;
            const QString problem = compareOnRandomBoxes(index, indexed, rng);
            QVERIFY2(problem.isEmpty(), qPrintable(QString("after cut %1: %2").arg(k).arg(problem)));
        }
        QVERIFY(cuts >= 4);
    }
};

QTEST_GUILESS_MAIN(TestSurfaceIndex)
#include "test_surface_index.moc"
