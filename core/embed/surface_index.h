#pragma once
// Where a cut looks for the surface triangles near its sweep (section 5.1, step 1 of
// cut_surface.h) without a pass over the whole surface: the triangles in blocks of consecutive
// indices, each block with the box of the vertex blocks its corners lie in.
//
// Kept current cheaply: a cut appends vertices and triangles and replaces a few; the index
// grows the boxes and the lists of the blocks they touch (in proportion to the cut). When the
// vertices move (EmbeddedSurface::update, every frame of a simulation), positionsChanged() only
// marks the boxes stale; the next query recomputes them in one streaming pass over the
// positions (a min/max per coordinate, no triangle gathers), once for any number of frames.
// (Keeping them current inside SurfaceBinding::apply instead cost about 1 ns per vertex and
// frame, a third of the update: a poor trade for an index read once per cut.)
//
// Queries are exact: a block's box holds every corner of its triangles, and inside the blocks
// whose box meets the query each triangle is tested as cutSurface's candidates are defined.

#include "core/mesh/triangle_surface.h"
#include "core/sweep/sweep_surface.h"

#include <span>
#include <vector>

namespace resect {

class SurfaceIndex {
public:
    static constexpr int kVertexBlock = 64;    ///< consecutive vertices per box
    static constexpr int kTriangleBlock = 64;  ///< consecutive triangles per block

    /// Builds the blocks of `surface`. O(surface).
    void build(const TriangleSurface& surface);
    bool empty() const { return m_vertexBoxes.empty() && m_refs.empty(); }
    /// The vertices moved: the boxes are recomputed at the next query. O(1).
    void positionsChanged() { m_stale = true; }

    /// Triangles whose three corners are not all strictly beyond one face of `box` (exact
    /// comparisons; the definition of cutSurface's candidates), in ascending order (appended to
    /// out, cleared first). O(blocks + triangles in blocks meeting the box), plus one pass over
    /// the positions when they moved since the last query.
    void candidates(const TriangleSurface& surface, const Box3& box, std::vector<int>& out);

    /// After a cut of `surface` that appended the vertices from `firstNewVertex` and the
    /// triangles from `firstNewTriangle` on and replaced the triangles `replaced` (their new
    /// corners): grows the boxes and block lists they touch. O(what the cut added).
    void followCut(const TriangleSurface& surface, int firstNewVertex, int firstNewTriangle,
                   std::span<const int> replaced);

private:
    void refit(const TriangleSurface& surface);
    void addTriangle(const TriangleSurface& surface, int t);
    void growVertexBox(const Vec3& p, int block);
    Box3 triangleBlockBox(int block) const;

    std::vector<Box3> m_vertexBoxes;         ///< per vertex block
    std::vector<std::vector<int>> m_refs;    ///< per triangle block: the vertex blocks of its corners
    int m_vertices = 0;                      ///< vertices covered by the boxes
    bool m_stale = true;                     ///< the boxes predate the positions
};

} // namespace resect
