// Step 3 alone (select_cut_nodes.h, section 4.3): literal tets, a sweep in the plane z = 0
// and the crossings given literally. One test per rule of the header: the nearer end within
// d becomes a cut node (and its crossed edges are not split), beyond d it does not; a node
// exactly on the sweep is always a cut node, also for subdivision; nodes of partially cut
// tets are never cut nodes, through the fixed-point iteration; the result does not depend on
// the order of nodes, tets or crossed edges (except in exact midpoint ties: an expected
// failure documents it); a tet never gets a fourth cut node (the nearer nominee wins);
// crossings too close to an end are clamped to minEdgeFraction; nodes a hair from the sweep
// count as cut nodes when tets are classified (near nodes).
#include "step_fixtures.h"

#include "core/cut/select_cut_nodes.h"
#include "core/mesh/predicates.h"

#include <QTest>

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <numeric>

using namespace resect;
using resect::testing::crossingsOfZ0;
using resect::testing::planeZ0;

namespace {

using Edges = std::vector<std::array<int, 2>>;

/// A literal configuration: positions, tets, the crossed edges and the nodes on the sweep.
struct Fixture {
    std::vector<Vec3> nodes;
    std::vector<Tet> tets;
    Edges crossed;
    std::vector<int> onSweep;
    SweepSurface sweep;
};

/// The result in terms of the fixture's own numbering, comparable across relabellings.
struct Outcome {
    std::vector<int> cutNodes;                     ///< sorted
    std::vector<double> cutNodeDistance;           ///< in the order of cutNodes
    std::map<std::array<int, 2>, double> cutEdges; ///< (a, b), a < b -> crossing parameter from a
    std::map<int, Scheme> scheme;                  ///< tet -> scheme
    std::map<int, bool> partial;                   ///< tet -> partially cut
    CutSelection raw; ///< the selection itself (identity numbering only)
};

/// Runs selectCutNodes on the fixture with its nodes renumbered (newIndex[old]), its tets
/// listed in the order `tetOrder` (old tet indices) and its crossed edges reversed if
/// `reverseEdges`; maps the result back to the fixture's numbering.
Outcome select(const Fixture& f, const SelectOptions& options, std::vector<int> newIndex = {},
               std::vector<int> tetOrder = {}, bool reverseEdges = false) {
    const int n = static_cast<int>(f.nodes.size());
    if (newIndex.empty()) {
        newIndex.resize(n);
        std::iota(newIndex.begin(), newIndex.end(), 0);
    }
    if (tetOrder.empty()) {
        tetOrder.resize(f.tets.size());
        std::iota(tetOrder.begin(), tetOrder.end(), 0);
    }
    std::vector<int> oldIndex(n);
    std::vector<Vec3> nodes(n);
    for (int i = 0; i < n; ++i) {
        oldIndex[newIndex[i]] = i;
        nodes[newIndex[i]] = f.nodes[i];
    }
    std::vector<Tet> tets;
    for (int t : tetOrder) {
        Tet q = f.tets[t];
        for (int& v : q)
            v = newIndex[v];
        tets.push_back(q);
    }
    const TetMesh mesh = TetMesh::fromArrays(nodes, tets);
    Edges crossed;
    for (const auto& e : f.crossed)
        crossed.push_back({newIndex[e[0]], newIndex[e[1]]});
    if (reverseEdges)
        std::reverse(crossed.begin(), crossed.end());
    std::vector<int> onSweep;
    for (int v : f.onSweep)
        onSweep.push_back(newIndex[v]);
    Outcome o;
    o.raw = selectCutNodes(mesh, f.sweep, crossingsOfZ0(mesh, f.sweep, crossed, onSweep), options);
    std::vector<std::pair<int, double>> nodesAndDistances;
    for (std::size_t k = 0; k < o.raw.cutNodes.size(); ++k)
        nodesAndDistances.push_back({oldIndex[o.raw.cutNodes[k]], o.raw.cutNodeDistance[k]});
    std::sort(nodesAndDistances.begin(), nodesAndDistances.end());
    for (const auto& [v, d] : nodesAndDistances) {
        o.cutNodes.push_back(v);
        o.cutNodeDistance.push_back(d);
    }
    for (const EdgeCrossing& c : o.raw.cutEdges) {
        const int a = oldIndex[c.a], b = oldIndex[c.b];
        o.cutEdges[{std::min(a, b), std::max(a, b)}] = a < b ? c.hit.t : 1.0 - c.hit.t;
    }
    for (const TetCut& tc : o.raw.tets) {
        o.scheme[tetOrder[tc.tet]] = tc.scheme;
        o.partial[tetOrder[tc.tet]] = tc.partial;
    }
    return o;
}

SelectOptions hybrid(double d) {
    SelectOptions o;
    o.d = d;
    return o;
}
SelectOptions subdivision() {
    SelectOptions o;
    o.allowCutNodes = false;
    return o;
}

/// One tet: node 0 at height zTop over (0.2, 0.2), nodes 1-3 at height zBottom; a sweep
/// covering the whole plane z = 0 crosses the three edges at node 0 (an A pattern).
Fixture nearerEndFixture(double zTop, double zBottom) {
    return {{Vec3(0.2, 0.2, zTop), Vec3(1, 0, zBottom), Vec3(0, 1, zBottom), Vec3(0, 0, zBottom)},
            {{0, 2, 1, 3}},
            {{0, 1}, {0, 2}, {0, 3}},
            {},
            planeZ0(-5, 5, -5, 5)};
}

/// Three tets in a chain along which partial cuts spread (sweep: z = 0 for x in [-2, 1.5]):
///  T0 = (0, 1, 2, 3): only edge 0-1 is crossed (the sweep's border runs through T0, edges
///       1-2 and 0-2 cross z = 0 beyond it) and node 3 lies on the sweep: partially cut.
///  T1 = (3, 7, 4, 5): nodes 3 and 7 on the sweep, edge 4-5 crossed: complete (scheme Y)
///       only while node 3 may be a cut node.
///  T2 = (7, 8, 9, 10): node 7 on the sweep, edges 8-9 and 8-10 crossed: complete (X) only
///       while node 7 may be a cut node.
/// Node 6 is not used. Without T0 both 3 and 7 are cut nodes.
Fixture chainFixture(bool withPartialTet) {
    Fixture f{{Vec3(1, 0.5, 1), Vec3(1, 0.5, -1), Vec3(3, 0, 0.5), Vec3(1, 0, 0),
               Vec3(0.5, -0.2, 1), Vec3(0.2, -0.5, -1), Vec3(9, 9, 9), Vec3(0, -1, 0),
               Vec3(-1, -1.5, 1), Vec3(-1.5, -1, -1), Vec3(-0.5, -2, -1)},
              {{0, 1, 2, 3}, {3, 7, 4, 5}, {7, 8, 9, 10}},
              {{0, 1}, {4, 5}, {8, 9}, {8, 10}},
              {3, 7},
              planeZ0(-2, 1.5, -3, 3)};
    if (!withPartialTet) {
        f.tets.erase(f.tets.begin());
        f.crossed.erase(f.crossed.begin());
    }
    return f;
}

/// Ta: nodes 0 and 1 on the sweep (plane z = 0), node 2 at height z2 > 0 and node 3 at
/// z3 < 0, so edge 2-3 is crossed (complete, scheme Y). Ta is a sliver, of signed volume
/// (z2 + z3) / 6 in the order 0, 1, 2, 3, so its node order follows that sign.
/// Tb = (2, 4, 5, 6) crosses the sweep around node 4 (A) and nominates node 2 through edge
/// 2-4; Tc = (3, 7, 8, 9) likewise nominates node 3 through edge 3-7. Ta can take only one
/// of the two.
Fixture fourthCutNodeFixture(double z2, double z3) {
    return {{Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0.3, 1, z2), Vec3(0.3, -1, z3), Vec3(0.3, 2, -1),
             Vec3(0, 2, 1), Vec3(1, 2, 1), Vec3(0.3, -2, 1), Vec3(0, -2, -1), Vec3(1, -2, -1)},
            {z2 + z3 > 0 ? Tet{0, 1, 2, 3} : Tet{0, 1, 3, 2}, {2, 4, 5, 6}, {3, 7, 8, 9}},
            {{2, 3}, {2, 4}, {4, 5}, {4, 6}, {3, 7}, {7, 8}, {7, 9}},
            {0, 1},
            planeZ0(-5, 5, -5, 5)};
}

} // namespace

