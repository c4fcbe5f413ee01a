// Tests of the validity check: each kind of problem is caught, valid meshes are clean,
// and separated (cut) meshes with coincident nodes raise no false alarm.
#include "core/mesh/box_mesh.h"
#include "core/mesh/predicates.h"
#include "core/mesh/validity.h"

#include <QTest>

#include <algorithm>
#include <limits>

using namespace resect;
using Kind = MeshProblem::Kind;

namespace {

int countKind(const std::vector<MeshProblem>& problems, Kind kind, int element = -1) {
    return int(std::count_if(problems.begin(), problems.end(), [&](const MeshProblem& p) {
        return p.kind == kind && (element < 0 || p.element == element);
    }));
}

QString describe(const std::vector<MeshProblem>& problems) {
    QStringList lines;
    for (const auto& p : problems)
        lines << QString::fromStdString(p.message);
    return lines.join("; ");
}

// Face (a, b, c) in the plane z = 0, apex d above it, e below it.
const Vec3 a(0, 0, 0), b(2, 0, 0), c(0, 2, 0), d(0.5, 0.5, 1), e(0.5, 0.5, -1);

} // namespace

class TestValidity : public QObject {
    Q_OBJECT
private slots:
    void validMeshesAreClean_data() {
        QTest::addColumn<double>("scale");
        QTest::newRow("1") << 1.0;
        QTest::newRow("1e-6") << 1e-6;
        QTest::newRow("1e6") << 1e6;
    }
    void validMeshesAreClean() {
        QFETCH(double, scale);
        const TetMesh m = makeBoxTetMesh(Vec3::Zero(), Vec3(1, 2, 3) * scale, 3, 2, 4);
        const auto problems = checkValidity(m);
        QVERIFY2(problems.empty(), qPrintable(describe(problems)));
    }

    void twoTetsSharingAFace() {
        const TetMesh m = TetMesh::fromArrays({a, b, c, d, e}, {{0, 1, 2, 3}, {0, 2, 1, 4}});
        const auto problems = checkValidity(m);
        QVERIFY2(problems.empty(), qPrintable(describe(problems)));
    }

    void invertedTet() {
        TetMesh m = makeBoxTetMesh(Vec3::Zero(), Vec3(1, 1, 1), 2, 2, 2);
        Tet t = m.tet(17);
        std::swap(t[0], t[1]);
        m.replaceTet(17, t);
        const auto problems = checkValidity(m);
        QCOMPARE(countKind(problems, Kind::InvertedTet), 1);
        QCOMPARE(countKind(problems, Kind::InvertedTet, 17), 1);
    }

    void zeroVolumeTet() {
        const TetMesh m = TetMesh::fromArrays({a, b, c, Vec3(1, 1, 0)}, {{0, 1, 2, 3}});
        const auto problems = checkValidity(m);
        QCOMPARE(countKind(problems, Kind::ZeroVolumeTet, 0), 1);
        QCOMPARE(countKind(problems, Kind::InvertedTet), 0);
    }

    void nearlyFlatTetIsNotZero() {
        // Exact predicates: a tiny but non-zero volume is positive, not zero.
        const TetMesh m = TetMesh::fromArrays({a, b, c, Vec3(1, 1, 1e-300)}, {{0, 1, 2, 3}});
        const auto problems = checkValidity(m);
        QVERIFY2(problems.empty(), qPrintable(describe(problems)));
    }

    void nonFiniteCoordinates_data() {
        QTest::addColumn<double>("value");
        QTest::addColumn<bool>("reference");
        QTest::newRow("NaN reference") << std::numeric_limits<double>::quiet_NaN() << true;
        QTest::newRow("inf current") << std::numeric_limits<double>::infinity() << false;
    }
    void nonFiniteCoordinates() {
        QFETCH(double, value);
        QFETCH(bool, reference);
        TetMesh m = makeBoxTetMesh(Vec3::Zero(), Vec3(1, 1, 1), 1, 1, 1);
        if (reference)
            m.referencePositions()[5].y() = value;
        else
            m.positions()[5].z() = value;
        const auto problems = checkValidity(m);
        QCOMPARE(countKind(problems, Kind::NonFiniteCoordinate, 5), 1);
    }

