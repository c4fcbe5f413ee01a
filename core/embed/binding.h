#pragma once
// The embedded high-resolution surface (section 5): every surface vertex is bound to the tet
// that contains it (or the nearest one, for vertices just outside the coarse mesh) with
// barycentric coordinates; applying the binding after the tets move places every vertex.
// A mapper in the sense of STYLE.md: bind() once, apply() every frame, rebind() only what a
// cut touched.

#include "core/cut/cut_types.h"
#include "core/mesh/tet_grid.h"
#include "core/mesh/triangle_surface.h"
#include "core/status.h"
#include "core/sweep/sweep_surface.h"

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

    /// Positions of every vertex from the tets' current positions (out: #V positions).
    /// Streams through memory: vertices are processed in tet order.
    void apply(const TetMesh& mesh, std::vector<Vec3>& out) const;

    /// After a cut: vertices bound to a tet that was decomposed get the piece that contains
    /// them (pieces lie on one side of the cut each, so a vertex off the sweep lands on its own
    /// side); vertices whose tet was only re-attached or had nodes moved get new coordinates.
    /// `positions` are the vertices' current positions (as apply() gave them before the cut).
    /// Costs in proportion to the affected vertices; the streaming order is refreshed by bind().
    /// The vertex and its new tet are on the same side of the sweep (section 5.1).
    /// Returns how many vertices were re-bound.
    int rebind(const TetMesh& mesh, const CutChanges& changes, const std::vector<Vec3>& positions,
               const SweepSurface& sweep);

    /// Binds vertices added by a surface cut (from `first` on): each to the tet containing it
    /// best among the tets near the ones its source edge's ends are bound to, on its own side
    /// of the sweep (`sides`: +1 / -1, 0 for either). Costs in proportion to the new vertices.
    void bindNewVertices(const TetMesh& mesh, const std::vector<Vec3>& positions, int first,
                         const std::vector<std::array<int, 2>>& sourceEdges, const std::vector<int>& sides,
                         const CutChanges& changes, const SweepSurface& sweep);

    /// After tets were removed and the rest renumbered: keeps the vertices `kept` (vertex
    /// kept[i] becomes vertex i), their tets mapped through `newTetOf` (old tet -> new tet; every
    /// kept vertex's tet must survive). O(kept vertices + tets).
    /// `rebound` gives new (tet, weights) for kept vertices whose tet did not survive.
    void compact(const std::vector<int>& kept, const std::vector<int>& newTetOf, int tetCount,
                 const std::unordered_map<int, std::pair<int, std::array<double, 4>>>& rebound = {});

    /// After the tets were remeshed locally (core/cut/improve_mesh.h): `vertices` (at their
    /// current `positions`) are bound again to the tet of `candidates[i]` that contains them best;
    /// every other vertex keeps its coordinates, its tet renumbered through `newTet` (old -> new;
    /// empty: no renumbering; the tets of the other vertices must survive). O(vertices) without a
    /// renumbering, O(surface) with one.
    void rebindAfterRemesh(const TetMesh& mesh, const std::vector<int>& vertices, const std::vector<Vec3>& positions,
                           const std::vector<std::vector<int>>& candidates, const std::vector<int>& newTet);
    /// Vertices bound to tet t.
    const std::vector<int>& verticesOf(int t) const;

    int vertexCount() const { return static_cast<int>(m_tet.size()); }
    int tetOf(int vertex) const { return m_tet[vertex]; }
    const std::array<double, 4>& weightsOf(int vertex) const { return m_weights[vertex]; }
    /// Vertices bound to a tet they lie outside of (just outside the coarse mesh): count.
    int outsideCount() const { return m_outside; }
    const BindingTolerances& tolerances() const { return m_tolerances; }

private:
    void bindVertex(const TetMesh& mesh, int v, const Vec3& p, const std::vector<int>& candidates);
    void sortByTet();

    std::vector<int> m_tet;                         ///< #V bound tet
    std::vector<std::array<double, 4>> m_weights;   ///< #V barycentric weights
    std::vector<int> m_order;                       ///< vertices sorted by their tet
    std::vector<std::vector<int>> m_verticesOfTet;  ///< #tets vertex lists (for rebinding)
    int m_outside = 0;
    BindingTolerances m_tolerances;
};

/// Barycentric coordinates (w0..w3, summing to 1) of p in the tet (current positions).
std::array<double, 4> barycentricInTet(const TetMesh& mesh, int tet, const Vec3& p);

} // namespace resect
