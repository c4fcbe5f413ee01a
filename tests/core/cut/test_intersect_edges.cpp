// Step 2 alone (intersect_edges.h, section 4.3) on literal tets and literal sweeps: which
// edges are crossed and where (t, point, side), edges crossed twice discarded and three times
// split at the middle crossing, nodes lying exactly on the sweep reported as such (never as
// crossings), and the candidate tets from the spatial grid (a filter only: the same
// crossings as with every tet examined).
#include "step_fixtures.h"

#include "core/cut/intersect_edges.h"
#include "core/mesh/box_mesh.h"

#include <QTest>

#include <algorithm>
#include <set>

using namespace resect;
using resect::testing::unitTet;

namespace {

using Edges = std::vector<std::array<int, 2>>;

/// The square c + s u + r w, s, r in [-R, R], as a sweep (the paper's m = 2 curves).
SweepSurface squareSweep(const Vec3& c, const Vec3& u, const Vec3& w, double R) {
    SweepSurface s;
    const Status st = SweepSurface::fromStartEnd({c - R * w - R * u, c - R * w + R * u},
                                                 {c + R * w - R * u, c + R * w + R * u}, s);
    if (!st.ok())
        qFatal("%s", st.message().c_str());
    return s;
}

Edges edgesOf(const IntersectedEdges& x) {
    Edges e;
    for (const EdgeCrossing& c : x.edges)
        e.push_back({c.a, c.b});
    std::sort(e.begin(), e.end());
    return e;
}

} // namespace

class TestIntersectEdges : public QObject {
    Q_OBJECT
private slots:
    void crossedEdges_data() {
        QTest::addColumn<int>("plane");
        QTest::addColumn<Edges>("crossed");
        QTest::addColumn<std::vector<double>>("t"); ///< crossing parameter of each crossed edge
        // Unit tet.
        QTest::newRow("x + y + z = 1/2: the three edges at node 0")
            << 0 << Edges{{0, 1}, {0, 2}, {0, 3}} << std::vector<double>{0.5, 0.5, 0.5};
        QTest::newRow("y + z = 1/2: four edges, two and two")
            << 1 << Edges{{0, 2}, {0, 3}, {1, 2}, {1, 3}}
            << std::vector<double>{0.5, 0.5, 0.5, 0.5};
        QTest::newRow("x = 1/4: the three edges at node 1, t from the lower index")
            << 2 << Edges{{0, 1}, {1, 2}, {1, 3}} << std::vector<double>{0.25, 0.75, 0.75};
        QTest::newRow("z = 2: none") << 3 << Edges{} << std::vector<double>{};
    }
    void crossedEdges() {
        QFETCH(int, plane);
        QFETCH(Edges, crossed);
        QFETCH(std::vector<double>, t);
        const TetMesh mesh = unitTet();
        SweepSurface sweep;
        switch (plane) {
        case 0:
            sweep = squareSweep(Vec3(0.5, 0, 0), Vec3(1, -1, 0), Vec3(1, 1, -2), 3);
            break;
        case 1:
            sweep = squareSweep(Vec3(0, 0.25, 0.25), Vec3(1, 0, 0), Vec3(0, 1, -1), 3);
            break;
        case 2:
            sweep = squareSweep(Vec3(0.25, 0, 0), Vec3(0, 1, 0), Vec3(0, 0, 1), 3);
            break;
        case 3:
            sweep = squareSweep(Vec3(0, 0, 2), Vec3(1, 0, 0), Vec3(0, 1, 0), 3);
            break;
        }
        const IntersectedEdges x = intersectEdges(mesh, TetGrid{}, sweep);
        QCOMPARE(edgesOf(x), crossed);
        QCOMPARE(x.discardedEdges, 0);
        QCOMPARE(x.multiplyCrossedEdges, 0);
        QCOMPARE(x.onSweepNodes, std::vector<int>{});
        QCOMPARE(x.candidateTets, std::vector<int>{0}); // no grid: every tet
        for (std::size_t k = 0; k < x.edges.size(); ++k) {
            const EdgeCrossing& c = x.edges[k];
            QVERIFY(c.a < c.b);
            QCOMPARE(x.index.at(edgeKey(c.a, c.b)), int(k));
            // Parameter from a, the point at it, on the sweep; a on side sideP, b opposite.
            const std::size_t e =
                std::find(crossed.begin(), crossed.end(), std::array<int, 2>{c.a, c.b}) -
                crossed.begin();
            QVERIFY2(std::abs(c.hit.t - t[e]) <= 1e-15,
                     qPrintable(QString::number(c.hit.t, 'g', 17)));
            QVERIFY((c.hit.point - (mesh.pos(c.a) + c.hit.t * (mesh.pos(c.b) - mesh.pos(c.a))))
                        .norm() <= 1e-15);
            QVERIFY(sweep.closestPoint(c.hit.point).distance <= 1e-15);
            QCOMPARE(c.hit.sideP, sweep.sideOf(mesh.pos(c.a)));
            QCOMPARE(sweep.sideOf(mesh.pos(c.b)), -c.hit.sideP);
        }
        QCOMPARE(int(x.index.size()), int(x.edges.size()));
    }

