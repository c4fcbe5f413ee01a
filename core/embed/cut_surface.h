#pragma once
// Cutting the embedded high-resolution surface (section 5.1) and closing it with new faces
// (section 5.2).
//
// Surface edges crossed by the sweep (exact test, in the deformed configuration) are split at
// the crossing; texture coordinates and reference positions are interpolated with the crossing
// parameter. A triangle with two split edges is cut into three triangles; the split points are
// duplicated, one copy per side. A triangle with one split edge (the sweep's border passes
// through it: a partial cut) is cut into two triangles and its split point is shared by both
// sides: it is a "face vertex" of the paper. Surface vertices are never moved.
//
// The cut boundary is then traced (several loops for concave models), mapped to the sweep's
// (u, v) plane and triangulated there with CGAL's constrained Delaunay triangulation; a loop
// through two face vertices is closed by the chord between them (the paper's jump from one
// face vertex to the other). One side's caps are triangulated and the other side gets the same
// triangles, reversed, on its own copies: both pieces are closed and their volumes add up to the
// original exactly (to rounding).

#include "core/mesh/triangle_surface.h"
#include "core/status.h"
#include "core/sweep/sweep_surface.h"

#include <vector>

namespace resect {

struct SurfaceCut {
    int splitEdges = 0;      ///< surface edges split
    int faceVertices = 0;    ///< shared split points (partial cuts)
    int loops = 0;           ///< cut-boundary loops traced
    int capTriangles = 0;    ///< new triangles closing the cut, both sides together
    int firstNewVertex = 0;  ///< vertices from here on were created by the cut
    int candidateTriangles = 0;  ///< triangles near the sweep whose edges were tested
    std::vector<Vec2> sweepUv;  ///< (u, v) on the sweep of every new vertex
    std::vector<std::array<int, 2>> sourceEdge;  ///< surface edge each new vertex was split from
    std::vector<int> side;      ///< side of the sweep of each new vertex (+1, -1; 0 if shared)
};

/// Cuts a closed, manifold, outward-oriented surface along the sweep, in place: crossed
/// triangles are replaced and new vertices and triangles appended (triangles the cut does not
/// touch keep their index). `rest` (optional) holds one reference position per vertex and is
/// extended like the positions; `surface.cutUvs` and `surface.cutFaces` are filled. Cost:
/// one bounding-box pass over the index array, then in proportion to the triangles near the
/// sweep (plus one pass over the triangles when cut loops overlap in (u, v), to tell pieces
/// apart). On error nothing is changed. A surface the sweep misses is left unchanged
/// (success, zero counts).
Status cutSurface(TriangleSurface& surface, std::vector<Vec3>* rest, const SweepSurface& sweep, SurfaceCut& out);

} // namespace resect
