// The embedded surface's binding (section 5): every vertex bound through a spatial search,
// apply() reproduces the surface and follows any affine motion of the tets, and after a cut
// re-binding keeps the surface in place while each side follows its own piece.
#include "core/cut/hybrid_cutter.h"
#include "core/cut/improve_mesh.h"
#include "core/embed/binding.h"
#include "core/embed/embedded_surface.h"
#include "core/embed/cut_surface.h"
#include "core/mesh/box_mesh.h"
#include "core/mesh/topology.h"
#include "core/mesher/samples.h"
#include "core/mesher/tetrahedralize.h"

#include <QTest>

#include <algorithm>
#include <functional>
#include <limits>
#include <numeric>
#include <cstring>
#include <random>

using namespace resect;

namespace {

struct Scene {
    TriangleSurface surface;
    TetMesh mesh;
};

Scene sample(Sample which, double scale) {
    Scene s;
    s.surface = sampleSurface(which, 0.25);
    for (Vec3& p : s.surface.positions)
        p *= scale;
    if (!tetrahedralize(s.surface, MeshingOptions{}, s.mesh).ok())
        qFatal("meshing failed");
    return s;
}

/// Moves every node of the piece that has a node above height `above` by `lift`; returns false
/// unless the mesh is in exactly two pieces.
bool liftUpperPiece(TetMesh& mesh, double above, const Vec3& lift) {
    const Components c = connectedComponents(mesh);
    if (c.count != 2)
        return false;
    int upper = -1;
    for (int n = 0; n < mesh.nodeCount() && upper < 0; ++n)
        if (mesh.pos(n).z() > above)
            upper = c.nodeComponent[n];
    for (int n = 0; n < mesh.nodeCount(); ++n)
        if (c.nodeComponent[n] == upper)
            mesh.positions()[n] += lift;
    return upper >= 0;
}


double size(const TriangleSurface& s) {
    const auto [lo, hi] = boundingBox(s.positions);
    return (hi - lo).norm();
}

/// The binding as plain arrays, for comparisons.
struct BindingState {
    std::vector<int> tet;
    std::vector<std::array<double, 4>> weights;
};
BindingState stateOf(const SurfaceBinding& b) {
    BindingState s;
    for (int v = 0; v < b.vertexCount(); ++v) {
        s.tet.push_back(b.tetOf(v));
        s.weights.push_back(b.weightsOf(v));
    }
    return s;
}

/// Empty if the binding's per-tet lists and outside count agree with its tets and weights.
QString listProblems(const SurfaceBinding& b, const TetMesh& mesh) {
    std::vector<std::vector<int>> expected(mesh.tetCount());
    int outside = 0;
    for (int v = 0; v < b.vertexCount(); ++v) {
        if (b.tetOf(v) < 0 || b.tetOf(v) >= mesh.tetCount())
            return QString("vertex %1 bound to tet %2 of %3").arg(v).arg(b.tetOf(v)).arg(mesh.tetCount());
        expected[b.tetOf(v)].push_back(v);
        const auto w = b.weightsOf(v);
        if (std::min({w[0], w[1], w[2], w[3]}) < -b.tolerances().inside)
            ++outside;
    }
    for (int t = 0; t < mesh.tetCount(); ++t) {
        std::vector<int> listed = b.verticesOf(t);
        std::sort(listed.begin(), listed.end());
        if (listed != expected[t])
            return QString("tet %1 lists %2 vertices, %3 are bound to it").arg(t).arg(listed.size()).arg(expected[t].size());
    }
    if (b.outsideCount() != outside)
        return QString("outside count %1, %2 vertices are outside").arg(b.outsideCount()).arg(outside);
    return {};
}

/// The remeshing follower as it was before issue 20 (a scan of every vertex with dense maps):
/// every vertex's tet through newTet; each recorded vertex bound to the first of its sorted
/// candidates (the tets of its recorded nodes through newNode) with the largest smallest weight.
BindingState followRemeshReference(BindingState s, const TetMesh& mesh, const EmbeddedSurface::RemeshRecord& record,
                                   const std::function<int(int)>& newTet, const std::function<int(int)>& newNode) {
    for (int& t : s.tet)
        t = newTet(t);
    for (std::size_t i = 0; i < record.vertices.size(); ++i) {
        std::vector<int> candidates;
        for (int n : record.nodes[i])
            if (const int node = newNode(n); node >= 0)
                candidates.insert(candidates.end(), mesh.nodeTets(node).begin(), mesh.nodeTets(node).end());
        std::sort(candidates.begin(), candidates.end());
        candidates.erase(std::unique(candidates.begin(), candidates.end()), candidates.end());
        const int v = record.vertices[i];
        const int old = s.tet[v];
        double best = -std::numeric_limits<double>::infinity();
        int bestTet = -1;
        for (int t : candidates) {
            const auto w = barycentricInTet(mesh, t, record.positions[i]);
            const double m = std::min({w[0], w[1], w[2], w[3]});
            if (std::isfinite(m) && m > best) {
                best = m;
                bestTet = t;
                s.weights[v] = w;
            }
        }
        s.tet[v] = bestTet >= 0 ? bestTet : (old >= 0 ? old : 0);
        if (bestTet < 0)
            s.weights[v] = barycentricInTet(mesh, s.tet[v], record.positions[i]);
    }
    return s;
}

/// Empty if the two bindings are bit for bit the same.
QString difference(const BindingState& a, const BindingState& b) {
    if (a.tet.size() != b.tet.size())
        return QString("%1 vs %2 vertices").arg(a.tet.size()).arg(b.tet.size());
    for (std::size_t v = 0; v < a.tet.size(); ++v)
        if (a.tet[v] != b.tet[v] || std::memcmp(a.weights[v].data(), b.weights[v].data(), sizeof(a.weights[v])) != 0)
            return QString("vertex %1: tet %2 vs %3").arg(v).arg(a.tet[v]).arg(b.tet[v]);
    return {};
}

/// A local remeshing with removals, as improveMesh makes them: the star of interior node c is
/// removed, then c (the last node takes its index), and the hole is filled again from a new
/// node at c's position. Returns the renumbering (removed: -1; the last element moves into the
/// freed slot).
MeshRenumbering restar(TetMesh& mesh, int c) {
    MeshRenumbering r;
    r.tets.oldCount = mesh.tetCount();
    r.nodes.oldCount = mesh.nodeCount();
    std::vector<Tet> star;
    for (int t : mesh.nodeTets(c))
        star.push_back(mesh.tet(t));
    std::vector<int> origin(mesh.tetCount());  // current slot -> old tet (-1: new)
    std::iota(origin.begin(), origin.end(), 0);
    std::vector<int> doomed(mesh.nodeTets(c).begin(), mesh.nodeTets(c).end());
    std::sort(doomed.rbegin(), doomed.rend());  // highest first: the slots below stay valid
    std::vector<int> newIndex(mesh.tetCount());
    std::iota(newIndex.begin(), newIndex.end(), 0);
    for (int t : doomed) {
        const int last = mesh.tetCount() - 1;
        newIndex[origin[t]] = -1;
        if (t != last)
            newIndex[origin[last]] = t;
        origin[t] = origin[last];
        origin.pop_back();
        mesh.removeTet(t);
    }
    const Vec3 ref = mesh.ref(c), cur = mesh.pos(c);
    const int lastNode = mesh.nodeCount() - 1;
    mesh.removeNode(c);
    for (int t = 0; t < r.tets.oldCount; ++t)
        if (newIndex[t] != t)
            r.tets.changed.emplace_back(t, newIndex[t]);
    r.nodes.changed.emplace_back(c, -1);
    if (c != lastNode)
        r.nodes.changed.emplace_back(lastNode, c);
    std::sort(r.nodes.changed.begin(), r.nodes.changed.end());
    const int centre = mesh.addNode(ref, cur);
    for (Tet q : star) {
        for (int& n : q)
            n = n == c ? centre : (n == lastNode && c != lastNode ? c : n);
        mesh.addTet(q);
    }
    r.tets.newCount = mesh.tetCount();
    r.nodes.newCount = mesh.nodeCount();
    return r;
}

} // namespace