    void unusedNode() {
        TetMesh m = makeBoxTetMesh(Vec3::Zero(), Vec3(1, 1, 1), 1, 1, 1);
        const int n = m.addNode(Vec3(5, 5, 5), Vec3(5, 5, 5));
        const auto problems = checkValidity(m);
        QCOMPARE(countKind(problems, Kind::UnusedNode, n), 1);
        QCOMPARE(int(problems.size()), 1);
    }

    void invertedInCurrentConfiguration() {
        TetMesh m = TetMesh::fromArrays({a, b, c, d}, {{0, 1, 2, 3}});
        m.positions()[3] = Vec3(0.5, 0.5, -1);  // apex pushed through the base
        const auto problems = checkValidity(m);
        QCOMPARE(countKind(problems, Kind::InvertedCurrentTet, 0), 1);
        QCOMPARE(countKind(problems, Kind::InvertedTet), 0);
    }

    void faceSharedByThreeTets() {
        const Vec3 d2(1.5, 0.2, 2);
        const TetMesh m =
            TetMesh::fromArrays({a, b, c, d, e, d2}, {{0, 1, 2, 3}, {0, 2, 1, 4}, {0, 1, 2, 5}});
        const auto problems = checkValidity(m);
        QCOMPARE(countKind(problems, Kind::OverSharedFace), 1);
    }

    void hangingNodeOnEdge() {
        // Above face abc one tet; below it, abc is split at the midpoint m of ab.
        const Vec3 mid = (a + b) / 2;
        const TetMesh m = TetMesh::fromArrays({a, b, c, d, e, mid},
                                              {{0, 1, 2, 3}, {0, 2, 5, 4}, {5, 2, 1, 4}});
        for (int t = 0; t < m.tetCount(); ++t)
            QVERIFY(m.referenceVolume(t) > 0);
        const auto problems = checkValidity(m);
        QVERIFY2(countKind(problems, Kind::TJunction) >= 1, qPrintable(describe(problems)));
    }

    void hangingNodeInsideFace() {
        // Below face abc, three tets meet at its centroid g: g hangs inside abc.
        const Vec3 g = (a + b + c) / 3;
        const TetMesh m = TetMesh::fromArrays(
            {a, b, c, d, e, g}, {{0, 1, 2, 3}, {0, 5, 1, 4}, {1, 5, 2, 4}, {2, 5, 0, 4}});
        for (int t = 0; t < m.tetCount(); ++t)
            QVERIFY(m.referenceVolume(t) > 0);
        const auto problems = checkValidity(m);
        QCOMPARE(countKind(problems, Kind::TJunction, 5), 1);
    }

    void separatedCoincidentNodesAreValid() {
        // A cut along abc: the lower tet has its own copies of a, b, c at the same places,
        // and its side of the cut is triangulated differently (split at the midpoint of ab).
        const Vec3 mid = (a + b) / 2;
        const TetMesh m = TetMesh::fromArrays({a, b, c, d, a, b, c, e, mid},
                                              {{0, 1, 2, 3}, {4, 6, 8, 7}, {8, 6, 5, 7}});
        const auto problems = checkValidity(m);
        QVERIFY2(problems.empty(), qPrintable(describe(problems)));
    }

