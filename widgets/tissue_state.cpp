#include "widgets/tissue_state.h"

#include "core/mesh/stable_time_step.h"
#include "core/mesh/validity.h"

#include <algorithm>
#include <atomic>
#include <limits>

namespace resect {

std::uint64_t newBaseId() {
    static std::atomic<std::uint64_t> next{1};
    return next++;
}

bool sameSweep(const SweepSurface& a, const SweepSurface& b) {
    if (a.vertices().size() != b.vertices().size() || a.triangles() != b.triangles())
        return false;
    for (std::size_t i = 0; i < a.vertices().size(); ++i)
        if (a.vertices()[i] != b.vertices()[i])
            return false;
    return true;
}

bool sameCutOptions(const CutOptions& a, const CutOptions& b) {
    // Every field of CutOptions (core/cut/hybrid_cutter.h); a new field belongs here too.
    return a.method == b.method && a.triangulation == b.triangulation && a.d == b.d &&
           a.faceNodeAdvantage == b.faceNodeAdvantage && a.snap == b.snap &&
           a.snapQualityFloor == b.snapQualityFloor && a.relaxSteps == b.relaxSteps &&
           a.wSpring == b.wSpring && a.wParticle == b.wParticle && a.relaxRings == b.relaxRings &&
           a.relaxDamping == b.relaxDamping && a.density == b.density &&
           a.improve == b.improve && a.improveQuality == b.improveQuality &&
           a.improveShortEdge == b.improveShortEdge && a.improveCoarsen == b.improveCoarsen &&
           a.minEdgeFraction == b.minEdgeFraction;
}

double worstRadiusRatio(const TetMesh& mesh) {
    if (mesh.tetCount() == 0)
        return std::numeric_limits<double>::quiet_NaN();
    double worst = std::numeric_limits<double>::infinity();
    for (int t = 0; t < mesh.tetCount(); ++t) {
        const Tet& q = mesh.tet(t);
        worst = std::min(worst, radiusRatio(mesh.ref(q[0]), mesh.ref(q[1]), mesh.ref(q[2]), mesh.ref(q[3])));
    }
    return worst;
}

int appendedCuts(const AppliedCuts& earlier, const AppliedCuts& later) {
    if (earlier.baseId == 0 || earlier.baseId != later.baseId ||
        earlier.sweeps.size() > later.sweeps.size())
        return -1;
    if (!earlier.sweeps.empty() && !sameCutOptions(earlier.options, later.options))
        return -1;
    for (std::size_t i = 0; i < earlier.sweeps.size(); ++i)
        if (!sameSweep(earlier.sweeps[i], later.sweeps[i]))
            return -1;
    return static_cast<int>(later.sweeps.size() - earlier.sweeps.size());
}

Status TissueState::cut(const SweepSurface& sweep, const CutOptions& options,
                        const CutStageCallback& proceed) {
    if (!applied.sweeps.empty() && !sameCutOptions(applied.options, options))
        return Status::error(
            "the cuts of one tissue state share their options: derive the state from its base "
            "to cut with others");
    TissueCut result;
    if (Status s = tissue.cut(sweep, options, &result, proceed); !s.ok())
        return s;
    applied.options = options;
    applied.sweeps.push_back(sweep);
    cutStats += result.tets;
    surfaceCutMs += result.surfaceMs;
    surfaceCapTriangles += result.surface.surface.capTriangles;
    collapsedEdges += result.collapsedEdges;
    smoothedNodes += result.smoothedNodes;
    removedTets += result.removedTets;
    improveMs += result.improveMs;
    totalMs += result.totalMs;
    worstRatios.push_back(worstRadiusRatio(tissue.mesh()));
    return Status::success();
}

void TissueState::clearCutFigures() {
    cutStats = {};
    surfaceCutMs = 0;
    surfaceCapTriangles = 0;
    collapsedEdges = smoothedNodes = removedTets = 0;
    improveMs = totalMs = 0;
}

void TissueState::settle() {
    tissue.updateSurface();
    const TetMesh& m = tissue.mesh();
    quality = summarizeQuality(m);
    stableDt = tissue.empty() ? 0 : stableTimeStep(m, tissue.material()).dt;
    overlap = tissue.empty() ? 0 : deepestOverlap(m).depth;
    pieces = tissue.empty() ? 0 : tissue.pieces().count + static_cast<int>(tissue.chips().size());
}

} // namespace resect
