// Anatomy -> coarse tet mesh with CGAL's 3-D mesh generator (Mesh_3). All of Mesh_3 lives
// in this translation unit (it takes about 90 s and 3.5 GB to compile at -O2).
//
// Pipeline: checkSurface -> CGAL Surface_mesh -> Polyhedral_mesh_domain_with_features_3
// (sharp edges protected) -> make_mesh_3 (Delaunay refinement) -> perturb_mesh_3 and
// exude_mesh_3 (sliver removal) -> cells of the complex -> TetMesh.

#include "core/mesher/tetrahedralize.h"

#include "core/mesher/check_surface.h"

// Boost.Graph, used by CGAL's feature detection, trips a false positive of GCC's
// -Wmaybe-uninitialized (boost::add_edge); silence only that one, only here.
#if defined(__GNUC__) && !defined(__clang__)
#pragma GCC diagnostic ignored "-Wmaybe-uninitialized"
#endif

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Mesh_complex_3_in_triangulation_3.h>
#include <CGAL/Mesh_criteria_3.h>
#include <CGAL/Mesh_error_code.h>
#include <CGAL/Mesh_triangulation_3.h>
#include <CGAL/Polyhedral_mesh_domain_with_features_3.h>
#include <CGAL/Random.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/exude_mesh_3.h>
#include <CGAL/make_mesh_3.h>
#include <CGAL/perturb_mesh_3.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <exception>
#include <map>
#include <sstream>
#include <string>
#include <vector>

