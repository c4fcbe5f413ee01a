// Step 7 alone (improve_mesh.h): local mesh improvement on literal meshes. A short interior
// edge and a short edge on a flat face are collapsed at scales 1e-3, 1 and 1e3 (volume and
// mass kept to 1e-12, the merged node on the face plane, every tet positive in both
// configurations, no unused node); a short edge on a curved boundary keeps the volume by
// moving the merged node along the old boundary, within maxDeviation of it; the link
// condition refuses a collapse that would pinch the body; fixed nodes are bit-identical;
// no node enters the keepOut box; smoothing raises the worst radius ratio; current positions
// and velocities follow an affine deformation exactly; the renumbering maps name the same
// tets. Also TetMesh::removeTet / removeNode: swap-with-last without a backup, and exact undo
// by a TetMeshBackup.
#include "core/cut/improve_mesh.h"

#include "core/mesh/box_mesh.h"
#include "core/mesh/masses.h"
#include "core/mesh/predicates.h"
#include "core/mesh/quality.h"
#include "core/mesh/tet_mesh_backup.h"
#include "core/mesh/topology.h"
#include "core/mesh/validity.h"
#include "improve_regressions.h"
#include "pit_regressions.h"

#include <QStringList>
#include <QTest>

#include <algorithm>
#include <cstring>
#include <limits>
#include <map>
#include <numeric>
#include <random>
#include <set>

using namespace resect;

