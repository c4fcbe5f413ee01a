#pragma once
// The embedded high-resolution surface (section 5): every surface vertex is bound to the tet
// that contains it (or the nearest one, for vertices just outside the coarse mesh) with
// barycentric coordinates; applying the binding after the tets move places every vertex.
// A mapper in the sense of STYLE.md: bind() once, apply() every frame, rebind() only what a
// cut touched.

#include "core/cut/cut_types.h"
#include "core/embed/cut_sides.h"
#include "core/embed/flat_marks.h"
#include "core/mesh/renumbering.h"
#include "core/mesh/tet_grid.h"
#include "core/mesh/triangle_surface.h"
#include "core/status.h"
#include "core/sweep/sweep_surface.h"

#include <cstdint>
#include <span>
#include <unordered_map>
#include <vector>

namespace resect {

/// Where bind() stops looking for a vertex's tet. Weights are barycentric (dimensionless; a
/// vertex is inside a tet when its smallest weight is >= 0).
struct BindingTolerances {
    /// A tet whose smallest weight is >= -inside contains the vertex (rounding); in [0, 1e-3].
    double inside = 1e-9;
    /// A vertex slightly outside the coarse mesh (its boundary lies inside the curved
    /// surface) keeps a tet found in its own cell whose smallest weight is >= -nearOutside
    /// (0.25: within about a quarter of the tet); in [inside, 1].
    double nearOutside = 0.25;
    /// The search box grows (doubling, from one grid cell) up to this many cells before all
    /// tets are scanned; in [1, 1024].
    double maxSearchCells = 64;
};

class SurfaceBinding {
public:
    /// Binds every vertex of `surface` (positions in the mesh's current configuration) to a
    /// tet, found through a spatial grid (not a scan of all tets). Fails for an empty mesh,
    /// non-finite positions or tolerances outside their ranges.
    Status bind(const TetMesh& mesh, const TriangleSurface& surface, const BindingTolerances& tolerances = {});

    /// Positions of every vertex from the tets' current positions (out: #V positions), each
    /// w0 p0 + w1 p1 + w2 p2 + w3 p3 evaluated in that order in double precision (bit for bit
    /// what weightsOf() and the tet's nodes give). `render` (optional) receives the same
    /// positions as floats, x y z per vertex (3 #V), ready for a renderer. Streams through
    /// memory in vertex order (the tet index and w1..w3 of each vertex, the positions written
    /// in order; the nodes of consecutive vertices' tets are mostly the same and stay in cache),
    /// on `threads` threads (0: OpenMP's default; fewer for small surfaces, threadsFor). The
    /// result does not depend on the thread count.
    void apply(const TetMesh& mesh, std::vector<Vec3>& out, std::vector<float>* render = nullptr,
               int threads = 0) const;
    /// Bytes apply() streams per vertex (tet index, weights, position written; plus the float
    /// position when rendering), for bandwidth figures.
    static constexpr int kStreamedBytesPerVertex = 4 + 3 * 8 + 3 * 8;
    static constexpr int kRenderBytesPerVertex = 3 * 4;

    /// After a cut: vertices bound to a tet that was decomposed get the piece that contains
    /// them (pieces lie on one side of the cut each, so a vertex off the sweep lands on its own
    /// side); vertices whose tet was only re-attached or had nodes moved get new coordinates.
    /// `positions` are the vertices' current positions (as apply() gave them before the cut).
    /// Costs in proportion to the affected vertices and the tets around the cut.
    /// The vertex and its new tet are on the same side of the sweep (section 5.1).
    /// Returns how many vertices were re-bound.
    int rebind(const TetMesh& mesh, const CutChanges& changes, const std::vector<Vec3>& positions,
               const SweepSurface& sweep);

    /// Binds vertices added by a surface cut (from `first` on): each to the tet containing it
    /// best among the tets near the ones its source edge's ends are bound to, on its own side
    /// of the sweep (`sides`: +1 / -1, 0 for either). Costs in proportion to the new vertices.
    /// `afterRebind`: called right after rebind() with the same mesh, changes and sweep, whose
    /// sides of tets it reuses.
    void bindNewVertices(const TetMesh& mesh, const std::vector<Vec3>& positions, int first,
                         const std::vector<std::array<int, 2>>& sourceEdges, const std::vector<int>& sides,
                         const CutChanges& changes, const SweepSurface& sweep, bool afterRebind = false);

    /// After tets were removed and the rest renumbered: keeps the vertices `kept` (vertex
    /// kept[i] becomes vertex i), their tets mapped through `newTetOf` (old tet -> new tet; every
    /// kept vertex's tet must survive). O(kept vertices + tets).
    /// `rebound` gives new (tet, weights) for kept vertices whose tet did not survive.
    void compact(const std::vector<int>& kept, const std::vector<int>& newTetOf, int tetCount,
                 const std::unordered_map<int, std::pair<int, std::array<double, 4>>>& rebound = {});