    void edgeCrossedTwiceIsDiscarded() {
        // A V-shaped stroke (three tool curves) crosses edge 0-1 (along y at z = 1/2) twice,
        // at y = 0.4 and y = 0.6: its ends are on the same side, the crossings are discarded.
        const TetMesh mesh = TetMesh::fromArrays(
            {Vec3(0.5, 0.25, 0.5), Vec3(0.5, 0.75, 0.5), Vec3(1, 0.5, 0), Vec3(0, 0.5, 0)},
            {{0, 1, 2, 3}});
        QVERIFY(mesh.referenceVolume(0) > 0);
        SweepSurface sweep;
        QVERIFY(SweepSurface::fromCurves({{Vec3(-1, 0.3, 1.5), Vec3(2, 0.3, 1.5)},
                                          {Vec3(-1, 0.5, 0.3), Vec3(2, 0.5, 0.3)},
                                          {Vec3(-1, 0.7, 1.5), Vec3(2, 0.7, 1.5)}},
                                         sweep)
                    .ok());
        const IntersectedEdges x = intersectEdges(mesh, TetGrid{}, sweep);
        QCOMPARE(x.discardedEdges, 1);
        QCOMPARE(x.multiplyCrossedEdges, 0);
        QCOMPARE(edgesOf(x), Edges{});
        QVERIFY(x.index.empty());
    }

    void edgeCrossedThreeTimesIsSplitAtTheMiddleCrossing() {
        // A W-shaped stroke (four tool curves) crosses edge 0-1, from y = 0 to y = 1 at
        // z = 1/2, at y = 1/4, 1/2 and 3/4: an odd count, so the ends are on opposite sides
        // and the edge is split once, at the middle crossing.
        const TetMesh mesh = TetMesh::fromArrays(
            {Vec3(0.5, 0, 0.5), Vec3(0.5, 1, 0.5), Vec3(1, 0.5, -1), Vec3(0, 0.5, -1)},
            {{0, 1, 2, 3}});
        QVERIFY(mesh.referenceVolume(0) > 0);
        SweepSurface sweep;
        QVERIFY(SweepSurface::fromCurves({{Vec3(-1, 0.125, 1.5), Vec3(2, 0.125, 1.5)},
                                          {Vec3(-1, 0.375, -0.5), Vec3(2, 0.375, -0.5)},
                                          {Vec3(-1, 0.625, 1.5), Vec3(2, 0.625, 1.5)},
                                          {Vec3(-1, 0.875, -0.5), Vec3(2, 0.875, -0.5)}},
                                         sweep)
                    .ok());
        const IntersectedEdges x = intersectEdges(mesh, TetGrid{}, sweep);
        QCOMPARE(x.multiplyCrossedEdges, 1);
        QCOMPARE(x.discardedEdges, 0);
        const auto it = x.index.find(edgeKey(0, 1));
        QVERIFY(it != x.index.end());
        const EdgeCrossing& c = x.edges[it->second];
        QVERIFY2(std::abs(c.hit.t - 0.5) <= 1e-15, qPrintable(QString::number(c.hit.t, 'g', 17)));
        QCOMPARE(std::abs(c.hit.sideP), 1);
    }