namespace {

constexpr double kDensity = 1.5e-3; // g/mm^3, not ImproveOptions' default on purpose


/// Index of node (i, j, k) of makeBoxTetMesh with `cells` cells along x and y.
int boxNode(int cells, int i, int j, int k) {
    return i + (cells + 1) * (j + (cells + 1) * k);
}

/// The cube [0, size]^3 split into cells^3 Kuhn cubes.
TetMesh cube(double size, int cells) {
    return makeBoxTetMesh(Vec3::Zero(), Vec3::Constant(size), cells, cells, cells);
}

/// Moves node n to p in both configurations (no backup is open in these tests).
void place(TetMesh& m, int n, const Vec3& p) {
    m.referencePositions()[n] = p;
    m.positions()[n] = p;
}

/// The cube of `cells`^3 cells of side `size`, its interior nodes moved at random by up to
/// `jitter` cells (reproducible from `seed`).
TetMesh jitteredCube(double size, int cells, unsigned seed, double jitter) {
    TetMesh m = cube(size, cells);
    std::mt19937 rng(seed);
    const double h = size / cells;
    std::uniform_real_distribution<double> u(-jitter * h, jitter * h);
    for (int k = 1; k < cells; ++k)
        for (int j = 1; j < cells; ++j)
            for (int i = 1; i < cells; ++i) {
                const int n = boxNode(cells, i, j, k);
                place(m, n, m.ref(n) + Vec3(u(rng), u(rng), u(rng)));
            }
    return m;
}

bool bitIdentical(const Vec3& a, const Vec3& b) {
    return std::memcmp(a.data(), b.data(), sizeof(double) * 3) == 0;
}

/// Every problem checkValidity finds, plus any tet that is not strictly positive (exact
/// orient3d) in the reference or the current configuration.
QString meshViolations(const TetMesh& m) {
    QStringList problems;
    for (const MeshProblem& p : checkValidity(m)) {
        problems << QString::fromStdString(p.message);
        if (problems.size() > 10)
            break;
    }
    for (int t = 0; t < m.tetCount(); ++t) {
        const Tet& q = m.tet(t);
        if (orient3d(m.ref(q[0]), m.ref(q[1]), m.ref(q[2]), m.ref(q[3])) <= 0)
            problems << QString("tet %1 is not positive in the reference configuration").arg(t);
        if (orient3d(m.pos(q[0]), m.pos(q[1]), m.pos(q[2]), m.pos(q[3])) <= 0)
            problems << QString("tet %1 is not positive in the current configuration").arg(t);
    }
    return problems.join("; ");
}

/// Empty if the boundary is a manifold: at every boundary node the boundary triangles form
/// one disc (the edges opposite the node form a single oriented cycle).
QString boundaryViolations(const TetMesh& m) {
    std::vector<std::vector<std::array<int, 2>>> link(m.nodeCount());
    for (const BoundaryFace& f : boundaryFaces(m))
        for (int i = 0; i < 3; ++i)
            link[f.nodes[i]].push_back({f.nodes[(i + 1) % 3], f.nodes[(i + 2) % 3]});
    QStringList problems;
    for (int n = 0; n < m.nodeCount(); ++n) {
        if (link[n].empty())
            continue;
        std::map<int, int> next;
        bool ok = true;
        for (const auto& e : link[n])
            ok = ok && next.emplace(e[0], e[1]).second;
        const int first = link[n][0][0];
        int v = first;
        std::size_t steps = 0;
        while (ok && steps < link[n].size()) {
            const auto it = next.find(v);
            if (it == next.end())
                ok = false;
            else
                v = it->second;
            ++steps;
            if (v == first)
                break;
        }
        if (!ok || v != first || steps != link[n].size())
            problems << QString("boundary not a disc at node %1").arg(n);
    }
    return problems.join("; ");
}

Tet sortedTet(Tet q) {
    std::sort(q.begin(), q.end());
    return q;
}

/// Empty if the result's renumbering describes `after` from `before`: without renumbering
/// the tets are the same; with it, the node map is onto every final node (merged nodes onto the
/// node they merged into), the tet map is injective, every surviving tet keeps its node set
/// (mapped through the node map), the created tets are those no old tet maps to, and the maps
/// list only indices that changed, sorted.
QString renumberingViolations(const TetMesh& before, const TetMesh& after, const ImproveResult& r) {
    QStringList problems;
    if (!r.renumbered()) {
        if (!r.renumbering.nodes.empty() || !r.createdTets.empty())
            problems << "a node renumbering or created tets without tets changing";
        if (after.tetCount() != before.tetCount() || after.nodeCount() != before.nodeCount())
            return "counts changed without renumbering";
        for (int t = 0; t < before.tetCount(); ++t)
            if (after.tet(t) != before.tet(t))
                problems << QString("tet %1 changed without renumbering").arg(t);
        return problems.join("; ");
    }
    const SparseRenumbering &tets = r.renumbering.tets, &nodes = r.renumbering.nodes;
    if (tets.oldCount != before.tetCount() || nodes.oldCount != before.nodeCount() ||
        tets.newCount != after.tetCount() || nodes.newCount != after.nodeCount())
        return QString("counts %1 -> %2 tets, %3 -> %4 nodes for %5 -> %6, %7 -> %8")
            .arg(tets.oldCount).arg(tets.newCount).arg(nodes.oldCount).arg(nodes.newCount)
            .arg(before.tetCount()).arg(after.tetCount()).arg(before.nodeCount()).arg(after.nodeCount());
    // Sparse: only changed indices, sorted, each once.
    for (const SparseRenumbering* map : {&tets, &nodes})
        for (std::size_t i = 0; i < map->changed.size(); ++i) {
            if (map->changed[i].first == map->changed[i].second)
                problems << QString("unchanged index %1 listed").arg(map->changed[i].first);
            if (i > 0 && map->changed[i - 1].first >= map->changed[i].first)
                problems << QString("changed indices not sorted at %1").arg(map->changed[i].first);
        }
    if (before.nodeCount() - after.nodeCount() != r.removedNodes - r.splits)
        problems << QString("%1 nodes removed, %2 reported (%3 added by splits)")
                        .arg(before.nodeCount() - after.nodeCount())
                        .arg(r.removedNodes)
                        .arg(r.splits);
    std::vector<int> hits(after.nodeCount(), 0);
    for (int n = 0; n < before.nodeCount(); ++n) {
        const int to = nodes(n);
        if (to < 0 || to >= after.nodeCount()) {
            problems << QString("node %1 maps to %2").arg(n).arg(to);
            continue;
        }
        ++hits[to];
    }
    // A final node no old node maps to was added by a split: it was placed, so it is reported
    // as moved, and there are no more of them than splits.
    int added = 0;
    for (int n = 0; n < after.nodeCount(); ++n)
        if (hits[n] == 0) {
            ++added;
            if (!std::binary_search(r.movedNodes.begin(), r.movedNodes.end(), n))
                problems << QString("final node %1 stands for no old node and was not reported moved").arg(n);
        }
    if (added > r.splits)
        problems << QString("%1 new nodes after %2 splits").arg(added).arg(r.splits);
    std::vector<int> tetHits(after.tetCount(), 0);
    for (int t = 0; t < before.tetCount(); ++t) {
        const int to = tets(t);
        if (to < 0)
            continue;
        if (to >= after.tetCount()) {
            problems << QString("tet %1 maps to %2").arg(t).arg(to);
            continue;
        }
        if (tetHits[to]++)
            problems << QString("two old tets map to tet %1").arg(to);
        Tet mapped = before.tet(t);
        for (int& v : mapped)
            v = nodes(v);
        if (sortedTet(mapped) != sortedTet(after.tet(to)))
            problems << QString("old tet %1 maps to tet %2 with other nodes").arg(t).arg(to);
    }
    // The tets no old tet maps to are exactly the created ones.
    std::vector<int> created;
    for (int t = 0; t < after.tetCount(); ++t)
        if (tetHits[t] == 0)
            created.push_back(t);
    if (created != r.createdTets)
        problems << QString("%1 tets stand for no old tet, %2 reported created").arg(created.size()).arg(r.createdTets.size());
    return problems.join("; ");
}

/// Final index of old node n.
int finalIndex(const ImproveResult& r, int n) {
    return r.renumbering.nodes(n);
}

double shortestEdge(const TetMesh& m) {
    double shortest = std::numeric_limits<double>::infinity();
    for (const auto& e : uniqueEdges(m))
        shortest = std::min(shortest, (m.ref(e[0]) - m.ref(e[1])).norm());
    return shortest;
}

double worstRatioAround(const TetMesh& m, int n) {
    double worst = 1;
    for (int t : m.nodeTets(n)) {
        const Tet& q = m.tet(t);
        worst = std::min(worst, radiusRatio(m.ref(q[0]), m.ref(q[1]), m.ref(q[2]), m.ref(q[3])));
    }
    return worst;
}

/// Boundary triangles of m (reference positions) that have a corner in `nodes`, each once.
std::vector<std::array<Vec3, 3>> boundaryTrianglesAt(const TetMesh& m,
                                                     const std::vector<int>& nodes) {
    std::vector<std::array<Vec3, 3>> tris;
    for (const BoundaryFace& f : boundaryFaces(m)) {
        const bool at = std::any_of(f.nodes.begin(), f.nodes.end(), [&](int v) {
            return std::find(nodes.begin(), nodes.end(), v) != nodes.end();
        });
        if (at)
            tris.push_back({m.ref(f.nodes[0]), m.ref(f.nodes[1]), m.ref(f.nodes[2])});
    }
    return tris;
}

double distanceTo(const Vec3& p, const std::vector<std::array<Vec3, 3>>& tris) {
    double best = std::numeric_limits<double>::infinity();
    for (const auto& t : tris)
        best = std::min(best, pointTriangleDistance(p, t[0], t[1], t[2]));
    return best;
}

/// Mean edge length of the boundary triangles at a and at b, a triangle at both counted
/// twice (the "local edge" that ImproveOptions::maxDeviation is a fraction of).
double meanBoundaryEdge(const TetMesh& m, int a, int b) {
    double sum = 0;
    int count = 0;
    for (int n : {a, b})
        for (const auto& t : boundaryTrianglesAt(m, {n}))
            for (int i = 0; i < 3; ++i) {
                sum += (t[i] - t[(i + 1) % 3]).norm();
                ++count;
            }
    return sum / count;
}

/// The reference volume of the tets of a and b if both were placed at p (the tets of the edge
/// become flat): what a collapse into p without a volume correction would leave.
double volumeIfMergedAt(const TetMesh& m, int a, int b, const Vec3& p) {
    std::set<int> tets(m.nodeTets(a).begin(), m.nodeTets(a).end());
    tets.insert(m.nodeTets(b).begin(), m.nodeTets(b).end());
    double volume = 0;
    for (int t : tets) {
        std::array<Vec3, 4> c;
        for (int i = 0; i < 4; ++i) {
            const int v = m.tet(t)[i];
            c[i] = v == a || v == b ? p : m.ref(v);
        }
        volume += signedVolume(c[0], c[1], c[2], c[3]);
    }
    return volume;
}

double volumeOfStars(const TetMesh& m, int a, int b) {
    std::set<int> tets(m.nodeTets(a).begin(), m.nodeTets(a).end());
    tets.insert(m.nodeTets(b).begin(), m.nodeTets(b).end());
    double volume = 0;
    for (int t : tets)
        volume += m.referenceVolume(t);
    return volume;
}

double relative(double value, double reference) {
    return std::abs(value - reference) / std::abs(reference);
}

/// What every pass keeps, or what it broke: an exact renumbering, the volume and the mass,
/// Eq. 3 at every node (density kDensity), a valid mesh.
QString brokenInvariants(const TetMesh& before, const TetMesh& after, const ImproveResult& r) {
    QStringList problems;
    if (const QString renumbering = renumberingViolations(before, after, r); !renumbering.isEmpty())
        problems << renumbering;
    if (relative(after.totalReferenceVolume(), before.totalReferenceVolume()) > 1e-12)
        problems << QString("volume %1 -> %2").arg(before.totalReferenceVolume()).arg(after.totalReferenceVolume());
    if (relative(sumOfMasses(after), sumOfMasses(before)) > 1e-12)
        problems << QString("mass %1 -> %2").arg(sumOfMasses(before)).arg(sumOfMasses(after));
    TetMesh scratch = after;
    computeLumpedMasses(scratch, kDensity);
    for (int n = 0; n < after.nodeCount(); ++n)
        if (relative(after.masses()[n], scratch.masses()[n]) > 1e-12)
            problems << QString("node %1's mass is not Eq. 3's").arg(n);
    if (const auto validity = checkValidity(after); !validity.empty())
        problems << QString::fromStdString(validity.front().message);
    return problems.join("; ");
}

/// Empty if the two meshes are bit-identical: tets, every node array, and every node's
/// adjacency list in the same order.
QString differences(const TetMesh& a, const TetMesh& b) {
    if (a.nodeCount() != b.nodeCount() || a.tetCount() != b.tetCount())
        return QString("counts %1/%2 vs %3/%4")
            .arg(a.nodeCount())
            .arg(a.tetCount())
            .arg(b.nodeCount())
            .arg(b.tetCount());
    QStringList problems;
    for (int t = 0; t < a.tetCount(); ++t)
        if (a.tet(t) != b.tet(t))
            problems << QString("tet %1").arg(t);
    for (int n = 0; n < a.nodeCount(); ++n) {
        if (!bitIdentical(a.ref(n), b.ref(n)) || !bitIdentical(a.pos(n), b.pos(n)) ||
            !bitIdentical(a.velocities()[n], b.velocities()[n]) ||
            std::memcmp(&a.masses()[n], &b.masses()[n], sizeof(double)) != 0)
            problems << QString("data of node %1").arg(n);
        if (!std::equal(a.nodeTets(n).begin(), a.nodeTets(n).end(), b.nodeTets(n).begin(),
                        b.nodeTets(n).end()))
            problems << QString("adjacency of node %1").arg(n);
    }
    return problems.join("; ");
}

/// Empty if every node's adjacency list holds exactly the tets that use it.
QString adjacencyViolations(const TetMesh& m) {
    std::vector<std::vector<int>> expected(m.nodeCount());
    for (int t = 0; t < m.tetCount(); ++t)
        for (int v : m.tet(t))
            expected[v].push_back(t);
    QStringList problems;
    for (int n = 0; n < m.nodeCount(); ++n) {
        std::vector<int> got(m.nodeTets(n).begin(), m.nodeTets(n).end());
        std::sort(got.begin(), got.end());
        if (got != expected[n])
            problems << QString("adjacency of node %1").arg(n);
    }
    return problems.join("; ");
}

/// The old nodes whose reference position changed (a merged node compared with the node
/// standing for it).
std::vector<int> movedOldNodes(const TetMesh& before, const TetMesh& after,
                               const ImproveResult& r) {
    std::vector<int> moved;
    for (int n = 0; n < before.nodeCount(); ++n)
        if (!bitIdentical(before.ref(n), after.ref(finalIndex(r, n))))
            moved.push_back(n);
    return moved;
}

/// The unit cube split into five tets: corners x + 2y + 4z; the corner tets of the odd
/// corners 1, 2, 4, 7 (each the only tet of its corner) and the central tet (0, 5, 3, 6).
TetMesh fiveTetCube() {
    return TetMesh::fromArrays(
        {Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0), Vec3(1, 1, 0), Vec3(0, 0, 1), Vec3(1, 0, 1),
         Vec3(0, 1, 1), Vec3(1, 1, 1)},
        {{1, 3, 0, 5}, {2, 0, 3, 6}, {4, 6, 5, 0}, {7, 5, 6, 3}, {0, 5, 3, 6}});
}

} // namespace

class TestImproveMesh : public QObject {
    Q_OBJECT
private slots:
    void regionIsSeedsAndRingsWithoutFixedNodes() {
        // One ring around the centre of a 4^3 cube: the centre and its 14 neighbours; the
        // fixed neighbour is listed apart, the fixed corner (outside the ring) nowhere; the
        // tets are those of all 15.
        const TetMesh m = cube(1, 4);
        const int centre = boxNode(4, 2, 2, 2), fixed = boxNode(4, 1, 2, 2),
                  far = boxNode(4, 0, 0, 0);
        const ImproveRegion region = improveRegion(m, {centre}, {fixed, far}, 1);
        std::vector<int> ring = m.nodeNeighbours(centre);
        QCOMPARE(int(ring.size()), 14); // an interior Kuhn node
        ring.push_back(centre);
        std::sort(ring.begin(), ring.end());
        std::vector<int> expected = ring;
        expected.erase(std::find(expected.begin(), expected.end(), fixed));
        QCOMPARE(region.nodes, expected);
        QCOMPARE(region.fixed, std::vector<int>{fixed});
        std::set<int> tets;
        for (int n : ring)
            tets.insert(m.nodeTets(n).begin(), m.nodeTets(n).end());
        QCOMPARE(region.tets, std::vector<int>(tets.begin(), tets.end()));
        // Two rings: the neighbours of the first ring too.
        std::set<int> twoRings;
        for (int n : m.nodeNeighbours(centre))
            for (int u : m.nodeNeighbours(n))
                twoRings.insert(u);
        const ImproveRegion wider = improveRegion(m, {centre}, {}, 2);
        QCOMPARE(wider.nodes, std::vector<int>(twoRings.begin(), twoRings.end()));
        QVERIFY(wider.fixed.empty());
        QVERIFY(wider.nodes.size() > ring.size());
    }

