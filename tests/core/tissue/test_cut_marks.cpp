// The cut marks of a Tissue (core/tissue/tissue.h): onCutSurface() marks every node a cut put
// on its cut surface, tetCuts() the cut that last produced or changed each tet. The views draw
// a boundary face whose three nodes are marked as a cut face, and the last cut's tets as
// touched. Checked on the polyp sample at three scales: the marks are exactly the cut's change
// list; the cut faces lie within the cut-node threshold d of the sweep and cover both sides of
// the cut alike; the marks follow a resection (into the chips) and the improvement's
// renumbering, and accumulate over cuts.
#include "core/mesh/topology.h"
#include "core/mesher/samples.h"
#include "core/mesher/tetrahedralize.h"
#include "core/tissue/tissue.h"

#include <QTest>

#include <algorithm>
#include <map>
#include <set>

using namespace resect;

namespace {

const TetMesh& polypMesh(double scale) {
    static std::map<double, TetMesh> cache;
    auto it = cache.find(scale);
    if (it != cache.end())
        return it->second;
    TriangleSurface surface = sampleSurface(Sample::Polyp, 0.25);
    for (Vec3& p : surface.positions)
        p *= scale;
    TetMesh mesh;
    if (!tetrahedralize(surface, MeshingOptions{}, mesh).ok())
        qFatal("meshing the polyp failed");
    return cache.emplace(scale, std::move(mesh)).first->second;
}

/// The polyp, anchored at its base (z in [-0.5, 1] mm) if `anchored`.
Tissue makeTissue(double scale, bool anchored) {
    FixedSelection anchors;
    if (anchored)
        anchors.box = std::array<Vec3, 2>{Vec3(-6, -6, -0.5) * scale, Vec3(6, 6, 1) * scale};
    Tissue t;
    if (const Status s = Tissue::create(polypMesh(scale), {}, Material{}, anchors, t); !s.ok())
        qFatal("%s", s.message().c_str());
    return t;
}

/// A plane across the whole polyp at height z (mm, before scaling), tilted slightly: the plane
/// z' = z + 0.3 (x + 12) / 24 + 0.2 (y + 12) / 24 (all scaled).
struct TiltedPlane {
    double z, scale;
    SweepSurface sweep() const {
        SweepSurface s;
        if (!SweepSurface::fromStartEnd(
                 {Vec3(-12, -12, z) * scale, Vec3(12, -12, z + 0.3) * scale},
                 {Vec3(-12, 12, z + 0.2) * scale, Vec3(12, 12, z + 0.5) * scale}, s)
                 .ok())
            qFatal("bad sweep");
        return s;
    }
    double distance(const Vec3& p) const {
        const Vec3 n = Vec3(-0.3 / 24, -0.2 / 24, 1).normalized();
        return std::abs((p - Vec3(-12, -12, z) * scale).dot(n));
    }
};

/// The boundary faces of `mesh` whose three nodes are marked (reference positions).
std::vector<BoundaryFace> cutFaces(const TetMesh& mesh, const std::vector<std::uint8_t>& marked) {
    std::vector<BoundaryFace> out;
    for (const BoundaryFace& f : boundaryFaces(mesh))
        if (marked[f.nodes[0]] && marked[f.nodes[1]] && marked[f.nodes[2]])
            out.push_back(f);
    return out;
}

double area(const TetMesh& mesh, const Tri& f) {
    return 0.5 * (mesh.ref(f[1]) - mesh.ref(f[0])).cross(mesh.ref(f[2]) - mesh.ref(f[0])).norm();
}

} // namespace