Q_DECLARE_METATYPE(resect::Scheme)
Q_DECLARE_METATYPE(resect::SelectOptions)

class TestSelectCutNodes : public QObject {
    Q_OBJECT
private slots:
    void fixturesArePositivelyOriented() {
        // Literal tets that are not positive would make the tests below meaningless.
        const std::vector<Fixture> fixtures{nearerEndFixture(0.05, -1), nearerEndFixture(1, -0.05),
                                            chainFixture(true), fourthCutNodeFixture(0.01, -0.02),
                                            fourthCutNodeFixture(0.02, -0.01)};
        for (const Fixture& f : fixtures) {
            const TetMesh m = TetMesh::fromArrays(f.nodes, f.tets);
            for (int t = 0; t < m.tetCount(); ++t)
                QVERIFY(m.referenceVolume(t) > 0);
        }
    }

    void nearerEndWithinD_data() {
        QTest::addColumn<double>("zTop");
        QTest::addColumn<double>("zBottom");
        QTest::addColumn<SelectOptions>("options");
        QTest::addColumn<std::vector<int>>("cutNodes");
        QTest::addColumn<int>("cutEdges");
        QTest::addColumn<Scheme>("scheme");
        // Node 0 is 0.05 from the sweep and the nearer end of its three edges.
        QTest::newRow("nearer end a, within d")
            << 0.05 << -1.0 << hybrid(0.06) << std::vector<int>{0} << 0 << Scheme::Touch;
        QTest::newRow("nearer end a, beyond d")
            << 0.05 << -1.0 << hybrid(0.04) << std::vector<int>{} << 3 << Scheme::A;
        QTest::newRow("nearer end a, d = 0")
            << 0.05 << -1.0 << hybrid(0.0) << std::vector<int>{} << 3 << Scheme::A;
        QTest::newRow("nearer end a, subdivision")
            << 0.05 << -1.0 << subdivision() << std::vector<int>{} << 3 << Scheme::A;
        // Nodes 1-3 are 0.05 from the sweep, the nearer ends (b) of the three edges.
        QTest::newRow("nearer end b, within d")
            << 1.0 << -0.05 << hybrid(0.06) << std::vector<int>{1, 2, 3} << 0 << Scheme::Z;
        QTest::newRow("nearer end b, beyond d")
            << 1.0 << -0.05 << hybrid(0.04) << std::vector<int>{} << 3 << Scheme::A;
    }
    void nearerEndWithinD() {
        QFETCH(double, zTop);
        QFETCH(double, zBottom);
        QFETCH(SelectOptions, options);
        QFETCH(std::vector<int>, cutNodes);
        QFETCH(int, cutEdges);
        QFETCH(Scheme, scheme);
        const Fixture f = nearerEndFixture(zTop, zBottom);
        const Outcome o = select(f, options);
        QCOMPARE(o.cutNodes, cutNodes);
        QCOMPARE(int(o.cutEdges.size()), cutEdges);
        QCOMPARE(o.scheme.at(0), scheme);
        QCOMPARE(o.partial.at(0), false);
        // Cut nodes carry their distance to the sweep; the largest is reported.
        for (double d : o.cutNodeDistance)
            QVERIFY(std::abs(d - 0.05) <= 1e-15);
        QCOMPARE(o.raw.maxCutNodeDistance,
                 cutNodes.empty()
                     ? 0.0
                     : *std::max_element(o.cutNodeDistance.begin(), o.cutNodeDistance.end()));
        // Sides: cut nodes 0; the others from the crossings, node 0 opposite to nodes 1-3.
        const TetCut& tc = o.raw.tets.at(0);
        const TetMesh mesh = TetMesh::fromArrays(f.nodes, f.tets);
        for (int i = 0; i < 4; ++i) {
            const int v = mesh.tet(0)[i];
            const bool isCut = std::count(cutNodes.begin(), cutNodes.end(), v) > 0;
            QCOMPARE(int(tc.side[i]), isCut ? 0 : f.sweep.sideOf(mesh.pos(v)));
        }
    }

