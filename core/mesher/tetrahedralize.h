#pragma once
// Anatomy -> coarse tet mesh with CGAL's 3-D mesh generator (Mesh_3). CGAL is confined to
// tetrahedralize.cpp; this interface is plain.

#include "core/mesh/tet_mesh.h"
#include "core/mesh/triangle_surface.h"
#include "core/status.h"

#include <atomic>
#include <functional>

namespace resect {

/// The stages of tetrahedralize(), in order; every attempt runs Refining to CheckingQuality.
enum class MeshingStage { CheckingSurface, Refining, Perturbing, Exuding, MatchingVolume, CheckingQuality };

/// What tetrahedralize() is doing: the stage, the attempt (1-based; a later attempt
/// re-meshes with the next seed because the last one missed the quality bound) and the
/// fraction of the whole work done, 0..1, estimated from the stages' typical share (CGAL's
/// stages report no progress of their own).
struct MeshingProgress {
    MeshingStage stage = MeshingStage::CheckingSurface;
    int attempt = 1;
    int attempts = 1;
    double fraction = 0;
};

struct MeshingOptions {
    /// Target edge length (facet and cell size); 0 chooses defaultEdgeLength().
    double edgeLength = 0;
    /// Maximum distance between the surface and the mesh boundary, as a fraction of
    /// the edge length.
    double facetDistanceFraction = 0.1;
    /// Radius-edge bound for cells (CGAL's cell_radius_edge_ratio).
    double cellRadiusEdgeRatio = 2.5;
    /// Seed of CGAL's random generator, for reproducible meshes. Attempt k (0-based) uses
    /// seed + k.
    unsigned seed = 0;
    /// Protect sharp surface edges (normals differing by more than featureAngleDeg) with
    /// small elements along them: for CAD-like input with real edges. Off by default: on a
    /// scanned surface every crease of the noise would be such an edge, and the protecting
    /// balls along them, not the edge length, would set the element size (CGAL's femur:
    /// 1 634 "sharp" edges, 88 000 slivers instead of 1 000 tets).
    bool protectFeatures = false;
    double featureAngleDeg = 60.0;
    /// Enforced quality: the smallest dihedral angle of every tet, in degrees. A mesh below
    /// it is re-meshed with the next seed, up to `attempts` times; if none reaches it the
    /// result is an error naming the best angle found. 0 accepts any mesh.
    double minDihedralDeg = 10.0;
    int attempts = 4;
    /// Move the boundary nodes off the surface so that the mesh volume equals the
    /// surface's (match_volume.h); otherwise the inscribed boundary loses 3-8 %.
    bool matchVolume = true;
    /// Largest accepted relative difference between the tet mesh volume and the surface's
    /// enclosed volume; a larger one means the edge length is too coarse for the shape
    /// (or a separate part of the surface was missed) and is returned as an error.
    /// Checked after volume matching (which usually leaves none); without matching it is
    /// about 3-8 % at the default edge length (the boundary is inscribed in the surface).
    double maxVolumeError = 0.2;
    /// Number the nodes and tets along a space-filling curve (core/mesh/reorder.h): the
    /// refinement's order is close to random in space, and an explicit step on it is several
    /// times slower.
    bool reorder = true;
    /// Optional: set to true from another thread to cancel; the result is then an error.
    const std::atomic<bool>* cancel = nullptr;
    /// Optional: called (on the meshing thread) as each stage starts.
    std::function<void(const MeshingProgress&)> progress;
};

/// What meshing found and did, for reports.
struct MeshingReport {
    double edgeLength = 0;        ///< the h used
    unsigned seed = 0;            ///< the seed of the accepted attempt
    int attempts = 0;             ///< attempts made (1 if the first one was good; the others
                                  ///< describe the best attempt, the one returned)
    double minDihedralDeg = 0;    ///< smallest dihedral angle of the result
    double surfaceVolume = 0;     ///< enclosed by the surface
    double inscribedVolume = 0;   ///< of the mesh before volume matching
    double volume = 0;            ///< of the result
    double maxBoundaryOffset = 0; ///< largest move of a boundary node by volume matching
    int restrainedNodes = 0;      ///< boundary nodes the quality guard kept from moving fully
    int featureEdges = 0;         ///< surface edges protected as sharp (protectFeatures)
    int collapsedEdges = 0;       ///< edges shorter than h / 4 collapsed after refinement
    double seconds = 0;           ///< wall time of the whole call
    /// Relative difference of the result's volume from the surface's.
    double volumeError() const {
        return surfaceVolume > 0 ? (volume - surfaceVolume) / surfaceVolume : 0.0;
    }
};

/// Edge length giving a coarse mesh of the paper's kind (a few hundred to a few thousand
/// tets) for a surface of this bounding box: cbrt(box volume) / 7.5, at most a 2.5th of
/// the smallest box extent and a 2.25th of the body's mean thickness 3 V / A (about 900
/// tets for each sample, 700-1 100 for the scanned-style corpus).
double defaultEdgeLength(const TriangleSurface& surface);

/// Tetrahedralizes a closed, manifold surface free of self-intersections (see
/// check_surface.h; this function checks again and returns the same errors). Inside and
/// outside are decided by ray parity, so an inside-out surface gives the same mesh. The tets are positively oriented,
/// unused nodes are removed, reference positions equal current positions, masses are 0.
/// Pipeline: CGAL Mesh_3 Delaunay refinement with facet and cell size h, perturbation and
/// exudation (sliver removal), volume matching, and the quality check with retries (see
/// MeshingOptions). Sharp edges are protected only with protectFeatures.
/// Deterministic: the same surface, options and seed give the same mesh.
/// Cancellation is polled during CGAL's refinement and between its stages.
Status tetrahedralize(const TriangleSurface& surface, const MeshingOptions& options,
                      TetMesh& out, MeshingReport* report = nullptr);

} // namespace resect
