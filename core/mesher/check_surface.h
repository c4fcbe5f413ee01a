#pragma once
// Checks that a triangle surface can be tetrahedralized: finite, non-empty, closed,
// manifold, consistently oriented, free of self-intersections.

#include "core/mesh/triangle_surface.h"
#include "core/status.h"

#include <string>

namespace resect {

struct SurfaceCheck {
    int vertices = 0;
    int triangles = 0;
    int nonFiniteVertices = 0;      ///< vertices with a NaN or infinite coordinate
    int badIndexTriangles = 0;      ///< triangles with an out-of-range or repeated index
    int degenerateTriangles = 0;    ///< zero-area triangles (exactly collinear corners)
    int borderEdges = 0;            ///< edges in exactly one triangle (open surface)
    int nonManifoldEdges = 0;       ///< edges in more than two triangles
    int nonManifoldVertices = 0;    ///< vertices whose triangle fan is not one disc
    int orientationErrors = 0;      ///< interior edges traversed twice in the same direction
    bool selfIntersecting = false;  ///< two non-adjacent triangles intersect (exact test)
    double enclosedVolume = 0;      ///< signed, meaningful only if closed and oriented
};

struct SurfaceCheckOptions {
    bool testSelfIntersection = true;  ///< exact CGAL test; O(F log F)
};

SurfaceCheck checkSurface(const TriangleSurface& surface, const SurfaceCheckOptions& options = {});

/// Success if the surface is fit for meshing; else one plain sentence naming the first
/// problem with counts, e.g. "open surface: 12 border edges (try --repair to fill holes)".
/// Problems are reported in this order: no triangles, non-finite vertices, bad indices,
/// non-manifold edges, non-manifold vertices, inconsistent orientation, border edges,
/// zero-area triangles, self-intersection, zero enclosed volume. An inside-out surface
/// (negative enclosed volume) is fit for meshing; orientOutward() turns it around.
Status surfaceProblem(const SurfaceCheck& check);

/// Closes holes (border loops) with CGAL's hole filling (triangulate, refine, fair).
/// Returns how many holes were filled, or an error when a hole cannot be closed.
Status fillHoles(TriangleSurface& surface, int* holesFilled = nullptr);

/// Reverses every triangle if the enclosed volume is negative (inside-out surface).
void orientOutward(TriangleSurface& surface);

} // namespace resect
