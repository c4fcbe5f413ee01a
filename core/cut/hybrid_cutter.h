#pragma once
// HybridCutter: the cut of section 4.1, one step per file, in the paper's order:
//   intersect_edges -> select_cut_nodes -> decompose_tets -> separate
//   (-> snap_nodes -> relax_nodes -> update_rest_state, see the snapping issue).
// The subdivision baseline (Bielser et al. 1999, the paper's ref. [3]) is the same pipeline
// with no cut nodes chosen by distance and the standard face triangulation.

#include "core/cut/cut_types.h"
#include "core/mesh/material.h"
#include "core/mesh/tet_grid.h"
#include "core/status.h"
#include "core/sweep/sweep_surface.h"

#include <functional>

namespace resect {

enum class CutMethod { Hybrid, Subdivision };
enum class FaceTriangulation { Standard, Enhanced };

/// Accepted ranges of the CutOptions fields (validateCutOptions checks them; its messages
/// print these constants).
/// The CLI, the scenario reader and the studio's editors take their ranges from here too.
struct CutLimits {
    static constexpr double kMaxD = 0.5;                  ///< d in [0, kMaxD] mean edge lengths
    static constexpr double kMaxFaceNodeAdvantage = 100;  ///< faceNodeAdvantage in [0, this]
    static constexpr double kMaxMinEdgeFraction = 0.01;   ///< minEdgeFraction in (0, this]
    static constexpr int kMaxRelaxSteps = 10000;          ///< relaxSteps in [0, this]
    static constexpr double kMaxRelaxWeight = 1e6;        ///< wSpring, wParticle in [0, this]
    static constexpr double kMaxRelaxDamping = 1e6;       ///< relaxDamping in (0, this]
    static constexpr int kMaxRelaxRings = 5;              ///< relaxRings in [1, this]
    static constexpr double kMaxImproveQuality = 4;       ///< improveQuality in [0, this]
    static constexpr double kMaxImproveShortEdge = 4;     ///< improveShortEdge in [0, this]
    static constexpr double kMaxImproveCoarsen = 1;       ///< improveCoarsen in [0, this]
};

struct CutOptions {
    CutMethod method = CutMethod::Hybrid;
    FaceTriangulation triangulation = FaceTriangulation::Enhanced;
    /// Cut-node threshold as a fraction of the mean edge length (the paper: one fifth);
    /// dimensionless, in [0, CutLimits::kMaxD].
    double d = 0.2;
    /// Enhanced faces: how much better a face node's triangles must be than the better
    /// diagonal's for the face node to be used (0: always, the paper's plain symmetric rule;
    /// see decompose_tets.h); dimensionless, in [0, CutLimits::kMaxFaceNodeAdvantage].
    double faceNodeAdvantage = 1.5;
    /// Node snapping (section 4.5): move cut nodes onto the sweep.
    bool snap = false;
    /// A snap may not push a tet's radius ratio below min(floor, its ratio before); in [0, 1].
    double snapQualityFloor = 0.05;
    /// Relaxation (section 4.6, relax_nodes.h): steps (0: off, >= 0), weights (>= 0),
    /// neighbourhood rings (in [1, CutLimits::kMaxRelaxRings]), damping (> 0).
    int relaxSteps = 0;
    double wSpring = 1.0;
    double wParticle = 0.2;
    int relaxRings = 2;
    double relaxDamping = 10.0;
    /// Density (g/mm^3, > 0) for the masses of Eq. 3, updated for every node whose tets
    /// changed. Tissue::cut uses its material's density instead.
    double density = Material{}.density;
    /// Local mesh improvement after the cut (Tissue::cut, core/cut/improve_mesh.h), in the
    /// cut's neighbourhood: tets whose radius ratio is below improveQuality times the tissue's
    /// worst as created are improved, edges shorter than improveShortEdge times its shortest
    /// as created are collapsed, and edges shorter than improveCoarsen times its mean edge
    /// (the unit of d) are collapsed where quality allows, so that repeated cuts do not keep
    /// adding tets. Dimensionless, in [0, CutLimits::kMaxImproveQuality], [0,
    /// CutLimits::kMaxImproveShortEdge] and [0, CutLimits::kMaxImproveCoarsen] (0: off);
    /// improve = false turns the step off.
    bool improve = true;
    double improveQuality = 1.0;
    double improveShortEdge = 0.6;
    double improveCoarsen = 0.5;
    /// Smallest fraction of an edge a split may cut off (see select_cut_nodes.h); in
    /// (0, CutLimits::kMaxMinEdgeFraction].
    double minEdgeFraction = 1e-6;
};

/// Checks every field against its documented range; the message names the field, the range
/// and the value.
Status validateCutOptions(const CutOptions& options);

/// The stages of applying a cut that can still be cancelled, in order: HybridCutter's (section
/// 4.1), then the embedded surface's (Tissue::cut).
enum class CutStage { Intersect, Select, Decompose, Snap, Relax, RestState, Surface };
const char* cutStageName(CutStage stage);
/// Called before each stage; returning false cancels the cut, which is then undone exactly.
using CutStageCallback = std::function<bool(CutStage)>;

/// Counts and timings of one cut (the "cut" object of the cut report, DESIGN.md).
struct CutStats {
    int crossedEdges = 0;
    int discardedEdges = 0;
    int cutEdges = 0;
    int cutNodes = 0;
    int snappedNodes = 0;
    int refusedSnaps = 0;
    int relaxedMoves = 0;
    int rejectedRelaxMoves = 0;
    int decomposedTets = 0;
    int separatedTets = 0;
    int duplicatedNodes = 0;
    int addedTets = 0;
    int addedNodes = 0;
    int steinerPoints = 0;
    int faceNodes = 0;
    int touchedTets = 0;  ///< tets examined or changed by the cut
    double maxCutNodeDistance = 0;
    std::array<int, 10> schemeCount{};  ///< indexed by Scheme
    struct {
        double intersect = 0, select = 0, decompose = 0, snap = 0, relax = 0, update = 0, total = 0;
    } timeMs;