    /// After the tets were remeshed locally (core/cut/improve_mesh.h): `vertices` (at their
    /// current `positions`) are bound again to the tet of `candidates[i]` (new indices) that
    /// contains them best; every other vertex keeps its coordinates, its tet renumbered through
    /// `tets` (old -> new; the tets of the other vertices must survive): a tet's vertex list
    /// moves with it. O(vertices + their tets' lists + changed indices), not O(surface).
    void rebindAfterRemesh(const TetMesh& mesh, const std::vector<int>& vertices, const std::vector<Vec3>& positions,
                           const std::vector<std::vector<int>>& candidates, const SparseRenumbering& tets);
    /// The same with a dense renumbering (`newTet`: old -> new for every old tet; empty: none),
    /// converted to the sparse one (O(tets)).
    void rebindAfterRemesh(const TetMesh& mesh, const std::vector<int>& vertices, const std::vector<Vec3>& positions,
                           const std::vector<std::vector<int>>& candidates, const std::vector<int>& newTet);
    /// Vertices bound to tet t.
    const std::vector<int>& verticesOf(int t) const;

    int vertexCount() const { return static_cast<int>(m_tet.size()); }
    int tetOf(int vertex) const { return m_tet[vertex]; }
    /// Barycentric weights w0..w3 (w0 = 1 - w1 - w2 - w3, bit for bit as barycentric() gives it).
    std::array<double, 4> weightsOf(int vertex) const {
        const auto& w = m_weights[vertex];
        return {1.0 - w[0] - w[1] - w[2], w[0], w[1], w[2]};
    }
    /// Vertices bound to a tet they lie outside of (just outside the coarse mesh): count.
    int outsideCount() const { return m_outside; }
    const BindingTolerances& tolerances() const { return m_tolerances; }

    /// What barycentric() computes of a tet before it looks at the point (node a, the edges
    /// from it, (c - a) x (d - a) and six times the signed volume), kept while one call of
    /// rebind() or bindNewVertices() evaluates the tet for many vertices.
    struct TetFrame {
        Vec3 a, ab, ac, ad, acCrossAd;
        double volume6 = 0;
    };

private:
    /// The frame of tet t (computed at its first use in a call; valid until the next frameOf).
    const TetFrame& frameOf(const TetMesh& mesh, int t);
    void forgetFrames();
    /// Binds v to the candidate that contains p best (largest smallest weight; among equals the
    /// first listed); leaves v unchanged if no candidate gives finite weights.
    void bindVertex(const TetMesh& mesh, int v, const Vec3& p, std::span<const int> candidates);
    /// The same over a set: among equals the smallest tet index (as a sorted list would give).
    /// `likely` (members of the set) are tried first, which only saves time.
    void bindVertexInSet(const TetMesh& mesh, int v, const Vec3& p, std::span<const int> candidates,
                         std::span<const int> likely);
    void setWeights(int v, const std::array<double, 4>& w) { m_weights[v] = {w[1], w[2], w[3]}; }
    bool isOutside(int v) const;
    /// Pieces of a changed tet (rebind): the tet itself when modified, then its appended pieces.
    std::span<const int> piecesOf(int t) const;
    void collectPieces(const CutChanges& changes);
    /// rebind(): the tets (of the `oldTets` before the cut) whose vertices get new coordinates.
    void markRecomputeTets(const TetMesh& mesh, const CutChanges& changes, int oldTets);
    /// rebind() of one vertex at p (its position before the cut).
    void rebindVertex(const TetMesh& mesh, int v, const Vec3& p, const SweepSurface& sweep);

    std::vector<int> m_tet;                         ///< #V bound tet
    /// #V barycentric weights w1, w2, w3 (w0 follows, weightsOf): what apply() streams.
    std::vector<std::array<double, 3>> m_weights;
    std::vector<std::vector<int>> m_verticesOfTet;  ///< #tets vertex lists (for rebinding)
    int m_outside = 0;
    BindingTolerances m_tolerances;

    // Scratch of rebind() and bindNewVertices(), kept between cuts (no per-cut allocation).
    CutSides m_sides;
    StampedMarks m_pieceSlot;                         ///< changed tet -> its list in m_pieces
    StampedMarks m_recomputeMark, m_nodeMark;         ///< tets in m_recompute; nodes whose tets are in
    std::vector<std::vector<int>> m_pieces;
    std::vector<int> m_pieceKeys, m_recompute, m_affected, m_kept, m_likely, m_ring;
    std::vector<std::int8_t> m_ringSides;  ///< bindNewVertices: CutSides::tetSide of m_ring
    std::vector<TetFrame> m_frames;                 ///< of the tets evaluated in this call
    StampedMarks m_frameSlot;                         ///< tet -> its frame in m_frames
};

/// Barycentric coordinates (w0..w3, summing to 1) of p in the tet (current positions).
std::array<double, 4> barycentricInTet(const TetMesh& mesh, int tet, const Vec3& p);

} // namespace resect
