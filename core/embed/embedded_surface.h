#pragma once
// The embedded high-resolution surface as one object (section 5): the surface, its binding to
// the tets and the cut that keeps both in step. Tissue (core/tissue/tissue.h) owns one and
// sequences it with the tet cut: update() whenever the tets moved, cut() right after each tet
// cut, with the cut's change list.
//
// cut() cuts the surface along the sweep and closes it (cutSurface, finding the triangles near
// the sweep through a SurfaceIndex), re-binds the vertices the tet cut touched
// (SurfaceBinding::rebind), and binds the new vertices on their side
// (SurfaceBinding::bindNewVertices).

#include "core/embed/binding.h"
#include "core/embed/cut_surface.h"
#include "core/embed/surface_index.h"
#include "core/mesh/renumbering.h"

namespace resect {

/// What EmbeddedSurface::cut did, with the time of each stage.
struct EmbeddedCut {
    SurfaceCut surface;      ///< the surface cut (section 5.1, 5.2)
    int reboundVertices = 0; ///< vertices re-bound because the tet cut touched their tet
    double rebindMs = 0, cutMs = 0, bindNewMs = 0;
};

class EmbeddedSurface {
public:
    /// Binds `surface` (positions in the mesh's current configuration). On error the object
    /// is left empty.
    Status bind(const TetMesh& mesh, TriangleSurface surface);

    /// Moves every vertex with the tets (SurfaceBinding::apply, on `threads` threads, 0: OpenMP's
    /// default), and refreshes renderPositions() when it is kept.
    void update(const TetMesh& mesh, int threads = 0);
    /// Keep a float copy of the positions (x y z per vertex) that update() writes in the same
    /// pass, for a renderer (off by default: 12 more bytes per vertex and update).
    void keepRenderPositions(bool keep);
    /// The positions as floats, as of the last update() (empty unless kept).
    const std::vector<float>& renderPositions() const { return m_render; }

    /// After a tet cut (see above). The surface's positions must be those update() gave
    /// before the tet cut. On error the surface and its binding are unchanged.
    Status cut(const TetMesh& mesh, const CutChanges& changes, const SweepSurface& sweep, EmbeddedCut* stats = nullptr);

    /// After a resection (core/tissue/resect_pieces.h): splits off the surface of every piece
    /// that left the tissue. `pieceOfTet` (old tet -> -1 if kept, else the index of its resected
    /// piece) decides where each connected part of the surface goes (the piece most of its
    /// vertices are bound to); `newTetOf` renumbers the kept tets. Returns one surface per
    /// resected piece (`pieces` of them; positions as they are). O(surface).
    /// `mesh` is the tissue's mesh after the resection (a kept vertex bound to a removed tet, on
    /// a part split by rounding, is bound to the nearest kept tet).
    std::vector<TriangleSurface> splitOff(const std::vector<int>& pieceOfTet, int pieces,
                                          const std::vector<int>& newTetOf, const TetMesh& mesh);

    /// Around a local remeshing of the tets (core/cut/improve_mesh.h): recordAround() notes the
    /// vertices bound to the tets that may change, with their current positions and their tets'
    /// nodes; followRemesh() binds them again among the tets of those nodes afterwards (mapped
    /// through renumbering.nodes; a removed node adds none), and renumbers the other vertices'
    /// tets through renumbering.tets (a tet's vertex list moves with it). In proportion to the
    /// recorded vertices, their candidate tets and the changed indices, not to the surface.
    struct RemeshRecord {
        std::vector<int> vertices;
        std::vector<Vec3> positions;
        std::vector<Tet> nodes;
    };
    RemeshRecord recordAround(const TetMesh& mesh, const std::vector<int>& tets) const;
    void followRemesh(const TetMesh& mesh, const RemeshRecord& record, const MeshRenumbering& renumbering);
    /// The same with dense renumberings (old -> new for every old tet and node; empty: none; a
    /// collapsed node maps to the node it merged into, whose tets are then candidates too), as
    /// ImproveResult gives them. O(tets) for the conversion.
    void followRemesh(const TetMesh& mesh, const RemeshRecord& record, const std::vector<int>& newTet,
                      const std::vector<int>& newNode);

    bool empty() const { return m_surface.triangles.empty(); }
    const TriangleSurface& surface() const { return m_surface; }
    const SurfaceBinding& binding() const { return m_binding; }

private:
    TriangleSurface m_surface;
    SurfaceBinding m_binding;
    SurfaceIndex m_index;              ///< where cuts find the triangles near their sweep
    SurfaceCutWorkspace m_workspace;   ///< the surface cut's scratch, kept between cuts
    bool m_keepRender = false;
    std::vector<float> m_render;  ///< 3 #V, when kept
};

} // namespace resect