namespace resect {

namespace {

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Point = Kernel::Point_3;
using SurfaceMesh = CGAL::Surface_mesh<Point>;
using Domain = CGAL::Polyhedral_mesh_domain_with_features_3<Kernel, SurfaceMesh>;
using Triangulation = CGAL::Mesh_triangulation_3<Domain, CGAL::Default, CGAL::Sequential_tag>::type;
using C3t3 = CGAL::Mesh_complex_3_in_triangulation_3<Triangulation, Domain::Corner_index,
                                                     Domain::Curve_index>;
using Criteria = CGAL::Mesh_criteria_3<Triangulation>;

/// Surface edges whose two triangles' normals differ by more than this are protected as
/// sharp features (box edges stay sharp; the samples have none at detail 1, where their
/// largest normal difference is about 40 degrees).
constexpr double kFeatureAngleDeg = 60.0;

/// Facet angle bound (degrees) of CGAL's surface criteria; 25 is CGAL's usual choice and
/// below the 30 degrees for which refinement is proven to terminate.
constexpr double kFacetAngleDeg = 25.0;

/// Mean Mesh_3 tet volume over h^3 for cell_size = facet_size = h, measured on the
/// samples, tori and ellipsoids: 0.15 - 0.22. The size guard uses the low end, so its
/// estimate errs towards more tets.
constexpr double kMeanTetVolumePerCubedEdge = 0.15;
/// Largest mesh the size guard lets through (estimated tets).
constexpr double kMaxEstimatedTets = 5.0e6;
/// Hard cap on Mesh_3 vertices (about 6 tets per vertex), behind the estimate.
constexpr std::size_t kMaxVertices = 1'000'000;

/// Random rays shot from the bounding-box centre to find the first surface points. The
/// initial points stay in the mesh, so few is better for quality (CGAL's default is 8);
/// but 8 sometimes misses a torus entirely (no restricted facet, empty mesh). 16 never
/// failed in our tests; an empty result is retried once with kRetryInitialPoints.
constexpr int kInitialPoints = 16;
constexpr int kRetryInitialPoints = 64;

/// Time limits of the optimisation passes (0 would be unlimited). On meshes of the
/// intended size they take 0.01 - 1 s and stop on their own; only if a limit were reached
/// would the result depend on timing and no longer be reproducible from the seed.
constexpr double kPerturbTimeLimitSeconds = 20.0;
constexpr double kExudeTimeLimitSeconds = 20.0;

bool cancelled(const MeshingOptions& o) {
    return o.cancel != nullptr && o.cancel->load(std::memory_order_relaxed);
}

Status cancelledStatus() {
    return Status::error("meshing cancelled");
}

/// Estimated tet count for edge length h: the enclosed volume over the mean tet volume,
/// or, for thin shapes whose volume says little, the number of equilateral facets of edge
/// h covering the surface area A, 4 A / (sqrt(3) h^2) (each is the face of one tet).
double estimatedTets(const TriangleSurface& surface, double h) {
    const double volume = std::abs(enclosedVolume(surface));
    double area = 0.0;
    for (const Tri& t : surface.triangles) {
        const Vec3& a = surface.positions[t[0]];
        area += 0.5 * (surface.positions[t[1]] - a).cross(surface.positions[t[2]] - a).norm();
    }
    const double byVolume = volume / (kMeanTetVolumePerCubedEdge * h * h * h);
    const double byArea = 4.0 * area / (std::sqrt(3.0) * h * h);
    return std::max(byVolume, byArea);
}

/// Builds the CGAL surface mesh. The surface has passed checkSurface (manifold, oriented),
/// so every face is accepted; false otherwise.
bool toSurfaceMesh(const TriangleSurface& s, SurfaceMesh& mesh) {
    std::vector<SurfaceMesh::Vertex_index> v;
    v.reserve(s.positions.size());
    for (const Vec3& p : s.positions)
        v.push_back(mesh.add_vertex(Point(p.x(), p.y(), p.z())));
    for (const Tri& t : s.triangles)
        if (mesh.add_face(v[t[0]], v[t[1]], v[t[2]]) == SurfaceMesh::null_face())
            return false;
    return true;
}

/// The cells of the complex as a TetMesh: used vertices numbered compactly in order of
/// first use (deterministic for a given complex), every tet positively oriented.
TetMesh extractTets(const C3t3& c3t3) {
    const Triangulation& tr = c3t3.triangulation();
    std::map<Triangulation::Vertex_handle, int> index;
    std::vector<Vec3> nodes;
    std::vector<Tet> tets;
    tets.reserve(static_cast<std::size_t>(c3t3.number_of_cells_in_complex()));
    for (auto c = c3t3.cells_in_complex_begin(); c != c3t3.cells_in_complex_end(); ++c) {
        std::array<Point, 4> corner;
        for (int i = 0; i < 4; ++i)
            corner[i] = tr.point(c->vertex(i)).point(); // drop the weight
        // Our convention: det[p1-p0, p2-p0, p3-p0] > 0, which is CGAL's POSITIVE
        // orientation of (p0, p1, p2, p3) (exact predicate). A Delaunay cell is never
        // flat; should one be, it is dropped rather than passed on.
        const CGAL::Orientation o = CGAL::orientation(corner[0], corner[1], corner[2], corner[3]);
        if (o == CGAL::COPLANAR)
            continue;
        std::array<int, 4> order{0, 1, 2, 3};
        if (o == CGAL::NEGATIVE)
            std::swap(order[2], order[3]);
        Tet t{};
        for (int i = 0; i < 4; ++i) {
            const int k = order[i];
            const auto [it, inserted] =
                index.try_emplace(c->vertex(k), static_cast<int>(nodes.size()));
            if (inserted)
                nodes.emplace_back(corner[k].x(), corner[k].y(), corner[k].z());
            t[i] = it->second;
        }
        tets.push_back(t);
    }
    return TetMesh::fromArrays(std::move(nodes), std::move(tets));
}

} // namespace

double defaultEdgeLength(const TriangleSurface& surface) {
    const auto [lo, hi] = boundingBox(surface.positions);
    const Vec3 extent = hi - lo;
    if (!extent.allFinite())
        return 1.0;
    const double longest = extent.maxCoeff();
    if (!(longest > 0.0))
        return 1.0;
    // cbrt(V_box) / 7.5 gives about 900-1300 tets for a sphere-like body (measured: polyp
    // about 900, myoma about 1000) with a volume deficit of about 4 %. Thin shapes are
    // limited to a 2.5th of their smallest extent, so they still get a few layers of
    // tets; flat (degenerate) boxes fall back to the longest extent.
    const double smallest = extent.minCoeff();
    double h = std::cbrt(extent.x() * extent.y() * extent.z()) / 7.5;
    if (smallest > 0.0)
        h = std::min(h, smallest / 2.5);
    if (!(h > 0.0))
        h = longest / 20.0;
    return h;
}

Status tetrahedralize(const TriangleSurface& surface, const MeshingOptions& options, TetMesh& out) {
    out = TetMesh();
    const SurfaceCheck check = checkSurface(surface);
    if (Status problem = surfaceProblem(check); !problem)
        return problem;

    double h = options.edgeLength;
    if (std::isnan(h) || std::isinf(h) || h < 0.0)
        return Status::error("--edge-length must be a positive finite number, got " +
                             formatNumber(h));
    if (h == 0.0)
        h = defaultEdgeLength(surface);
    const double estimate = estimatedTets(surface, h);
    if (!(estimate <= kMaxEstimatedTets))
        return Status::error("--edge-length " + formatNumber(h) +
                             " is too small for this surface: it would give about " +
                             formatNumber(estimate) + " tets (at most " +
                             formatNumber(kMaxEstimatedTets) +
                             " are allowed); the default for this surface is " +
                             formatNumber(defaultEdgeLength(surface)));
    const double distanceFraction = options.facetDistanceFraction;
    if (!std::isfinite(distanceFraction) || distanceFraction <= 0.0)
        return Status::error("facet distance fraction must be a positive finite number, got " +
                             formatNumber(distanceFraction));
    // Mesh_3's refinement is guaranteed to terminate for radius-edge bounds >= 2.
    const double radiusEdge = options.cellRadiusEdgeRatio;
    if (!std::isfinite(radiusEdge) || radiusEdge < 2.0)
        return Status::error("cell radius-edge ratio must be at least 2, got " +
                             formatNumber(radiusEdge));

    if (cancelled(options))
        return cancelledStatus();

    try {
        SurfaceMesh mesh;
        if (!toSurfaceMesh(surface, mesh))
            return Status::error("the surface is not a valid halfedge mesh");

        namespace p = CGAL::parameters;
        const Criteria criteria(p::edge_size = h, p::facet_angle = kFacetAngleDeg,
                                p::facet_size = h, p::facet_distance = distanceFraction * h,
                                p::cell_radius_edge_ratio = radiusEdge, p::cell_size = h);
        // mesh_3_options is undocumented in CGAL 5.5 but present since 4.x. It sets the
        // number of initial points, a hard vertex cap, an error code, and a stop flag that
        // Mesh_3 polls during refinement (so cancellation is honoured mid-run). CGAL only
        // loads the flag, so the const_cast never leads to a write.
        auto* stop = const_cast<std::atomic<bool>*>(options.cancel);

        C3t3 c3t3;
        for (const int initialPoints : {kInitialPoints, kRetryInitialPoints}) {
            // Reproducibility: the domain's initial rays and the refinement and
            // optimisation passes draw from these generators only.
            CGAL::get_default_random() = CGAL::Random(options.seed);
            CGAL::Random domainRandom(options.seed);
            Domain domain(mesh, &domainRandom);
            domain.detect_features(kFeatureAngleDeg);

            CGAL::Mesh_error_code error = CGAL::CGAL_MESH_3_NO_ERROR;
            c3t3 = CGAL::make_mesh_3<C3t3>(
                domain, criteria, p::no_perturb(), p::no_exude(),
                p::mesh_3_options(p::number_of_initial_points = initialPoints,
                                  p::maximal_number_of_vertices = kMaxVertices,
                                  p::pointer_to_error_code = &error,
                                  p::pointer_to_stop_atomic_boolean = stop));
            if (cancelled(options) || error == CGAL::CGAL_MESH_3_STOPPED)
                return cancelledStatus();
            if (error == CGAL::CGAL_MESH_3_MAXIMAL_NUMBER_OF_VERTICES_REACHED)
                return Status::error("--edge-length " + formatNumber(h) +
                                     " is too small for this surface: meshing stopped at " +
                                     std::to_string(kMaxVertices) + " vertices");
            if (c3t3.number_of_cells_in_complex() == 0)
                continue; // no restricted facet found from the initial points: retry

            // Sliver removal: perturbation moves vertices to raise the smallest dihedral
            // angles, exudation re-weights vertices so that slivers flip away (Cheng et
            // al., "Sliver exudation", 2000). Measured on the samples, the minimum radius
            // ratio rises from about 0.01-0.04 to 0.15-0.3 for 0.1-1 s.
            CGAL::perturb_mesh_3(c3t3, domain, p::time_limit = kPerturbTimeLimitSeconds);
            if (cancelled(options))
                return cancelledStatus();
            CGAL::exude_mesh_3(c3t3, p::time_limit = kExudeTimeLimitSeconds);
            if (cancelled(options))
                return cancelledStatus();
            break;
        }

        TetMesh result = extractTets(c3t3);
        if (result.empty())
            return Status::error("meshing produced no tets; --edge-length " + formatNumber(h) +
                                 " is probably too large for this surface");
        // The surface may be inside out (negative volume); the mesh is not.
        const double volume = result.totalReferenceVolume();
        const double surfaceVolume = std::abs(check.enclosedVolume);
        const double relativeError = std::abs(volume - surfaceVolume) / surfaceVolume;
        if (!(relativeError <= options.maxVolumeError))
            return Status::error("the tet mesh volume " + formatNumber(volume) +
                                 " differs from the surface's enclosed volume " +
                                 formatNumber(surfaceVolume) + " by " +
                                 formatNumber(std::round(relativeError * 1000.0) / 10.0) +
                                 " %; try a smaller --edge-length than " + formatNumber(h));
        if (cancelled(options))
            return cancelledStatus();
        out = std::move(result);
        return Status::success();
    } catch (const std::exception& e) {
        return Status::error(std::string("meshing failed: ") + e.what());
    } catch (...) {
        return Status::error("meshing failed: unknown error in CGAL Mesh_3");
    }
}

} // namespace resect
