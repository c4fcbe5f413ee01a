// Step 5 alone (separate.h, sections 4.3-4.4) on literal tets with a literal selection and
// decomposition (cut vertices and the side of each tet): cut vertices are duplicated once per
// extra group of their tets, tets are re-attached to the copy of their side, the copies
// coincide with the original (positions, reference positions, velocities), and the two sides
// no longer share a node. A face is only a cut face between opposite sides with all corners
// cut, so the border of a partial cut and tets on one side are not separated.
#include "step_fixtures.h"

#include "core/cut/separate.h"
#include "core/mesh/topology.h"

#include <QTest>

#include <algorithm>
#include <map>
#include <set>

using namespace resect;

namespace {

/// Two tets on face (0, 1, 2) in the plane z = 0: tet 0 = (0, 1, 2, 3) above, tet 1 =
/// (0, 2, 1, 4) below.
TetMesh twoTets() {
    return TetMesh::fromArrays(
        {Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0), Vec3(0.2, 0.2, 1), Vec3(0.3, 0.3, -1)},
        {{0, 1, 2, 3}, {0, 2, 1, 4}});
}

/// Four tets around edge (0, 1) from (0, 0, -1) to (0, 0, 1) through the ring 2..5 at
/// (1, 0, 0), (0, 1, 0), (-1, 0, 0), (0, -1, 0): tets 0 and 1 at y >= 0, tets 2 and 3 at
/// y <= 0. The plane y = 0 holds nodes 0, 1, 2 and 4.
TetMesh ring() {
    return TetMesh::fromArrays({Vec3(0, 0, -1), Vec3(0, 0, 1), Vec3(1, 0, 0), Vec3(0, 1, 0),
                                Vec3(-1, 0, 0), Vec3(0, -1, 0)},
                               {{0, 1, 2, 3}, {0, 1, 3, 4}, {0, 1, 4, 5}, {0, 1, 5, 2}});
}

struct SeparateCase {
    TetMesh mesh;
    CutSelection selection;
    Decomposition decomposition;
};

SeparateCase makeCase(int id) {
    SeparateCase c;
    switch (id) {
    case 0: // the shared face's corners are cut nodes, the tets on opposite sides
        c.mesh = twoTets();
        c.selection.cutNodes = {0, 1, 2};
        c.decomposition.tetSide = {{0, 1}, {1, -1}};
        break;
    case 1: // the same with node 2 a split point (the key of its cut edge is not read)
        c.mesh = twoTets();
        c.selection.cutNodes = {0, 1};
        c.decomposition.edgePoint = {{edgeKey(3, 4), 2}};
        c.decomposition.tetSide = {{0, 1}, {1, -1}};
        break;
    case 2: // node 2 not on the cut (the border of a partial cut): the face joins the tets
        c.mesh = twoTets();
        c.selection.cutNodes = {0, 1};
        c.decomposition.tetSide = {{0, 1}, {1, -1}};
        break;
    case 3: // both tets on the same side: no cut face
        c.mesh = twoTets();
        c.selection.cutNodes = {0, 1, 2};
        c.decomposition.tetSide = {{0, 1}, {1, 1}};
        break;
    case 4: // tets inside a partially cut tet (side 0) are never separated
        c.mesh = twoTets();
        c.selection.cutNodes = {0, 1, 2};
        c.decomposition.tetSide = {{0, 0}, {1, 0}};
        break;
    case 5: // the ring cut by y = 0: two tets on each side
        c.mesh = ring();
        c.selection.cutNodes = {0, 1, 2, 4};
        c.decomposition.tetSide = {{0, 1}, {1, 1}, {2, -1}, {3, -1}};
        break;
    }
    return c;
}

} // namespace

class TestSeparate : public QObject {
    Q_OBJECT
private slots:
    void fixturesArePositivelyOriented() {
        for (const TetMesh& m : {twoTets(), ring()})
            for (int t = 0; t < m.tetCount(); ++t)
                QVERIFY(m.referenceVolume(t) > 0);
    }

