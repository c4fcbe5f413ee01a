// CutSides (re-binding's per-cut answers about tets) against the definitions it replaced, on
// literal change lists: the ring of tets around a few tets reads the duplicated-node pairs in
// one pass in list order (a pair joins when a node of it is already in, so a chain only joins
// forwards), and a tet's side comes from the change list, else its first node off the cut
// surface that is off the sweep, else its centre.
#include "core/embed/cut_sides.h"
#include "core/mesh/box_mesh.h"

#include <QTest>

#include <algorithm>
#include <random>
#include <set>
#include <unordered_set>

using namespace resect;

namespace {

/// The ring as the binding computed it before issue 20: a hash set of nodes, the pairs in one
/// pass, the nodes' tets sorted.
std::vector<int> ringReference(const TetMesh& mesh, const CutChanges& changes, const std::vector<int>& tets) {
    std::unordered_set<int> nodes;
    for (int t : tets)
        for (int node : mesh.tet(t))
            nodes.insert(node);
    for (const auto& [orig, copy] : changes.duplicatedNodes)
        if (nodes.count(orig) || nodes.count(copy)) {
            nodes.insert(orig);
            nodes.insert(copy);
        }
    std::vector<int> ring;
    for (int node : nodes)
        ring.insert(ring.end(), mesh.nodeTets(node).begin(), mesh.nodeTets(node).end());
    std::sort(ring.begin(), ring.end());
    ring.erase(std::unique(ring.begin(), ring.end()), ring.end());
    return ring;
}

int tetSideReference(const TetMesh& mesh, const CutChanges& changes, const SweepSurface& sweep, int t) {
    if (auto it = changes.tetSide.find(t); it != changes.tetSide.end())
        return it->second;
    const std::set<int> onCut(changes.cutSurfaceNodes.begin(), changes.cutSurfaceNodes.end());
    Vec3 centre = Vec3::Zero();
    for (int node : mesh.tet(t)) {
        if (!onCut.count(node))
            if (const int s = sweep.sideOf(mesh.pos(node)); s != 0)
                return s;
        centre += mesh.pos(node) / 4.0;
    }
    return sweep.sideOf(centre);
}

SweepSurface planeAt(double z) {
    SweepSurface sweep;
    if (!SweepSurface::fromStartEnd({Vec3(-1, -1, z), Vec3(5, -1, z)}, {Vec3(-1, 5, z), Vec3(5, 5, z)}, sweep).ok())
        qFatal("sweep");
    return sweep;
}

} // namespace

class TestCutSides : public QObject {
    Q_OBJECT
private slots:
    /// Pairs whose order matters: (a, b) then (b, c) joins c when a is in; (b, c) then (a, b)
    /// does not. Both orders, and a node with two copies.
    void ringReadsPairsInListOrder() {
        const TetMesh mesh = makeBoxTetMesh(Vec3::Zero(), Vec3::Constant(4), 4, 4, 4);
        const int a = mesh.tet(0)[0];
        // b and c: nodes far from tet 0 (the last tets' nodes).
        const int b = mesh.tet(mesh.tetCount() - 1)[3], c = mesh.tet(mesh.tetCount() / 2)[2];
        QVERIFY(a != b && b != c && a != c);
        const SweepSurface sweep = planeAt(2.01);
        for (const auto& pairs : std::vector<std::vector<std::array<int, 2>>>{
                 {{a, b}, {b, c}}, {{b, c}, {a, b}}, {{a, b}, {a, c}}, {{c, b}, {b, a}}, {}}) {
            CutChanges changes;
            changes.duplicatedNodes = pairs;
            CutSides sides;
            sides.begin(mesh, changes, sweep);
            std::vector<int> ring;
            sides.ring(std::vector<int>{0}, ring);
            std::sort(ring.begin(), ring.end());
            QCOMPARE(ring, ringReference(mesh, changes, {0}));
            for (int t : ring)
                QVERIFY(sides.inRing(t));
        }
        // The forward chain reaches c's tets, the backward one does not.
        CutChanges forward, backward;
        forward.duplicatedNodes = {{a, b}, {b, c}};
        backward.duplicatedNodes = {{b, c}, {a, b}};
        QVERIFY(ringReference(mesh, forward, {0}).size() > ringReference(mesh, backward, {0}).size());
    }

    /// Random change lists (pairs, cut nodes, recorded tet sides) on a box: ring and tetSide
    /// agree with the definitions for every tet, and a second begin() forgets the first cut.
    void agreesWithTheDefinitions() {
        const TetMesh mesh = makeBoxTetMesh(Vec3::Zero(), Vec3::Constant(4), 4, 4, 4);
        std::mt19937 rng(3);
        std::uniform_int_distribution<int> node(0, mesh.nodeCount() - 1), tet(0, mesh.tetCount() - 1), coin(0, 2);
        CutSides sides;
        for (int round = 0; round < 20; ++round) {
            // Planes through node layers (z = 1, 2, 3: nodes on the sweep) and between them.
            const SweepSurface sweep = planeAt(round % 2 ? 1.0 + round % 3 : 1.37 + 0.2 * (round % 3));
            CutChanges changes;
            for (int k = 0; k < 12; ++k)
                changes.duplicatedNodes.push_back({node(rng), node(rng)});
            for (int k = 0; k < 15; ++k)
                changes.cutSurfaceNodes.push_back(node(rng));
            for (int k = 0; k < 10; ++k)
                changes.tetSide[tet(rng)] = static_cast<std::int8_t>(coin(rng) - 1);
            sides.begin(mesh, changes, sweep);
            for (int t = 0; t < mesh.tetCount(); ++t)
                QCOMPARE(sides.tetSide(t), tetSideReference(mesh, changes, sweep, t));
            for (int k = 0; k < 10; ++k) {
                const std::vector<int> tets{tet(rng), tet(rng)};
                std::vector<int> ring;
                sides.ring(tets, ring);
                std::sort(ring.begin(), ring.end());
                QCOMPARE(ring, ringReference(mesh, changes, tets));
            }
        }
    }
};

QTEST_GUILESS_MAIN(TestCutSides)
#include "test_cut_sides.moc"
