// TetMeshBackup (exact undo of a mesh edit) and TetGrid checkpoints (undo of grid inserts):
// random edits of every kind are undone to the bit, node adjacency order included; nested
// backups restore LIFO; committed edits stay; the grid answers queries as before its inserts.
#include "core/mesh/box_mesh.h"
#include "core/mesh/tet_grid.h"
#include "core/mesh/tet_mesh_backup.h"

#include <QTest>

#include <algorithm>
#include <cstring>
#include <random>

using namespace resect;

namespace {

struct MeshState {
    std::vector<Vec3> ref, pos, vel;
    std::vector<double> mass;
    std::vector<Tet> tets;
    std::vector<std::vector<int>> adjacency;
    explicit MeshState(const TetMesh& m)
        : ref(m.referencePositions().begin(), m.referencePositions().end()),
          pos(m.positions().begin(), m.positions().end()), vel(m.velocities().begin(), m.velocities().end()),
          mass(m.masses().begin(), m.masses().end()), tets(m.tets()) {
        for (int n = 0; n < m.nodeCount(); ++n)
            adjacency.emplace_back(m.nodeTets(n).begin(), m.nodeTets(n).end());
    }
    bool operator==(const MeshState& o) const {
        const auto bits = [](const auto& a, const auto& b) {
            return a.size() == b.size() && std::memcmp(a.data(), b.data(), a.size() * sizeof(a[0])) == 0;
        };
        return bits(ref, o.ref) && bits(pos, o.pos) && bits(vel, o.vel) && bits(mass, o.mass) && bits(tets, o.tets) &&
               adjacency == o.adjacency;
    }
};

TetMesh box() {
    TetMesh m = makeBoxTetMesh(Vec3::Zero(), Vec3::Constant(3), 3, 3, 3);
    for (int n = 0; n < m.nodeCount(); ++n)
        m.masses()[n] = 1 + n;
    return m;
}

/// Random edits of every kind a cut makes: new nodes, new tets on old and new nodes, tets
/// replaced (their nodes changed), nodes moved and masses set.
void randomEdits(TetMesh& m, std::mt19937& rng, int count) {
    for (int i = 0; i < count; ++i) {
        const int nodes = m.nodeCount(), tets = m.tetCount();
        std::uniform_int_distribution<int> node(0, nodes - 1), tet(0, tets - 1), kind(0, 4);
        switch (kind(rng)) {
        case 0: {
            const int n = m.addNode(Vec3(i, 0, 0), Vec3(i, 1, 0));
            m.velocities()[n] = Vec3(1, 2, 3);  // new nodes may be written freely
            break;
        }
        case 1: {
            const Tet& t = m.tet(tet(rng));
            m.addTet({t[0], t[1], t[2], m.addNode(Vec3(0, 0, i), Vec3(0, 0, i))});
            break;
        }
        case 2: {
            const int t = tet(rng);
            Tet q = m.tet(t);
            q[0] = node(rng);
            if (std::count(q.begin(), q.end(), q[0]) == 1)
                m.replaceTet(t, q);
            break;
        }
        case 3:
            m.setNodePosition(node(rng), Vec3(i, i, i), Vec3(-i, i, -i));
            break;
        case 4:
            m.setMass(node(rng), 0.5 * i);
            break;
        }
    }
}

} // namespace

class TestTetMeshBackup : public QObject {
    Q_OBJECT
private slots:
    void restoreUndoesEveryEdit_data() {
        QTest::addColumn<unsigned>("seed");
        for (unsigned seed = 1; seed <= 20; ++seed)
            QTest::newRow(qPrintable(QString("seed %1").arg(seed))) << seed;
    }
    void restoreUndoesEveryEdit() {
        QFETCH(unsigned, seed);
        TetMesh m = box();
        std::mt19937 rng(seed);
        randomEdits(m, rng, 10);  // some history before the backup
        const MeshState before(m);
        {
            TetMeshBackup backup(m);
            randomEdits(m, rng, 60);
            QVERIFY(!(MeshState(m) == before));
            QVERIFY(backup.recordedNodes() > 0);
        }  // not committed: restored on destruction
        QVERIFY(MeshState(m) == before);
        // The restored mesh edits exactly like one that never changed.
        TetMesh twin = box();
        std::mt19937 rng2(seed);
        randomEdits(twin, rng2, 10);
        std::mt19937 a(99), b(99);
        randomEdits(m, a, 30);
        randomEdits(twin, b, 30);
        QVERIFY(MeshState(m) == MeshState(twin));
    }

    void commitKeepsTheEdit() {
        TetMesh m = box();
        std::mt19937 rng(7);
        TetMeshBackup backup(m);
        randomEdits(m, rng, 40);
        const MeshState edited(m);
        backup.commit();
        QVERIFY(!backup.isOpen());
        backup.restore();  // closed: does nothing
        QVERIFY(MeshState(m) == edited);
        m.setMass(0, 42);  // no backup open: nothing recorded, nothing breaks
        QCOMPARE(m.masses()[0], 42.0);
    }

    void nestedBackupsRestoreInOrder() {
        TetMesh m = box();
        std::mt19937 rng(3);
        const MeshState start(m);
        TetMeshBackup outer(m);
        randomEdits(m, rng, 20);
        const MeshState middle(m);
        {
            TetMeshBackup inner(m);
            randomEdits(m, rng, 20);
            inner.restore();
            QVERIFY(MeshState(m) == middle);
        }
        {
            TetMeshBackup inner(m);
            randomEdits(m, rng, 20);
            inner.commit();  // the outer backup still undoes it
        }
        TetMeshBackup innermost(m);
        randomEdits(m, rng, 5);
        outer.restore();  // restores the open inner one first
        QVERIFY(!innermost.isOpen());
        QVERIFY(MeshState(m) == start);
    }

    void copiesDoNotRecord() {
        TetMesh m = box();
        const MeshState start(m);
        TetMeshBackup backup(m);
        TetMesh copy = m;
        copy.setMass(1, 99);
        copy.addNode(Vec3::Zero(), Vec3::Zero());
        QCOMPARE(backup.recordedNodes(), 0);
        backup.restore();
        QVERIFY(MeshState(m) == start);
        QCOMPARE(copy.masses()[1], 99.0);
    }

    void gridCheckpointUndoesInserts() {
        TetMesh m = box();
        TetGrid grid;
        grid.build(m);
        const Eigen::AlignedBox3d everywhere(Vec3::Constant(-1), Vec3::Constant(4));
        std::vector<int> before, after;
        grid.query(everywhere, before);
        const TetGrid::Checkpoint outer = grid.checkpoint();
        const int t = m.addTet({0, 1, 2, m.addNode(Vec3(0.5, 0.5, 0.5), Vec3(0.5, 0.5, 0.5))});
        grid.insert(m, t);
        const TetGrid::Checkpoint inner = grid.checkpoint();
        grid.insert(m, 0);  // a tet re-registered after its nodes moved
        grid.rollback(inner);
        grid.query(everywhere, after);
        QVERIFY(std::find(after.begin(), after.end(), t) != after.end());
        grid.rollback(outer);
        grid.query(everywhere, after);
        std::sort(before.begin(), before.end());
        std::sort(after.begin(), after.end());
        QCOMPARE(after, before);
        // Released inserts stay.
        const TetGrid::Checkpoint kept = grid.checkpoint();
        grid.insert(m, t);
        grid.release(kept);
        grid.query(everywhere, after);
        QVERIFY(std::find(after.begin(), after.end(), t) != after.end());
    }
};

QTEST_GUILESS_MAIN(TestTetMeshBackup)
#include "test_tet_mesh_backup.moc"