    void separate_data() {
        QTest::addColumn<int>("id");
        QTest::addColumn<int>("duplicated");
        QTest::addColumn<int>("separatedTets");
        QTest::addColumn<int>("pieces");
        QTest::newRow("face of cut nodes between opposite sides") << 0 << 3 << 1 << 2;
        QTest::newRow("a split point is duplicated like a cut node") << 1 << 3 << 1 << 2;
        QTest::newRow("border of a partial cut: not duplicated") << 2 << 0 << 0 << 1;
        QTest::newRow("one side only: not duplicated") << 3 << 0 << 0 << 1;
        QTest::newRow("inside a partially cut tet: not duplicated") << 4 << 0 << 0 << 1;
        QTest::newRow("ring around an edge cut through it") << 5 << 4 << 2 << 2;
    }
    void separate() {
        QFETCH(int, id);
        QFETCH(int, duplicated);
        QFETCH(int, separatedTets);
        QFETCH(int, pieces);
        SeparateCase c = makeCase(id);
        TetMesh& mesh = c.mesh;
        const int nodesBefore = mesh.nodeCount();
        for (int v = 0; v < nodesBefore; ++v)
            mesh.velocities()[v] = Vec3(v, 2 * v, 3 * v);
        const std::vector<Tet> before = mesh.tets();
        CutChanges changes;
        changes.firstNewNode = nodesBefore;
        changes.firstNewTet = mesh.tetCount();
        const Separation s = resect::separate(mesh, c.selection, c.decomposition, changes);

        QCOMPARE(s.duplicatedNodes, duplicated);
        QCOMPARE(s.separatedTets, separatedTets);
        QCOMPARE(mesh.nodeCount(), nodesBefore + duplicated);
        QCOMPARE(int(changes.duplicatedNodes.size()), duplicated);
        QCOMPARE(connectedComponents(mesh).count, pieces);
        // Copies are new nodes coinciding with their original.
        std::map<int, int> originalOf;
        for (const auto& [orig, copy] : changes.duplicatedNodes) {
            QVERIFY(orig < nodesBefore);
            QVERIFY(copy >= nodesBefore);
            QCOMPARE(mesh.ref(copy), mesh.ref(orig));
            QCOMPARE(mesh.pos(copy), mesh.pos(orig));
            QCOMPARE(mesh.velocities()[copy], mesh.velocities()[orig]);
            originalOf[copy] = orig;
        }
        // Re-attachment: each tet has its old nodes or their copies, and is listed as
        // modified if anything changed; the + side keeps the original nodes.
        std::vector<int> modified;
        for (int t = 0; t < mesh.tetCount(); ++t) {
            Tet q = mesh.tet(t);
            for (int& v : q)
                if (originalOf.count(v))
                    v = originalOf[v];
            QCOMPARE(q, before[t]);
            if (mesh.tet(t) != before[t])
                modified.push_back(t);
            if (c.decomposition.tetSide.at(t) > 0)
                QCOMPARE(mesh.tet(t), before[t]);
        }
        // (once per re-attached node: the cutter removes repeats when it finishes the list)
        std::vector<int> listed = changes.modifiedTets;
        std::sort(listed.begin(), listed.end());
        listed.erase(std::unique(listed.begin(), listed.end()), listed.end());
        QCOMPARE(listed, modified);
        QCOMPARE(int(modified.size()), separatedTets);
        // The two sides share no node any more where they were separated.
        if (duplicated > 0)
            for (int t = 0; t < mesh.tetCount(); ++t)
                for (int u = 0; u < mesh.tetCount(); ++u) {
                    if (c.decomposition.tetSide.at(t) * c.decomposition.tetSide.at(u) >= 0)
                        continue;
                    const std::set<int> a(mesh.tet(t).begin(), mesh.tet(t).end());
                    for (int v : mesh.tet(u))
                        QVERIFY2(!a.count(v),
                                 qPrintable(
                                     QString("tets %1 and %2 share node %3").arg(t).arg(u).arg(v)));
                }
    }
};

QTEST_GUILESS_MAIN(TestSeparate)
#include "test_separate.moc"