    void nothingToDoLeavesTheMeshAlone() {
        TetMesh m = jitteredCube(1, 3, 7, 0.3);
        computeLumpedMasses(m, kDensity);
        const TetMesh before = m;
        const ImproveRegion region = improveRegion(m, {boxNode(3, 1, 1, 1)}, {}, 2);
        ImproveOptions o; // badRatio = shortEdge = 0: nothing is bad
        o.density = kDensity;
        const ImproveResult r = improveMesh(m, region, o);
        QCOMPARE(r.collapses + r.smoothed + r.removedTets + r.removedNodes, 0);
        QVERIFY(!r.renumbered());
        QVERIFY2(differences(before, m).isEmpty(), qPrintable(differences(before, m)));
    }

    void shortInteriorEdgeIsCollapsed_data() {
        QTest::addColumn<double>("scale");
        QTest::newRow("1e-3") << 1e-3;
        QTest::newRow("1") << 1.0;
        QTest::newRow("1e3") << 1e3;
    }
    void shortInteriorEdgeIsCollapsed() {
        // Node b = (2, 2, 2) of a 4^3 cube moved to 5% of the way from its neighbour
        // a = (1, 2, 2): the edge a-b is 0.05 cells long, every other edge at least 0.95.
        QFETCH(double, scale);
        const int cells = 4;
        const double h = scale / cells;
        TetMesh m = cube(scale, cells);
        const int a = boxNode(cells, 1, 2, 2), b = boxNode(cells, 2, 2, 2);
        place(m, b, m.ref(a) + 0.05 * (m.ref(b) - m.ref(a)));
        computeLumpedMasses(m, kDensity);
        QVERIFY2(meshViolations(m).isEmpty(), qPrintable(meshViolations(m)));
        const TetMesh before = m;
        const double volume = m.totalReferenceVolume(), mass = sumOfMasses(m);

        ImproveOptions o;
        o.shortEdge = 0.2 * h;
        o.density = kDensity;
        const ImproveResult r = improveMesh(m, improveRegion(m, {b}, {}, 2), o);

        QVERIFY2(r.collapses >= 1, qPrintable(QString::number(r.collapses)));
        QVERIFY(r.renumbered());
        QCOMPARE(r.renumbering.nodes(b), r.renumbering.nodes(a)); // the edge is gone: its ends are one node
        QCOMPARE(r.removedNodes, r.collapses);
        QCOMPARE(m.nodeCount(), before.nodeCount() - r.removedNodes);
        QVERIFY2(shortestEdge(m) >= o.shortEdge, qPrintable(QString::number(shortestEdge(m) / h)));
        QVERIFY2(meshViolations(m).isEmpty(), qPrintable(meshViolations(m)));
        QVERIFY2(renumberingViolations(before, m, r).isEmpty(),
                 qPrintable(renumberingViolations(before, m, r)));
        QVERIFY2(relative(m.totalReferenceVolume(), volume) <= 1e-12,
                 qPrintable(QString::number(relative(m.totalReferenceVolume(), volume))));
        QVERIFY2(relative(sumOfMasses(m), mass) <= 1e-12,
                 qPrintable(QString::number(relative(sumOfMasses(m), mass))));
        // Eq. 3 holds at every node, not only in total.
        TetMesh scratch = m;
        computeLumpedMasses(scratch, kDensity);
        for (int n = 0; n < m.nodeCount(); ++n)
            QVERIFY2(relative(m.masses()[n], scratch.masses()[n]) <= 1e-12,
                     qPrintable(QString::number(n)));
        // The merged node is reported as moved and touched.
        const int merged = r.renumbering.nodes(a);
        QVERIFY(std::binary_search(r.movedNodes.begin(), r.movedNodes.end(), merged));
        QVERIFY(std::binary_search(r.touchedNodes.begin(), r.touchedNodes.end(), merged));
    }

    void shortBoundaryEdgeStaysOnItsFace_data() { shortInteriorEdgeIsCollapsed_data(); }
    void shortBoundaryEdgeStaysOnItsFace() {
        // Node b = (2, 2, 0) on the face z = 0 moved within the face to 5% of the way from
        // a = (1, 2, 0): the edge a-b is a short edge of the boundary.
        QFETCH(double, scale);
        const int cells = 4;
        const double h = scale / cells;
        TetMesh m = cube(scale, cells);
        const int a = boxNode(cells, 1, 2, 0), b = boxNode(cells, 2, 2, 0);
        place(m, b, m.ref(a) + 0.05 * (m.ref(b) - m.ref(a)));
        QCOMPARE(m.ref(b).z(), 0.0);
        computeLumpedMasses(m, kDensity);
        QVERIFY2(meshViolations(m).isEmpty(), qPrintable(meshViolations(m)));
        const TetMesh before = m;
        const double mass = sumOfMasses(m);

        ImproveOptions o;
        o.shortEdge = 0.2 * h;
        o.density = kDensity;
        const ImproveResult r = improveMesh(m, improveRegion(m, {b}, {}, 2), o);

        QVERIFY2(r.collapses >= 1, qPrintable(QString::number(r.collapses)));
        QVERIFY(r.renumbered());
        QCOMPARE(r.renumbering.nodes(b), r.renumbering.nodes(a));
        const Vec3 merged = m.ref(r.renumbering.nodes(a));
        QVERIFY2(std::abs(merged.z()) < 1e-12 * scale,
                 qPrintable(QString::number(merged.z() / scale)));
        // Every node on a face of the cube is still on it; none left the cube.
        for (int n = 0; n < before.nodeCount(); ++n)
            for (int axis = 0; axis < 3; ++axis) {
                const double was = before.ref(n)[axis], is = m.ref(r.renumbering.nodes(n))[axis];
                if (was == 0 || was == scale)
                    QVERIFY2(std::abs(is - was) < 1e-12 * scale,
                             qPrintable(QString("node %1 axis %2").arg(n).arg(axis)));
                QVERIFY(is > -1e-12 * scale && is < scale * (1 + 1e-12));
            }
        QVERIFY2(shortestEdge(m) >= o.shortEdge, qPrintable(QString::number(shortestEdge(m) / h)));
        QVERIFY2(meshViolations(m).isEmpty(), qPrintable(meshViolations(m)));
        QVERIFY2(renumberingViolations(before, m, r).isEmpty(),
                 qPrintable(renumberingViolations(before, m, r)));
        const double cubeVolume = scale * scale * scale;
        QVERIFY2(relative(m.totalReferenceVolume(), cubeVolume) <= 1e-12,
                 qPrintable(QString::number(relative(m.totalReferenceVolume(), cubeVolume))));
        QVERIFY2(relative(sumOfMasses(m), mass) <= 1e-12,
                 qPrintable(QString::number(relative(sumOfMasses(m), mass))));
    }

