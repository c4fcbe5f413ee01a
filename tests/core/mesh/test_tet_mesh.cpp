// Tests of TetMesh: adjacency, incremental edits, derived topology.
#include "core/mesh/box_mesh.h"
#include "core/mesh/tet_mesh.h"
#include "core/mesh/topology.h"
#include "core/mesh/triangle_surface.h"

#include <QTest>

#include <algorithm>
#include <random>
#include <set>

using namespace resect;

namespace {

std::multiset<int> sortedTets(std::span<const int> s) { return {s.begin(), s.end()}; }

/// Every node's adjacency equals that of a mesh rebuilt from scratch.
bool adjacencyMatchesRebuild(const TetMesh& mesh) {
    const TetMesh rebuilt = TetMesh::fromArrays(
        std::vector<Vec3>(mesh.referencePositions().begin(), mesh.referencePositions().end()),
        mesh.tets());
    for (int n = 0; n < mesh.nodeCount(); ++n)
        if (sortedTets(mesh.nodeTets(n)) != sortedTets(rebuilt.nodeTets(n)))
            return false;
    return true;
}

} // namespace

class TestTetMesh : public QObject {
    Q_OBJECT
private slots:
    void singleTetAdjacency() {
        const TetMesh m = TetMesh::fromArrays(
            {Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0), Vec3(0, 0, 1)}, {{0, 1, 2, 3}});
        QCOMPARE(m.nodeCount(), 4);
        QCOMPARE(m.tetCount(), 1);
        for (int n = 0; n < 4; ++n)
            QCOMPARE(m.nodeTets(n).size(), std::size_t(1));
        std::vector<int> out;
        m.edgeTets(0, 3, out);
        QCOMPARE(out, std::vector<int>{0});
        m.faceTets(1, 2, 3, out);
        QCOMPARE(out, std::vector<int>{0});
        QCOMPARE(m.nodeNeighbours(0), (std::vector<int>{1, 2, 3}));
        QCOMPARE(m.referenceVolume(0), 1.0 / 6.0);
        QCOMPARE(uniqueEdges(m).size(), std::size_t(6));
        QCOMPARE(boundaryFaces(m).size(), std::size_t(4));
    }

    void boxMeshCountsAndVolume_data() {
        QTest::addColumn<int>("n");
        QTest::addColumn<double>("scale");
        QTest::newRow("1 cube") << 1 << 1.0;
        QTest::newRow("2^3 cubes") << 2 << 1.0;
        QTest::newRow("3^3 cubes, 1e-3") << 3 << 1e-3;
        QTest::newRow("4^3 cubes, 1e3") << 4 << 1e3;
    }
    void boxMeshCountsAndVolume() {
        QFETCH(int, n);
        QFETCH(double, scale);
        const TetMesh m = makeBoxTetMesh(Vec3::Zero(), Vec3(2, 3, 5) * scale, n, n, n);
        QCOMPARE(m.tetCount(), 6 * n * n * n);
        QCOMPARE(m.nodeCount(), (n + 1) * (n + 1) * (n + 1));
        // Kuhn subdivision: axis edges + one diagonal per square + one per cube.
        const int edges = 3 * n * (n + 1) * (n + 1) + 3 * n * n * (n + 1) + n * n * n;
        QCOMPARE(int(uniqueEdges(m).size()), edges);
        const double volume = 30 * scale * scale * scale;
        QVERIFY(std::abs(m.totalReferenceVolume() - volume) <= 1e-12 * volume);
        for (int t = 0; t < m.tetCount(); ++t)
            QVERIFY(m.referenceVolume(t) > 0);
        // Euler characteristic of a ball: V - E + F - T = 1.
        const int faces = int(allFaces(m).size());
        QCOMPARE(m.nodeCount() - edges + faces - m.tetCount(), 1);
        // Boundary faces: two triangles per boundary square, oriented outward, so the
        // volume they enclose is the mesh volume.
        const auto boundary = boundaryFaces(m);
        QCOMPARE(int(boundary.size()), 12 * n * n);
        TriangleSurface s;
        s.positions.assign(m.referencePositions().begin(), m.referencePositions().end());
        for (const auto& f : boundary)
            s.triangles.push_back(f.nodes);
        QVERIFY(std::abs(enclosedVolume(s) - volume) <= 1e-12 * volume);
        QCOMPARE(connectedComponents(m).count, 1);
    }

    void componentsOfSeparatedTets() {
        // Two tets touching geometrically along a face but with distinct nodes: two pieces.
        TetMesh m = TetMesh::fromArrays({Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0), Vec3(0, 0, 1),
                                         Vec3(0, 0, 0), Vec3(0, 1, 0), Vec3(1, 0, 0), Vec3(0, 0, -1)},
                                        {{0, 1, 2, 3}, {4, 5, 6, 7}});
        Components c = connectedComponents(m);
        QCOMPARE(c.count, 2);
        QVERIFY(c.tetComponent[0] != c.tetComponent[1]);
        // Gluing them by re-attaching the second tet to the first tet's nodes: one piece.
        m.replaceTet(1, {0, 2, 1, 7});
        c = connectedComponents(m);
        QCOMPARE(c.count, 1);
        QCOMPARE(c.nodeComponent[4], -1);  // now unused
        QVERIFY(adjacencyMatchesRebuild(m));
    }

    void incrementalEditsMatchRebuild() {
        // Random 1-to-4 splits at centroids, each done with replaceTet + addTet + addNode.
        TetMesh m = makeBoxTetMesh(Vec3::Zero(), Vec3(1, 1, 1), 2, 2, 2);
        const double volume = m.totalReferenceVolume();
        std::mt19937 rng(42);
        for (int step = 0; step < 200; ++step) {
            const int t = std::uniform_int_distribution<int>(0, m.tetCount() - 1)(rng);
            const Tet q = m.tet(t);
            Vec3 c = Vec3::Zero();
            for (int v : q)
                c += m.ref(v) / 4.0;
            const int mid = m.addNode(c, c);
            m.replaceTet(t, {q[0], q[1], q[2], mid});
            m.addTet({q[0], q[3], q[1], mid});
            m.addTet({q[0], q[2], q[3], mid});
            m.addTet({q[1], q[3], q[2], mid});
        }
        QCOMPARE(m.tetCount(), 48 + 3 * 200);
        QVERIFY(adjacencyMatchesRebuild(m));
        for (int t = 0; t < m.tetCount(); ++t)
            QVERIFY2(m.referenceVolume(t) > 0, qPrintable(QString("tet %1").arg(t)));
        QVERIFY(std::abs(m.totalReferenceVolume() - volume) <= 1e-12 * volume);
    }

    void checkTetIndicesReportsBadInput() {
        QVERIFY(checkTetIndices(4, std::vector<Tet>{{0, 1, 2, 3}}).empty());
        QVERIFY(checkTetIndices(4, std::vector<Tet>{{0, 1, 2, 4}}).find("node 4") != std::string::npos);
        QVERIFY(checkTetIndices(4, std::vector<Tet>{{0, 1, 2, -1}}).find("tet 0") != std::string::npos);
        QVERIFY(checkTetIndices(4, std::vector<Tet>{{0, 1, 1, 3}}).find("twice") != std::string::npos);
    }
};

QTEST_GUILESS_MAIN(TestTetMesh)
#include "test_tet_mesh.moc"
