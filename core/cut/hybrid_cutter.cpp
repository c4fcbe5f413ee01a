#include "core/cut/hybrid_cutter.h"

#include "core/cut/decompose_tets.h"
#include "core/cut/intersect_edges.h"
#include "core/cut/select_cut_nodes.h"
#include "core/cut/separate.h"
#include "core/cut/relax_nodes.h"
#include "core/cut/snap_nodes.h"
#include "core/cut/update_rest_state.h"
#include "core/mesh/quality.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <string>
#include <unordered_set>

namespace resect {
namespace {

double msSince(std::chrono::steady_clock::time_point t0) {
    return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
}

} // namespace

CutStats& CutStats::operator+=(const CutStats& c) {
    crossedEdges += c.crossedEdges;
    discardedEdges += c.discardedEdges;
    cutEdges += c.cutEdges;
    cutNodes += c.cutNodes;
    snappedNodes += c.snappedNodes;
    refusedSnaps += c.refusedSnaps;
    relaxedMoves += c.relaxedMoves;
    rejectedRelaxMoves += c.rejectedRelaxMoves;
    decomposedTets += c.decomposedTets;
    separatedTets += c.separatedTets;
    duplicatedNodes += c.duplicatedNodes;
    addedTets += c.addedTets;
    addedNodes += c.addedNodes;
    steinerPoints += c.steinerPoints;
    faceNodes += c.faceNodes;
    touchedTets += c.touchedTets;
    maxCutNodeDistance = std::max(maxCutNodeDistance, c.maxCutNodeDistance);
    for (std::size_t i = 0; i < schemeCount.size(); ++i)
        schemeCount[i] += c.schemeCount[i];
    timeMs.intersect += c.timeMs.intersect;
    timeMs.select += c.timeMs.select;
    timeMs.decompose += c.timeMs.decompose;
    timeMs.snap += c.timeMs.snap;
    timeMs.relax += c.timeMs.relax;
    timeMs.update += c.timeMs.update;
    timeMs.total += c.timeMs.total;
    return *this;
}

HybridCutter::HybridCutter(TetMesh& mesh) : m_mesh(mesh) {
    // Headroom for the nodes and tets cuts add, so that a cut never pays for reallocating
    // the whole mesh (growth beyond it is amortised as usual).
    mesh.reserve(mesh.nodeCount() + mesh.nodeCount() / 4 + 1024, mesh.tetCount() + mesh.tetCount() / 4 + 4096);
    m_grid.build(mesh);
    m_meanEdge = resect::meanEdgeLength(mesh);
}

void HybridCutter::refreshSpatialIndex() { m_grid.build(m_mesh); }

Status HybridCutter::cut(const SweepSurface& sweep, const CutOptions& options, CutResult& result) {
    if (!std::isfinite(options.d) || options.d < 0 || options.d > 0.5)
        return Status::error("d must be in [0, 0.5] (a fraction of the mean edge length), got " +
                             std::to_string(options.d));
    if (options.relaxSteps < 0 || options.relaxRings < 1 || options.relaxRings > 5 || !(options.relaxDamping > 0) ||
        !(options.wSpring >= 0) || !(options.wParticle >= 0))
        return Status::error("relaxation needs steps >= 0, rings in [1, 5], damping > 0 and weights >= 0");
    if (!(options.faceNodeAdvantage >= 0) || options.faceNodeAdvantage > 100)
        return Status::error("faceNodeAdvantage must be in [0, 100]");
    if (!(options.minEdgeFraction > 0) || options.minEdgeFraction > 0.01)
        return Status::error("minEdgeFraction must be in (0, 0.01]");
    if (sweep.triangles().empty())
        return Status::error("empty sweep surface");
    result = {};
    CutStats& stats = result.stats;
    CutChanges& changes = result.changes;
    const int nodesBefore = m_mesh.nodeCount();
    const int tetsBefore = m_mesh.tetCount();
    changes.firstNewNode = nodesBefore;
    changes.firstNewTet = tetsBefore;
    const auto start = std::chrono::steady_clock::now();

    auto t0 = std::chrono::steady_clock::now();
    const IntersectedEdges crossed = intersectEdges(m_mesh, m_grid, sweep);
    stats.timeMs.intersect = msSince(t0);
    stats.crossedEdges = static_cast<int>(crossed.edges.size());
    stats.discardedEdges = crossed.discardedEdges;

    t0 = std::chrono::steady_clock::now();
    SelectOptions select;
    const bool hybrid = options.method == CutMethod::Hybrid;
    select.allowCutNodes = hybrid;
    select.d = hybrid ? options.d * m_meanEdge : 0.0;
    select.minEdgeFraction = options.minEdgeFraction;
    const CutSelection selection = selectCutNodes(m_mesh, sweep, crossed, select);
    stats.timeMs.select = msSince(t0);
    stats.cutNodes = static_cast<int>(selection.cutNodes.size());
    stats.cutEdges = static_cast<int>(selection.cutEdges.size());
    stats.maxCutNodeDistance = selection.maxCutNodeDistance;
    changes.tetScheme.reserve(selection.tets.size());
    for (const TetCut& tc : selection.tets) {
        ++stats.schemeCount[static_cast<int>(tc.scheme)];
        changes.tetScheme.emplace_back(tc.tet, tc.scheme);
    }
    std::sort(changes.tetScheme.begin(), changes.tetScheme.end());
    changes.cutNodes = selection.cutNodes;

    // Keep what is needed to roll back: the nodes of every tet that may change.
    std::unordered_set<int> mayChange;
    for (const TetCut& tc : selection.tets)
        mayChange.insert(tc.tet);
    for (int n : selection.cutNodes)
        mayChange.insert(m_mesh.nodeTets(n).begin(), m_mesh.nodeTets(n).end());
    std::vector<std::pair<int, Tet>> backup;
    backup.reserve(mayChange.size());
    for (int t : mayChange)
        backup.push_back({t, m_mesh.tet(t)});
    const auto rollback = [&] {
        for (const auto& [t, q] : backup)
            m_mesh.replaceTet(t, q);
        m_mesh.truncate(nodesBefore, tetsBefore);
    };

    // Cut nodes, and cut edges, on the boundary before the cut: they keep their place when
    // snapping and relaxing, so the body's shape and volume are kept.
    const bool moves = options.snap || options.relaxSteps > 0;
    const std::vector<int> surfaceCutNodes = moves ? boundaryNodesAmong(m_mesh, selection.cutNodes) : std::vector<int>{};
    std::vector<std::uint64_t> surfaceCutEdges;
    if (options.relaxSteps > 0) {
        std::vector<int> faceScratch, edgeScratch;
        for (const EdgeCrossing& e : selection.cutEdges) {
            m_mesh.edgeTets(e.a, e.b, edgeScratch);
            bool boundary = false;
            for (int t : edgeScratch)
                for (int v : m_mesh.tet(t)) {
                    if (v == e.a || v == e.b)
                        continue;
                    m_mesh.faceTets(e.a, e.b, v, faceScratch);
                    boundary = boundary || faceScratch.size() == 1;
                }
            if (boundary)
                surfaceCutEdges.push_back(edgeKey(e.a, e.b));
        }
    }

    t0 = std::chrono::steady_clock::now();
    DecomposeOptions decompose;
    decompose.symmetricFaces = hybrid && options.triangulation == FaceTriangulation::Enhanced;
    decompose.sweep = &sweep;
    decompose.faceNodeAdvantage = options.faceNodeAdvantage;
    Decomposition decomposition;
    if (Status s = decomposeTets(m_mesh, selection, decompose, decomposition, changes); !s.ok()) {
        rollback();
        return Status::error("cut failed, mesh unchanged: " + s.message());
    }
    const Separation separation = separate(m_mesh, selection, decomposition, changes);
    std::vector<int> relaxedNodes;
    stats.timeMs.decompose = msSince(t0);
    changes.tetSide = decomposition.tetSide;
    stats.decomposedTets = decomposition.decomposedTets;
    stats.steinerPoints = decomposition.steinerPoints;
    stats.faceNodes = decomposition.faceNodes;
    stats.separatedTets = separation.separatedTets;
    stats.duplicatedNodes = separation.duplicatedNodes;

    // Nodes on the cut (needed by relaxation and by the change list): cut nodes, split points,
    // their copies, and the points placed on the sweep inside partially cut tets.
    changes.cutSurfaceNodes = selection.cutNodes;
    for (const auto& [key, n] : decomposition.edgePoint)
        changes.cutSurfaceNodes.push_back(n);
    for (const auto& [orig, copy] : changes.duplicatedNodes)
        changes.cutSurfaceNodes.push_back(copy);
    for (int n : decomposition.sweepPoints)
        changes.cutSurfaceNodes.push_back(n);
    std::sort(changes.cutSurfaceNodes.begin(), changes.cutSurfaceNodes.end());
    changes.cutSurfaceNodes.erase(std::unique(changes.cutSurfaceNodes.begin(), changes.cutSurfaceNodes.end()),
                                  changes.cutSurfaceNodes.end());

    if (options.snap && !changes.cutNodes.empty()) {
        t0 = std::chrono::steady_clock::now();
        SnapOptions snap;
        snap.qualityFloor = options.snapQualityFloor;
        const SnapResult snapped = snapNodes(m_mesh, sweep, changes, surfaceCutNodes, snap);
        stats.snappedNodes = snapped.snapped;
        stats.refusedSnaps = snapped.refused;
        stats.maxCutNodeDistance = snapped.maxDistanceAfter;
        // Tets around moved nodes may have grown out of their grid cells.
        for (int n : changes.cutNodes)
            for (int t : m_mesh.nodeTets(n))
                m_grid.insert(m_mesh, t);
        for (const auto& [orig, copy] : changes.duplicatedNodes)
            for (int t : m_mesh.nodeTets(copy))
                m_grid.insert(m_mesh, t);
        stats.timeMs.snap = msSince(t0);
    }

    if (options.relaxSteps > 0) {
        t0 = std::chrono::steady_clock::now();
        std::vector<int> fixed = surfaceCutNodes;
        for (std::uint64_t key : surfaceCutEdges)
            fixed.push_back(decomposition.edgePoint.at(key));
        RelaxOptions relax;
        relax.steps = options.relaxSteps;
        relax.wSpring = options.wSpring;
        relax.wParticle = options.wParticle;
        relax.rings = options.relaxRings;
        relax.damping = options.relaxDamping;
        const RelaxResult relaxed = relaxNodes(m_mesh, sweep, changes, fixed, relax);
        stats.relaxedMoves = relaxed.acceptedMoves;
        stats.rejectedRelaxMoves = relaxed.rejectedMoves;
        relaxedNodes = relaxed.movedNodes;
        stats.timeMs.relax = msSince(t0);
    }

    // Change list: modified tets once, nodes whose tets changed.
    std::sort(changes.modifiedTets.begin(), changes.modifiedTets.end());
    changes.modifiedTets.erase(std::unique(changes.modifiedTets.begin(), changes.modifiedTets.end()),
                               changes.modifiedTets.end());
    std::unordered_set<int> touched;
    for (int t : changes.modifiedTets)
        touched.insert(m_mesh.tet(t).begin(), m_mesh.tet(t).end());
    for (int t = tetsBefore; t < m_mesh.tetCount(); ++t)
        touched.insert(m_mesh.tet(t).begin(), m_mesh.tet(t).end());
    for (const auto& [orig, copy] : changes.duplicatedNodes)
        touched.insert(orig);
    // Nodes moved by snapping or relaxation change their neighbours' rest volumes too.
    std::vector<int> moved = relaxedNodes;
    if (options.snap) {
        moved.insert(moved.end(), changes.cutNodes.begin(), changes.cutNodes.end());
        for (const auto& [orig, copy] : changes.duplicatedNodes)
            moved.push_back(copy);
    }
    for (int n : moved)
        for (int t : m_mesh.nodeTets(n)) {
            touched.insert(m_mesh.tet(t).begin(), m_mesh.tet(t).end());
            m_grid.insert(m_mesh, t);
        }
    changes.touchedNodes.assign(touched.begin(), touched.end());
    std::sort(changes.touchedNodes.begin(), changes.touchedNodes.end());

    // Rest state (section 4.7): masses by Eq. 3 for every node whose tets changed.
    t0 = std::chrono::steady_clock::now();
    updateMasses(m_mesh, changes.touchedNodes, options.density);
    stats.timeMs.update = msSince(t0);

    for (int t = tetsBefore; t < m_mesh.tetCount(); ++t)
        m_grid.insert(m_mesh, t);
    stats.addedTets = m_mesh.tetCount() - tetsBefore;
    stats.addedNodes = m_mesh.nodeCount() - nodesBefore;
    stats.touchedTets = static_cast<int>(crossed.candidateTets.size() + stats.addedTets);
    stats.timeMs.total = msSince(start);
    return Status::success();
}

} // namespace resect
