#pragma once
// Triangulation of new cut faces in the sweep's parameter plane (section 5.2, Figure 6):
// closed polygons in (u, v) are triangulated with CGAL's constrained Delaunay triangulation;
// nested polygons make holes (inside = odd nesting depth). CGAL stays in the .cpp.

#include "core/status.h"
#include "core/sweep/sweep_surface.h"

#include <vector>

namespace resect {

/// `loops`: closed polygons as indices into `points` (#P (u, v) points). Returns triangles
/// (indices into `points`) covering the region inside an odd number of loops, counter-
/// clockwise in (u, v). No points are added (no refinement).
Status triangulateInPlane(const std::vector<Vec2>& points, const std::vector<std::vector<int>>& loops,
                          std::vector<std::array<int, 3>>& triangles);

} // namespace resect
