#include "core/cut/hybrid_cutter.h"

#include "core/cut/decompose_tets.h"
#include "core/cut/intersect_edges.h"
#include "core/cut/relax_nodes.h"
#include "core/cut/select_cut_nodes.h"
#include "core/cut/separate.h"
#include "core/cut/snap_nodes.h"
#include "core/cut/update_rest_state.h"
#include "core/mesh/index_marks.h"
#include "core/mesh/quality.h"
#include "core/mesh/tet_mesh_backup.h"
#include "core/mesh/topology.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <string>

namespace resect {
namespace {

using Clock = std::chrono::steady_clock;

double msSince(Clock::time_point t0) {
    return std::chrono::duration<double, std::milli>(Clock::now() - t0).count();
}

/// Undo of everything a cut changes in the cutter's state, undone unless committed: the mesh
/// (exactly, TetMeshBackup) and the grid's inserts.
class CutBackup {
public:
    CutBackup(TetMesh& mesh, TetGrid& grid) : m_mesh(mesh), m_grid(grid), m_checkpoint(grid.checkpoint()) {}
    ~CutBackup() {
        if (!m_done)
            m_grid.rollback(m_checkpoint);
        // m_mesh restores itself unless committed.
    }
    CutBackup(const CutBackup&) = delete;
    CutBackup& operator=(const CutBackup&) = delete;
    void commit() {
        m_mesh.commit();
        m_grid.release(m_checkpoint);
        m_done = true;
    }

private:
    TetMeshBackup m_mesh;
    TetGrid& m_grid;
    TetGrid::Checkpoint m_checkpoint;
    bool m_done = false;
};

Status cancelledAt(CutStage stage) {
    return Status::error(std::string("cut cancelled before stage '") + cutStageName(stage) + "', mesh unchanged");
}

/// Step 3: the selection, with its counts and the per-tet schemes entered in the change list.
CutSelection selectStep(const TetMesh& mesh, const SweepSurface& sweep, const IntersectedEdges& crossed,
                        const CutOptions& options, double meanEdge, CutResult& result) {
    SelectOptions select;
    const bool hybrid = options.method == CutMethod::Hybrid;
    select.allowCutNodes = hybrid;
    select.d = hybrid ? options.d * meanEdge : 0.0;
    select.minEdgeFraction = options.minEdgeFraction;
    CutSelection selection = selectCutNodes(mesh, sweep, crossed, select);
    CutStats& stats = result.stats;
    CutChanges& changes = result.changes;
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
    return selection;
}

/// Cut edges that lie on the mesh boundary before the cut: their split points keep their
/// place when relaxing, as boundary cut nodes do, so the body's shape and volume are kept.
std::vector<std::uint64_t> boundaryCutEdges(const TetMesh& mesh, const CutSelection& selection) {
    std::vector<std::uint64_t> keys;
    for (const EdgeCrossing& e : selection.cutEdges)
        if (isBoundaryEdge(mesh, e.a, e.b))
            keys.push_back(edgeKey(e.a, e.b));
    return keys;
}

/// Every node on the sweep after steps 4-5: cut nodes, split points, their copies, and the
/// points placed on the sweep inside partially cut tets (sorted, unique).
std::vector<int> nodesOnCut(const CutSelection& selection, const Decomposition& decomposition,
                            const CutChanges& changes) {
    std::vector<int> nodes = selection.cutNodes;
    for (const auto& [key, n] : decomposition.edgePoint)
        nodes.push_back(n);
    for (const auto& [orig, copy] : changes.duplicatedNodes)
        nodes.push_back(copy);
    nodes.insert(nodes.end(), decomposition.sweepPoints.begin(), decomposition.sweepPoints.end());
    std::sort(nodes.begin(), nodes.end());
    nodes.erase(std::unique(nodes.begin(), nodes.end()), nodes.end());
    return nodes;
}

/// Steps 4-5 (section 4.4): decomposition of the affected tets and separation of the sides,
/// with their counts and change-list entries (including every node now on the cut).
Status decomposeStep(TetMesh& mesh, const CutSelection& selection, const SweepSurface& sweep,
                     const CutOptions& options, Decomposition& decomposition, CutResult& result) {
    DecomposeOptions decompose;
    decompose.symmetricFaces = options.method == CutMethod::Hybrid && options.triangulation == FaceTriangulation::Enhanced;
    decompose.sweep = &sweep;
    decompose.faceNodeAdvantage = options.faceNodeAdvantage;
    CutChanges& changes = result.changes;
    if (Status s = decomposeTets(mesh, selection, decompose, decomposition, changes); !s.ok())
        return s;
    const Separation separation = separate(mesh, selection, decomposition, changes);
    changes.tetSide = decomposition.tetSide;
    CutStats& stats = result.stats;
    stats.decomposedTets = decomposition.decomposedTets;
    stats.steinerPoints = decomposition.steinerPoints;
    stats.faceNodes = decomposition.faceNodes;
    stats.separatedTets = separation.separatedTets;
    stats.duplicatedNodes = separation.duplicatedNodes;
    changes.cutSurfaceNodes = nodesOnCut(selection, decomposition, changes);
    return Status::success();
}

/// Step 6: snapping (section 4.5); the tets around moved nodes are re-registered in the grid.
void snapStep(TetMesh& mesh, TetGrid& grid, const SweepSurface& sweep, const CutOptions& options,
              const std::vector<int>& boundaryCutNodes, CutResult& result) {
    SnapOptions snap;
    snap.qualityFloor = options.snapQualityFloor;
    const SnapResult snapped = snapNodes(mesh, sweep, result.changes, boundaryCutNodes, snap);
    result.stats.snappedNodes = snapped.snapped;
    result.stats.refusedSnaps = snapped.refused;
    result.stats.maxCutNodeDistance = snapped.maxDistanceAfter;
    // Tets around moved nodes may have grown out of their grid cells (each registered once:
    // a second registration at the same place would change no query). A mark per tet, kept
    // between cuts on this thread (see "Marks" at HybridCutter::cut).
    thread_local IndexMarks<char> registered;
    const auto scope = registered.use(mesh.tetCount());
    const auto registerTetsAt = [&](int n) {
        for (int t : mesh.nodeTets(n))
            if (!registered[t]) {
                registered.set(t, 1);
                grid.insert(mesh, t);
            }
    };
    for (int n : result.changes.cutNodes)
        registerTetsAt(n);
    for (const auto& [orig, copy] : result.changes.duplicatedNodes)
        registerTetsAt(copy);
}

/// Step 7: relaxation (section 4.6) with the boundary cut nodes and boundary split points
/// fixed. Returns the moved nodes.
std::vector<int> relaxStep(TetMesh& mesh, const SweepSurface& sweep, const CutOptions& options,
                           std::vector<int> fixed, const std::vector<std::uint64_t>& boundaryEdges,
                           const Decomposition& decomposition, CutResult& result) {
    for (std::uint64_t key : boundaryEdges)
        fixed.push_back(decomposition.edgePoint.at(key));
    RelaxOptions relax;
    relax.steps = options.relaxSteps;
    relax.wSpring = options.wSpring;
    relax.wParticle = options.wParticle;
    relax.rings = options.relaxRings;
    relax.damping = options.relaxDamping;
    RelaxResult relaxed = relaxNodes(mesh, sweep, result.changes, fixed, relax);
    result.stats.relaxedMoves = relaxed.acceptedMoves;
    result.stats.rejectedRelaxMoves = relaxed.rejectedMoves;
    return std::move(relaxed.movedNodes);
}

/// The change list's remaining entries: modified tets once, and every node whose incident
/// tets changed (new, modified or re-attached tets, and the tets around moved nodes, whose
/// rest volumes changed). Tets around moved nodes are re-registered in the grid, once each;
/// `registered` marks them (per tet; clear on entry, covering every tet of the mesh now).
void finishChangeList(TetMesh& mesh, TetGrid& grid, const std::vector<int>& moved,
                      CutChanges& changes, IndexMarks<char>& registered) {
    std::sort(changes.modifiedTets.begin(), changes.modifiedTets.end());
    changes.modifiedTets.erase(std::unique(changes.modifiedTets.begin(), changes.modifiedTets.end()),
                               changes.modifiedTets.end());
    // Each node once (a mark per node, kept between cuts on this thread: see "Marks" at
    // HybridCutter::cut), then sorted.
    thread_local IndexMarks<char> isTouched;
    const auto scope = isTouched.use(mesh.nodeCount());
    std::vector<int>& touched = changes.touchedNodes;
    touched.clear();
    const auto touch = [&](int n) {
        if (!isTouched[n]) {
            isTouched.set(n, 1);
            touched.push_back(n);
        }
    };
    const auto touchTet = [&](int t) {
        for (int n : mesh.tet(t))
            touch(n);
    };
    for (int t : changes.modifiedTets)
        touchTet(t);
    for (int t = changes.firstNewTet; t < mesh.tetCount(); ++t)
        touchTet(t);
    for (const auto& [orig, copy] : changes.duplicatedNodes)
        touch(orig);
    for (int n : moved)
        for (int t : mesh.nodeTets(n)) {
            if (registered[t])
                continue; // its nodes are touched already
            registered.set(t, 1);
            touchTet(t);
            grid.insert(mesh, t);
        }
    std::sort(touched.begin(), touched.end());
}

} // namespace

const char* cutStageName(CutStage stage) {
    switch (stage) {
    case CutStage::Intersect: return "intersect";
    case CutStage::Select: return "select";
    case CutStage::Decompose: return "decompose";
    case CutStage::Snap: return "snap";
    case CutStage::Relax: return "relax";
    case CutStage::RestState: return "rest state";
    case CutStage::Surface: return "surface";
    }
    return "?";
}

Status validateCutOptions(const CutOptions& o) {
    const auto range = [](const char* name, double lo, double hi, double value, bool openLo = false) {
        return std::string(name) + " must be in " + (openLo ? "(" : "[") + formatNumber(lo) + ", " +
               formatNumber(hi) + "], got " + formatNumber(value);
    };
    if (!std::isfinite(o.d) || o.d < 0 || o.d > CutLimits::kMaxD)
        return Status::error(range("d (a fraction of the mean edge length)", 0, CutLimits::kMaxD, o.d));
    if (!(o.faceNodeAdvantage >= 0) || o.faceNodeAdvantage > CutLimits::kMaxFaceNodeAdvantage)
        return Status::error(range("faceNodeAdvantage", 0, CutLimits::kMaxFaceNodeAdvantage, o.faceNodeAdvantage));
    if (!(o.improveQuality >= 0) || o.improveQuality > CutLimits::kMaxImproveQuality)
        return Status::error(range("improveQuality", 0, CutLimits::kMaxImproveQuality, o.improveQuality));
    if (!(o.improveShortEdge >= 0) || o.improveShortEdge > CutLimits::kMaxImproveShortEdge)
        return Status::error(range("improveShortEdge", 0, CutLimits::kMaxImproveShortEdge, o.improveShortEdge));
    if (!(o.improveCoarsen >= 0) || o.improveCoarsen > CutLimits::kMaxImproveCoarsen)
        return Status::error(range("improveCoarsen", 0, CutLimits::kMaxImproveCoarsen, o.improveCoarsen));
    if (!(o.minEdgeFraction > 0) || o.minEdgeFraction > CutLimits::kMaxMinEdgeFraction)
        return Status::error(range("minEdgeFraction", 0, CutLimits::kMaxMinEdgeFraction, o.minEdgeFraction, true));
    if (!(o.snapQualityFloor >= 0) || o.snapQualityFloor > 1)
        return Status::error(range("snapQualityFloor", 0, 1, o.snapQualityFloor));
    if (o.relaxSteps < 0 || o.relaxSteps > CutLimits::kMaxRelaxSteps)
        return Status::error(range("relaxation steps", 0, CutLimits::kMaxRelaxSteps, o.relaxSteps));
    if (o.relaxRings < 1 || o.relaxRings > CutLimits::kMaxRelaxRings)
        return Status::error(range("relaxation rings", 1, CutLimits::kMaxRelaxRings, o.relaxRings));
    if (!(o.relaxDamping > 0) || o.relaxDamping > CutLimits::kMaxRelaxDamping)
        return Status::error(range("relaxation damping", 0, CutLimits::kMaxRelaxDamping, o.relaxDamping, true));
    if (!(o.wSpring >= 0) || o.wSpring > CutLimits::kMaxRelaxWeight)
        return Status::error(range("w_spring", 0, CutLimits::kMaxRelaxWeight, o.wSpring));
    if (!(o.wParticle >= 0) || o.wParticle > CutLimits::kMaxRelaxWeight)
        return Status::error(range("w_particle", 0, CutLimits::kMaxRelaxWeight, o.wParticle));
    if (!(o.density > 0) || !std::isfinite(o.density))
        return Status::error("density must be > 0, got " + formatNumber(o.density));
    return Status::success();
}

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

HybridCutter::HybridCutter(const HybridCutter& other, TetMesh& mesh)
    : m_mesh(mesh), m_grid(other.m_grid), m_meanEdge(other.m_meanEdge) {
    mesh.reserve(mesh.nodeCount() + mesh.nodeCount() / 4 + 1024, mesh.tetCount() + mesh.tetCount() / 4 + 4096);
}

void HybridCutter::refreshSpatialIndex() { m_grid.build(m_mesh); }

Status HybridCutter::cut(const SweepSurface& sweep, const CutOptions& options, CutResult& result,
                         const CutStageCallback& proceed) {
    if (Status s = validateCutOptions(options); !s.ok())
        return s;
    if (sweep.triangles().empty())
        return Status::error("empty sweep surface");
    result = {};
    CutStats& stats = result.stats;
    CutChanges& changes = result.changes;
    changes.firstNewNode = m_mesh.nodeCount();
    changes.firstNewTet = m_mesh.tetCount();
    const auto start = Clock::now();
    const auto stage = [&](CutStage s) { return !proceed || proceed(s); };
    CutBackup backup(m_mesh, m_grid);

    // Step 2 (section 4.3): the edges the sweep crosses.
    if (!stage(CutStage::Intersect))
        return cancelledAt(CutStage::Intersect);
    auto t0 = Clock::now();
    const IntersectedEdges crossed = intersectEdges(m_mesh, m_grid, sweep);
    stats.timeMs.intersect = msSince(t0);
    stats.crossedEdges = static_cast<int>(crossed.edges.size());
    stats.discardedEdges = crossed.discardedEdges;

    // Step 3 (section 4.3): cut nodes, cut edges, per-tet codes.
    if (!stage(CutStage::Select))
        return cancelledAt(CutStage::Select);
    t0 = Clock::now();
    const CutSelection selection = selectStep(m_mesh, sweep, crossed, options, m_meanEdge, result);
    stats.timeMs.select = msSince(t0);
    // What snapping and relaxation keep in place, read before the mesh changes.
    const bool moves = options.snap || options.relaxSteps > 0;
    const std::vector<int> boundaryCutNodes = moves ? boundaryNodesAmong(m_mesh, selection.cutNodes) : std::vector<int>{};
    const std::vector<std::uint64_t> boundaryEdges =
        options.relaxSteps > 0 ? boundaryCutEdges(m_mesh, selection) : std::vector<std::uint64_t>{};

    // Steps 4-5 (section 4.4): decomposition and separation.
    if (!stage(CutStage::Decompose))
        return cancelledAt(CutStage::Decompose);
    t0 = Clock::now();
    Decomposition decomposition;
    if (Status s = decomposeStep(m_mesh, selection, sweep, options, decomposition, result); !s.ok())
        return Status::error("cut failed, mesh unchanged: " + s.message());
    stats.timeMs.decompose = msSince(t0);

    // Step 6 (section 4.5): snapping.
    if (!stage(CutStage::Snap))
        return cancelledAt(CutStage::Snap);
    if (options.snap && !changes.cutNodes.empty()) {
        t0 = Clock::now();
        snapStep(m_mesh, m_grid, sweep, options, boundaryCutNodes, result);
        stats.timeMs.snap = msSince(t0);
    }

    // Step 7 (section 4.6): relaxation.
    if (!stage(CutStage::Relax))
        return cancelledAt(CutStage::Relax);
    std::vector<int> moved;
    if (options.relaxSteps > 0) {
        t0 = Clock::now();
        moved = relaxStep(m_mesh, sweep, options, boundaryCutNodes, boundaryEdges, decomposition, result);
        stats.timeMs.relax = msSince(t0);
    }
    if (options.snap) {
        moved.insert(moved.end(), changes.cutNodes.begin(), changes.cutNodes.end());
        for (const auto& [orig, copy] : changes.duplicatedNodes)
            moved.push_back(copy);
    }

    // Step 8 (section 4.7): rest state, masses by Eq. 3 for every node whose tets changed.
    if (!stage(CutStage::RestState))
        return cancelledAt(CutStage::RestState);
    // Tets finishChangeList re-registered in the grid (a mark per tet, see "Marks" at
    // HybridCutter::cut).
    thread_local IndexMarks<char> registered;
    const auto registeredScope = registered.use(m_mesh.tetCount());
    finishChangeList(m_mesh, m_grid, moved, changes, registered);
    t0 = Clock::now();
    updateMasses(m_mesh, changes.touchedNodes, options.density);
    stats.timeMs.update = msSince(t0);

    for (int t = changes.firstNewTet; t < m_mesh.tetCount(); ++t)
        if (!registered[t])
            m_grid.insert(m_mesh, t);
    stats.addedTets = m_mesh.tetCount() - changes.firstNewTet;
    stats.addedNodes = m_mesh.nodeCount() - changes.firstNewNode;
    stats.touchedTets = static_cast<int>(crossed.candidateTets.size() + stats.addedTets);
    stats.timeMs.total = msSince(start);
    backup.commit();
    return Status::success();
}

} // namespace resect