    void nodeOnTheSweepIsAlwaysACutNode_data() {
        QTest::addColumn<SelectOptions>("options");
        QTest::newRow("hybrid") << hybrid(0.2);
        QTest::newRow("hybrid, d = 0") << hybrid(0.0);
        QTest::newRow("subdivision") << subdivision();
    }
    void nodeOnTheSweepIsAlwaysACutNode() {
        QFETCH(SelectOptions, options);
        const SweepSurface sweep = planeZ0(-5, 5, -5, 5);
        // Node 0 exactly on the sweep, node 1 above, nodes 2 and 3 below: edges 1-2 and 1-3
        // are crossed (scheme X around the cut node).
        const Fixture through{{Vec3(0, 0, 0), Vec3(0.5, 0.5, 1), Vec3(1, 0, -1), Vec3(0, 1, -1)},
                              {{0, 1, 2, 3}},
                              {{1, 2}, {1, 3}},
                              {0},
                              sweep};
        Outcome o = select(through, options);
        QCOMPARE(o.cutNodes, std::vector<int>{0});
        QCOMPARE(o.cutNodeDistance, std::vector<double>{0.0});
        QCOMPARE(int(o.cutEdges.size()), 2);
        QCOMPARE(o.scheme.at(0), Scheme::X);
        QCOMPARE(int(o.raw.tets[0].side[0]), 0);
        QCOMPARE(int(o.raw.tets[0].side[1]), -int(o.raw.tets[0].side[2]));
        QCOMPARE(int(o.raw.tets[0].side[2]), int(o.raw.tets[0].side[3]));
        QVERIFY(o.raw.tets[0].side[1] != 0);
        // Node 0 on the sweep and the rest of the tet above it: touched at a corner.
        const Fixture touch{{Vec3(0, 0, 0), Vec3(1, 0, 1), Vec3(0, 1, 1), Vec3(0, 0, 1)},
                            {{0, 1, 2, 3}},
                            {},
                            {0},
                            sweep};
        o = select(touch, options);
        QCOMPARE(o.cutNodes, std::vector<int>{0});
        QCOMPARE(o.scheme.at(0), Scheme::Touch);
    }

