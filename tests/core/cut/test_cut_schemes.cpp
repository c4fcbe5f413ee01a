// Hand-built cuts with literal coordinates: every scheme A-E, X, Y, Z, and degenerate
// contact (through a node, along a face, through an edge, tangent, an edge cut twice).
#include "cut_checks.h"

#include "core/mesh/box_mesh.h"

#include <QTest>

using namespace resect;
using resect::testing::cutViolations;

namespace {

/// Planar quad sweep: curve 0 = c + r0 w + s u, curve 1 = c + r1 w + s u, s in [s0, s1]
/// (curve 1 may span [s2, s3] instead, for trapezoids).
SweepSurface quadSweep(const Vec3& c, const Vec3& u, const Vec3& w, double s0, double s1, double r0,
                       double r1, int n = 4, double s2 = NAN, double s3 = NAN) {
    if (std::isnan(s2)) {
        s2 = s0;
        s3 = s1;
    }
    std::vector<Vec3> a, b;
    for (int j = 0; j <= n; ++j) {
        a.push_back(c + r0 * w + (s0 + (s1 - s0) * j / n) * u);
        b.push_back(c + r1 * w + (s2 + (s3 - s2) * j / n) * u);
    }
    SweepSurface s;
    const Status st = SweepSurface::fromStartEnd(a, b, s);
    if (!st.ok())
        qFatal("%s", st.message().c_str());
    return s;
}

TetMesh unitTet() {
    return TetMesh::fromArrays({Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0), Vec3(0, 0, 1)}, {{0, 1, 2, 3}});
}

struct Outcome {
    CutResult result;
    int pieces = 0;
    QString violations;
};

Outcome run(TetMesh& mesh, const SweepSurface& sweep, CutOptions options) {
    Outcome o;
    const double volume = mesh.totalReferenceVolume();
    HybridCutter cutter(mesh);
    const Status s = cutter.cut(sweep, options, o.result);
    if (!s.ok()) {
        o.violations = QString::fromStdString(s.message());
        return o;
    }
    o.violations = cutViolations(mesh, sweep, volume, o.result);
    o.pieces = connectedComponents(mesh).count;
    return o;
}

int schemes(const CutResult& r, Scheme s) { return r.stats.schemeCount[static_cast<int>(s)]; }

CutOptions hybrid(FaceTriangulation tri = FaceTriangulation::Enhanced) {
    CutOptions o;
    o.triangulation = tri;
    return o;
}
CutOptions subdivision() {
    CutOptions o;
    o.method = CutMethod::Subdivision;
    o.triangulation = FaceTriangulation::Standard;
    return o;
}

} // namespace

Q_DECLARE_METATYPE(resect::Scheme)

