#pragma once
// TissueState: one published state of the studio's tissue (TissueSession's base and current,
// CutPreview's preview), never modified once published and shared by the views.
//
// It holds the Tissue (core/tissue/tissue.h: the tet mesh, its spatial index, the embedded
// surface, anchors, schemes and pieces), the cuts applied to it since its base (AppliedCuts:
// what the SimulationController compares to follow new cuts locally instead of rebuilding)
// and the measures the panels show. A state is derived by copying another (the copy keeps
// the spatial index and the unit of d, so it cuts exactly as the original would) and cutting
// the copy through TissueState::cut, which is Tissue::cut plus the bookkeeping of this record.

#include "core/cut/hybrid_cutter.h"
#include "core/mesh/quality.h"
#include "core/sweep/sweep_surface.h"
#include "core/tissue/tissue.h"

#include <QString>

#include <cstdint>
#include <vector>

namespace resect {

/// What was cut into a tissue since its base: the base (an id given when it was loaded), the
/// sweeps in the order they were applied and the options they were cut with.
struct AppliedCuts {
    std::uint64_t baseId = 0;
    std::vector<SweepSurface> sweeps;
    CutOptions options;
};

/// A new id for a freshly loaded base (never 0; unique within the process).
std::uint64_t newBaseId();

/// True if the two sweeps are the same surface: vertices and triangles exactly equal.
bool sameSweep(const SweepSurface& a, const SweepSurface& b);
/// True if every field of the two options is equal (exact comparison).
bool sameCutOptions(const CutOptions& a, const CutOptions& b);

/// How many cuts `later` adds to `earlier`: if both come from the same base and `later`'s
/// sweeps are `earlier`'s followed by more, cut with the same options (when `earlier` has
/// cuts at all), the number of sweeps added (0: the same cuts); else -1 (a cut was removed
/// or changed, the options changed under existing cuts, or another base).
int appendedCuts(const AppliedCuts& earlier, const AppliedCuts& later);

/// The smallest radius ratio over the mesh's tets in the reference configuration (as
/// summarizeQuality's minRadiusRatio, in one pass without the other measures); NaN for a
/// mesh without tets.
double worstRadiusRatio(const TetMesh& mesh);

/// One state of the tissue. Copy it to derive another (explicitly: the Tissue copies deeply).
struct TissueState {
    Tissue tissue;       ///< mesh, spatial index, surface (following the tets), schemes
    AppliedCuts applied; ///< what was cut into `tissue` since the base
    /// What reading the tissue's tet mesh dropped or noticed (MeshReadReport::summary), empty
    /// if nothing: the studio tells the author once the tissue is shown.
    QString readNote;
    QualitySummary quality;
    double stableDt = 0;         ///< s, stableTimeStep of the mass-spring model
    /// How deep the tet mesh overlaps itself (deepestOverlap, core/mesh/validity.h; reference
    /// configuration, model units): 0 unless the improvement pushed one wall of a crack into
    /// the other (issue 16's known defect).
    double overlap = 0;
    int pieces = 0;              ///< pieces cut: the tissue's connected components and its resected chips
    CutStats cutStats;           ///< summed over the cuts since base (a preview: the pending cut)
    double surfaceCutMs = 0;     ///< embedded-surface update, cut and re-binding, summed likewise
    int surfaceCapTriangles = 0; ///< cap triangles those cuts added to the surface
    /// The mesh improvement after those cuts (TissueCut, step 7 of Tissue::cut), summed likewise:
    /// edges collapsed, nodes smoothed, tets the collapses removed, and its time.
    int collapsedEdges = 0, smoothedNodes = 0, removedTets = 0;
    double improveMs = 0;
    double totalMs = 0;          ///< whole cuts, every stage (TissueCut::totalMs), summed likewise
    /// The smallest radius ratio (3 r_in / R_circ, reference configuration) of the tet mesh
    /// after each cut since base, in order (not cleared by clearCutFigures: a preview's ends
    /// with its pending cut). With tissue.inputWorstRatio(), the curve of the quality dock.
    std::vector<double> worstRatios;
    /// The tets with the smallest own stable time step (tetStableTimeSteps,
    /// core/mesh/stable_time_step.h: the ones that limit stableDt), worst first, at most a few;
    /// filled only for a preview that warns (CutPreview::warnings), else empty.
    std::vector<int> stepLimitingTets;
    QString tissueName;

    const TetMesh& mesh() const { return tissue.mesh(); }
    const EmbeddedSurface& surface() const { return tissue.surface(); }
    /// Cuts applied since the base.
    int cuts() const { return static_cast<int>(applied.sweeps.size()); }

    /// Cuts the tissue along `sweep` (Tissue::cut) and records the sweep and its figures. On
    /// failure (or cancellation through `proceed`) the state is unchanged. The cuts of one
    /// state share their options: other options than the recorded ones are refused.
    Status cut(const SweepSurface& sweep, const CutOptions& options,
               const CutStageCallback& proceed = {});
    /// Zeroes the figures of the cuts (cutStats, the surface's and the improvement's counts and
    /// times), e.g. for a preview that reports its pending cut alone.
    void clearCutFigures();
    /// Before publishing: the surface follows the tets (Tissue::updateSurface) and the measures
    /// (quality, stable time step, pieces) are taken.
    void settle();
};

} // namespace resect
