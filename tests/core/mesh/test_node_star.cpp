// Tests of NodeStar (core/mesh/node_star.h) against the queries it stands in for,
// TetMesh::nodeNeighbours and isBoundaryNode: on a box mesh, on a box after cuts (crack
// faces, copies of cut nodes), and on stars of more than 64 neighbours, closed and opened,
// where it counts faces by sorting instead of with bit masks.
#include "core/cut/hybrid_cutter.h"
#include "core/mesh/box_mesh.h"
#include "core/mesh/node_star.h"
#include "core/mesh/topology.h"

#include <QTest>

#include <cmath>
#include <numbers>
#include <vector>

using namespace resect;

namespace {

/// Node 0 at the origin inside a closed ring of `k` nodes in the plane z = 0 between a top
/// and a bottom node: 2k tets, 2 + k neighbours. Without `closed` the last two tets are left
/// out, which opens the star.
TetMesh ringStar(int k, bool closed) {
    std::vector<Vec3> nodes{Vec3::Zero(), Vec3(0, 0, 1), Vec3(0, 0, -1)};
    for (int i = 0; i < k; ++i) {
        const double a = 2 * std::numbers::pi * i / k;
        nodes.push_back(Vec3(std::cos(a), std::sin(a), 0));
    }
    std::vector<Tet> tets;
    for (int i = 0; i < (closed ? k : k - 1); ++i) {
        const int r0 = 3 + i, r1 = 3 + (i + 1) % k;
        tets.push_back({0, r0, r1, 1});
        tets.push_back({0, r1, r0, 2});
    }
    return TetMesh::fromArrays(nodes, tets);
}

/// Every node's star against nodeNeighbours and isBoundaryNode; returns how many nodes are
/// on the boundary (so that callers can check both answers occurred).
int compareEveryNode(const TetMesh& mesh) {
    NodeStar star;
    int boundary = 0;
    for (int n = 0; n < mesh.nodeCount(); ++n) {
        star.gather(mesh, n);
        const std::vector<int> expected = mesh.nodeNeighbours(n);
        const std::vector<int> got(star.neighbours().begin(), star.neighbours().end());
        if (got != expected)
            qFatal("neighbours of node %d differ", n);
        if (star.onBoundary() != isBoundaryNode(mesh, n))
            qFatal("boundary flag of node %d differs", n);
        boundary += star.onBoundary() ? 1 : 0;
    }
    return boundary;
}

} // namespace

class TestNodeStar : public QObject {
    Q_OBJECT
private slots:
    void boxMesh() {
        const TetMesh m = makeBoxTetMesh(Vec3::Zero(), Vec3(1, 1, 1), 3, 3, 3);
        // 64 nodes, of which the 2 x 2 x 2 inside the box are interior.
        QCOMPARE(compareEveryNode(m), 64 - 8);
    }

    void boxAfterCuts() {
        TetMesh m = makeBoxTetMesh(Vec3::Zero(), Vec3(1, 1, 1), 5, 5, 5);
        HybridCutter cutter(m);
        const int boundaryBefore = compareEveryNode(m);
        // A tilted plane through the whole box, then a partial cut ending inside it.
        const std::vector<std::vector<Vec3>> sweeps[2] = {
            {{Vec3(-1, -1, 0.43), Vec3(2, -1, 0.52)}, {Vec3(-1, 2, 0.47), Vec3(2, 2, 0.55)}},
            {{Vec3(0.31, -1, -1), Vec3(0.36, -1, 2)}, {Vec3(0.33, 0.6, -1), Vec3(0.38, 0.6, 2)}},
        };
        for (const auto& curves : sweeps) {
            SweepSurface sweep;
            QVERIFY(SweepSurface::fromCurves(curves, sweep).ok());
            CutOptions options;
            options.snap = true;
            CutResult result;
            QVERIFY(cutter.cut(sweep, options, result).ok());
            QVERIFY(!result.changes.duplicatedNodes.empty());
        }
        // The crack faces put nodes inside the box on the boundary.
        QVERIFY(compareEveryNode(m) > boundaryBefore);
    }

    void largeStars_data() {
        QTest::addColumn<int>("ring");
        QTest::addColumn<bool>("closed");
        // 2 + ring neighbours: 62 fits the bit masks, 80 does not (sorted faces).
        QTest::newRow("60 closed") << 60 << true;
        QTest::newRow("60 open") << 60 << false;
        QTest::newRow("80 closed") << 80 << true;
        QTest::newRow("80 open") << 80 << false;
    }
    void largeStars() {
        QFETCH(int, ring);
        QFETCH(bool, closed);
        const TetMesh m = ringStar(ring, closed);
        NodeStar star;
        star.gather(m, 0);
        QCOMPARE(static_cast<int>(star.neighbours().size()), ring + 2);
        QCOMPARE(star.onBoundary(), !closed);
        QCOMPARE(star.onBoundary(), isBoundaryNode(m, 0));
        compareEveryNode(m);
    }
};

QTEST_GUILESS_MAIN(TestNodeStar)
#include "test_node_star.moc"
