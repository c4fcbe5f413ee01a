// The surface cut does not change under optimisation (issue 20): four sequences of ten
// intersecting cuts (loop scoops, mouse-like strokes, planes through earlier cut vertices) on the
// polyp and the myoma surfaces, straight through cutSurface (no tets), give after every cut
// exactly the surface the code before issue 20 gave: the same triangles in the same order with
// the same corners and cut-face flags, and the same vertex positions and cut (u, v)s to the bit.
// Run through a SurfaceIndex with a kept workspace (as EmbeddedSurface cuts) and, for the first
// sequence, also without. The fingerprints were recorded with the code of 428944b.
//
// When a change is meant to change cuts, print the new fingerprints with
// RESECT_PRINT_GOLDEN=1 and say in the commit why they changed.
#include "core/embed/cut_surface.h"
#include "core/embed/surface_index.h"
#include "core/mesher/samples.h"
#include "core/sweep/stroke_shapes.h"

#include "surface_checks.h"
#include "tests/core/fingerprint.h"

#include <QTest>

#include <cinttypes>
#include <cstdio>
#include <cstdlib>
#include <random>

using namespace resect;

namespace {

struct Golden {
    int sequence, cut;
    int triangles;  ///< -1: the stroke was refused before cutting
    int vertices;
    std::uint64_t topology, geometry;
};

const Golden kGolden[] = {
    {0, 0, 4458, 2233, 0xee3f993f1de06034ull, 0x2cd722089e0b015dull},
    {0, 1, 5088, 2548, 0xd5a505c9a51bffe8ull, 0x67856292fa4385ceull},
    {0, 2, 5764, 2890, 0xcc71719612e8735full, 0x6f14d9cfd51b2dfaull},
    {0, 3, 7076, 3558, 0xe0f16ca8afefefefull, 0xcab92d300643edbeull},
    {0, 4, 7790, 3915, 0x5deeca0d076dc3ddull, 0xa2710da5c8bf5146ull},
    {0, 5, 9038, 4541, 0x5611b716a492172full, 0x528ac94b00cda08aull},
    {0, 6, 10922, 5509, 0x8aaf817485a609abull, 0x872f55b387823722ull},
    {0, 7, 13982, 7045, 0x9087ab0843b9c564ull, 0x11f1242098859802ull},
    {0, 8, 15614, 7883, 0xfe21703df539f621ull, 0x445b5946b2dad1eeull},
    {0, 9, 18514, 9373, 0x769f55600d3aa6f6ull, 0x81f14f0e47661006ull},
    {1, 0, 4486, 2247, 0xab342d16b5b0653dull, 0xfa52bfef889a6a40ull},
    {1, 1, 4830, 2417, 0x2f959aad4ba0ca1bull, 0x8b8bf71a02c0fb73ull},
    {1, 2, 5674, 2843, 0xd06a2786f419b93full, 0x408e21b71d6f7f3full},
    {1, 3, 7270, 3651, 0x2b88842c208397f3ull, 0x687b3c2242cd51abull},
    {1, 4, 9200, 4618, 0xd38b1754196cb666ull, 0x8a1fe53c6fa23ed7ull},
    {1, 5, 11508, 5782, 0x6a62753f314e1769ull, 0xb9c0fa7affc8115full},
    {1, 6, 13892, 6990, 0x615385c6e3d49c06ull, 0xe9a3ff9c1c038b8full},
    {1, 7, 21368, 10736, 0x1560f02347e0238cull, 0x86dc2e35ac7f1ec0ull},
    {1, 8, 24428, 12288, 0x1afa82ba097833f6ull, 0xd04eff240b7be950ull},
    {1, 9, 27820, 14012, 0x21d910f4b09a1c7dull, 0xfc23b758f55adedcull},
    {2, 0, 4478, 2243, 0xc988540f1bad27e4ull, 0x4267bfd74b5753adull},
    {2, 1, 4954, 2479, 0x5d9a41b4a58ef124ull, 0xadc8b43f8ae32adfull},
    {2, 2, 5510, 2761, 0x224b557e70dcae54ull, 0x2beb2a2bc4e2f5a7ull},
    {2, 3, 6638, 3335, 0xcda947a60db31dd2ull, 0xcbec3df79a4e14a6ull},
    {2, 4, 8566, 4299, 0x4a754da8fd3c2d9aull, 0xf7ff6a9097e220f3ull},
    {2, 5, 10030, 5047, 0x9f63950f621ee284ull, 0x058aa61966bb4cdfull},
    {2, 6, 12934, 6537, 0xb35a9bd87182c00bull, 0x8ecfee3d6cd98245ull},
    {2, 7, 17424, 8792, 0xe32295e0fc58729eull, 0xa55e402c680a53aaull},
    {2, 8, 19828, 10014, 0x7a837a12a2275269ull, 0x82b5f0c0836caa32ull},
    {2, 9, 24192, 12256, 0x4f0ead093bb8759cull, 0xe4ab4c1fdea18c4aull},
    {3, 0, 4510, 2259, 0x374cccc1ab512b15ull, 0x0b19c045e28f9368ull},
    {3, 1, 4886, 2445, 0x5430b1df2191eb3eull, 0xc64537bcbb14e0f1ull},
    {3, 2, 6234, 3121, 0x461a8b0d1e11c87bull, 0xdc28d9525fcfe6e9ull},
    {3, 3, 7750, 3889, 0xba2dad88eda0e0e3ull, 0x158e6c8e36e662c7ull},
    {3, 4, 9658, 4843, 0x67c04cdcc7b2def4ull, 0x4161095600df49d2ull},
    {3, 5, 11278, 5671, 0xe3fdb183b8b6c9c9ull, 0xb26871fe8e3048c2ull},
    {3, 6, 14842, 7487, 0xde828d359792b0dfull, 0xf1eb523f724ca54aull},
    {3, 7, 18982, 9563, 0xf633e820679b4b6aull, 0xdf47234c84917226ull},
    {3, 8, 25330, 12777, 0xed21b1967de86446ull, 0x2e98717763737c7eull},
    {3, 9, 31160, 15746, 0x11164575eda101ceull, 0xb477fe07bcedf0e9ull},
};

using testing::Fnv1a;
using testing::planeThrough;


} // namespace