    /// Adds another cut's statistics (counts and times summed, the distance maximised), for
    /// totals over several cuts.
    CutStats& operator+=(const CutStats& c);
};

struct CutResult {
    CutStats stats;
    CutChanges changes;
};

class HybridCutter {
public:
    /// Keeps a reference to the mesh; builds the spatial grid and the mean edge length
    /// (the unit of d) once, in O(mesh).
    explicit HybridCutter(TetMesh& mesh);
    /// A cutter for `mesh`, a copy of other's mesh: the same grid and unit of d, so that both
    /// cut identically from here on.
    HybridCutter(const HybridCutter& other, TetMesh& mesh);
    HybridCutter(const HybridCutter&) = delete;
    HybridCutter& operator=(const HybridCutter&) = delete;

    /// Rebuilds the spatial grid after positions changed (e.g. after simulation steps).
    void refreshSpatialIndex();
    double meanEdgeLength() const { return m_meanEdge; }
    /// The spatial grid (a caller that may undo a cut after it succeeded takes a checkpoint).
    TetGrid& grid() { return m_grid; }

    /// Cuts the mesh along the sweep, the steps of section 4.1 in order. On failure, or when
    /// `proceed` cancels before a stage, the mesh and the grid are left exactly as they were
    /// (TetMeshBackup). Cost: in proportion to the tets near the sweep.
    /// Marks: the steps mark nodes and tets in per-index arrays (IndexMarks,
    /// core/mesh/index_marks.h), function-local thread_local in each step. They are scratch of
    /// a step, not state of a mesh or a cutter, so they are kept from cut to cut on a thread
    /// whichever cutter cuts (every copy of a Tissue has a new cutter, and the studies and
    /// benchmarks copy one per cut: a cutter's own marks would cost O(mesh) again), and each use
    /// clears only what it set. A thread's first cut on a mesh larger than any before grows them
    /// in O(mesh); they then hold 13 bytes per tet and 15 per node of the largest mesh cut on
    /// the thread (plus a quarter of headroom) until the thread ends. The steps never nest, and
    /// cuts on other threads have their own marks.
    Status cut(const SweepSurface& sweep, const CutOptions& options, CutResult& result,
               const CutStageCallback& proceed = {});

private:
    TetMesh& m_mesh;
    TetGrid m_grid;
    double m_meanEdge = 0;
};

} // namespace resect