    void nodesOfPartialTetsAreNeverCutNodes_data() {
        QTest::addColumn<SelectOptions>("options");
        QTest::newRow("hybrid") << hybrid(0.2);
        QTest::newRow("subdivision") << subdivision();
    }
    void nodesOfPartialTetsAreNeverCutNodes() {
        QFETCH(SelectOptions, options);
        // The sweep covers z = 0 for x <= 0.5 only. Node 0 is 0.05 above it and the nearer
        // end of edge 0-1, the only crossed edge (edges 1-2 and 1-3 cross z = 0 at x = 2/3,
        // beyond the sweep): partially cut (C); node 0 stays an ordinary node.
        const SweepSurface sweep = planeZ0(-2, 0.5, -2, 2);
        const Fixture nominee{
            {Vec3(0, 0, 0.05), Vec3(0, 0.2, -1), Vec3(1, 0, 0.5), Vec3(1, 1, 0.5)},
            {{0, 2, 1, 3}},
            {{0, 1}},
            {},
            sweep};
        Outcome o = select(nominee, options);
        QCOMPARE(o.cutNodes, std::vector<int>{});
        QCOMPARE(int(o.cutEdges.size()), 1);
        QCOMPARE(o.scheme.at(0), Scheme::C);
        QCOMPARE(o.partial.at(0), true);
        // Node 0 exactly on the sweep, edge 1-2 crossed below it and edge 1-3 crossing z = 0
        // beyond the sweep: partial, so node 0 is not a cut node although it is on the sweep.
        const Fixture onSweep{
            {Vec3(0, 0, 0), Vec3(0, 0.5, -0.5), Vec3(0, 0.5, 0.5), Vec3(1.5, 0.5, 0.5)},
            {{0, 1, 2, 3}},
            {{1, 2}},
            {0},
            sweep};
        o = select(onSweep, options);
        QCOMPARE(o.cutNodes, std::vector<int>{});
        QCOMPARE(o.scheme.at(0), Scheme::C);
        QCOMPARE(o.partial.at(0), true);
    }