class TestCutMarks : public QObject {
    Q_OBJECT
private slots:
    void marksAreTheCutsChanges_data() {
        QTest::addColumn<double>("scale");
        QTest::newRow("1e-3") << 1e-3;
        QTest::newRow("1") << 1.0;
        QTest::newRow("1e3") << 1e3;
    }
    void marksAreTheCutsChanges() {
        // Without the improvement the change list indexes the tissue as it is after the cut.
        QFETCH(double, scale);
        Tissue tissue = makeTissue(scale, false);
        QCOMPARE(int(tissue.onCutSurface().size()), tissue.mesh().nodeCount());
        QCOMPARE(int(tissue.tetCuts().size()), tissue.mesh().tetCount());
        QVERIFY(std::all_of(tissue.onCutSurface().begin(), tissue.onCutSurface().end(),
                            [](auto m) { return m == 0; }));
        QVERIFY(std::all_of(tissue.tetCuts().begin(), tissue.tetCuts().end(),
                            [](int c) { return c == 0; }));

        const TiltedPlane plane{15, scale};
        TissueCut cut;
        CutOptions options;
        options.improve = false;
        QVERIFY(tissue.cut(plane.sweep(), options, &cut).ok());
        const TetMesh& mesh = tissue.mesh();
        QCOMPARE(tissue.pieces().count, 2);
        QCOMPARE(int(tissue.onCutSurface().size()), mesh.nodeCount());
        QCOMPARE(int(tissue.tetCuts().size()), mesh.tetCount());
        const std::set<int> onCut(cut.changes.cutSurfaceNodes.begin(),
                                  cut.changes.cutSurfaceNodes.end());
        QVERIFY(!onCut.empty());
        for (int n = 0; n < mesh.nodeCount(); ++n)
            QCOMPARE(tissue.onCutSurface()[n] != 0, onCut.count(n) == 1);
        const std::set<int> modified(cut.changes.modifiedTets.begin(),
                                     cut.changes.modifiedTets.end());
        int touched = 0;
        for (int t = 0; t < mesh.tetCount(); ++t) {
            const bool expected = t >= cut.changes.firstNewTet || modified.count(t) == 1;
            QCOMPARE(tissue.tetCuts()[t], expected ? 1 : 0);
            touched += expected;
        }
        QVERIFY(touched > 0 && touched < mesh.tetCount());

        // The cut faces: within d (of the mean edge length) of the sweep, and as much of them on
        // each side of the cut (the two copies of the cut surface coincide in the reference
        // configuration).
        const std::vector<BoundaryFace> faces = cutFaces(mesh, tissue.onCutSurface());
        QVERIFY(faces.size() >= 10);
        const double tolerance = options.d * tissue.meanEdgeLength() * (1 + 1e-9);
        const Components& pieces = tissue.pieces();
        double areas[2] = {0, 0};
        for (const BoundaryFace& f : faces) {
            for (int n : f.nodes)
                QVERIFY2(plane.distance(mesh.ref(n)) <= tolerance,
                         qPrintable(QString("node %1 at %2 from the sweep")
                                        .arg(n)
                                        .arg(plane.distance(mesh.ref(n)))));
            areas[pieces.tetComponent[f.tet]] += area(mesh, f.nodes);
        }
        QVERIFY(areas[0] > 0);
        QVERIFY2(
            std::abs(areas[0] - areas[1]) <= 1e-9 * areas[0],
            qPrintable(QString("%1 vs %2").arg(areas[0], 0, 'g', 17).arg(areas[1], 0, 'g', 17)));
        // The polyp's cross-section at z = 15 is several mm^2 (scaled): the cut faces cover it,
        // the surface of the polyp is not among them.
        double boundary = 0;
        for (const BoundaryFace& f : boundaryFaces(mesh))
            boundary += area(mesh, f.nodes);
        QVERIFY(areas[0] > 0.01 * boundary && 2 * areas[0] < 0.5 * boundary);

        // A copy carries the marks.
        const Tissue copy(tissue);
        QCOMPARE(copy.onCutSurface(), tissue.onCutSurface());
        QCOMPARE(copy.tetCuts(), tissue.tetCuts());
    }

