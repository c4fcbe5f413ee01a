// reorderForLocality (core/mesh/reorder.h): the same mesh, numbered along a space-filling
// curve. Every tet survives with its corners in order (so its orientation and volume), every
// node keeps its positions, velocity and mass, and the numbering becomes local.
#include "core/mesh/box_mesh.h"
#include "core/mesh/reorder.h"

#include <QTest>

#include <algorithm>
#include <map>
#include <numeric>
#include <random>

using namespace resect;

namespace {

/// A box of 12^3 cells (10 368 tets) at `scale`, numbered at random, with distinct masses and
/// velocities and current positions off the reference ones.
TetMesh shuffledBox(double scale) {
    const TetMesh box = makeBoxTetMesh(Vec3(-3, 1, 2) * scale, Vec3(5, 9, 4) * scale, 12, 12, 12);
    std::mt19937 rng(3);
    std::vector<int> newNode(box.nodeCount()), newTet(box.tetCount());
    std::iota(newNode.begin(), newNode.end(), 0);
    std::iota(newTet.begin(), newTet.end(), 0);
    std::shuffle(newNode.begin(), newNode.end(), rng);
    std::shuffle(newTet.begin(), newTet.end(), rng);
    std::vector<Vec3> ref(box.nodeCount());
    for (int n = 0; n < box.nodeCount(); ++n)
        ref[newNode[n]] = box.ref(n);
    std::vector<Tet> tets(box.tetCount());
    for (int t = 0; t < box.tetCount(); ++t) {
        Tet q = box.tet(t);
        for (int& v : q)
            v = newNode[v];
        tets[newTet[t]] = q;
    }
    TetMesh mesh = TetMesh::fromArrays(std::move(ref), std::move(tets));
    for (int n = 0; n < mesh.nodeCount(); ++n) {
        mesh.positions()[n] = mesh.ref(n) + Vec3(0.01, -0.02, 0.03) * scale * (n % 5);
        mesh.velocities()[n] = Vec3(n, -n, 2 * n);
        mesh.masses()[n] = 1.0 + n;
    }
    return mesh;
}

/// Signed volume (times 6) of tet q in the reference configuration.
double volume6(const TetMesh& m, const Tet& q) {
    return (m.ref(q[1]) - m.ref(q[0])).dot((m.ref(q[2]) - m.ref(q[0])).cross(m.ref(q[3]) - m.ref(q[0])));
}

} // namespace

class TestReorder : public QObject {
    Q_OBJECT
private slots:
    void sameMeshLocalNumbering_data() {
        QTest::addColumn<double>("scale");
        QTest::newRow("1e-3") << 1e-3;
        QTest::newRow("1") << 1.0;
        QTest::newRow("1e3") << 1e3;
    }

    void sameMeshLocalNumbering() {
        QFETCH(double, scale);
        const TetMesh before = shuffledBox(scale);
        TetMesh after = before;
        const Reordering r = reorderForLocality(after);
        QCOMPARE(after.nodeCount(), before.nodeCount());
        QCOMPARE(after.tetCount(), before.tetCount());
        // Permutations.
        for (const std::vector<int>* map : {&r.newNode, &r.newTet}) {
            std::vector<int> sorted = *map;
            std::sort(sorted.begin(), sorted.end());
            std::vector<int> identity(sorted.size());
            std::iota(identity.begin(), identity.end(), 0);
            QCOMPARE(sorted, identity);
        }
        // Nodes keep every array; tets keep their corners in order, so their signed volume.
        for (int n = 0; n < before.nodeCount(); ++n) {
            const int m = r.newNode[n];
            QCOMPARE(after.ref(m), before.ref(n));
            QCOMPARE(after.pos(m), before.pos(n));
            QCOMPARE(after.velocities()[m], before.velocities()[n]);
            QCOMPARE(after.masses()[m], before.masses()[n]);
        }
        for (int t = 0; t < before.tetCount(); ++t) {
            Tet mapped = before.tet(t);
            for (int& v : mapped)
                v = r.newNode[v];
            QCOMPARE(after.tet(r.newTet[t]), mapped);
            QCOMPARE(volume6(after, after.tet(r.newTet[t])), volume6(before, before.tet(t)));
        }
        // The numbering is local: a random one spreads a tet's nodes over more than half of the
        // nodes (0.60 measured); along the curve, over less than a tenth (0.083: the curve's
        // few long jumps between octants).
        const double spreadBefore = nodeIndexSpread(before), spreadAfter = nodeIndexSpread(after);
        qInfo("node index spread: %.4f random, %.4f reordered", spreadBefore, spreadAfter);
        QVERIFY(spreadBefore > 0.5);
        QVERIFY2(spreadAfter < 0.1, qPrintable(QString::number(spreadAfter)));
        // Consecutive tets are near each other: the mean distance between the centroids of
        // tets t and t + 1 is a few cells, not a fraction of the box.
        const auto centroid = [&](const TetMesh& m, int t) {
            const Tet& q = m.tet(t);
            return Vec3(0.25 * (m.ref(q[0]) + m.ref(q[1]) + m.ref(q[2]) + m.ref(q[3])));
        };
        double step = 0;
        for (int t = 0; t + 1 < after.tetCount(); ++t)
            step += (centroid(after, t + 1) - centroid(after, t)).norm();
        step /= after.tetCount() - 1;
        const double cell = scale * 8.0 / 12.0;
        QVERIFY2(step < 1.0 * cell, qPrintable(QString("%1 cells between consecutive tets").arg(step / cell)));
    }

    void smallAndEmptyMeshes() {
        TetMesh empty;
        const Reordering r = reorderForLocality(empty);
        QVERIFY(r.newNode.empty() && r.newTet.empty());
        QCOMPARE(nodeIndexSpread(empty), 0.0);
        // One tet; and a flat set of nodes (zero extent along z) with a tet of zero volume:
        // the order is still a permutation, nothing divides by the extent.
        TetMesh one = TetMesh::fromArrays({Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0), Vec3(0, 0, 1)}, {Tet{0, 1, 2, 3}});
        reorderForLocality(one);
        QCOMPARE(one.tetCount(), 1);
        QVERIFY(volume6(one, one.tet(0)) > 0);
        TetMesh point = TetMesh::fromArrays({Vec3(2, 2, 2), Vec3(2, 2, 2), Vec3(2, 2, 2), Vec3(2, 2, 2)}, {Tet{3, 2, 1, 0}});
        const Reordering p = reorderForLocality(point);
        QCOMPARE(point.tet(0), (Tet{p.newNode[3], p.newNode[2], p.newNode[1], p.newNode[0]}));
    }
};

QTEST_GUILESS_MAIN(TestReorder)
#include "test_reorder.moc"