    void nearNodesAreCutNodesOfTetsCutOnlyNearThem_data() {
        QTest::addColumn<double>("nearFraction");
        QTest::addColumn<bool>("nodeZeroCut");
        QTest::newRow("0.1") << 0.1 << true;
        QTest::newRow("off (the default)") << 0.0 << false;
    }
    void nearNodesAreCutNodesOfTetsCutOnlyNearThem() {
        QFETCH(double, nearFraction);
        QFETCH(bool, nodeZeroCut);
        // As in nodesOfPartialTetsAreNeverCutNodes, with node 0 a hair (0.005, under 0.1 d)
        // above the sweep: the sweep crosses the tet only at node 0's edge 0-1. Where a later
        // cut runs along an earlier cut's wall it crosses the wall's tets like this, over and
        // over (issue 16: a random pull on a scanned surface left edges of 0.01 of the mean
        // and a sliver of radius ratio 0.009). Node 0 counts as a cut node: the tet is
        // touched there, not partially cut, and no edge is split 0.005 from its end.
        const Fixture f{{Vec3(0, 0, 0.005), Vec3(0, 0.2, -1), Vec3(1, 0, 0.5), Vec3(1, 1, 0.5)},
                        {{0, 2, 1, 3}},
                        {{0, 1}},
                        {},
                        planeZ0(-2, 0.5, -2, 2)};
        SelectOptions options = hybrid(0.2);
        options.nearFraction = nearFraction;
        QCOMPARE(SelectOptions{}.nearFraction, 0.0);
        const Outcome o = select(f, options);
        if (nodeZeroCut) {
            QCOMPARE(o.cutNodes, std::vector<int>{0});
            QCOMPARE(o.cutNodeDistance.front(), 0.005);
            QVERIFY(o.cutEdges.empty());
            QCOMPARE(o.scheme.at(0), Scheme::Touch);
            QCOMPARE(o.partial.at(0), false);
        } else {
            QCOMPARE(o.cutNodes, std::vector<int>{});
            QCOMPARE(int(o.cutEdges.size()), 1);
            QCOMPARE(o.scheme.at(0), Scheme::C);
            QCOMPARE(o.partial.at(0), true);
        }
    }

    void aNearNodeThatCannotBeACutNodeIsDropped() {
        // T0: a flat tet with all four nodes near the sweep (0.01-0.013 above and below it,
        // d = 0.2); they cannot all be cut nodes, and the farthest, node 3, is refused. T1 =
        // (3, 4, 5, 6) is crossed only at edge 3-4, near node 3 (the sweep ends at x = 1.5;
        // edges 4-5 and 4-6 cross z = 0 beyond it): complete while node 3 counts as a cut node,
        // partial without. So the selection is made again without node 3 near: T1 is partially
        // cut (C) and its edge 3-4 is split. Taking the first selection as it was would leave
        // T1 with a split edge and no scheme (a hanging split point).
        const Fixture f{{Vec3(0, 0, 0.01), Vec3(1, 0, 0.011), Vec3(0, 1, -0.012), Vec3(1, 1, -0.013),
                         Vec3(1, 1.5, 1), Vec3(3, 1, -0.5), Vec3(3, 2, -0.5)},
                        {{0, 2, 1, 3}, {3, 4, 5, 6}},
                        {{0, 2}, {0, 3}, {1, 2}, {1, 3}, {3, 4}},
                        {},
                        planeZ0(-5, 1.5, -5, 5)};
        for (const Tet& q : f.tets)
            QVERIFY(signedVolume(f.nodes[q[0]], f.nodes[q[1]], f.nodes[q[2]], f.nodes[q[3]]) > 0);
        SelectOptions options = hybrid(0.2);
        options.nearFraction = 0.1;
        const Outcome o = select(f, options);
        QCOMPARE(o.cutNodes, (std::vector<int>{0, 1, 2}));
        QCOMPARE(o.scheme.at(0), Scheme::Z);
        QCOMPARE(o.partial.at(0), false);
        QCOMPARE(o.scheme.at(1), Scheme::C);
        QCOMPARE(o.partial.at(1), true);
        QCOMPARE(int(o.cutEdges.size()), 1);
        QVERIFY(o.cutEdges.count({3, 4}));
    }