    void curvedBoundaryKeepsVolume_data() {
        // onOldBoundary: a point of the old boundary keeps the volume (around a saddle the
        // boundary rises on one side and falls on the other), so the merged node must be on it.
        // At the top of a dome (bottom of a bowl) none does: it moves off within maxDeviation.
        QTest::addColumn<double>("bulge");
        QTest::addColumn<double>("saddle");
        QTest::addColumn<bool>("onOldBoundary");
        QTest::newRow("dome 0.2") << 0.2 << 0.0 << false;
        QTest::newRow("dome 0.4") << 0.4 << 0.0 << false;
        QTest::newRow("bowl -0.2") << -0.2 << 0.0 << false;
        QTest::newRow("saddle 0.2") << 0.0 << 0.2 << true;
        QTest::newRow("saddle -0.3") << 0.0 << -0.3 << true;
        QTest::newRow("saddle 0.2, dome 0.1") << 0.1 << 0.2 << true;
    }
    void curvedBoundaryKeepsVolume() {
        // The unit 4^3 cube with its top raised into a dome (or lowered into a bowl, or bent
        // into a saddle): z -> z (1 + bulge (1 - 4 r^2) + saddle 4 (dx^2 - dy^2)), r, dx and dy
        // measured from the vertical axis x = y = 1/2.
        // Node b = (1, 2, 4) of the top is moved to 10% of the way from the centre a = (2, 2, 4),
        // along the edge a-b. Merging a and b at a, at b or at the midpoint changes the
        // volume (checked): the merged node must go where the volume is kept.
        QFETCH(double, bulge);
        QFETCH(double, saddle);
        QFETCH(bool, onOldBoundary);
        const int cells = 4;
        TetMesh m = cube(1, cells);
        for (int n = 0; n < m.nodeCount(); ++n) {
            const Vec3 p = m.ref(n);
            const double x2 = (p.x() - 0.5) * (p.x() - 0.5), y2 = (p.y() - 0.5) * (p.y() - 0.5);
            const double lift = bulge * (1 - 4 * (x2 + y2)) + saddle * 4 * (x2 - y2);
            place(m, n, Vec3(p.x(), p.y(), p.z() * (1 + lift)));
        }
        const int a = boxNode(cells, 2, 2, 4), b = boxNode(cells, 1, 2, 4);
        place(m, b, m.ref(a) + 0.1 * (m.ref(b) - m.ref(a)));
        computeLumpedMasses(m, kDensity);
        QVERIFY2(meshViolations(m).isEmpty(), qPrintable(meshViolations(m)));
        const TetMesh before = m;
        const double volume = m.totalReferenceVolume(), mass = sumOfMasses(m);
        const double stars = volumeOfStars(m, a, b);
        for (const Vec3& p : {m.ref(a), m.ref(b), Vec3(0.5 * (m.ref(a) + m.ref(b)))})
            QVERIFY2(std::abs(volumeIfMergedAt(m, a, b, p) - stars) > 1e-4 * volume,
                     qPrintable(QString::number(relative(volumeIfMergedAt(m, a, b, p), stars))));

        ImproveOptions o;
        o.shortEdge = 0.05; // the edge a-b is 0.025 long, the others at least 0.2
        o.density = kDensity;
        const ImproveResult r = improveMesh(m, improveRegion(m, {b}, {}, 2), o);

        QVERIFY2(r.collapses >= 1, qPrintable(QString::number(r.collapses)));
        QCOMPARE(r.renumbering.nodes(b), r.renumbering.nodes(a));
        QVERIFY2(relative(m.totalReferenceVolume(), volume) <= 1e-9,
                 qPrintable(QString::number(relative(m.totalReferenceVolume(), volume))));
        QVERIFY2(relative(sumOfMasses(m), mass) <= 1e-9,
                 qPrintable(QString::number(relative(sumOfMasses(m), mass))));
        QVERIFY2(meshViolations(m).isEmpty(), qPrintable(meshViolations(m)));
        QVERIFY2(renumberingViolations(before, m, r).isEmpty(),
                 qPrintable(renumberingViolations(before, m, r)));
        // The merged node is within maxDeviation local edges of the old boundary around a and
        // b, and a and b were within that of the new boundary around the merged node.
        const int merged = r.renumbering.nodes(a);
        const double tolerance = o.maxDeviation * meanBoundaryEdge(before, a, b);
        const double off = distanceTo(m.ref(merged), boundaryTrianglesAt(before, {a, b}));
        const auto newBoundary = boundaryTrianglesAt(m, {merged});
        const double offA = distanceTo(before.ref(a), newBoundary);
        const double offB = distanceTo(before.ref(b), newBoundary);
        QVERIFY2(off <= (onOldBoundary ? 1e-12 : tolerance),
                 qPrintable(QString::number(off / tolerance)));
        QVERIFY2(offA <= tolerance, qPrintable(QString::number(offA / tolerance)));
        QVERIFY2(offB <= tolerance, qPrintable(QString::number(offB / tolerance)));
    }

    void linkConditionRefusesAPinch_data() {
        QTest::addColumn<double>("tilt");
        QTest::addColumn<double>("gap");
        QTest::newRow("tilt 0.3, gap 0.02") << 0.3 << 0.02;
        QTest::newRow("tilt 0.2, gap 0.01") << 0.2 << 0.01;
    }
    void linkConditionRefusesAPinch() {
        // A slab of 4 x 4 x 1 cells, its top tilted (z -> z (1 + tilt x)); node a = (2, 2, 0)
        // of the bottom is raised and node b = (2, 2, 1) of the top lowered until they are
        // `gap` top heights apart. The edge a-b is interior, its ends on the boundary (the
        // virtual vertex is in both links, not in the edge's): collapsing it would pinch the
        // slab into a non-manifold point, though a placement keeping the volume and every tet
        // positive exists (without the link condition the pass collapses it).
        QFETCH(double, tilt);
        QFETCH(double, gap);
        const int cells = 4;
        TetMesh m = makeBoxTetMesh(Vec3::Zero(), Vec3(4, 4, 1), cells, cells, 1);
        for (int n = 0; n < m.nodeCount(); ++n) {
            const Vec3 p = m.ref(n);
            place(m, n, Vec3(p.x(), p.y(), p.z() * (1 + tilt * p.x())));
        }
        const int a = boxNode(cells, 2, 2, 0), b = boxNode(cells, 2, 2, 1);
        const double top = m.ref(b).z();
        place(m, a, Vec3(2, 2, (0.5 - gap / 2) * top));
        place(m, b, Vec3(2, 2, (0.5 + gap / 2) * top));
        computeLumpedMasses(m, kDensity);
        QVERIFY2(meshViolations(m).isEmpty(), qPrintable(meshViolations(m)));
        QVERIFY(!isBoundaryEdge(m, a, b) && isBoundaryNode(m, a) && isBoundaryNode(m, b));
        QVERIFY2(boundaryViolations(m).isEmpty(), qPrintable(boundaryViolations(m)));
        const TetMesh before = m;
        ImproveOptions o;
        o.shortEdge = 0.2; // only a-b is shorter
        o.density = kDensity;
        const ImproveResult r = improveMesh(m, improveRegion(m, {a, b}, {}, 1), o);
        QCOMPARE(r.collapses, 0);
        QVERIFY(!r.renumbered());
        QVERIFY2(renumberingViolations(before, m, r).isEmpty(),
                 qPrintable(renumberingViolations(before, m, r)));
        QVERIFY2(boundaryViolations(m).isEmpty(), qPrintable(boundaryViolations(m)));
        // Nothing else was short or bad: unless a or b was smoothed, nothing changed at all.
        if (r.smoothed == 0)
            QVERIFY2(differences(before, m).isEmpty(), qPrintable(differences(before, m)));
        QVERIFY2(meshViolations(m).isEmpty(), qPrintable(meshViolations(m)));
    }

    void fixedNodesNeverMove() {
        // A jittered 4^3 cube with a short interior edge, improved once freely; then again with
        // every other node that moved the first time given as fixed: those are bit-identical
        // (both configurations) and nothing merges into them, while the others still move.
        TetMesh start = jitteredCube(1, 4, 11, 0.25);
        const int a = boxNode(4, 2, 1, 2), b = boxNode(4, 2, 2, 2);
        place(start, b, start.ref(a) + 0.1 * (start.ref(b) - start.ref(a)));
        computeLumpedMasses(start, kDensity);
        QVERIFY2(meshViolations(start).isEmpty(), qPrintable(meshViolations(start)));
        ImproveOptions o;
        o.badRatio = 0.5;
        o.shortEdge = 0.08;
        o.density = kDensity;
        const std::vector<int> seeds{b, boxNode(4, 1, 1, 1), boxNode(4, 3, 3, 2)};

        TetMesh free = start;
        const ImproveResult r0 = improveMesh(free, improveRegion(free, seeds, {}, 2), o);
        const std::vector<int> moved = movedOldNodes(start, free, r0);
        std::vector<int> fixed;
        for (std::size_t i = 0; i < moved.size(); i += 2)
            fixed.push_back(moved[i]);
        QVERIFY2(fixed.size() >= 3, qPrintable(QString::number(fixed.size())));

        TetMesh m = start;
        const ImproveRegion region = improveRegion(m, seeds, fixed, 2);
        for (int f : fixed)
            QVERIFY(!std::binary_search(region.nodes.begin(), region.nodes.end(), f));
        const ImproveResult r = improveMesh(m, region, o);
        QVERIFY(r.collapses + r.smoothed > 0);
        QVERIFY(!movedOldNodes(start, m, r).empty());
        for (int f : fixed) {
            const int n = finalIndex(r, f);
            QVERIFY2(bitIdentical(m.ref(n), start.ref(f)) && bitIdentical(m.pos(n), start.pos(f)),
                     qPrintable(QString("fixed node %1 moved").arg(f)));
            for (int u = 0; u < start.nodeCount(); ++u)
                QVERIFY2(u == f || finalIndex(r, u) != n,
                         qPrintable(QString("node %1 merged into fixed node %2").arg(u).arg(f)));
        }
        QVERIFY2(meshViolations(m).isEmpty(), qPrintable(meshViolations(m)));
        QVERIFY2(renumberingViolations(start, m, r).isEmpty(),
                 qPrintable(renumberingViolations(start, m, r)));
    }