class TestCutSchemes : public QObject {
    Q_OBJECT
private slots:
    void singleTetSchemes_data() {
        QTest::addColumn<int>("cut");
        QTest::addColumn<bool>("useHybrid");
        QTest::addColumn<Scheme>("scheme");
        QTest::addColumn<int>("pieces");
        QTest::addColumn<int>("cutNodes");
        for (bool h : {true, false}) {
            const char* m = h ? "hybrid" : "subdivision";
            QTest::addRow("A, %s", m) << 0 << h << Scheme::A << 2 << 0;
            QTest::addRow("B, %s", m) << 1 << h << Scheme::B << 2 << 0;
            QTest::addRow("C partial, %s", m) << 2 << h << Scheme::C << 1 << 0;
            QTest::addRow("D partial, %s", m) << 3 << h << Scheme::D << 1 << 0;
            QTest::addRow("E partial, %s", m) << 4 << h << Scheme::E << 1 << 0;
        }
        QTest::newRow("X, hybrid") << 5 << true << Scheme::X << 2 << 1;
        QTest::newRow("X plane, subdivision is A") << 5 << false << Scheme::A << 2 << 0;
        QTest::newRow("Y, hybrid") << 6 << true << Scheme::Y << 2 << 2;
        QTest::newRow("Y plane, subdivision is A") << 6 << false << Scheme::A << 2 << 0;
        QTest::newRow("Z, hybrid") << 7 << true << Scheme::Z << 1 << 3;
        QTest::newRow("Z plane, subdivision is A") << 7 << false << Scheme::A << 2 << 0;
        QTest::newRow("touch, hybrid") << 8 << true << Scheme::Touch << 1 << 1;
    }
    void singleTetSchemes() {
        QFETCH(int, cut);
        QFETCH(bool, useHybrid);
        QFETCH(Scheme, scheme);
        QFETCH(int, pieces);
        QFETCH(int, cutNodes);
        const Vec3 diag(1, 1, 1);
        SweepSurface sweep;
        switch (cut) {
        case 0: sweep = quadSweep(diag * (0.5 / 3), Vec3(1, -1, 0), Vec3(1, 1, -2), -3, 3, -3, 3); break;
        case 1: sweep = quadSweep(Vec3(0.25, 0.25, 0), Vec3(1, -1, 0), Vec3(0, 0, 1), -3, 3, -3, 3); break;
        case 2: sweep = quadSweep(Vec3(0.5, 0, 0), Vec3(0, 1, 0), Vec3(0, 0, 1), -0.5, 0.2, -0.5, 0.2); break;
        case 3: sweep = quadSweep(Vec3(0.5, 0, 0), Vec3(0, 1, 0), Vec3(0, 0, 1), -0.5, 0.6, -0.5, 0.2); break;
        case 4:  // trapezoid over three of the four edges a B-plane would cross
            sweep = quadSweep(Vec3(0.25, 0.25, 0), Vec3(1, -1, 0), Vec3(0, 0, 1), -0.6, 0.4, -0.5, 0.6, 4, 0.0, 0.4);
            break;
        case 5: sweep = quadSweep(Vec3(0.02, 0, 0), Vec3(0, 1, -1), Vec3(1, 1, 1), -3, 3, -3, 3); break;
        case 6: sweep = quadSweep(Vec3(0, 0.01, 0), Vec3(1, 0, 0), Vec3(0, 1, 1), -3, 3, -3, 3); break;
        case 7: sweep = quadSweep(diag * (0.98 / 3), Vec3(1, -1, 0), Vec3(1, 1, -2), -3, 3, -3, 3); break;
        case 8: sweep = quadSweep(diag * (0.01 / 3), Vec3(1, -1, 0), Vec3(1, 1, -2), -3, 3, -3, 3); break;
        }
        for (FaceTriangulation tri : {FaceTriangulation::Standard, FaceTriangulation::Enhanced}) {
            TetMesh mesh = unitTet();
            const Outcome o = run(mesh, sweep, useHybrid ? hybrid(tri) : subdivision());
            QVERIFY2(o.violations.isEmpty(), qPrintable(o.violations));
            QCOMPARE(schemes(o.result, scheme), 1);
            QCOMPARE(o.result.stats.cutNodes, cutNodes);
            QCOMPARE(o.pieces, pieces);
            if (scheme == Scheme::Z || scheme == Scheme::Touch)
                QCOMPARE(mesh.tetCount(), 1);
            else
                QVERIFY(mesh.tetCount() > 1);
        }
    }

    void degenerateContact_data() {
        QTest::addColumn<int>("cut");
        QTest::addColumn<bool>("useHybrid");
        QTest::addColumn<int>("pieces");
        QTest::addColumn<bool>("unchangedTets");
        for (bool h : {true, false}) {
            const char* m = h ? "hybrid" : "subdivision";
            QTest::addRow("through a node, %s", m) << 0 << h << 2 << false;
            QTest::addRow("along existing faces, %s", m) << 1 << h << 2 << true;
            QTest::addRow("through an edge, %s", m) << 2 << h << 2 << false;
            QTest::addRow("tangent to the top face, %s", m) << 3 << h << 1 << true;
            QTest::addRow("tangent to an edge, %s", m) << 4 << h << 1 << true;
        }
    }
    void degenerateContact() {
        QFETCH(int, cut);
        QFETCH(bool, useHybrid);
        QFETCH(int, pieces);
        QFETCH(bool, unchangedTets);
        // 2 x 2 x 2 cubes on [0, 1]^3: nodes at multiples of 0.5. All sweep coordinates below
        // are exact in binary, so the contact is exact.
        TetMesh mesh = makeBoxTetMesh(Vec3::Zero(), Vec3(1, 1, 1), 2, 2, 2);
        const Vec3 centre(0.5, 0.5, 0.5);
        SweepSurface sweep;
        switch (cut) {
        case 0:  // plane (x-.5) + 2(y-.5) + 4(z-.5) = 0 holds no node but the centre
            sweep = quadSweep(centre, Vec3(2, -1, 0), Vec3(4, 0, -1), -2, 2, -2, 2);
            break;
        case 1: sweep = quadSweep(centre, Vec3(1, 0, 0), Vec3(0, 1, 0), -2, 2, -2, 2); break;
        case 2:  // plane (y-.5) + 3(z-.5) = 0 holds the nodes on the line y = z = 0.5
            sweep = quadSweep(centre, Vec3(1, 0, 0), Vec3(0, 3, -1), -2, 2, -2, 2);
            break;
        case 3: sweep = quadSweep(Vec3(0.5, 0.5, 1), Vec3(1, 0, 0), Vec3(0, 1, 0), -2, 2, -2, 2); break;
        case 4: sweep = quadSweep(Vec3(1, 0.5, 1), Vec3(0, 1, 0), Vec3(1, 0, -1), -2, 2, -2, 2); break;
        }
        const int tetsBefore = mesh.tetCount();
        const Outcome o = run(mesh, sweep, useHybrid ? hybrid() : subdivision());
        QVERIFY2(o.violations.isEmpty(), qPrintable(o.violations));
        QCOMPARE(o.pieces, pieces);
        if (unchangedTets) {
            QCOMPARE(mesh.tetCount(), tetsBefore);
            QCOMPARE(o.result.stats.decomposedTets, 0);
        }
        if (cut == 0) {
            const auto& cn = o.result.changes.cutNodes;
            QVERIFY(std::find(cn.begin(), cn.end(), 13) != cn.end());  // node (1, 1, 1) = centre
        }
        if (cut == 1)
            QCOMPARE(o.result.stats.duplicatedNodes, 9);  // the 3 x 3 nodes at z = 0.5
    }