Q_DECLARE_METATYPE(resect::Sample)

class TestBinding : public QObject {
    Q_OBJECT
private slots:
    void bindAndFollowAffineMotion_data() {
        QTest::addColumn<Sample>("which");
        QTest::addColumn<double>("scale");
        QTest::newRow("polyp") << Sample::Polyp << 1.0;
        QTest::newRow("myoma 1e-3") << Sample::Myoma << 1e-3;
        QTest::newRow("polyp 1e3") << Sample::Polyp << 1e3;
    }
    void bindAndFollowAffineMotion() {
        QFETCH(Sample, which);
        QFETCH(double, scale);
        Scene s = sample(which, scale);
        SurfaceBinding binding;
        QVERIFY(binding.bind(s.mesh, s.surface).ok());
        QCOMPARE(binding.vertexCount(), s.surface.vertexCount());
        // The coarse mesh lies a little inside the curved surface: most surface vertices are
        // just outside it, bound to a tet next to them (no weight far below zero).
        for (int v = 0; v < s.surface.vertexCount(); ++v) {
            const auto& w = binding.weightsOf(v);
            QVERIFY(std::min({w[0], w[1], w[2], w[3]}) > -1.0);
        }
        std::vector<Vec3> out;
        binding.apply(s.mesh, out);
        const double tol = 1e-10 * size(s.surface);
        for (int v = 0; v < s.surface.vertexCount(); ++v)
            QVERIFY((out[v] - s.surface.positions[v]).norm() <= tol);
        // Move every node by x -> A x + b: the surface moves by the same map.
        Eigen::Matrix3d A;
        A << 1.1, 0.2, -0.1, 0.05, 0.9, 0.3, -0.2, 0.1, 1.2;
        const Vec3 b = Vec3(3, -2, 1) * scale;
        for (Vec3& p : s.mesh.positions())
            p = A * p + b;
        binding.apply(s.mesh, out);
        for (int v = 0; v < s.surface.vertexCount(); ++v)
            QVERIFY((out[v] - (A * s.surface.positions[v] + b)).norm() <= 10 * tol);
    }