    void noNodeEntersTheKeepOutBox() {
        // The same mesh improved freely; a box around where a node went (no node inside at the
        // start) is then kept out: no node ends up in it.
        TetMesh start = jitteredCube(1, 4, 5, 0.25);
        const int a = boxNode(4, 2, 1, 2), b = boxNode(4, 2, 2, 2);
        place(start, b, start.ref(a) + 0.1 * (start.ref(b) - start.ref(a)));
        computeLumpedMasses(start, kDensity);
        QVERIFY2(meshViolations(start).isEmpty(), qPrintable(meshViolations(start)));
        ImproveOptions o;
        o.badRatio = 0.5;
        o.shortEdge = 0.08;
        o.density = kDensity;
        const std::vector<int> seeds{b, boxNode(4, 1, 1, 1), boxNode(4, 3, 3, 2)};

        TetMesh free = start;
        const ImproveResult r0 = improveMesh(free, improveRegion(free, seeds, {}, 2), o);
        QVERIFY(!r0.movedNodes.empty());
        int boxes = 0;
        for (int moved : r0.movedNodes) {
            // The box: the cube around the new position reaching half-way to the nearest
            // starting node (max norm).
            const Vec3 q = free.ref(moved);
            double nearest = std::numeric_limits<double>::infinity();
            for (int n = 0; n < start.nodeCount(); ++n)
                nearest = std::min(nearest, (start.ref(n) - q).lpNorm<Eigen::Infinity>());
            if (!(nearest > 1e-3))
                continue; // a node that stayed (nearly) where one was
            ++boxes;
            o.keepOut = std::array<Vec3, 2>{q - Vec3::Constant(nearest / 2),
                                            q + Vec3::Constant(nearest / 2)};
            TetMesh m = start;
            const ImproveResult r = improveMesh(m, improveRegion(m, seeds, {}, 2), o);
            const auto& [lo, hi] = *o.keepOut;
            for (int n = 0; n < m.nodeCount(); ++n)
                QVERIFY2(!((m.ref(n).array() >= lo.array()).all() &&
                           (m.ref(n).array() <= hi.array()).all()),
                         qPrintable(QString("node %1 in the box around the free result's node %2")
                                        .arg(n)
                                        .arg(moved)));
            QVERIFY2(meshViolations(m).isEmpty(), qPrintable(meshViolations(m)));
            QVERIFY2(renumberingViolations(start, m, r).isEmpty(),
                     qPrintable(renumberingViolations(start, m, r)));
        }
        QVERIFY(boxes >= 3);
    }

    void anchoredNodesMoveWithinTheKeepOutBox_data() {
        QTest::addColumn<bool>("moveAnchored");
        QTest::newRow("anchored nodes may move") << true;
        QTest::newRow("anchored nodes stay") << false;
    }
    void anchoredNodesMoveWithinTheKeepOutBox() {
        QFETCH(bool, moveAnchored);
        // A jittered 4^3 cube whose lower two layers of nodes (z <= 0.4) are anchored: fixed,
        // and the keepOut box. A cut has left a short edge in there (b 0.1 of the way from a,
        // both anchored). With moveAnchored the anchored nodes mend it among themselves: they
        // stay in the box, no free node goes in, and no free node merges with an anchored
        // one. Without it they stay bit-identical and the short edge stays (issue 16: the
        // worst tets of twenty partial strokes were all anchored).
        TetMesh start = jitteredCube(1, 4, 11, 0.25);
        const int a = boxNode(4, 2, 2, 1), b = boxNode(4, 2, 1, 1);
        place(start, b, start.ref(a) + 0.1 * (start.ref(b) - start.ref(a)));
        computeLumpedMasses(start, kDensity);
        QVERIFY2(meshViolations(start).isEmpty(), qPrintable(meshViolations(start)));
        const std::array<Vec3, 2> box{Vec3(-1, -1, -1), Vec3(2, 2, 0.4)};
        const auto inBox = [&](const Vec3& p) {
            return (p.array() >= box[0].array()).all() && (p.array() <= box[1].array()).all();
        };
        std::vector<int> anchored;
        for (int n = 0; n < start.nodeCount(); ++n)
            if (inBox(start.ref(n)))
                anchored.push_back(n);
        QCOMPARE(static_cast<int>(anchored.size()), 2 * 25);
        ImproveOptions o;
        o.badRatio = 0.5;
        o.shortEdge = 0.08;
        o.density = kDensity;
        o.keepOut = box;
        o.moveAnchored = moveAnchored;
        TetMesh m = start;
        const ImproveRegion region = improveRegion(m, {a, b}, anchored, 2);
        QVERIFY(region.nodes.size() > 0 && region.fixed.size() > 10);
        const double worstBefore = summarizeQuality(m).minRadiusRatio;
        const ImproveResult r = improveMesh(m, region, o);
        QVERIFY2(meshViolations(m).isEmpty(), qPrintable(meshViolations(m)));
        QVERIFY2(renumberingViolations(start, m, r).isEmpty(), qPrintable(renumberingViolations(start, m, r)));
        const double worstAfter = summarizeQuality(m).minRadiusRatio;
        if (!moveAnchored) {
            for (int f : anchored) {
                const int n = finalIndex(r, f);
                QVERIFY2(n >= 0 && bitIdentical(m.ref(n), start.ref(f)) && bitIdentical(m.pos(n), start.pos(f)),
                         qPrintable(QString("anchored node %1 moved").arg(f)));
            }
            qInfo("worst ratio %g -> %g (flips only)", worstBefore, worstAfter);
            QVERIFY2(!(worstAfter > 2 * worstBefore), qPrintable(QString("worst ratio %1 -> %2").arg(worstBefore).arg(worstAfter)));
            return;
        }
        qInfo("worst ratio %g -> %g", worstBefore, worstAfter);
        QVERIFY2(worstAfter > 2 * worstBefore, qPrintable(QString("worst ratio %1 -> %2").arg(worstBefore).arg(worstAfter)));
        QVERIFY(!movedOldNodes(start, m, r).empty());
        for (int u = 0; u < start.nodeCount(); ++u) {
            const int n = finalIndex(r, u);
            if (n < 0)
                continue;
            const bool wasAnchored = std::binary_search(anchored.begin(), anchored.end(), u);
            QVERIFY2(inBox(m.ref(n)) == wasAnchored,
                     qPrintable(QString("node %1 (%2) ends %3 the box").arg(u).arg(wasAnchored ? "anchored" : "free").arg(wasAnchored ? "outside" : "inside")));
        }
        for (int n = start.nodeCount(); n < m.nodeCount(); ++n)
            QVERIFY2(!inBox(m.ref(n)), qPrintable(QString("new node %1 in the box").arg(n)));
    }

    void smoothingRaisesTheWorstRatio_data() {
        QTest::addColumn<bool>("alone");
        QTest::newRow("only the node") << true;
        QTest::newRow("with its rings") << false;
    }
    void smoothingRaisesTheWorstRatio() {
        // The centre of a 4^3 cube moved 90% of the way to the centroid of the face opposite it
        // in one of its tets: that tet is flat (radius ratio below 0.2, the Kuhn tets' is 0.72).
        QFETCH(bool, alone);
        TetMesh m = cube(1, 4);
        const int c = boxNode(4, 2, 2, 2);
        const Tet flat = m.tet(m.nodeTets(c)[0]);
        Vec3 centroid = Vec3::Zero();
        for (int v : flat)
            if (v != c)
                centroid += m.ref(v) / 3;
        place(m, c, m.ref(c) + 0.9 * (centroid - m.ref(c)));
        computeLumpedMasses(m, kDensity);
        QVERIFY2(meshViolations(m).isEmpty(), qPrintable(meshViolations(m)));
        const double worstBefore = worstRatioAround(m, c);
        QVERIFY2(worstBefore < 0.2, qPrintable(QString::number(worstBefore)));
        const TetMesh before = m;
        const double volume = m.totalReferenceVolume(), mass = sumOfMasses(m);
        std::vector<int> fixed;
        if (alone)
            for (int n = 0; n < m.nodeCount(); ++n)
                if (n != c)
                    fixed.push_back(n);
        const ImproveRegion region = improveRegion(m, {c}, fixed, 1);
        if (alone)
            QCOMPARE(region.nodes, std::vector<int>{c});
        ImproveOptions o;
        o.badRatio = 0.5;
        o.density = kDensity;
        o.split = !alone;  // (alone: smoothing only)
        const ImproveResult r = improveMesh(m, region, o);
        QVERIFY2(r.smoothed >= 1, qPrintable(QString::number(r.smoothed)));
        QVERIFY2(r.worstAfter > r.worstBefore,
                 qPrintable(QString("%1 -> %2").arg(r.worstBefore).arg(r.worstAfter)));
        if (alone) {
            // Only smoothing was possible: the worst ratios are those of the node's tets.
            QCOMPARE(r.worstBefore, worstBefore);
            QCOMPARE(r.worstAfter, worstRatioAround(m, c));
            // (The tets may be flipped, the fixed nodes' too: the nodes stay.)
            QCOMPARE(r.collapses, 0);
            QCOMPARE(m.nodeCount(), before.nodeCount());
            QCOMPARE(r.movedNodes, std::vector<int>{c});
            for (int n = 0; n < m.nodeCount(); ++n)
                QVERIFY(n == c || bitIdentical(m.ref(n), before.ref(n)));
            QVERIFY(r.worstAfter >= o.badRatio);
        }
        QVERIFY2(meshViolations(m).isEmpty(), qPrintable(meshViolations(m)));
        QVERIFY2(renumberingViolations(before, m, r).isEmpty(),
                 qPrintable(renumberingViolations(before, m, r)));
        QVERIFY2(relative(m.totalReferenceVolume(), volume) <= 1e-12,
                 qPrintable(QString::number(relative(m.totalReferenceVolume(), volume))));
        QVERIFY2(relative(sumOfMasses(m), mass) <= 1e-12,
                 qPrintable(QString::number(relative(sumOfMasses(m), mass))));
        TetMesh scratch = m;
        computeLumpedMasses(scratch, kDensity);
        for (int n = 0; n < m.nodeCount(); ++n)
            QVERIFY2(relative(m.masses()[n], scratch.masses()[n]) <= 1e-12,
                     qPrintable(QString::number(n)));
    }