    void partialCutsSpreadToAFixedPoint_data() {
        QTest::addColumn<std::vector<int>>("tetOrder");
        // In the order T2, T1, T0 each pass of the iteration reaches one more tet of the
        // chain: T0 makes node 3 ineligible, then T1 is partial and makes node 7 ineligible,
        // then T2 is partial.
        QTest::newRow("T0 first") << std::vector<int>{0, 1, 2};
        QTest::newRow("T0 last") << std::vector<int>{2, 1, 0};
        QTest::newRow("T0 in the middle") << std::vector<int>{1, 0, 2};
    }
    void partialCutsSpreadToAFixedPoint() {
        QFETCH(std::vector<int>, tetOrder);
        const Outcome o = select(chainFixture(true), subdivision(), {}, tetOrder);
        QCOMPARE(o.cutNodes, std::vector<int>{});
        QCOMPARE(o.scheme.at(0), Scheme::C);
        QCOMPARE(o.scheme.at(1), Scheme::C);
        QCOMPARE(o.scheme.at(2), Scheme::D);
        for (int t : {0, 1, 2})
            QCOMPARE(o.partial.at(t), true);
        QCOMPARE(int(o.cutEdges.size()), 4);
        // Without T0 nothing is partial: nodes 3 and 7 are cut nodes.
        const Outcome control = select(chainFixture(false), subdivision());
        QCOMPARE(control.cutNodes, (std::vector<int>{3, 7}));
        QCOMPARE(control.scheme.at(0), Scheme::Y);
        QCOMPARE(control.scheme.at(1), Scheme::X);
    }

    void resultDoesNotDependOnOrder_data() {
        QTest::addColumn<int>("fixture");
        QTest::addColumn<std::vector<int>>("newIndex");
        QTest::addColumn<std::vector<int>>("tetOrder");
        QTest::addColumn<bool>("reverseEdges");
        const std::vector<int> shuffled11{4, 9, 0, 7, 2, 10, 5, 1, 8, 3, 6};
        for (int fixture : {0, 1, 2}) {
            const int n = fixture == 0 ? 11 : 10; // nodes of the fixture
            std::vector<int> rev(n), shuf;
            for (int i = 0; i < n; ++i)
                rev[i] = n - 1 - i;
            for (int v : shuffled11)
                if (v < n)
                    shuf.push_back(v);
            const char* name = fixture == 0   ? "chain"
                               : fixture == 1 ? "fourth cut node, z2 nearer"
                                              : "fourth cut node, z3 nearer";
            QTest::addRow("%s, nodes reversed", name)
                << fixture << rev << std::vector<int>{} << false;
            QTest::addRow("%s, nodes shuffled", name)
                << fixture << shuf << std::vector<int>{} << false;
            QTest::addRow("%s, tets reversed", name)
                << fixture << std::vector<int>{} << std::vector<int>{2, 1, 0} << false;
            QTest::addRow("%s, crossed edges reversed", name)
                << fixture << std::vector<int>{} << std::vector<int>{} << true;
            QTest::addRow("%s, everything permuted", name)
                << fixture << shuf << std::vector<int>{1, 2, 0} << true;
        }
    }
    void resultDoesNotDependOnOrder() {
        QFETCH(int, fixture);
        QFETCH(std::vector<int>, newIndex);
        QFETCH(std::vector<int>, tetOrder);
        QFETCH(bool, reverseEdges);
        const Fixture f = fixture == 0   ? chainFixture(true)
                          : fixture == 1 ? fourthCutNodeFixture(0.01, -0.02)
                                         : fourthCutNodeFixture(0.02, -0.01);
        const SelectOptions options = hybrid(0.1);
        const Outcome expected = select(f, options);
        const Outcome o = select(f, options, newIndex, tetOrder, reverseEdges);
        QCOMPARE(o.cutNodes, expected.cutNodes);
        QCOMPARE(o.scheme, expected.scheme);
        QCOMPARE(o.partial, expected.partial);
        QCOMPARE(o.cutEdges.size(), expected.cutEdges.size());
        for (const auto& [edge, t] : expected.cutEdges) {
            QVERIFY(o.cutEdges.count(edge));
            QVERIFY(std::abs(o.cutEdges.at(edge) - t) <= 1e-15);
        }
    }

