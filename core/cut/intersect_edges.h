#pragma once
// Step 2 of the cut (section 4.3): the mesh edges crossed by the sweep surface, decided
// with exact predicates in the deformed configuration. An edge crossed more than once (a
// curved sweep) is discarded, as the paper says. Candidate tets come from a spatial grid,
// so the cost grows with the sweep's area, not with the mesh size.

#include "core/cut/cut_types.h"
#include "core/mesh/tet_grid.h"
#include "core/sweep/sweep_surface.h"

namespace resect {

/// `grid` must have been built on the mesh's current positions (or be empty: then every
/// tet is examined).
IntersectedEdges intersectEdges(const TetMesh& mesh, const TetGrid& grid,
                                const SweepSurface& sweep);

} // namespace resect
