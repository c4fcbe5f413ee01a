// A whole resection cuts the embedded surface every time (issue 15): 20 intersecting strokes
// (loop scoops, mouse-like strokes, sweeps through earlier cut vertices) on the polyp through
// Tissue::cut, at three scales and several seeds. After every stroke the surface is closed and
// 2-manifold, the pieces' enclosed volumes add up to the volume before the cut, and the cut
// faces carry their (u, v).
#include "core/mesher/samples.h"
#include "core/mesher/tetrahedralize.h"
#include "core/sweep/stroke_shapes.h"
#include "core/tissue/tissue.h"
#include "surface_checks.h"

#include <QTest>

#include <map>

using namespace resect;

namespace {

struct Inputs {
    TetMesh mesh;
    TriangleSurface surface;
};

const Inputs& polyp(double scale) {
    static std::map<double, Inputs> cache;
    if (auto it = cache.find(scale); it != cache.end())
        return it->second;
    Inputs in;
    in.surface = sampleSurface(Sample::Polyp, 0.25);
    for (Vec3& p : in.surface.positions)
        p *= scale;
    if (!tetrahedralize(in.surface, MeshingOptions{}, in.mesh).ok())
        qFatal("meshing the polyp failed");
    return cache.emplace(scale, std::move(in)).first->second;
}


} // namespace

class TestResectionSurface : public QObject {
    Q_OBJECT
private slots:
    void twentyStrokes_data() {
        QTest::addColumn<double>("scale");
        QTest::addColumn<unsigned>("seed");
        for (double scale : {1e-3, 1.0, 1e3})
            for (unsigned seed : {1u, 2u, 3u})
                QTest::newRow(qPrintable(QString("scale %1, seed %2").arg(scale).arg(seed))) << scale << seed;
    }
    void twentyStrokes() {
        QFETCH(double, scale);
        QFETCH(unsigned, seed);
        const Inputs& in = polyp(scale);
        Tissue tissue;
        QVERIFY(Tissue::create(in.mesh, in.surface, Material{}, {}, tissue).ok());
        const auto [lo, hi] = boundingBox(in.surface.positions);
        const Eigen::AlignedBox3d bounds(lo, hi);
        const Vec3 axis = Vec3(1.2, 0.5, 0) * scale;  // the polyp's head sits off the z axis
        std::mt19937 rng(seed);
        int scoops = 0, strokes = 0, throughVertices = 0;
        for (int k = 0; k < 20; ++k) {
            SweepSurface sweep;
            const int kind = k % 4;
            QString what;
            if (kind == 3 && tissue.surface().surface().vertexCount() > in.surface.vertexCount()) {
                // Through a vertex the last cuts made (it lies on an earlier sweep and cap).
                const TriangleSurface& s = tissue.surface().surface();
                std::uniform_int_distribution<int> pick(in.surface.vertexCount(), s.vertexCount() - 1);
                const Vec3 p = s.positions[pick(rng)];
                std::uniform_real_distribution<double> u(-1, 1);
                if (!testing::planeThrough(p, Vec3(u(rng), u(rng), 1.5), 20 * scale, sweep))
                    continue;
                what = "a plane through an earlier cut vertex";
                ++throughVertices;
            } else if (kind == 0 || kind == 2) {
                const Curves c = loopScoop(resectionScoop(bounds, axis, scoops));
                QVERIFY(SweepSurface::fromCurves(c, sweep).ok());
                what = QString("scoop %1").arg(scoops++);
            } else {
                if (!SweepSurface::fromCurves(mouseStroke(rng, bounds), sweep).ok())
                    continue;  // a self-intersecting stroke is refused before it cuts
                what = QString("mouse stroke %1").arg(strokes++);
            }
            tissue.updateSurface();
            const double before = enclosedVolume(tissue.surface().surface());
            TissueCut cut;
            const Status s = tissue.cut(sweep, CutOptions{.snap = true, .relaxSteps = 10}, &cut);
            QVERIFY2(s.ok(), qPrintable(QString("stroke %1 (%2): %3").arg(k).arg(what, s.message().c_str())));
            const TriangleSurface& surface = tissue.surface().surface();
            const QString manifold = testing::manifoldProblems(surface);
            QVERIFY2(manifold.isEmpty(), qPrintable(QString("after %1: %2").arg(what, manifold)));
            const double after = enclosedVolume(surface);
            QVERIFY2(std::abs(after - before) <= 1e-9 * std::abs(before),
                     qPrintable(QString("after %1: volume %2 -> %3").arg(what).arg(before, 0, 'g', 17).arg(after, 0, 'g', 17)));
            const QString uv = testing::capUvProblems(surface);
            QVERIFY2(uv.isEmpty(), qPrintable(QString("after %1: %2").arg(what, uv)));
        }
        QVERIFY(scoops >= 10);
        QVERIFY(strokes >= 2);
        QVERIFY(throughVertices >= 2);
    }
};

QTEST_GUILESS_MAIN(TestResectionSurface)
#include "test_resection_surface.moc"