    void cutMeshAndSurfaceTogether() {
        // The whole section-5 pipeline: cut the tets, re-bind, cut and close the surface, bind
        // its new vertices; then each closed surface piece follows its own tet piece.
        Scene s = sample(Sample::Polyp, 1.0);
        EmbeddedSurface embedded;
        QVERIFY(embedded.bind(s.mesh, s.surface).ok());
        const auto [lo, hi] = boundingBox(s.mesh.positions());
        const double z = lo.z() + 0.62 * (hi.z() - lo.z());
        SweepSurface sweep;
        QVERIFY(SweepSurface::fromStartEnd({Vec3(lo.x() - 5, lo.y() - 5, z), Vec3(hi.x() + 5, lo.y() - 5, z + 0.3)},
                                           {Vec3(lo.x() - 5, hi.y() + 5, z + 0.2), Vec3(hi.x() + 5, hi.y() + 5, z + 0.5)},
                                           sweep)
                    .ok());
        embedded.update(s.mesh);
        HybridCutter cutter(s.mesh);
        CutOptions options;
        options.snap = true;
        options.relaxSteps = 5;
        CutResult r;
        QVERIFY(cutter.cut(sweep, options, r).ok());
        EmbeddedCut ec;
        QVERIFY(embedded.cut(s.mesh, r.changes, sweep, &ec).ok());
        const SurfaceCut& sc = ec.surface;
        QVERIFY(sc.capTriangles > 0);
        QVERIFY(ec.reboundVertices > 0);
        const TriangleSurface cutSurf = embedded.surface();
        QCOMPARE(embedded.binding().vertexCount(), cutSurf.vertexCount());
        // Re-applying the binding reproduces the cut surface: every vertex (old, re-bound and
        // new) has its tet and coordinates.
        embedded.update(s.mesh);
        std::vector<Vec3> after = embedded.surface().positions;
        const double tol = 1e-9 * size(s.surface);
        for (int v = 0; v < cutSurf.vertexCount(); ++v)
            QVERIFY2((after[v] - cutSurf.positions[v]).norm() <= tol, qPrintable(QString::number(v)));
        // Lift the upper tet piece: the surface vertices on the + side (new copies included)
        // go with it, the others stay; vertices within d of the sweep are the cut's business.
        const Vec3 lift(0, 0, 10);
        QVERIFY(liftUpperPiece(s.mesh, z + 3, lift));
        embedded.update(s.mesh);
        after = embedded.surface().positions;
        int newMoved = 0, newChecked = 0;
        for (int v = sc.firstNewVertex; v < cutSurf.vertexCount(); ++v) {
            const int side = sc.side[v - sc.firstNewVertex];
            if (side == 0)
                continue;
            ++newChecked;
            const Vec3 expected = side > 0 ? cutSurf.positions[v] + lift : cutSurf.positions[v];
            if ((after[v] - expected).norm() <= tol)
                ++newMoved;
        }
        QVERIFY(newChecked > 0);
        QCOMPARE(newMoved, newChecked);
    }