class TestCutSurfaceGolden : public QObject {
    Q_OBJECT
private slots:
    void cutsAreUnchanged_data() {
        QTest::addColumn<int>("sequence");
        QTest::addColumn<bool>("indexed");
        for (int seq = 0; seq < 4; ++seq)
            QTest::newRow(qPrintable(QString("sequence %1, indexed").arg(seq))) << seq << true;
        QTest::newRow("sequence 0, plain") << 0 << false;
    }
    void cutsAreUnchanged() {
        QFETCH(int, sequence);
        QFETCH(bool, indexed);
        const bool print = std::getenv("RESECT_PRINT_GOLDEN") != nullptr;
        const Sample sample = sequence % 2 ? Sample::Myoma : Sample::Polyp;
        TriangleSurface s = sampleSurface(sample, 0.1);
        const auto [lo, hi] = boundingBox(s.positions);
        const Eigen::AlignedBox3d bounds(lo, hi);
        const Vec3 axis = sample == Sample::Polyp ? Vec3(1.2, 0.5, 0) : Vec3(0.5 * (lo + hi));
        const int first = s.vertexCount();
        SurfaceIndex index;
        index.build(s);
        SurfaceCutWorkspace workspace;
        std::mt19937 rng(sequence + 1);
        int scoops = 0, checked = 0;
        for (int k = 0; k < 10; ++k) {
            const Golden* g = nullptr;
            for (const Golden& row : kGolden)
                if (row.sequence == sequence && row.cut == k)
                    g = &row;
            QVERIFY(g || print);
            SweepSurface sweep;
            if (k % 3 == 2 && s.vertexCount() > first) {
                std::uniform_int_distribution<int> pick(first, s.vertexCount() - 1);
                std::uniform_real_distribution<double> u(-1, 1);
                const Vec3 p = s.positions[pick(rng)];
                QVERIFY(planeThrough(p, Vec3(u(rng), u(rng), 1.5), (hi - lo).norm(), sweep));
            } else if (k % 3 == 1) {
                if (!SweepSurface::fromCurves(mouseStroke(rng, bounds), sweep).ok()) {
                    QVERIFY(print || g->triangles == -1);
                    continue;
                }
            } else {
                QVERIFY(SweepSurface::fromCurves(loopScoop(resectionScoop(bounds, axis, scoops++ + sequence)), sweep).ok());
            }
            SurfaceCut out;
            const Status st = indexed ? cutSurface(s, nullptr, sweep, out, &index, &workspace)
                                      : cutSurface(s, nullptr, sweep, out);
            Fnv1a topology, geometry;
            for (const Tri& q : s.triangles)
                topology.add(q.data(), sizeof(Tri));
            topology.add(s.cutFaces.data(), s.cutFaces.size());
            for (const Vec3& p : s.positions)
                geometry.add(p.data(), sizeof(Vec3));
            for (const Vec2& uv : s.cutUvs)
                geometry.add(uv.data(), sizeof(Vec2));
            const int triangles = st.ok() ? s.triangleCount() : -2;
            if (print) {
                std::printf("{%d, %d, %d, %d, 0x%016" PRIx64 "ull, 0x%016" PRIx64 "ull},\n", sequence, k, triangles,
                            s.vertexCount(), topology.h, geometry.h);
                continue;
            }
            const QString where = QString("sequence %1, cut %2").arg(sequence).arg(k);
            QVERIFY2(triangles == g->triangles && s.vertexCount() == g->vertices,
                     qPrintable(where + QString(": %1 triangles, %2 vertices; recorded %3, %4")
                                            .arg(triangles).arg(s.vertexCount()).arg(g->triangles).arg(g->vertices)));
            QVERIFY2(topology.h == g->topology, qPrintable(where + ": the triangles differ"));
            QVERIFY2(geometry.h == g->geometry, qPrintable(where + ": positions or cut (u, v)s differ"));
            ++checked;
        }
        QVERIFY(print || checked >= 9);
    }
};

QTEST_GUILESS_MAIN(TestCutSurfaceGolden)
#include "test_cut_surface_golden.moc"
