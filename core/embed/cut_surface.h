#pragma once
// Cutting the embedded high-resolution surface (section 5.1) and closing it with new faces
// (section 5.2), robustly enough for a whole resection: any sequence of cuts, crossing earlier
// cut faces and caps, through earlier cut vertices, partial or complete. The steps
// (SurfaceCutter in the .cpp):
//  1. candidates: triangles whose corners are not all beyond one face of the sweep's box;
//  2. edge splits: every crossing of a candidate edge with the sweep (exact predicates; all of
//     them, so an edge a curved sweep crosses twice is split twice); a crossing within rounding
//     of a vertex puts the cut through the vertex instead;
//  3. triangle splits: inside each crossed triangle the cut is traced across the sweep's
//     triangles (the points where sweep edges pierce it are added), so the cut's image in the
//     sweep's (u, v) plane is exact; the triangle is split into the pieces the cut bounds (ear
//     clipping in its plane, without edges between two points of the cut, which the cap could
//     also make, nor along one of its edges, which the triangle across could also make; where
//     the first cannot be avoided, such edges are split at their middle), each piece with its
//     side of the sweep;
//  4. separation: every vertex on the cut gets one copy per group of its triangles connected
//     through edges not on the cut (as the tets' separate step): two across a complete cut,
//     one at the end of a partial cut (the paper's face vertices);
//  5. boundary: the cut's boundary loops;
//  6. caps: per piece, the + side's loops (and the lips of partial cuts, joined along the
//     sweep's border) are triangulated in (u, v) (triangulate_cut.h); the - side gets the same
//     triangles reversed on its copies, so both pieces are closed and their volumes add up to
//     the original exactly (to rounding). Where that mirror is impossible (a cut passing twice
//     through one vertex), each side is triangulated on its own. A cap edge the surface has
//     too is flipped away, or split by a new cap vertex; a chord between lips that lies on a
//     surface edge splits that edge.
// Surface vertices are never moved.

#include "core/mesh/triangle_surface.h"
#include "core/status.h"
#include "core/sweep/sweep_surface.h"

#include <memory>
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

class SurfaceIndex;  // core/embed/surface_index.h

/// Reusable scratch of cutSurface: marks per vertex and triangle and edge tables, cleared per
/// cut in O(1), so that a cut allocates nothing in proportion to the surface. Scratch, not
/// state: a copy starts empty.
class SurfaceCutWorkspace {
public:
    SurfaceCutWorkspace();
    ~SurfaceCutWorkspace();
    SurfaceCutWorkspace(const SurfaceCutWorkspace&);
    SurfaceCutWorkspace& operator=(const SurfaceCutWorkspace&);
    struct Tables;
    Tables& tables() { return *m_tables; }

private:
    std::unique_ptr<Tables> m_tables;
};

/// Cuts a closed, manifold, outward-oriented surface along the sweep, in place: crossed
/// triangles are replaced and new vertices and triangles appended (triangles the cut does not
/// touch keep their index). `rest` (optional) holds one reference position per vertex and is
/// extended like the positions; `surface.cutUvs` and `surface.cutFaces` are filled. Cost: in
/// proportion to the triangles near the sweep when `index` (built for this surface, see
/// surface_index.h; kept current here) is given, else after one bounding-box pass over the
/// index array; plus one pass over the triangles when several cut loops on one side need to be
/// told apart by piece. `workspace` (optional) keeps the scratch tables between cuts. On error
/// nothing is changed. A surface the sweep misses is left unchanged (success, zero counts).
Status cutSurface(TriangleSurface& surface, std::vector<Vec3>* rest, const SweepSurface& sweep, SurfaceCut& out,
                  SurfaceIndex* index = nullptr, SurfaceCutWorkspace* workspace = nullptr);

} // namespace resect
