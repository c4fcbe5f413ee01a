// Tests of the boundary queries of core/mesh/topology.h on literal tets: isBoundaryEdge on a
// single tet, two tets sharing a face, a ring of tets closed around an edge (whose central
// edge is interior) and the same ring opened; both queries against their definition (a face
// in one tet only) on a box mesh.
#include "core/mesh/box_mesh.h"
#include "core/mesh/topology.h"

#include <QTest>

#include <algorithm>
#include <map>

#include <utility>
#include <vector>

using namespace resect;

namespace {

using Edges = std::vector<std::pair<int, int>>;

/// Four tets around the edge (0, 1) from (0, 0, -1) to (0, 0, 1), through the ring of nodes
/// 2..5 at (1, 0, 0), (0, 1, 0), (-1, 0, 0), (0, -1, 0) (an octahedron). `closed`: all four;
/// otherwise the tet (0, 1, 5, 2) is left out and the ring is open.
TetMesh ringAroundEdge(bool closed) {
    std::vector<Tet> tets{{0, 1, 2, 3}, {0, 1, 3, 4}, {0, 1, 4, 5}};
    if (closed)
        tets.push_back({0, 1, 5, 2});
    return TetMesh::fromArrays({Vec3(0, 0, -1), Vec3(0, 0, 1), Vec3(1, 0, 0), Vec3(0, 1, 0),
                                Vec3(-1, 0, 0), Vec3(0, -1, 0)},
                               tets);
}

/// The definition, through faceTets: some face (a, b, v) of a tet around the edge is in one tet.
bool boundaryEdgeByFaces(const TetMesh& mesh, int a, int b) {
    std::vector<int> around, face;
    mesh.edgeTets(a, b, around);
    for (int t : around)
        for (int v : mesh.tet(t)) {
            if (v == a || v == b)
                continue;
            mesh.faceTets(a, b, v, face);
            if (face.size() == 1)
                return true;
        }
    return false;
}

} // namespace

Q_DECLARE_METATYPE(Edges)

class TestTopology : public QObject {
    Q_OBJECT
private slots:
    void literalTetsArePositive() {
        // The fixtures below are valid meshes (else the test would test nothing).
        for (bool closed : {true, false}) {
            const TetMesh m = ringAroundEdge(closed);
            for (int t = 0; t < m.tetCount(); ++t)
                QVERIFY(m.referenceVolume(t) > 0);
        }
    }