    void currentPositionsFollowAnAffineDeformation_data() {
        QTest::addColumn<unsigned>("seed");
        for (unsigned seed : {1u, 2u, 3u})
            QTest::newRow(qPrintable(QString("seed %1").arg(seed))) << seed;
    }
    void currentPositionsFollowAnAffineDeformation() {
        // A jittered 4^3 cube with a short interior edge and a short edge on the face y = 0,
        // deformed by x -> A x + c with velocities v = B x + w. Barycentric interpolation is
        // exact for affine fields: every node's current position and velocity must still be
        // the affine image of its reference position.
        QFETCH(unsigned, seed);
        TetMesh m = jitteredCube(1, 4, seed, 0.25);
        const int a = boxNode(4, 2, 1, 2), b = boxNode(4, 2, 2, 2);
        place(m, b, m.ref(a) + 0.1 * (m.ref(b) - m.ref(a)));
        const int e = boxNode(4, 1, 0, 2), f = boxNode(4, 1, 0, 3);
        place(m, f, m.ref(e) + 0.1 * (m.ref(f) - m.ref(e)));
        Eigen::Matrix3d A, B;
        A << 1.1, 0.2, 0, -0.1, 0.9, 0.1, 0.05, 0, 1.2;
        B << 0, -1, 0, 1, 0, 0, 0, 0, 0.5;
        const Vec3 c(0.3, -0.2, 0.1), w(1, 2, 3);
        for (int n = 0; n < m.nodeCount(); ++n) {
            m.positions()[n] = A * m.ref(n) + c;
            m.velocities()[n] = B * m.ref(n) + w;
        }
        computeLumpedMasses(m, kDensity);
        QVERIFY2(meshViolations(m).isEmpty(), qPrintable(meshViolations(m)));
        const TetMesh before = m;
        ImproveOptions o;
        o.badRatio = 0.5;
        o.shortEdge = 0.08;
        o.density = kDensity;
        const ImproveResult r = improveMesh(m, improveRegion(m, {b, f}, {}, 2), o);
        QVERIFY2(r.collapses >= 2, qPrintable(QString::number(r.collapses)));
        QCOMPARE(r.renumbering.nodes(a), r.renumbering.nodes(b));
        QCOMPARE(r.renumbering.nodes(e), r.renumbering.nodes(f));
        for (int n = 0; n < m.nodeCount(); ++n) {
            const double dp = (m.pos(n) - (A * m.ref(n) + c)).norm();
            const double dv = (m.velocities()[n] - (B * m.ref(n) + w)).norm();
            QVERIFY2(dp <= 1e-9 && dv <= 1e-9,
                     qPrintable(QString("node %1: %2, %3").arg(n).arg(dp).arg(dv)));
        }
        QVERIFY2(meshViolations(m).isEmpty(), qPrintable(meshViolations(m)));
        QVERIFY2(renumberingViolations(before, m, r).isEmpty(),
                 qPrintable(renumberingViolations(before, m, r)));
    }

    void removalsSwapWithTheLast() {
        TetMesh m = fiveTetCube();
        for (int t = 0; t < m.tetCount(); ++t)
            QVERIFY(m.referenceVolume(t) > 0);
        QCOMPARE(m.totalReferenceVolume(), 1.0);
        for (int n = 0; n < m.nodeCount(); ++n) {
            m.velocities()[n] = Vec3(n, 0, 0);
            m.masses()[n] = 10 + n;
        }
        // Tet 0 is the only tet of node 1: the last tet, the central one, takes its slot.
        m.removeTet(0);
        QCOMPARE(m.tetCount(), 4);
        QCOMPARE(m.tet(0), (Tet{0, 5, 3, 6}));
        QCOMPARE(m.tet(3), (Tet{7, 5, 6, 3}));
        QVERIFY(m.nodeTets(1).empty());
        QVERIFY2(adjacencyViolations(m).isEmpty(), qPrintable(adjacencyViolations(m)));
        // Node 1 is unused: the last node (7, the corner (1, 1, 1)) takes its index.
        m.removeNode(1);
        QCOMPARE(m.nodeCount(), 7);
        QCOMPARE(m.ref(1), Vec3(1, 1, 1));
        QCOMPARE(m.pos(1), Vec3(1, 1, 1));
        QCOMPARE(m.velocities()[1], Vec3(7, 0, 0));
        QCOMPARE(m.masses()[1], 17.0);
        QCOMPARE(m.tet(3), (Tet{1, 5, 6, 3}));
        QVERIFY2(adjacencyViolations(m).isEmpty(), qPrintable(adjacencyViolations(m)));
        // Removing the last tet and the last node only shortens the arrays.
        m.removeTet(3);
        QCOMPARE(m.tetCount(), 3);
        QCOMPARE(m.tet(2), (Tet{4, 6, 5, 0}));
        m.removeNode(1); // (1, 1, 1) again, now unused; node 6 takes its index
        QCOMPARE(m.nodeCount(), 6);
        QCOMPARE(m.ref(1), Vec3(0, 1, 1));
        QVERIFY2(adjacencyViolations(m).isEmpty(), qPrintable(adjacencyViolations(m)));
        QVERIFY2(meshViolations(m).isEmpty(), qPrintable(meshViolations(m)));
        QCOMPARE(m.totalReferenceVolume(), 1.0 / 3.0 + 1.0 / 6.0 + 1.0 / 6.0);
    }

    void backupUndoesRemovalsExactly_data() {
        QTest::addColumn<unsigned>("seed");
        QTest::addColumn<bool>("byDestructor");
        for (unsigned seed : {1u, 2u, 3u, 4u})
            QTest::newRow(qPrintable(QString("restore, seed %1").arg(seed))) << seed << false;
        QTest::newRow("destructor, seed 5") << 5u << true;
    }
    void backupUndoesRemovalsExactly() {
        // A jittered 3^3 cube with random masses and velocities: 60 random tet removals with
        // a few moves, mass changes and added nodes and tets in between, the removal of all
        // tets of three nodes, then of every unused node in random order; restore() (or the
        // backup's destruction) gives back the mesh bit-identical, adjacency order included.
        QFETCH(unsigned, seed);
        QFETCH(bool, byDestructor);
        TetMesh m = jitteredCube(1, 3, seed, 0.2);
        std::mt19937 rng(seed);
        std::uniform_real_distribution<double> u(0, 1);
        for (int n = 0; n < m.nodeCount(); ++n) {
            m.masses()[n] = u(rng);
            m.velocities()[n] = Vec3(u(rng), u(rng), u(rng));
        }
        const TetMesh original = m;
        {
            TetMeshBackup backup(m);
            const auto pick = [&](int count) {
                return std::uniform_int_distribution<int>(0, count - 1)(rng);
            };
            for (int i = 0; i < 60; ++i) {
                m.removeTet(pick(m.tetCount()));
                if (i % 20 == 5) {
                    const int n = pick(m.nodeCount());
                    m.setNodePosition(n, m.ref(n) + Vec3(0.01, 0, 0), m.pos(n));
                    m.setMass(n, 5.0);
                    const int added = m.addNode(Vec3(2, 2, 2), Vec3(2, 2, 2));
                    const Tet q = m.tet(pick(m.tetCount()));
                    m.addTet({q[0], q[1], q[2], added});
                }
            }
            // Every tet of three random nodes, so that at least those become unused.
            for (int k = 0; k < 3; ++k) {
                const int n = pick(m.nodeCount());
                while (!m.nodeTets(n).empty())
                    m.removeTet(m.nodeTets(n)[pick(static_cast<int>(m.nodeTets(n).size()))]);
            }
            int removedNodes = 0;
            for (;;) {
                std::vector<int> unused;
                for (int n = 0; n < m.nodeCount(); ++n)
                    if (m.nodeTets(n).empty())
                        unused.push_back(n);
                if (unused.empty())
                    break;
                m.removeNode(unused[pick(static_cast<int>(unused.size()))]);
                ++removedNodes;
            }
            QVERIFY(removedNodes >= 3);
            QVERIFY2(adjacencyViolations(m).isEmpty(), qPrintable(adjacencyViolations(m)));
            QVERIFY(!differences(original, m).isEmpty());
            if (!byDestructor) {
                backup.restore();
                QVERIFY(!backup.isOpen());
                QVERIFY2(differences(original, m).isEmpty(), qPrintable(differences(original, m)));
            }
        }
        QVERIFY2(differences(original, m).isEmpty(), qPrintable(differences(original, m)));
    }

