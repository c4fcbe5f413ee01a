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
    /// Largest accepted relative difference between the tet mesh volume and the surface's
    /// enclosed volume; a larger one means the edge length is too coarse for the shape
    /// (or a separate part of the surface was missed) and is returned as an error.
    /// At the default edge length the difference is about 3-5 % (the mesh boundary is
    /// inscribed in the smooth surface).
    double maxVolumeError = 0.2;
    /// Optional: set to true from another thread to cancel; the result is then an error.
    const std::atomic<bool>* cancel = nullptr;
};

/// Edge length giving a coarse mesh of the paper's kind (a few hundred to a few thousand
/// tets) for a surface of this bounding box: cbrt(box volume) / 7.5, at most a 2.5th of
/// the smallest box extent (about 900 tets for each sample).
double defaultEdgeLength(const TriangleSurface& surface);

/// Tetrahedralizes a closed, manifold surface free of self-intersections (see
/// check_surface.h; this function checks again and returns the same errors). Inside and
/// outside are decided by ray parity, so an inside-out surface gives the same mesh. The tets are positively oriented,
/// unused nodes are removed, reference positions equal current positions, masses are 0.
/// Sharp surface edges (normals differing by more than 60 degrees) are preserved.
/// Deterministic: the same surface, options and seed give the same mesh.
/// Cancellation is polled during CGAL's refinement and between its stages.
Status tetrahedralize(const TriangleSurface& surface, const MeshingOptions& options,
                      TetMesh& out);

} // namespace resect
