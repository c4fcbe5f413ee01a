// The embedded surface's binding (section 5): every vertex bound through a spatial search,
// apply() reproduces the surface and follows any affine motion of the tets, and after a cut
// re-binding keeps the surface in place while each side follows its own piece.
#include "core/cut/hybrid_cutter.h"
#include "core/embed/binding.h"
#include "core/embed/embedded_surface.h"
#include "core/embed/cut_surface.h"
#include "core/mesh/topology.h"
#include "core/mesher/samples.h"
#include "core/mesher/tetrahedralize.h"

#include <QTest>

using namespace resect;

namespace {

struct Scene {
    TriangleSurface surface;
    TetMesh mesh;
};

Scene sample(Sample which, double scale) {
    Scene s;
    s.surface = sampleSurface(which, 0.25);
    for (Vec3& p : s.surface.positions)
        p *= scale;
    if (!tetrahedralize(s.surface, MeshingOptions{}, s.mesh).ok())
        qFatal("meshing failed");
    return s;
}

/// Moves every node of the piece that has a node above height `above` by `lift`; returns false
/// unless the mesh is in exactly two pieces.
bool liftUpperPiece(TetMesh& mesh, double above, const Vec3& lift) {
    const Components c = connectedComponents(mesh);
    if (c.count != 2)
        return false;
    int upper = -1;
    for (int n = 0; n < mesh.nodeCount() && upper < 0; ++n)
        if (mesh.pos(n).z() > above)
            upper = c.nodeComponent[n];
    for (int n = 0; n < mesh.nodeCount(); ++n)
        if (c.nodeComponent[n] == upper)
            mesh.positions()[n] += lift;
    return upper >= 0;
}

double size(const TriangleSurface& s) {
    const auto [lo, hi] = boundingBox(s.positions);
    return (hi - lo).norm();
}

} // namespace

Q_DECLARE_METATYPE(resect::Sample)

class TestBinding : public QObject {
    Q_OBJECT
private slots:
    void bindAndFollowAffineMotion_data() {
        QTest::addColumn<Sample>("which");
        QTest::addColumn<double>("scale");
        QTest::newRow("polyp") << Sample::Polyp << 1.0;
        QTest::newRow("myoma 1e-3") << Sample::Myoma << 1e-3;
        QTest::newRow("polyp 1e3") << Sample::Polyp << 1e3;
    }
    void bindAndFollowAffineMotion() {
        QFETCH(Sample, which);
        QFETCH(double, scale);
        Scene s = sample(which, scale);
        SurfaceBinding binding;
        QVERIFY(binding.bind(s.mesh, s.surface).ok());
        QCOMPARE(binding.vertexCount(), s.surface.vertexCount());
        // The coarse mesh lies a little inside the curved surface: most surface vertices are
        // just outside it, bound to a tet next to them (no weight far below zero).
        for (int v = 0; v < s.surface.vertexCount(); ++v) {
            const auto& w = binding.weightsOf(v);
            QVERIFY(std::min({w[0], w[1], w[2], w[3]}) > -1.0);
        }
        std::vector<Vec3> out;
        binding.apply(s.mesh, out);
        const double tol = 1e-10 * size(s.surface);
        for (int v = 0; v < s.surface.vertexCount(); ++v)
            QVERIFY((out[v] - s.surface.positions[v]).norm() <= tol);
        // Move every node by x -> A x + b: the surface moves by the same map.
        Eigen::Matrix3d A;
        A << 1.1, 0.2, -0.1, 0.05, 0.9, 0.3, -0.2, 0.1, 1.2;
        const Vec3 b = Vec3(3, -2, 1) * scale;
        for (Vec3& p : s.mesh.positions())
            p = A * p + b;
        binding.apply(s.mesh, out);
        for (int v = 0; v < s.surface.vertexCount(); ++v)
            QVERIFY((out[v] - (A * s.surface.positions[v] + b)).norm() <= 10 * tol);
    }