    void committedRemovalsStay() {
        // A committed inner backup inside an outer one: the inner edit stays after its commit
        // and is undone by the outer restore.
        TetMesh m = fiveTetCube();
        const TetMesh original = m;
        TetMeshBackup outer(m);
        {
            TetMeshBackup inner(m);
            m.removeTet(0);
            m.removeNode(1);
            inner.commit();
        }
        QCOMPARE(m.tetCount(), 4);
        QCOMPARE(m.nodeCount(), 7);
        m.removeTet(2);
        outer.restore();
        QVERIFY2(differences(original, m).isEmpty(), qPrintable(differences(original, m)));
    }

    void worstTetsOfABareResection_data() {
        QTest::addColumn<int>("which");
        QTest::newRow("polyp after 10 scoops") << 0;
        QTest::newRow("myoma after 12 scoops") << 1;
        QTest::newRow("box, ten scoops, cut 8") << 2;
        QTest::newRow("box, ten scoops moved 0.03, cut 4") << 3;
        QTest::newRow("box, ten scoops moved 0.2, cut 9") << 4;
    }
    void worstTetsOfABareResection() {
        // The worst tets the paper's pipeline alone, or with the improvement of before issue
        // 16's splits, left after a run of scoops (literal neighbourhoods,
        // improve_regressions.h): the pass, at the product's settings (Tissue::improve), lifts
        // them to at least half the input's worst ratio, with the volume kept and the fixed
        // context untouched.
        QFETCH(int, which);
        const testing::ImproveCase c = which == 0   ? testing::polypAfter10()
                                       : which == 1 ? testing::myomaAfter12()
                                       : which == 2 ? testing::boxTenScoopsCut8()
                                       : which == 3 ? testing::boxTenScoopsShiftedCut4()
                                                    : testing::boxTenScoopsShiftedCut9();
        TetMesh m = TetMesh::fromArrays(c.nodes, c.tets);
        computeLumpedMasses(m, 1e-3);
        const auto ratioOf = [&](const Tet& q) { return radiusRatio(m.ref(q[0]), m.ref(q[1]), m.ref(q[2]), m.ref(q[3])); };
        QVERIFY(ratioOf(c.worstTet) < 0.5 * c.inputWorstRatio);
        const double volume = m.totalReferenceVolume();
        const std::vector<Vec3> before(m.referencePositions().begin(), m.referencePositions().end());
        ImproveOptions o;
        o.badRatio = std::min(c.inputWorstRatio, 0.55);
        o.shortEdge = 0.6 * c.inputShortestEdge;
        o.floorEdge = 0.45 * c.inputShortestEdge;
        o.floorRatio = 0.55 * c.inputWorstRatio;
        o.sweeps = 8;
        // As Tissue::cut runs it: up to four passes, each around the tets the last left bad.
        std::vector<int> seeds(c.worstTet.begin(), c.worstTet.end()), fixed = c.fixedNodes;
        int changes = 0;
        for (int pass = 0; pass < 4 && !seeds.empty(); ++pass) {
            const ImproveResult r = improveMesh(m, improveRegion(m, seeds, fixed, 2), o);
            changes += r.collapses + r.flips + r.smoothed + r.splits;
            for (int& n : fixed)
                n = r.renumbering.nodes(n);
            seeds.clear();
            for (const Tet& q : m.tets())
                if (ratioOf(q) < o.badRatio)
                    seeds.insert(seeds.end(), q.begin(), q.end());
        }
        QVERIFY(changes > 0);
        double worst = 1;
        for (const Tet& q : m.tets())
            worst = std::min(worst, ratioOf(q));
        // Open (issue 16): the spike at the box corner (6, 0, 6), with nodes the older
        // improvement had moved outside the box, stays at 0.27 (0.38 times) within this fixed
        // context. (An unexpected pass fails too: then the mark goes.)
        if (which == 2)
            QEXPECT_FAIL("", "the box corner spike of cut 8 is not lifted to 0.5 times yet", Continue);
        QVERIFY2(worst >= 0.5 * c.inputWorstRatio, qPrintable(QString("worst %1, input %2").arg(worst).arg(c.inputWorstRatio)));
        QVERIFY(std::abs(m.totalReferenceVolume() - volume) <= 1e-12 * volume);
        if (const auto problems = checkValidity(m); !problems.empty())
            QFAIL(problems.front().message.c_str());
        for (std::size_t i = 0; i < fixed.size(); ++i) {
            QVERIFY(fixed[i] >= 0);
            QCOMPARE(m.ref(fixed[i]), before[c.fixedNodes[i]]);
        }
    }

    void aShortEdgeAcrossTheBoxBorderMergesIntoTheBox_data() {
        QTest::addColumn<bool>("merge");
        QTest::newRow("mergeFreeIntoAnchored") << true;
        QTest::newRow("not (the default)") << false;
    }
    void aShortEdgeAcrossTheBoxBorderMergesIntoTheBox() {
        // A jittered 4^3 cube whose nodes with z <= 0.3 are anchored (the keepOut box); a cut has
        // left free node b 0.05 cells above anchored node a, across the box's top. With
        // mergeFreeIntoAnchored the edge is collapsed, the merged node in the box (anchored by
        // position), the volume and Eq. 3 kept; without it the two stay apart, each on its side
        // (smoothing may lengthen the edge).
        QFETCH(bool, merge);
        QVERIFY(!ImproveOptions{}.mergeFreeIntoAnchored);
        TetMesh start = jitteredCube(1, 4, 3, 0.2);
        const std::array<Vec3, 2> box{Vec3(-1, -1, -1), Vec3(2, 2, 0.3)};
        const int a = boxNode(4, 2, 2, 1), b = boxNode(4, 2, 2, 2);
        place(start, a, Vec3(0.5, 0.5, 0.29));
        place(start, b, Vec3(0.5, 0.5, 0.29 + 0.05 * 0.25));
        computeLumpedMasses(start, kDensity);
        QVERIFY2(meshViolations(start).isEmpty(), qPrintable(meshViolations(start)));
        const auto inBox = [&](const Vec3& p) {
            return (p.array() >= box[0].array()).all() && (p.array() <= box[1].array()).all();
        };
        std::vector<int> anchored;
        for (int n = 0; n < start.nodeCount(); ++n)
            if (inBox(start.ref(n)))
                anchored.push_back(n);
        QVERIFY(std::binary_search(anchored.begin(), anchored.end(), a) && !inBox(start.ref(b)));
        ImproveOptions o;
        o.shortEdge = 0.03;  // (a, b) alone: 0.0125; the cube's edges are 0.25 x (1 - 2 * 0.2) and up
        o.density = kDensity;
        o.keepOut = box;
        o.mergeFreeIntoAnchored = merge;
        TetMesh m = start;
        const ImproveResult r = improveMesh(m, improveRegion(m, {a, b}, anchored, 2), o);
        QVERIFY2(brokenInvariants(start, m, r).isEmpty(), qPrintable(brokenInvariants(start, m, r)));
        QVERIFY2(meshViolations(m).isEmpty(), qPrintable(meshViolations(m)));
        if (!merge) {
            QVERIFY(finalIndex(r, a) != finalIndex(r, b));
            QVERIFY(inBox(m.ref(finalIndex(r, a))) && !inBox(m.ref(finalIndex(r, b))));
            return;
        }
        QCOMPARE(finalIndex(r, a), finalIndex(r, b));
        QVERIFY2(inBox(m.ref(finalIndex(r, a))), qPrintable(QString("merged node at z = %1").arg(m.ref(finalIndex(r, a)).z())));
        QVERIFY(shortestEdge(m) > 0.03);
        // Every other node keeps its side of the box's border.
        for (int u = 0; u < start.nodeCount(); ++u)
            if (u != a && u != b && finalIndex(r, u) >= 0)
                QCOMPARE(inBox(m.ref(finalIndex(r, u))), inBox(start.ref(u)));
    }

