#pragma once
// Anatomy -> coarse tet mesh with CGAL's 3-D mesh generator (Mesh_3). CGAL is confined to
// tetrahedralize.cpp; this interface is plain.

#include "core/mesh/tet_mesh.h"
#include "core/mesh/triangle_surface.h"
#include "core/status.h"

#include <atomic>

namespace resect {

struct MeshingOptions {
    /// Target edge length (facet and cell size); 0 chooses defaultEdgeLength().
    double edgeLength = 0;
    /// Maximum distance between the surface and the mesh boundary, as a fraction of
    /// the edge length.
    double facetDistanceFraction = 0.1;
    /// Radius-edge bound for cells (CGAL's cell_radius_edge_ratio).
    double cellRadiusEdgeRatio = 2.5;
    /// Seed of CGAL's random generator, for reproducible meshes.
    unsigned seed = 0;
    /// Optional: set to true from another thread to cancel; the result is then an error.
    const std::atomic<bool>* cancel = nullptr;
};

/// Edge length giving a coarse mesh of the paper's kind (a few hundred to a few thousand
/// tets) for a surface of this bounding box.
double defaultEdgeLength(const TriangleSurface& surface);

/// Tetrahedralizes a closed, manifold, outward-oriented surface (see check_surface.h; this
/// function checks again and returns the same errors). The tets are positively oriented,
/// unused nodes are removed, reference positions equal current positions, masses are 0.
Status tetrahedralize(const TriangleSurface& surface, const MeshingOptions& options,
                      TetMesh& out);

} // namespace resect