    void rebindAfterACut() {
        Scene s = sample(Sample::Myoma, 1.0);
        SurfaceBinding binding;
        QVERIFY(binding.bind(s.mesh, s.surface).ok());
        // A horizontal cut through the middle of the myoma.
        const auto [lo, hi] = boundingBox(s.mesh.positions());
        const double z = 0.5 * (lo.z() + hi.z()) + 0.013;
        SweepSurface sweep;
        QVERIFY(SweepSurface::fromStartEnd({Vec3(lo.x() - 5, lo.y() - 5, z), Vec3(hi.x() + 5, lo.y() - 5, z + 0.2)},
                                           {Vec3(lo.x() - 5, hi.y() + 5, z + 0.1), Vec3(hi.x() + 5, hi.y() + 5, z + 0.3)},
                                           sweep)
                    .ok());
        std::vector<Vec3> before;
        binding.apply(s.mesh, before);

        HybridCutter cutter(s.mesh);
        CutOptions options;
        const double band = options.d * cutter.meanEdgeLength();
        options.snap = true;
        options.relaxSteps = 5;
        CutResult r;
        QVERIFY(cutter.cut(sweep, options, r).ok());
        binding.rebind(s.mesh, r.changes, before, sweep);
        // The surface does not move through the cut.
        std::vector<Vec3> after;
        binding.apply(s.mesh, after);
        const double tol = 1e-9 * size(s.surface);
        for (int v = 0; v < s.surface.vertexCount(); ++v)
            QVERIFY2((after[v] - before[v]).norm() <= tol, qPrintable(QString::number(v)));
        // Each side follows its own piece: lift the piece above the cut.
        const Vec3 lift(0, 0, 10);
        QVERIFY(liftUpperPiece(s.mesh, z + 2, lift));
        binding.apply(s.mesh, after);
        int checked = 0;
        for (int v = 0; v < s.surface.vertexCount(); ++v) {
            const int side = sweep.sideOf(before[v]);
            // Within d of the sweep the mesh's cut may deviate from it (cut nodes kept off it on
            // the surface); there the surface is cut itself (the next step), not re-bound.
            if (sweep.closestPoint(before[v]).distance < band)
                continue;
            const Vec3 expected = side > 0 ? before[v] + lift : before[v];

            QVERIFY2((after[v] - expected).norm() <= tol, qPrintable(QString("vertex %1 side %2").arg(v).arg(side)));
            ++checked;
        }
        QVERIFY(checked > s.surface.vertexCount() * 9 / 10);
    }
    /// apply() is the scalar formula w0 p0 + w1 p1 + w2 p2 + w3 p3 (in that order, in double)
    /// for every vertex, bit for bit, on any number of threads, after cuts and deformation;
    /// the float copy for rendering is that, rounded. A surface large enough for two threads.
    void applyIsTheScalarFormula() {
        Scene s;
        s.surface = sampleSurface(Sample::Myoma, 2.0);  // about 40000 vertices
        if (!tetrahedralize(sampleSurface(Sample::Myoma, 0.25), MeshingOptions{}, s.mesh).ok())
            QFAIL("meshing failed");
        EmbeddedSurface embedded;
        QVERIFY(embedded.bind(s.mesh, s.surface).ok());
        QVERIFY(embedded.surface().vertexCount() > 30000);
        HybridCutter cutter(s.mesh);
        const auto [lo, hi] = boundingBox(s.mesh.positions());
        for (int k = 0; k < 2; ++k) {
            const double z = lo.z() + (0.4 + 0.25 * k) * (hi.z() - lo.z());
            SweepSurface sweep;
            QVERIFY(SweepSurface::fromStartEnd({Vec3(lo.x() - 5, lo.y() - 5, z), Vec3(hi.x() + 5, lo.y() - 5, z + 0.4)},
                                               {Vec3(lo.x() - 5, hi.y() + 5, z - 0.3), Vec3(hi.x() + 5, hi.y() + 5, z + 0.2)},
                                               sweep)
                        .ok());
            embedded.update(s.mesh);
            CutResult r;
            QVERIFY(cutter.cut(sweep, CutOptions{.snap = true, .relaxSteps = 5}, r).ok());
            EmbeddedCut ec;
            QVERIFY(embedded.cut(s.mesh, r.changes, sweep, &ec).ok());
            // Every new vertex's weights are barycentric() of its position in its tet, bit for bit.
            const SurfaceBinding& b = embedded.binding();
            QVERIFY(ec.surface.firstNewVertex < b.vertexCount());
            for (int v = ec.surface.firstNewVertex; v < b.vertexCount(); ++v) {
                const auto w = b.weightsOf(v);
                const auto expected = barycentricInTet(s.mesh, b.tetOf(v), embedded.surface().positions[v]);
                QVERIFY2(std::memcmp(w.data(), expected.data(), sizeof(w)) == 0, qPrintable(QString::number(v)));
            }
        }
        std::mt19937 rng(7);
        std::uniform_real_distribution<double> jitter(-0.05, 0.05);
        for (Vec3& p : s.mesh.positions())
            p += Vec3(jitter(rng), jitter(rng), jitter(rng));
        const SurfaceBinding& b = embedded.binding();
        std::vector<Vec3> expected(b.vertexCount());
        for (int v = 0; v < b.vertexCount(); ++v) {
            const Tet& q = s.mesh.tet(b.tetOf(v));
            const auto w = b.weightsOf(v);
            for (int k = 0; k < 3; ++k)
                expected[v][k] = w[0] * s.mesh.pos(q[0])[k] + w[1] * s.mesh.pos(q[1])[k] + w[2] * s.mesh.pos(q[2])[k] +
                                 w[3] * s.mesh.pos(q[3])[k];
        }
        for (int threads : {1, 2, 3}) {
            std::vector<Vec3> out;
            std::vector<float> render;
            b.apply(s.mesh, out, &render, threads);
            QCOMPARE(out.size(), expected.size());
            QCOMPARE(render.size(), 3 * expected.size());
            for (int v = 0; v < b.vertexCount(); ++v) {
                QVERIFY2(std::memcmp(out[v].data(), expected[v].data(), sizeof(Vec3)) == 0,
                         qPrintable(QString("%1 threads, vertex %2").arg(threads).arg(v)));
                for (int k = 0; k < 3; ++k)
                    QVERIFY(render[3 * v + k] == static_cast<float>(expected[v][k]));
            }
        }
        embedded.keepRenderPositions(true);
        embedded.update(s.mesh, 2);
        QCOMPARE(embedded.renderPositions().size(), 3 * expected.size());
        QVERIFY(embedded.renderPositions()[3 * (b.vertexCount() - 1) + 2] == static_cast<float>(expected.back().z()));
        QVERIFY(std::memcmp(embedded.surface().positions.data(), expected.data(), expected.size() * sizeof(Vec3)) == 0);
        // The per-tet lists and the outside count follow the cuts (not only bind()).
        const QString lists = listProblems(b, s.mesh);
        QVERIFY2(lists.isEmpty(), qPrintable(lists));
    }

