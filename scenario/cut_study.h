#pragma once
// The comparison of the paper's Table 1 (section 6): the same sweep cut with traditional
// subdivision (Bielser et al. 1999), hybrid with the standard face triangulation and hybrid
// with the enhanced (symmetric) one; element counts, quality ratios and the stable time step
// before and after.

#include "core/cut/hybrid_cutter.h"
#include "core/mesh/material.h"
#include "core/mesh/quality.h"

#include <string>
#include <vector>

namespace resect {

struct StudyColumn {
    std::string name;
    QualitySummary quality;
    double stableDt = 0;
    int pieces = 0;
    CutStats stats;  ///< zero for the original column
};

struct CutStudy {
    std::string title;
    double d = 0.2;
    /// original, subdivision, hybrid standard, hybrid enhanced, enhanced + snapping,
    /// enhanced + snapping + relaxation (10 steps)
    std::vector<StudyColumn> columns;
};

/// A loop electrode pulled straight through the mesh: a U-shaped curve of 16 segments in a
/// vertical plane, its bottom at `heightFraction` of the mesh's height, pulled along y from
/// before the mesh to behind it. The sweep is a curved trough that cuts off the part above
/// it (a polyp's head, a myoma's cap).
SweepSurface loopScoopSweep(const TetMesh& mesh, double heightFraction);

/// Runs the three methods on copies of `mesh` (masses are computed with the material).
Status runCutStudy(const TetMesh& mesh, const SweepSurface& sweep, double d, const Material& material,
                   CutStudy& out);

/// The table as Markdown, rows as in the paper plus pieces and added tets.
std::string formatCutStudy(const CutStudy& study);

} // namespace resect
