#pragma once
// Triangulation of a cut face in the sweep's parameter plane (section 5.2, Figure 6): the
// region bounded by the cut's boundary loops in (u, v) is triangulated with CGAL's constrained
// Delaunay triangulation, using the loops' points only. CGAL stays in the .cpp.
//
// Loops may touch and share points: a vertex of one loop may have the same (u, v) as a vertex
// of another (the two lips of an earlier partial cut, or a cut through an earlier cut vertex),
// and two loops may run along the same segment in opposite directions. Such coincident points
// are one vertex of the triangulation; each triangle corner is given back as the loop vertex of
// the boundary sector the triangle lies in (turning around the point until a loop edge is met),
// so the lips stay apart. Where the (u, v) image is degenerate (loop edges crossing by rounding,
// a point on another loop's edge, all points on a line, a triangulation that does not bound
// every loop edge exactly once), each loop is closed on its own by ear clipping instead: always
// closed and manifold, only less well shaped.

#include "core/status.h"
#include "core/sweep/sweep_surface.h"

#include <array>
#include <vector>

namespace resect {

/// `loops`: closed polygons as indices into `points` (#P (u, v) points). The region is where
/// the loops' winding number has the sign of `side` (+1: the region lies left of every loop
/// edge, so outer loops run counter-clockwise and holes clockwise; -1: the mirror image). Returns
/// triangles, counter-clockwise in (u, v), whose corners are indices into `points` (see above).
/// Fails only for a loop point that is not finite.
Status triangulateCap(const std::vector<Vec2>& points, const std::vector<std::vector<int>>& loops, int side,
                      std::vector<std::array<int, 3>>& triangles);

} // namespace resect