    void edgeCutTwiceIsDiscarded() {
        // A V-shaped stroke crosses edge (0, 1) twice: both crossings are discarded.
        TetMesh mesh = TetMesh::fromArrays({Vec3(0.5, 0.25, 0.5), Vec3(0.5, 0.75, 0.5), Vec3(1, 0.5, 0),
                                            Vec3(0, 0.5, 0)},
                                           {{0, 1, 2, 3}});
        QVERIFY(mesh.referenceVolume(0) > 0);
        SweepSurface sweep;
        QVERIFY(SweepSurface::fromCurves({{Vec3(-1, 0.3, 1.5), Vec3(2, 0.3, 1.5)},
                                          {Vec3(-1, 0.5, 0.3), Vec3(2, 0.5, 0.3)},
                                          {Vec3(-1, 0.7, 1.5), Vec3(2, 0.7, 1.5)}},
                                         sweep)
                    .ok());
        const Outcome o = run(mesh, sweep, hybrid());
        QVERIFY2(o.violations.isEmpty(), qPrintable(o.violations));
        QCOMPARE(o.result.stats.discardedEdges, 1);
        QCOMPARE(o.result.stats.crossedEdges, 0);
        QCOMPARE(mesh.tetCount(), 1);
        QCOMPARE(o.pieces, 1);
    }

    void twoTetsShareTheirFaceTriangulation_data() {
        QTest::addColumn<bool>("enhanced");
        QTest::addColumn<double>("advantage");
        QTest::newRow("standard") << false << 0.0;
        QTest::newRow("enhanced, plain symmetric faces") << true << 0.0;
        QTest::newRow("enhanced, face nodes where clearly better") << true << 1.5;
    }
    void twoTetsShareTheirFaceTriangulation() {
        // Two tets on face (0, 1, 2); a plane cuts both through that face: the face's
        // triangulation must agree from both sides (no T-junction, no over-shared face).
        QFETCH(bool, enhanced);
        QFETCH(double, advantage);
        TetMesh mesh = TetMesh::fromArrays({Vec3(0, 0, 0), Vec3(2, 0, 0), Vec3(0, 2, 0), Vec3(0.5, 0.5, 1.5),
                                            Vec3(0.6, 0.4, -1.5)},
                                           {{0, 1, 2, 3}, {0, 2, 1, 4}});
        const SweepSurface sweep = quadSweep(Vec3(0.4, 0, 0), Vec3(0, 1, 0), Vec3(0, 0, 1), -3, 3, -3, 3);
        CutOptions options = hybrid(enhanced ? FaceTriangulation::Enhanced : FaceTriangulation::Standard);
        options.d = 0.05;
        options.faceNodeAdvantage = advantage;
        const Outcome o = run(mesh, sweep, options);
        QVERIFY2(o.violations.isEmpty(), qPrintable(o.violations));
        QCOMPARE(o.pieces, 2);
        if (!enhanced || advantage == 0)  // plain symmetric: every face prism gets a node
            QCOMPARE(o.result.stats.faceNodes > 0, enhanced);
    }

    void failedCutLeavesMeshUnchanged() {
        // Bad options are refused before anything changes.
        TetMesh mesh = unitTet();
        HybridCutter cutter(mesh);
        CutResult r;
        CutOptions o;
        o.d = 0.9;
        const SweepSurface sweep = quadSweep(Vec3(0.25, 0.25, 0), Vec3(1, -1, 0), Vec3(0, 0, 1), -3, 3, -3, 3);
        QVERIFY(!cutter.cut(sweep, o, r).ok());
        o.d = std::nan("");
        QVERIFY(!cutter.cut(sweep, o, r).ok());
        QCOMPARE(mesh.tetCount(), 1);
        QCOMPARE(mesh.nodeCount(), 4);
    }
};

QTEST_GUILESS_MAIN(TestCutSchemes)
#include "test_cut_schemes.moc"