    /// followRemesh with a sparse renumbering (only the changed indices) binds exactly as the
    /// dense maps did, on a remeshing that removes tets and a node (the last ones take the freed
    /// slots), for several stars.
    void followRemeshSparseIsDense() {
        for (int round = 0; round < 4; ++round) {
            Scene s = sample(Sample::Polyp, 1.0);
            EmbeddedSurface embedded;
            QVERIFY(embedded.bind(s.mesh, s.surface).ok());
            embedded.update(s.mesh);
            // An interior node with vertices around it (nodes near the surface have them).
            int c = -1, best = 0;
            std::vector<char> boundary(s.mesh.nodeCount(), 0);
            for (const BoundaryFace& f : boundaryFaces(s.mesh))
                for (int n : f.nodes)
                    boundary[n] = 1;
            for (int n = round * 7; n < s.mesh.nodeCount(); ++n) {
                if (boundary[n])
                    continue;
                int bound = 0;
                for (int t : s.mesh.nodeTets(n))
                    bound += static_cast<int>(embedded.binding().verticesOf(t).size());
                if (bound > best && n != s.mesh.nodeCount() - 1) {
                    best = bound;
                    c = n;
                }
                if (best > 0 && n > round * 7 + 40)
                    break;
            }
            QVERIFY(c >= 0 && best > 0);
            std::vector<int> star(s.mesh.nodeTets(c).begin(), s.mesh.nodeTets(c).end());
            const EmbeddedSurface::RemeshRecord record = embedded.recordAround(s.mesh, star);
            QCOMPARE(static_cast<int>(record.vertices.size()), best);
            const BindingState before = stateOf(embedded.binding());
            TetMesh remeshed = s.mesh;
            const MeshRenumbering r = restar(remeshed, c);
            QVERIFY(!r.tets.empty() && !r.nodes.empty());
            const BindingState expected = followRemeshReference(before, remeshed, record, r.tets, r.nodes);

            EmbeddedSurface sparse = embedded;
            sparse.followRemesh(remeshed, record, r);
            QString diff = difference(stateOf(sparse.binding()), expected);
            QVERIFY2(diff.isEmpty(), qPrintable("sparse: " + diff));
            QString lists = listProblems(sparse.binding(), remeshed);
            QVERIFY2(lists.isEmpty(), qPrintable("sparse: " + lists));

            std::vector<int> newTet(r.tets.oldCount), newNode(r.nodes.oldCount);
            for (int t = 0; t < r.tets.oldCount; ++t)
                newTet[t] = r.tets(t);
            for (int n = 0; n < r.nodes.oldCount; ++n)
                newNode[n] = r.nodes(n);
            EmbeddedSurface dense = embedded;
            dense.followRemesh(remeshed, record, newTet, newNode);
            diff = difference(stateOf(dense.binding()), expected);
            QVERIFY2(diff.isEmpty(), qPrintable("dense: " + diff));
            lists = listProblems(dense.binding(), remeshed);
            QVERIFY2(lists.isEmpty(), qPrintable("dense: " + lists));
            // Re-applied, the surface stays where it was (the star was filled with the same shape).
            dense.update(remeshed);
            const double tol = 1e-9 * size(s.surface);
            for (int v = 0; v < s.surface.vertexCount(); ++v)
                QVERIFY((dense.surface().positions[v] - embedded.surface().positions[v]).norm() <= tol);
        }
    }