    void cutMeshAndSurfaceTogether() {
        // The whole section-5 pipeline: cut the tets, re-bind, cut and close the surface, bind
        // its new vertices; then each closed surface piece follows its own tet piece.
        Scene s = sample(Sample::Polyp, 1.0);
        EmbeddedSurface embedded;
        QVERIFY(embedded.bind(s.mesh, s.surface).ok());
        const auto [lo, hi] = boundingBox(s.mesh.positions());
        const double z = lo.z() + 0.62 * (hi.z() - lo.z());
        SweepSurface sweep;
        QVERIFY(SweepSurface::fromStartEnd({Vec3(lo.x() - 5, lo.y() - 5, z), Vec3(hi.x() + 5, lo.y() - 5, z + 0.3)},
                                           {Vec3(lo.x() - 5, hi.y() + 5, z + 0.2), Vec3(hi.x() + 5, hi.y() + 5, z + 0.5)},
                                           sweep)
                    .ok());
        embedded.update(s.mesh);
        HybridCutter cutter(s.mesh);
        CutOptions options;
        options.snap = true;
        options.relaxSteps = 5;
        CutResult r;
        QVERIFY(cutter.cut(sweep, options, r).ok());
        EmbeddedCut ec;
        QVERIFY(embedded.cut(s.mesh, r.changes, sweep, &ec).ok());
        const SurfaceCut& sc = ec.surface;
        QVERIFY(sc.capTriangles > 0);
        QVERIFY(ec.reboundVertices > 0);
        const TriangleSurface cutSurf = embedded.surface();
        QCOMPARE(embedded.binding().vertexCount(), cutSurf.vertexCount());
        // Re-applying the binding reproduces the cut surface: every vertex (old, re-bound and
        // new) has its tet and coordinates.
        embedded.update(s.mesh);
        std::vector<Vec3> after = embedded.surface().positions;
        const double tol = 1e-9 * size(s.surface);
        for (int v = 0; v < cutSurf.vertexCount(); ++v)
            QVERIFY2((after[v] - cutSurf.positions[v]).norm() <= tol, qPrintable(QString::number(v)));
        // Lift the upper tet piece: the surface vertices on the + side (new copies included)
        // go with it, the others stay; vertices within d of the sweep are the cut's business.
        const Vec3 lift(0, 0, 10);
        QVERIFY(liftUpperPiece(s.mesh, z + 3, lift));
        embedded.update(s.mesh);
        after = embedded.surface().positions;
        int newMoved = 0, newChecked = 0;
        for (int v = sc.firstNewVertex; v < cutSurf.vertexCount(); ++v) {
            const int side = sc.side[v - sc.firstNewVertex];
            if (side == 0)
                continue;
            ++newChecked;
            const Vec3 expected = side > 0 ? cutSurf.positions[v] + lift : cutSurf.positions[v];
            if ((after[v] - expected).norm() <= tol)
                ++newMoved;
        }
        QVERIFY(newChecked > 0);
        QCOMPARE(newMoved, newChecked);
    }

    void rebindAfterACut() {
        Scene s = sample(Sample::Myoma, 1.0);
        SurfaceBinding binding;
        QVERIFY(binding.bind(s.mesh, s.surface).ok());
        // A horizontal cut through the middle of the myoma.
        const auto [lo, hi] = boundingBox(s.mesh.positions());
        const double z = 0.5 * (lo.z() + hi.z()) + 0.013;
        SweepSurface sweep;
        QVERIFY(SweepSurface::fromStartEnd({Vec3(lo.x() - 5, lo.y() - 5, z), Vec3(hi.x() + 5, lo.y() - 5, z + 0.2)},
                                           {Vec3(lo.x() - 5, hi.y() + 5, z + 0.1), Vec3(hi.x() + 5, hi.y() + 5, z + 0.3)},
                                           sweep)
                    .ok());
        std::vector<Vec3> before;
        binding.apply(s.mesh, before);

        HybridCutter cutter(s.mesh);
        CutOptions options;
        const double band = options.d * cutter.meanEdgeLength();
        options.snap = true;
        options.relaxSteps = 5;
        CutResult r;
        QVERIFY(cutter.cut(sweep, options, r).ok());
        binding.rebind(s.mesh, r.changes, before, sweep);
        // The surface does not move through the cut.
        std::vector<Vec3> after;
        binding.apply(s.mesh, after);
        const double tol = 1e-9 * size(s.surface);
        for (int v = 0; v < s.surface.vertexCount(); ++v)
            QVERIFY2((after[v] - before[v]).norm() <= tol, qPrintable(QString::number(v)));
        // Each side follows its own piece: lift the piece above the cut.
        const Vec3 lift(0, 0, 10);
        QVERIFY(liftUpperPiece(s.mesh, z + 2, lift));
        binding.apply(s.mesh, after);
        int checked = 0;
        for (int v = 0; v < s.surface.vertexCount(); ++v) {
            const int side = sweep.sideOf(before[v]);
            // Within d of the sweep the mesh's cut may deviate from it (cut nodes kept off it on
            // the surface); there the surface is cut itself (the next step), not re-bound.
            if (sweep.closestPoint(before[v]).distance < band)
                continue;
            const Vec3 expected = side > 0 ? before[v] + lift : before[v];

            QVERIFY2((after[v] - expected).norm() <= tol, qPrintable(QString("vertex %1 side %2").arg(v).arg(side)));
            ++checked;
        }
        QVERIFY(checked > s.surface.vertexCount() * 9 / 10);
    }
};

QTEST_GUILESS_MAIN(TestBinding)
#include "test_binding.moc"