    void aTetNeverGetsAFourthCutNode_data() {
        QTest::addColumn<double>("z2");
        QTest::addColumn<double>("z3");
        QTest::addColumn<std::vector<int>>("cutNodes");
        QTest::addColumn<Scheme>("schemeB");
        QTest::addColumn<Scheme>("schemeC");
        QTest::newRow("node 2 nearer")
            << 0.01 << -0.02 << std::vector<int>{0, 1, 2} << Scheme::X << Scheme::A;
        QTest::newRow("node 3 nearer")
            << 0.02 << -0.01 << std::vector<int>{0, 1, 3} << Scheme::A << Scheme::X;
    }
    void aTetNeverGetsAFourthCutNode() {
        QFETCH(double, z2);
        QFETCH(double, z3);
        QFETCH(std::vector<int>, cutNodes);
        QFETCH(Scheme, schemeB);
        QFETCH(Scheme, schemeC);
        // Nodes 0 and 1 are on the sweep, 2 and 3 both within d = 0.1: Ta takes the nearer
        // nominee and refuses the other, which stays an ordinary node whose crossed edges
        // are split.
        const Outcome o = select(fourthCutNodeFixture(z2, z3), hybrid(0.1));
        QCOMPARE(o.cutNodes, cutNodes);
        QCOMPARE(o.scheme.at(0), Scheme::Z);
        QCOMPARE(o.scheme.at(1), schemeB);
        QCOMPARE(o.scheme.at(2), schemeC);
        // The refused node's edge to its other tet is split; edge 2-3 has a cut node.
        const std::array<int, 2> refusedEdge =
            cutNodes.back() == 2 ? std::array<int, 2>{3, 7} : std::array<int, 2>{2, 4};
        QVERIFY(o.cutEdges.count(refusedEdge));
        QVERIFY(!o.cutEdges.count({2, 3}));
    }

    void twinCopiesOfACrackWallAgree_data() {
        QTest::addColumn<double>("shiftB");
        QTest::addColumn<std::vector<int>>("cutNodes");
        QTest::newRow("twins") << 0.0 << std::vector<int>{1, 5, 7, 8};
        QTest::newRow("not twins") << -1e-3 << std::vector<int>{0, 1, 5, 7, 8};
    }
    void twinCopiesOfACrackWallAgree() {
        QFETCH(double, shiftB);
        QFETCH(std::vector<int>, cutNodes);
        // The two walls of an earlier crack in the plane y = 0: tet A (0, 1, 2, 3) on y > 0 and
        // tet B (4, 5, 6, 7) on y < 0, nodes 4-6 copies of 0-2 at the same positions. The
        // sweep z = 0 crosses edge 0-2 and its copy 4-6 near nodes 0 and 4 (0.1 above it, d
        // 0.2); nodes 1, 5, 7 and 8 lie on it. Node 0 becomes a cut node, its copy 4 cannot (tet
        // C, at 4, already has three), so A's edge would keep its length while B's copy is
        // split at a point on A's face (0, 1, 2): a T-junction (issue 16; box, twenty partial
        // strokes, seed 7). Node 0 is then no cut node either, and both copies are split.
        // Where B is not an exact copy (moved 0.001 off the wall), node 0 stays a cut node.
        const Vec3 P0(0, 0, 0.1), P1(1, 0, 0), P2(0, 0, -1), shift(0, shiftB, 0);
        std::vector<Vec3> nodes{P0, P1, P2, Vec3(0.3, 1, 0.5), P0 + shift, P1, P2 + shift, Vec3(0.3, -1, 0), Vec3(1, -1, 0)};
        std::vector<Tet> tets{{0, 1, 2, 3}, {4, 5, 6, 7}, {4, 5, 7, 8}};
        for (Tet& q : tets)
            if (orient3d(nodes[q[0]], nodes[q[1]], nodes[q[2]], nodes[q[3]]) < 0)
                std::swap(q[0], q[1]);
        const TetMesh mesh = TetMesh::fromArrays(nodes, tets);
        const SweepSurface sweep = planeZ0(-2, 2, -2, 2);
        const CutSelection sel =
            selectCutNodes(mesh, sweep, crossingsOfZ0(mesh, sweep, {{0, 2}, {2, 3}, {4, 6}}, {1, 5, 7, 8}), hybrid(0.2));
        QCOMPARE(sel.cutNodes, cutNodes);
        QVERIFY(sel.cutEdgeIndex.count(edgeKey(4, 6)));
        QCOMPARE(sel.cutEdgeIndex.count(edgeKey(0, 2)), cutNodes.front() == 0 ? std::size_t{0} : std::size_t{1});
    }