    /// The improvement step's remeshing (edge collapses: removed tets and nodes, a collapsed node
    /// standing for the node it merged into): the dense followRemesh binds as before issue 20.
    void followImproveMesh() {
        Scene s = sample(Sample::Polyp, 1.0);
        EmbeddedSurface embedded;
        QVERIFY(embedded.bind(s.mesh, s.surface).ok());
        embedded.update(s.mesh);
        double mean = 0;
        for (const Tet& q : s.mesh.tets())
            mean += (s.mesh.ref(q[1]) - s.mesh.ref(q[0])).norm() / s.mesh.tetCount();
        std::vector<int> seeds;
        for (int n = 0; n < s.mesh.nodeCount(); n += 3)
            seeds.push_back(n);
        const ImproveRegion region = improveRegion(s.mesh, seeds, {}, 1);
        const EmbeddedSurface::RemeshRecord record = embedded.recordAround(s.mesh, region.tets);
        const BindingState before = stateOf(embedded.binding());
        ImproveOptions io;
        io.badRatio = 0.3;
        io.coarsenEdge = 0.8 * mean;
        io.maxEdge = 2 * mean;
        const ImproveResult r = improveMesh(s.mesh, region, io);
        QVERIFY(r.renumbered() && r.removedNodes > 0);
        const MeshRenumbering& map = r.renumbering;
        const BindingState expected = followRemeshReference(
            before, s.mesh, record, [&](int t) { return map.tets(t); }, [&](int n) { return map.nodes(n); });
        // The sparse path (what Tissue::improve uses) and the dense one bind alike.
        EmbeddedSurface sparse = embedded;
        sparse.followRemesh(s.mesh, record, map);
        QString diff = difference(stateOf(sparse.binding()), expected);
        QVERIFY2(diff.isEmpty(), qPrintable("sparse: " + diff));
        QString lists = listProblems(sparse.binding(), s.mesh);
        QVERIFY2(lists.isEmpty(), qPrintable("sparse: " + lists));
        std::vector<int> newTet(map.tets.oldCount), newNode(map.nodes.oldCount);
        for (int t = 0; t < map.tets.oldCount; ++t)
            newTet[t] = map.tets(t);
        for (int n = 0; n < map.nodes.oldCount; ++n)
            newNode[n] = map.nodes(n);
        embedded.followRemesh(s.mesh, record, newTet, newNode);
        diff = difference(stateOf(embedded.binding()), expected);
        QVERIFY2(diff.isEmpty(), qPrintable("dense: " + diff));
        lists = listProblems(embedded.binding(), s.mesh);
        QVERIFY2(lists.isEmpty(), qPrintable("dense: " + lists));
    }
    /// A new vertex exactly on a node of a mesh with integer coordinates lies on the faces of
    /// every tet around the node: all have smallest weight exactly 0, and the binding takes the
    /// one of smallest index (what the sorted candidate list it was chosen from gave).
    void newVertexOnANodeTakesTheFirstTet() {
        const TetMesh mesh = makeBoxTetMesh(Vec3::Zero(), Vec3::Constant(3), 3, 3, 3);
        TriangleSurface surface;
        surface.positions = {Vec3(1.1, 1.2, 1.3), Vec3(0.9, 0.8, 0.7), Vec3(1.2, 0.7, 1.1)};
        surface.triangles = {{0, 1, 2}};
        SurfaceBinding binding;
        QVERIFY(binding.bind(mesh, surface).ok());
        const Vec3 node(1, 1, 1);
        std::vector<Vec3> positions = surface.positions;
        positions.push_back(node);
        SweepSurface sweep;
        QVERIFY(SweepSurface::fromStartEnd({Vec3(-1, -1, 2.5), Vec3(4, -1, 2.5)}, {Vec3(-1, 4, 2.5), Vec3(4, 4, 2.5)},
                                           sweep)
                    .ok());
        binding.bindNewVertices(mesh, positions, 3, {{0, 1}}, {0}, CutChanges{}, sweep);
        int around = 0;
        for (int t = 0; t < mesh.tetCount(); ++t) {
            const auto w = barycentricInTet(mesh, t, node);
            around += std::min({w[0], w[1], w[2], w[3]}) == 0 ? 1 : 0;
        }
        QVERIFY(around > 4);
        // The candidates are the tets around the nodes of the ends' tets; the smallest-index tet
        // around the node among them.
        std::vector<int> candidates;
        for (int end : {binding.tetOf(0), binding.tetOf(1)})
            for (int n : mesh.tet(end))
                candidates.insert(candidates.end(), mesh.nodeTets(n).begin(), mesh.nodeTets(n).end());
        std::sort(candidates.begin(), candidates.end());
        int expected = -1;
        for (int t : candidates) {
            const auto w = barycentricInTet(mesh, t, node);
            if (std::min({w[0], w[1], w[2], w[3]}) == 0) {
                expected = t;
                break;
            }
        }
        QVERIFY(expected >= 0);
        QCOMPARE(binding.tetOf(3), expected);
    }
};

QTEST_GUILESS_MAIN(TestBinding)
#include "test_binding.moc"