    void nodesExactlyOnTheSweep_data() {
        QTest::addColumn<int>("plane");
        QTest::addColumn<std::vector<int>>("onSweep");
        QTest::addColumn<Edges>("crossed");
        QTest::newRow("z = 0 holds face (0, 1, 2)") << 0 << std::vector<int>{0, 1, 2} << Edges{};
        QTest::newRow("x + y + z = 0 touches node 0") << 1 << std::vector<int>{0} << Edges{};
        QTest::newRow("z = 1 touches node 3") << 2 << std::vector<int>{3} << Edges{};
        QTest::newRow("x = y holds nodes 0 and 3, crosses edge 1-2")
            << 3 << std::vector<int>{0, 3} << Edges{{1, 2}};
        QTest::newRow("x - y + z/2 = 0 holds node 0, crosses 1-2 and 2-3")
            << 4 << std::vector<int>{0} << Edges{{1, 2}, {2, 3}};
    }
    void nodesExactlyOnTheSweep() {
        QFETCH(int, plane);
        QFETCH(std::vector<int>, onSweep);
        QFETCH(Edges, crossed);
        // Every sweep corner below is exactly on its plane, so the contact is exact: a node on
        // the sweep is reported as such and never makes its edges crossed.
        const TetMesh mesh = unitTet();
        SweepSurface sweep;
        switch (plane) {
        case 0:
            sweep = squareSweep(Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0), 3);
            break;
        case 1:
            sweep = squareSweep(Vec3(0, 0, 0), Vec3(1, -1, 0), Vec3(1, 1, -2), 3);
            break;
        case 2:
            sweep = squareSweep(Vec3(0, 0, 1), Vec3(1, 0, 0), Vec3(0, 1, 0), 3);
            break;
        case 3:
            sweep = squareSweep(Vec3(0, 0, 0), Vec3(1, 1, 0), Vec3(0, 0, 1), 3);
            break;
        case 4:
            sweep = squareSweep(Vec3(0, 0, 0), Vec3(1, 1, 0), Vec3(-1, 1, 4), 3);
            break;
        }
        const IntersectedEdges x = intersectEdges(mesh, TetGrid{}, sweep);
        QCOMPARE(x.onSweepNodes, onSweep);
        QCOMPARE(edgesOf(x), crossed);
        QCOMPARE(x.discardedEdges, 0);
    }

    void gridSelectsCandidateTets_data() {
        QTest::addColumn<double>("scale");
        QTest::newRow("1") << 1.0;
        QTest::newRow("1e-3") << 1e-3;
        QTest::newRow("1e3") << 1e3;
    }
    void gridSelectsCandidateTets() {
        QFETCH(double, scale);
        // 8 x 8 x 8 cubes (3072 tets); a small square sweep near one corner. The grid gives a
        // sorted subset of the tets holding every crossed edge, and the same crossings as
        // examining every tet.
        const TetMesh mesh = makeBoxTetMesh(Vec3::Zero(), Vec3(1, 1, 1) * scale, 8, 8, 8);
        const SweepSurface sweep = squareSweep(Vec3(0.2, 0.2, 0.3) * scale, Vec3(1, 0.1, 0),
                                               Vec3(0.1, 1, 0.2), 0.15 * scale);
        TetGrid grid;
        grid.build(mesh);
        const IntersectedEdges withGrid = intersectEdges(mesh, grid, sweep);
        const IntersectedEdges all = intersectEdges(mesh, TetGrid{}, sweep);
        QCOMPARE(int(all.candidateTets.size()), mesh.tetCount());
        QVERIFY(!withGrid.candidateTets.empty());
        QVERIFY(int(withGrid.candidateTets.size()) < mesh.tetCount() / 4);
        QVERIFY(std::is_sorted(withGrid.candidateTets.begin(), withGrid.candidateTets.end()));
        QVERIFY(std::adjacent_find(withGrid.candidateTets.begin(), withGrid.candidateTets.end()) ==
                withGrid.candidateTets.end());
        QVERIFY(!all.edges.empty());
        QCOMPARE(edgesOf(withGrid), edgesOf(all));
        const std::set<int> candidates(withGrid.candidateTets.begin(),
                                       withGrid.candidateTets.end());
        std::vector<int> around;
        for (const EdgeCrossing& c : all.edges) {
            mesh.edgeTets(c.a, c.b, around);
            QVERIFY(std::any_of(around.begin(), around.end(),
                                [&](int t) { return candidates.count(t) > 0; }));
            const EdgeCrossing& g = withGrid.edges[withGrid.index.at(edgeKey(c.a, c.b))];
            QVERIFY(g.hit.t == c.hit.t);
        }
    }
};

QTEST_GUILESS_MAIN(TestIntersectEdges)
#include "test_intersect_edges.moc"