    void marksFollowResectionsIntoTheChips() {
        // The anchored polyp, resected piece by piece with the improvement on (which renumbers
        // the tissue): the chips take their marks along, the marks accumulate over the cuts.
        Tissue tissue = makeTissue(1, true);
        tissue.setResectedPieces(ResectedPieces::Rigid);
        const TiltedPlane first{15, 1}, second{8, 1};
        const double tolerance = 0.2 * tissue.meanEdgeLength() * (1 + 1e-9);
        QVERIFY(tissue.cut(first.sweep(), CutOptions{}).ok());
        QCOMPARE(int(tissue.chips().size()), 1);
        QCOMPARE(int(tissue.onCutSurface().size()), tissue.mesh().nodeCount());
        QCOMPARE(int(tissue.tetCuts().size()), tissue.mesh().tetCount());
        const Chip& head = tissue.chips()[0];
        QCOMPARE(int(head.onCutSurface.size()), head.mesh.nodeCount());
        QCOMPARE(int(head.tetCuts.size()), head.mesh.tetCount());
        QVERIFY(std::count(head.tetCuts.begin(), head.tetCuts.end(), 1) > 0);
        QVERIFY(std::count(tissue.tetCuts().begin(), tissue.tetCuts().end(), 1) > 0);
        // Both sides of the cut have their cut faces, where the sweep passed, of about the same
        // area (the improvement moved some nodes of the tissue's side).
        double areas[2] = {0, 0};
        const std::vector<BoundaryFace> headFaces = cutFaces(head.mesh, head.onCutSurface);
        const std::vector<BoundaryFace> stumpFaces = cutFaces(tissue.mesh(), tissue.onCutSurface());
        QVERIFY(!headFaces.empty() && !stumpFaces.empty());
        for (const BoundaryFace& f : headFaces) {
            areas[0] += area(head.mesh, f.nodes);
            for (int n : f.nodes)
                QVERIFY(first.distance(head.mesh.ref(n)) <= tolerance);
        }
        for (const BoundaryFace& f : stumpFaces) {
            areas[1] += area(tissue.mesh(), f.nodes);
            for (int n : f.nodes)
                QVERIFY(first.distance(tissue.mesh().ref(n)) <= tolerance);
        }
        QVERIFY2(std::abs(areas[0] - areas[1]) <= 0.05 * areas[0],
                 qPrintable(QString("%1 vs %2").arg(areas[0]).arg(areas[1])));

        // The second cut takes off the stump's top, with the first cut's faces on it.
        QVERIFY(tissue.cut(second.sweep(), CutOptions{}).ok());
        QCOMPARE(int(tissue.chips().size()), 2);
        const Chip& slice = tissue.chips()[1];
        QCOMPARE(int(slice.onCutSurface.size()), slice.mesh.nodeCount());
        QCOMPARE(int(slice.tetCuts.size()), slice.mesh.tetCount());
        QCOMPARE(*std::max_element(tissue.tetCuts().begin(), tissue.tetCuts().end()), 2);
        QCOMPARE(*std::max_element(slice.tetCuts.begin(), slice.tetCuts.end()), 2);
        int nearFirst = 0, nearSecond = 0;
        for (const BoundaryFace& f : cutFaces(slice.mesh, slice.onCutSurface)) {
            const Vec3 c = (slice.mesh.ref(f.nodes[0]) + slice.mesh.ref(f.nodes[1]) +
                            slice.mesh.ref(f.nodes[2])) /
                           3;
            const bool a = first.distance(c) <= tolerance, b = second.distance(c) <= tolerance;
            QVERIFY2(a || b,
                     qPrintable(QString("a cut face at z = %1 on neither sweep").arg(c.z())));
            nearFirst += a;
            nearSecond += b;
        }
        QVERIFY(nearFirst > 0 && nearSecond > 0);
        // The tissue's own cut faces are now the second cut's only.
        for (const BoundaryFace& f : cutFaces(tissue.mesh(), tissue.onCutSurface()))
            for (int n : f.nodes)
                QVERIFY(second.distance(tissue.mesh().ref(n)) <= tolerance);
    }
};

QTEST_GUILESS_MAIN(TestCutMarks)
#include "test_cut_marks.moc"