    void midpointTieDependsOnNodeNumbering() {
        // Known limitation, kept as an expected failure: an edge crossed exactly at its middle
        // nominates its lower-indexed end (t <= 0.5 picks a). Here node 0 is 0.05 above the
        // sweep and nodes 1-3 0.05 below it, so t = 0.05 / 0.1 = 0.5 exactly on all three
        // edges: numbered first, node 0 becomes the one cut node (Touch); numbered last, nodes
        // 1-3 become cut nodes (Z). Any other tie rule changes cut results in such ties.
        const Fixture f = nearerEndFixture(0.05, -0.05);
        const Outcome first = select(f, hybrid(0.06));
        const Outcome last = select(f, hybrid(0.06), {3, 0, 1, 2});
        QCOMPARE(first.cutNodes, std::vector<int>{0});
        QEXPECT_FAIL("", "exact midpoint ties go to the lower-indexed end of the edge", Continue);
        QCOMPARE(last.cutNodes, first.cutNodes);
    }

    void crossingsNearAnEndAreClamped_data() {
        QTest::addColumn<double>("zTop");
        QTest::addColumn<double>("zBottom");
        QTest::addColumn<double>("minEdgeFraction");
        QTest::addColumn<double>("expectedT"); ///< from node 0; NaN: the exact crossing
        const double nan = std::numeric_limits<double>::quiet_NaN();
        QTest::newRow("1e-9 from node 0, default fraction") << 1e-9 << -1.0 << 1e-6 << 1e-6;
        QTest::newRow("1e-9 from node 0, fraction 1e-3") << 1e-9 << -1.0 << 1e-3 << 1e-3;
        QTest::newRow("1e-9 from nodes 1-3") << 1.0 << -1e-9 << 1e-6 << 1.0 - 1e-6;
        QTest::newRow("a quarter along, not clamped") << 0.25 << -0.75 << 1e-6 << nan;
        QTest::newRow("above the fraction, not clamped") << 1e-3 << -(1 - 1e-3) << 1e-4 << nan;
    }
    void crossingsNearAnEndAreClamped() {
        QFETCH(double, zTop);
        QFETCH(double, zBottom);
        QFETCH(double, minEdgeFraction);
        QFETCH(double, expectedT);
        // Subdivision: node 0 cannot be a cut node, so its crossings are split, no nearer
        // than minEdgeFraction of the edge to either end.
        const Fixture f = nearerEndFixture(zTop, zBottom);
        SelectOptions options = subdivision();
        options.minEdgeFraction = minEdgeFraction;
        const Outcome o = select(f, options);
        const TetMesh mesh = TetMesh::fromArrays(f.nodes, f.tets);
        const IntersectedEdges crossings = crossingsOfZ0(mesh, f.sweep, f.crossed);
        QCOMPARE(int(o.raw.cutEdges.size()), 3);
        for (std::size_t k = 0; k < o.raw.cutEdges.size(); ++k) {
            const EdgeCrossing& c = o.raw.cutEdges[k];
            const EdgeCrossing& x = crossings.edges[k];
            QCOMPARE(c.a, 0);
            if (std::isnan(expectedT)) {
                QVERIFY(c.hit.t == x.hit.t); // bit for bit
                QCOMPARE(c.hit.point, x.hit.point);
            } else {
                QVERIFY2(c.hit.t == expectedT, qPrintable(QString::number(c.hit.t, 'g', 17)));
                QCOMPARE(c.hit.point,
                         Vec3(mesh.pos(c.a) + expectedT * (mesh.pos(c.b) - mesh.pos(c.a))));
            }
            QCOMPARE(o.raw.cutEdgeIndex.at(edgeKey(c.a, c.b)), int(k));
        }
    }
};

QTEST_GUILESS_MAIN(TestSelectCutNodes)
#include "test_select_cut_nodes.moc"
