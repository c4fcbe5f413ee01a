// Step 8 alone (update_rest_state.h, section 4.7) on literal tets: updateMasses gives the
// masses of Eq. 3 (density times a quarter of the rest volume of every incident tet) to the
// listed nodes only, conserves the total mass after a literal split of a tet, and scales
// with the volume; springStiffness and volumeStiffness follow Eq. 4.
#include "core/cut/update_rest_state.h"
#include "core/mesh/masses.h"

#include <QTest>

#include <numeric>

using namespace resect;

namespace {

/// The unit tet (volume 1/6) and, below its face (0, 1, 2), the tet (0, 2, 1, 4) with node 4
/// at (0, 0, -2) (volume 1/3).
TetMesh twoTets(double scale = 1) {
    return TetMesh::fromArrays({Vec3(0, 0, 0) * scale, Vec3(1, 0, 0) * scale, Vec3(0, 1, 0) * scale,
                                Vec3(0, 0, 1) * scale, Vec3(0, 0, -2) * scale},
                               {{0, 1, 2, 3}, {0, 2, 1, 4}});
}

double totalMass(const TetMesh& m) {
    return std::accumulate(m.masses().begin(), m.masses().end(), 0.0);
}

} // namespace

class TestUpdateRestState : public QObject {
    Q_OBJECT
private slots:
    void massesFollowEq3_data() {
        QTest::addColumn<double>("scale");
        QTest::newRow("1") << 1.0;
        QTest::newRow("1e-3") << 1e-3;
        QTest::newRow("1e3") << 1e3;
    }
    void massesFollowEq3() {
        QFETCH(double, scale);
        TetMesh m = twoTets(scale);
        QCOMPARE(m.referenceVolume(0), 1.0 / 6.0 * scale * scale * scale);
        QCOMPARE(m.referenceVolume(1), 1.0 / 3.0 * scale * scale * scale);
        const double density = 3;
        const double v3 = scale * scale * scale;
        updateMasses(m, {0, 1, 2, 3, 4}, density);
        // Nodes 0, 1, 2 in both tets: 3 (1/6 + 1/3) / 4; node 3: 3 (1/6) / 4; node 4: 3 (1/3) / 4.
        QCOMPARE(m.masses()[0], 0.375 * v3);
        QCOMPARE(m.masses()[1], 0.375 * v3);
        QCOMPARE(m.masses()[2], 0.375 * v3);
        QCOMPARE(m.masses()[3], 0.125 * v3);
        QCOMPARE(m.masses()[4], 0.25 * v3);
        QCOMPARE(totalMass(m), density * 0.5 * v3);
    }

    void onlyTheListedNodesAreUpdated() {
        TetMesh m = twoTets();
        for (double& mass : m.masses())
            mass = -1;
        updateMasses(m, {0, 3}, 3.0);
        QCOMPARE(m.masses()[0], 0.375);
        QCOMPARE(m.masses()[3], 0.125);
        for (int v : {1, 2, 4})
            QCOMPARE(m.masses()[v], -1.0);
    }

    void massIsConservedAfterASplit() {
        // The unit tet split at the middle of edge 0-1 (node 4 at (1/2, 0, 0)) into
        // (0, 4, 2, 3) and (4, 1, 2, 3): updating the nodes whose tets changed (all five)
        // keeps the total mass, and gives what computing all masses from scratch gives.
        TetMesh m = TetMesh::fromArrays(
            {Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0), Vec3(0, 0, 1)}, {{0, 1, 2, 3}});
        const double density = 2;
        computeLumpedMasses(m, density);
        const double before = totalMass(m);
        QCOMPARE(before, density / 6.0);
        const int p = m.addNode(Vec3(0.5, 0, 0), Vec3(0.5, 0, 0));
        m.replaceTet(0, {0, p, 2, 3});
        m.addTet({p, 1, 2, 3});
        QVERIFY(m.referenceVolume(0) > 0 && m.referenceVolume(1) > 0);
        // Before the update the masses are stale: node 4 has none.
        QCOMPARE(m.masses()[p], 0.0);
        updateMasses(m, {0, 1, 2, 3, p}, density);
        QVERIFY2(std::abs(totalMass(m) - before) <= 1e-15 * before,
                 qPrintable(QString::number(totalMass(m), 'g', 17)));
        // Nodes 0 and 1 in one half (volume 1/12); nodes 2, 3 and the new one in both.
        QCOMPARE(m.masses()[0], density / 48.0);
        QCOMPARE(m.masses()[1], density / 48.0);
        for (int v : {2, 3, p})
            QCOMPARE(m.masses()[v], density / 24.0);
        TetMesh scratch = m;
        computeLumpedMasses(scratch, density);
        for (int v = 0; v < m.nodeCount(); ++v)
            QCOMPARE(m.masses()[v], scratch.masses()[v]);
    }

    void stiffnessesFollowEq4() {
        // Edge 0-1 has rest length 2; the tet has rest volume 1/3.
        TetMesh m = TetMesh::fromArrays(
            {Vec3(0, 0, 0), Vec3(2, 0, 0), Vec3(0, 1, 0), Vec3(0, 0, 1)}, {{0, 1, 2, 3}});
        const double masses[] = {0.1, 0.2, 0.3, 0.4};
        std::copy(std::begin(masses), std::end(masses), m.masses().begin());
        Material mat;
        mat.stiffness = 5.0;
        QCOMPARE(springStiffness(m, 0, 1, mat), 5.0 * (0.1 + 0.2) / 4.0); // l0^2 = 4
        QCOMPARE(springStiffness(m, 2, 3, mat), 5.0 * (0.3 + 0.4) / 2.0); // l0^2 = 2
        QCOMPARE(volumeStiffness(m, 0, mat), 5.0 * 1.0 / (1.0 / 9.0));    // V0^2 = 1/9
        // Degenerate rest geometry: no stiffness instead of a division by zero.
        TetMesh flat = TetMesh::fromArrays(
            {Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0), Vec3(1, 1, 0), Vec3(0, 0, 0)},
            {{0, 1, 2, 3}});
        std::fill(flat.masses().begin(), flat.masses().end(), 1.0);
        QCOMPARE(volumeStiffness(flat, 0, mat), 0.0);
        QCOMPARE(springStiffness(flat, 0, 4, mat), 0.0);
    }
};

QTEST_GUILESS_MAIN(TestUpdateRestState)
#include "test_update_rest_state.moc"