    void isBoundaryEdge_data() {
        QTest::addColumn<int>("mesh");
        QTest::addColumn<Edges>("boundary");
        QTest::addColumn<Edges>("interior");
        // 0: one tet: every edge is on the boundary.
        QTest::newRow("single tet")
            << 0 << Edges{{0, 1}, {0, 2}, {0, 3}, {1, 2}, {1, 3}, {2, 3}, {3, 0}} << Edges{};
        // 1: two tets on face (0, 1, 2): the shared face is interior, but each of its edges
        // also lies on a face of one tet only, so all nine edges are on the boundary.
        QTest::newRow("two tets sharing a face")
            << 1 << Edges{{0, 1}, {1, 2}, {2, 0}, {0, 3}, {1, 3}, {2, 3}, {0, 4}, {1, 4}, {2, 4}}
            << Edges{};
        // 2: the closed ring: its central edge is inside, every other edge on the hull.
        QTest::newRow("closed ring around an edge")
            << 2 << Edges{{0, 2}, {1, 3}, {2, 3}, {3, 4}, {4, 5}, {5, 2}, {0, 5}, {1, 4}}
            << Edges{{0, 1}, {1, 0}};
        // 3: the same ring with one tet removed: the central edge is on the boundary again.
        QTest::newRow("open ring around an edge")
            << 3 << Edges{{0, 1}, {1, 0}, {2, 3}, {0, 2}} << Edges{};
        // Pairs that are not edges of the mesh are not boundary edges.
        QTest::newRow("not an edge: opposite ring nodes") << 2 << Edges{} << Edges{{2, 4}, {3, 5}};
        QTest::newRow("not an edge: apexes of two tets") << 1 << Edges{} << Edges{{3, 4}};
    }
    void isBoundaryEdge() {
        QFETCH(int, mesh);
        QFETCH(Edges, boundary);
        QFETCH(Edges, interior);
        TetMesh m;
        switch (mesh) {
        case 0:
            m = TetMesh::fromArrays({Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0), Vec3(0, 0, 1)},
                                    {{0, 1, 2, 3}});
            break;
        case 1:
            m = TetMesh::fromArrays({Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0), Vec3(0.2, 0.2, 1),
                                     Vec3(0.3, 0.3, -1)},
                                    {{0, 1, 2, 3}, {0, 2, 1, 4}});
            break;
        case 2:
            m = ringAroundEdge(true);
            break;
        case 3:
            m = ringAroundEdge(false);
            break;
        }
        for (const auto& [a, b] : boundary)
            QVERIFY2(resect::isBoundaryEdge(m, a, b),
                     qPrintable(QString("(%1, %2)").arg(a).arg(b)));
        for (const auto& [a, b] : interior)
            QVERIFY2(!resect::isBoundaryEdge(m, a, b),
                     qPrintable(QString("(%1, %2)").arg(a).arg(b)));
    }

    void boundaryQueriesMatchTheirDefinition() {
        // 2 x 2 x 2 cubes: 27 nodes, one of them (the centre) interior; edges inside the box
        // are interior. Both queries agree with "a face in one tet" for every node and edge.
        const TetMesh m = makeBoxTetMesh(Vec3::Zero(), Vec3(1, 1, 1), 2, 2, 2);
        int interiorEdges = 0;
        for (const auto& e : uniqueEdges(m)) {
            const bool expected = boundaryEdgeByFaces(m, e[0], e[1]);
            QCOMPARE(resect::isBoundaryEdge(m, e[0], e[1]), expected);
            QCOMPARE(resect::isBoundaryEdge(m, e[1], e[0]), expected);
            interiorEdges += expected ? 0 : 1;
        }
        QVERIFY(interiorEdges > 0);
        std::vector<char> onBoundaryFace(m.nodeCount(), 0);
        for (const BoundaryFace& f : boundaryFaces(m))
            for (int v : f.nodes)
                onBoundaryFace[v] = 1;
        int interiorNodes = 0;
        for (int n = 0; n < m.nodeCount(); ++n) {
            QCOMPARE(resect::isBoundaryNode(m, n), onBoundaryFace[n] != 0);
            interiorNodes += onBoundaryFace[n] ? 0 : 1;
        }
        QCOMPARE(interiorNodes, 1);
    }

    void facesFollowTheirDefinition_data() {
        QTest::addColumn<int>("which");
        QTest::newRow("box") << 0;
        QTest::newRow("box cut in two, nodes duplicated") << 1;
        QTest::newRow("a face in three tets, an unused node") << 2;
        QTest::newRow("flat and repeated-node tets") << 3;
    }
    void facesFollowTheirDefinition() {
        // allFaces and boundaryFaces (a counting sort by smallest node, not a hash map) give the
        // faces a scan of the tets meets, in that order, oriented as in their first tet, with
        // their second tet and the count of extra ones; boundaryFaces those in one tet.
        QFETCH(int, which);
        TetMesh m;
        if (which == 0) {
            m = makeBoxTetMesh(Vec3::Zero(), Vec3(3, 2, 1), 4, 3, 2);
        } else if (which == 1) {
            // Every tet with its centroid above z = 0.5 gets its own copies of the nodes it
            // shares with the tets below (a complete cut along the cells' faces).
            const TetMesh box = makeBoxTetMesh(Vec3::Zero(), Vec3(2, 2, 1), 3, 3, 2);
            std::vector<Vec3> nodes(box.positions().begin(), box.positions().end());
            std::vector<Tet> tets(box.tets().begin(), box.tets().end());
            std::vector<int> copy(nodes.size(), -1);
            for (Tet& q : tets) {
                Vec3 c = Vec3::Zero();
                for (int v : q)
                    c += nodes[v] / 4;
                if (c.z() > 0.5)
                    for (int& v : q)
                        if (nodes[v].z() == 0.5) {
                            if (copy[v] < 0) {
                                copy[v] = static_cast<int>(nodes.size());
                                nodes.push_back(nodes[v]);
                            }
                            v = copy[v];
                        }
            }
            m = TetMesh::fromArrays(std::move(nodes), std::move(tets));
            QCOMPARE(connectedComponents(m).count, 2);
        } else if (which == 2) {
            m = TetMesh::fromArrays({Vec3(0, 0, 0), Vec3(2, 0, 0), Vec3(0, 2, 0), Vec3(0.5, 0.5, 1),
                                     Vec3(0.5, 0.5, -1), Vec3(1.5, 0.2, 2), Vec3(9, 9, 9)},
                                    {{0, 1, 2, 3}, {0, 2, 1, 4}, {0, 1, 2, 5}});
        } else {
            m = TetMesh::fromArrays({Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0), Vec3(1, 1, 0), Vec3(0, 0, 1)},
                                    {{0, 1, 2, 3}, {0, 1, 2, 4}, {0, 0, 1, 4}});
        }
        // The definition, straight: scan the tets' faces in order; a face met before (same
        // nodes in any order) gets the tet as its second, or counts as an extra.
        std::vector<MeshFace> expected;
        std::map<std::array<int, 3>, std::size_t> seen;
        for (int t = 0; t < m.tetCount(); ++t)
            for (const auto& lf : kTetFaces) {
                const Tri f{m.tet(t)[lf[0]], m.tet(t)[lf[1]], m.tet(t)[lf[2]]};
                std::array<int, 3> key = f;
                std::sort(key.begin(), key.end());
                const auto [it, fresh] = seen.emplace(key, expected.size());
                if (fresh)
                    expected.push_back({f, {t, -1}, 0});
                else if (expected[it->second].tets[1] < 0)
                    expected[it->second].tets[1] = t;
                else
                    ++expected[it->second].extraTets;
            }
        const std::vector<MeshFace> all = allFaces(m);
        QCOMPARE(all.size(), expected.size());
        for (std::size_t i = 0; i < all.size(); ++i)
            QVERIFY2(all[i].nodes == expected[i].nodes && all[i].tets == expected[i].tets &&
                         all[i].extraTets == expected[i].extraTets,
                     qPrintable(QString("face %1").arg(i)));
        std::vector<BoundaryFace> boundary;
        for (const MeshFace& f : expected)
            if (f.tets[1] < 0)
                boundary.push_back({f.nodes, f.tets[0]});
        const std::vector<BoundaryFace> got = boundaryFaces(m);
        QCOMPARE(got.size(), boundary.size());
        QVERIFY(!got.empty());
        for (std::size_t i = 0; i < got.size(); ++i)
            QVERIFY2(got[i].nodes == boundary[i].nodes && got[i].tet == boundary[i].tet,
                     qPrintable(QString("face %1").arg(i)));
        if (which == 2)
            QVERIFY(std::any_of(all.begin(), all.end(), [](const MeshFace& f) { return f.extraTets == 1; }));
    }
};

QTEST_GUILESS_MAIN(TestTopology)
#include "test_topology.moc"