    void aPitIsFilledForItsMouthsCollapse_data() {
        QTest::addColumn<bool>("fill");
        QTest::newRow("fillPits") << true;
        QTest::newRow("not (the default)") << false;
    }
    void aPitIsFilledForItsMouthsCollapse() {
        // A short boundary edge (a, b), the mouth of a pit (pit_regressions.h), whose collapse
        // the link condition refuses; every other node fixed. With fillPits the pit is filled
        // and the edge collapsed: the volume and Eq. 3 kept, every tet positive, the boundary a
        // manifold, the edge's tets gone (the filling tet came and went). Without, nothing
        // changes.
        QFETCH(bool, fill);
        QVERIFY(!ImproveOptions{}.fillPits);
        const testing::PitCase c = testing::pitOnTheMyoma();
        TetMesh m = TetMesh::fromArrays(c.nodes, c.tets);
        computeLumpedMasses(m, kDensity);
        QVERIFY2(meshViolations(m).isEmpty(), qPrintable(meshViolations(m)));
        const TetMesh before = m;
        std::vector<int> fixed;
        for (int n = 0; n < m.nodeCount(); ++n)
            if (n != c.a && n != c.b)
                fixed.push_back(n);
        ImproveOptions o;
        o.density = kDensity;
        o.shortEdge = 1.01 * (m.ref(c.a) - m.ref(c.b)).norm();  // only (a, b) is that short
        o.fillPits = fill;
        o.sweeps = 1;
        const ImproveResult r = improveMesh(m, improveRegion(m, {c.a, c.b}, fixed, 0), o);
        if (!fill) {
            QCOMPARE(r.collapses, 0);
            QCOMPARE(r.pitsFilled, 0);
            QVERIFY(!r.renumbered());
            QVERIFY(finalIndex(r, c.a) != finalIndex(r, c.b));
            return;
        }
        QCOMPARE(r.pitsFilled, 1);
        QCOMPARE(r.collapses, 1);
        QCOMPARE(finalIndex(r, c.a), finalIndex(r, c.b));
        const auto shell = std::count_if(before.tets().begin(), before.tets().end(), [&](const Tet& q) {
            return std::find(q.begin(), q.end(), c.a) != q.end() && std::find(q.begin(), q.end(), c.b) != q.end();
        });
        QCOMPARE(m.tetCount(), before.tetCount() - static_cast<int>(shell));
        QVERIFY2(brokenInvariants(before, m, r).isEmpty(), qPrintable(brokenInvariants(before, m, r)));
        QVERIFY2(meshViolations(m).isEmpty(), qPrintable(meshViolations(m)));
        QVERIFY2(boundaryViolations(m).isEmpty(), qPrintable(boundaryViolations(m)));
        for (int n : fixed)
            QVERIFY2(bitIdentical(m.ref(finalIndex(r, n)), before.ref(n)), qPrintable(QString("fixed node %1 moved").arg(n)));
    }

    void nearestToZeroInHullOfGradients() {
        const Vec3 x = Vec3::UnitX(), y = Vec3::UnitY(), z = Vec3::UnitZ();
        const auto near = [](const Vec3& a, const Vec3& b) { return (a - b).norm() <= 1e-14; };
        // One vector: itself. Nothing, or more than four: zero.
        QVERIFY(near(nearestToZeroInHull({Vec3(1, 2, 3)}), Vec3(1, 2, 3)));
        QVERIFY(near(nearestToZeroInHull({}), Vec3::Zero()));
        QVERIFY(near(nearestToZeroInHull({x, y, z, x, y}), Vec3::Zero()));
        // Two tied gradients pulling apart: their mean raises both (each has dot 0.5 with it).
        QVERIFY(near(nearestToZeroInHull({x, y}), Vec3(0.5, 0.5, 0)));
        // A vertex nearest: the hull's other points are farther.
        QVERIFY(near(nearestToZeroInHull({Vec3(1, 0, 0), Vec3(2, 1, 0), Vec3(2, -1, 0)}), x));
        // An edge nearest (its foot inside the edge), the third vector far off.
        QVERIFY(near(nearestToZeroInHull({Vec3(1, -1, 0), Vec3(1, 1, 0), Vec3(5, 0, 3)}), x));
        // The face of three: (1, 1, 1) / 3 is where x + y + z = 1 comes nearest.
        QVERIFY(near(nearestToZeroInHull({x, y, z}), Vec3::Constant(1.0 / 3)));
        // Zero inside the hull: no direction raises them all.
        QVERIFY(near(nearestToZeroInHull({x, -x}), Vec3::Zero()));
        QVERIFY(near(nearestToZeroInHull({x, y, -x - y + z, -z}), Vec3::Zero()));
        // Degenerate (parallel) vectors do not fool it; scale does not matter.
        QVERIFY(near(nearestToZeroInHull({2 * x, 4 * x, 3 * x}), 2 * x));
        for (double scale : {1e-6, 1.0, 1e6}) {
            const Vec3 g = nearestToZeroInHull({scale * x, scale * y, scale * Vec3(1, 1, -1)});
            QVERIFY2((g - scale * Vec3(0.5, 0.5, 0)).norm() <= 1e-12 * scale, qPrintable(QString::number(g.norm())));
        }
        // The result is in the hull and has no larger dot product with any point of the hull
        // than with itself (what makes it raise every gradient at once), on random sets.
        std::mt19937 rng(3);
        std::normal_distribution<double> n01;
        for (int trial = 0; trial < 500; ++trial) {
            std::vector<Vec3> g(1 + trial % 4);
            for (Vec3& v : g)
                v = Vec3(n01(rng), n01(rng), n01(rng)) + Vec3(0.5, 0, 0);
            const Vec3 d = nearestToZeroInHull(g);
            for (const Vec3& v : g)
                QVERIFY2(v.dot(d) >= d.squaredNorm() - 1e-12, qPrintable(QString("trial %1").arg(trial)));
        }
    }

    void splitMendsANeedle_data() { shortInteriorEdgeIsCollapsed_data(); }
    void splitMendsANeedle() {
        // A needle: one tet, its edge a-b four times longer than the others. Nothing but a
        // split mends it (with offSurface off, no node may leave the tet's faces): the new
        // node on a-b, placed by smoothing among the two halves, makes two better tets, the
        // volume and masses unchanged and the new node on the old surface.
        QFETCH(double, scale);
        const std::vector<Vec3> nodes{Vec3(0, 0, 0) * scale, Vec3(4, 0, 0) * scale, Vec3(2, 1, 0) * scale,
                                      Vec3(2, 0.5, 0.9) * scale};
        TetMesh m = TetMesh::fromArrays(nodes, {Tet{0, 1, 2, 3}});
        QVERIFY(orient3d(m.ref(0), m.ref(1), m.ref(2), m.ref(3)) > 0);
        computeLumpedMasses(m, kDensity);
        const double worstBefore = worstRatioAround(m, 0);
        const TetMesh before = m;
        ImproveOptions o;
        o.badRatio = 0.9;
        o.offSurface = false;
        o.density = kDensity;
        o.split = false;
        TetMesh without = m;
        const ImproveResult r0 = improveMesh(without, improveRegion(without, {0, 1, 2, 3}, {}, 1), o);
        QCOMPARE(r0.splits, 0);
        QCOMPARE(without.tetCount(), 1);
        o.split = true;
        const ImproveResult r = improveMesh(m, improveRegion(m, {0, 1, 2, 3}, {}, 1), o);
        QVERIFY2(r.splits >= 1, qPrintable(QString::number(r.splits)));
        QCOMPARE(m.nodeCount(), 4 + r.splits - r.removedNodes);
        QVERIFY2(r.worstAfter > r0.worstAfter + 0.05 && r.worstAfter > worstBefore + 0.05,
                 qPrintable(QString("%1 (split) / %2 (none) / %3 before").arg(r.worstAfter).arg(r0.worstAfter).arg(worstBefore)));
        double worst = 1;
        for (const Tet& q : m.tets())
            worst = std::min(worst, radiusRatio(m.ref(q[0]), m.ref(q[1]), m.ref(q[2]), m.ref(q[3])));
        QCOMPARE(worst, r.worstAfter);
        const QString broken = brokenInvariants(before, m, r);
        QVERIFY2(broken.isEmpty(), qPrintable(broken));
        // Every node, old or new, lies on the needle's surface.
        for (int n = 0; n < m.nodeCount(); ++n) {
            double distance = std::numeric_limits<double>::infinity();
            for (const auto& f : kTetFaces)
                distance = std::min(distance, pointTriangleDistance(m.ref(n), nodes[f[0]], nodes[f[1]], nodes[f[2]]));
            QVERIFY2(distance <= 1e-12 * scale, qPrintable(QString("node %1: %2").arg(n).arg(distance)));
        }
    }

    void splitsKeepTheInvariants_data() {
        QTest::addColumn<unsigned>("seed");
        for (unsigned seed : {1u, 2u, 3u, 4u})
            QTest::newRow(qPrintable(QString("seed %1").arg(seed))) << seed;
    }
    void splitsKeepTheInvariants() {
        // A cube jittered into slivers, improved with splits: valid, the volume and Eq. 3 kept,
        // the renumbering exact; and splits happen.
        QFETCH(unsigned, seed);
        TetMesh m = jitteredCube(3.0, 4, seed, 0.3);
        QVERIFY(checkValidity(m).empty());
        computeLumpedMasses(m, kDensity);
        const TetMesh before = m;
        std::vector<int> all(m.nodeCount());
        std::iota(all.begin(), all.end(), 0);
        ImproveOptions o;
        o.badRatio = 0.6;
        o.density = kDensity;
        o.sweeps = 5;
        const ImproveResult r = improveMesh(m, improveRegion(m, all, {}, 1), o);
        QVERIFY2(r.splits > 0, "no split");
        const QString broken = brokenInvariants(before, m, r);
        QVERIFY2(broken.isEmpty(), qPrintable(broken));
        for (const Tet& q : m.tets())
            QVERIFY(orient3d(m.pos(q[0]), m.pos(q[1]), m.pos(q[2]), m.pos(q[3])) > 0);
        QVERIFY(r.worstAfter > r.worstBefore);
    }
};

QTEST_GUILESS_MAIN(TestImproveMesh)
#include "test_improve_mesh.moc"