    // deepestOverlap: none in valid meshes (at three scales, and across a cut whose sides are
    // triangulated differently); the depth of a corner pushed into the neighbouring tet.
    void noOverlapInValidMeshes_data() { validMeshesAreClean_data(); }
    void noOverlapInValidMeshes() {
        QFETCH(double, scale);
        const TetMesh m = makeBoxTetMesh(Vec3::Zero(), Vec3(1, 2, 3) * scale, 3, 2, 4);
        QCOMPARE(deepestOverlap(m).depth, 0.0);
        QCOMPARE(deepestOverlap(m).node, -1);
        const Vec3 mid = (a + b) / 2;
        const TetMesh cut = TetMesh::fromArrays({a * scale, b * scale, c * scale, d * scale, a * scale, b * scale,
                                                 c * scale, e * scale, mid * scale},
                                                {{0, 1, 2, 3}, {4, 6, 8, 7}, {8, 6, 5, 7}});
        QCOMPARE(deepestOverlap(cut).depth, 0.0);
    }
    void overlapDepth_data() { validMeshesAreClean_data(); }
    void overlapDepth() {
        QFETCH(double, scale);
        // Two separate tets (the lower one with its own copies of a, b, c, as after a cut),
        // then the lower one's copy of a pushed up into the upper one, 0.1 above the plane of
        // abc (the upper tet's nearest face there).
        const Vec3 inside = Vec3(0.3, 0.3, 0.1);
        const TetMesh m = TetMesh::fromArrays({a * scale, b * scale, c * scale, d * scale, inside * scale, b * scale,
                                               c * scale, e * scale},
                                              {{0, 1, 2, 3}, {4, 6, 5, 7}});
        const MeshOverlap o = deepestOverlap(m);
        QCOMPARE(o.node, 4);
        QCOMPARE(o.tet, 0);
        QVERIFY2(std::abs(o.depth - 0.1 * scale) <= 1e-12 * scale, qPrintable(QString::number(o.depth)));
        // Sharing a node does not hide it: the same with the lower tet on the upper one's b, c.
        const TetMesh shared = TetMesh::fromArrays({a * scale, b * scale, c * scale, d * scale, inside * scale, e * scale},
                                                   {{0, 1, 2, 3}, {4, 2, 1, 5}});
        QCOMPARE(deepestOverlap(shared).node, 4);
        // Non-finite coordinates are skipped, not trusted.
        TetMesh bad = m;
        bad.setNodePosition(4, Vec3::Constant(std::numeric_limits<double>::quiet_NaN()),
                            Vec3::Constant(std::numeric_limits<double>::quiet_NaN()));
        QCOMPARE(deepestOverlap(bad).node, -1);
    }

    // depthInside: the distance to the nearest face plane strictly inside, 0 on a face, at a
    // corner and outside (exact decisions: a point rounded onto a face plane is not inside);
    // deepestOverlap measures an inverted tet too.
    void depthInsideAtScales_data() { validMeshesAreClean_data(); }
    void depthInsideAtScales() {
        QFETCH(double, scale);
        const std::array<Vec3, 4> t = {a * scale, b * scale, c * scale, d * scale};
        QVERIFY(orient3d(t[0], t[1], t[2], t[3]) > 0);
        const Vec3 inside = Vec3(0.2, 0.25, 0.1) * scale;  // nearest: the face abc (z = 0)
        QVERIFY2(std::abs(depthInside(inside, t) - 0.1 * scale) <= 1e-12 * scale,
                 qPrintable(QString::number(depthInside(inside, t))));
        QCOMPARE(depthInside(Vec3(0.2, 0.25, 0) * scale, t), 0.0);        // on abc
        QCOMPARE(depthInside(Vec3(0.2, 0.25, -1e-300) * scale, t), 0.0);  // just below it
        QCOMPARE(depthInside(t[3], t), 0.0);                               // a corner
        QCOMPARE(depthInside(Vec3(2, 2, 2) * scale, t), 0.0);              // outside
        QVERIFY(depthInside(Vec3(0.2, 0.25, 1e-300) * scale, t) > 0);     // just above abc
        // An inverted tet holding another tet's node: found as in its positive twin.
        const TetMesh m = TetMesh::fromArrays({a * scale, c * scale, b * scale, d * scale, inside, b * scale,
                                               c * scale, e * scale},
                                              {{0, 1, 2, 3}, {4, 6, 5, 7}});
        QVERIFY(orient3d(m.ref(0), m.ref(1), m.ref(2), m.ref(3)) < 0);
        const MeshOverlap o = deepestOverlap(m);
        QCOMPARE(o.node, 4);
        QCOMPARE(o.tet, 0);
        QVERIFY2(std::abs(o.depth - 0.1 * scale) <= 1e-12 * scale, qPrintable(QString::number(o.depth)));
    }

    void problemsNameTheElement() {
        const TetMesh m = TetMesh::fromArrays({a, b, c, Vec3(1, 1, 0)}, {{0, 1, 2, 3}});
        const auto problems = checkValidity(m);
        QVERIFY(!problems.empty());
        QVERIFY(problems[0].message.find("tet 0") != std::string::npos);
        QCOMPARE(QString(toString(problems[0].kind)), QString("zero_volume_tet"));
    }
};

QTEST_GUILESS_MAIN(TestValidity)
#include "test_validity.moc"
