// Anatomy -> coarse tet mesh with CGAL's 3-D mesh generator (Mesh_3). All of Mesh_3 lives
// in this translation unit (it takes about 90 s and 3.5 GB to compile at -O2).
//
// Pipeline: checkSurface -> CGAL Surface_mesh -> Polyhedral_mesh_domain_with_features_3
// (sharp edges protected only when asked) -> make_mesh_3 (Delaunay refinement) ->
// perturb_mesh_3 and exude_mesh_3 (sliver removal) -> cells of the complex -> TetMesh ->
// volume matching (match_volume.h) -> quality check, re-meshed with the next seed if low.

#include "core/mesher/tetrahedralize.h"

#include "core/mesh/reorder.h"

#include "core/cut/improve_mesh.h"
#include "core/mesh/quality.h"
#include "core/mesher/check_surface.h"
#include "core/mesher/match_volume.h"

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
#include <chrono>
#include <cmath>
#include <iterator>
#include <numbers>
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

/// Largest accepted --min-dihedral: a regular tet's dihedral angle is 70.5 degrees, and
/// no mesher gets anywhere near that bound everywhere.
constexpr double kMaxMinDihedralDeg = 35.0;

/// Volume matching may lower a tet's smallest dihedral angle only down to the enforced
/// bound plus this margin (so that it does not spend the quality the perturbation won:
/// without the margin the femur's worst angle fell from 12.0 to 10.9 degrees).
constexpr double kVolumeMatchMarginDeg = 2.0;

/// Edges shorter than this fraction of h are collapsed after refinement. Mesh_3 without
/// feature protection refines a sharp crease of the surface into a cluster of tiny (well
/// shaped) tets: on the corpus femur, edges of 1 % of h, a stable explicit step 30 times
/// shorter, and an edge length that no longer sets the size.
constexpr double kShortEdgeFraction = 0.25;

/// Collapses the edges shorter than kShortEdgeFraction h (improve_mesh.h: the boundary
/// stays on the surface and the volume is kept exactly; no tet falls below
/// min(kCollapseRatioFloor, its radius ratio before)). Returns the edges collapsed.
constexpr double kCollapseRatioFloor = 0.15;
/// The collapses are kept if the worst dihedral angle stays this far above the bound (or
/// does not get worse).
constexpr double kCollapseMarginDeg = 0.5;
int collapseShortEdges(TetMesh& mesh, double h) {
    const double shortEdge = kShortEdgeFraction * h;
    std::vector<int> seeds;
    for (int t = 0; t < mesh.tetCount(); ++t) {
        const Tet& k = mesh.tet(t);
        for (int i = 0; i < 4; ++i)
            for (int j = i + 1; j < 4; ++j)
                if ((mesh.ref(k[i]) - mesh.ref(k[j])).norm() < shortEdge) {
                    seeds.push_back(k[i]);
                    seeds.push_back(k[j]);
                }
    }
    if (seeds.empty())
        return 0;
    std::sort(seeds.begin(), seeds.end());
    seeds.erase(std::unique(seeds.begin(), seeds.end()), seeds.end());
    ImproveOptions o;
    o.shortEdge = shortEdge;
    o.badRatio = kCollapseRatioFloor;
    o.rings = 2;
    o.sweeps = 4;
    o.offSurface = false;
    const ImproveRegion region = improveRegion(mesh, seeds, {}, o.rings);
    const ImproveResult r = improveMesh(mesh, region, o);
    for (double& m : mesh.masses())
        m = 0.0; // the pass set masses of what it touched; the mesher's contract is 0
    return r.collapses;
}

/// See defaultEdgeLength.
constexpr double kEdgesPerThickness = 2.25;
constexpr double kMaxThicknessRefinement = 1.5;

/// Smallest dihedral angle over the mesh, in degrees.
double minDihedralDegrees(const TetMesh& mesh) {
    double worst = 180.0;
    for (int t = 0; t < mesh.tetCount(); ++t) {
        const Tet& k = mesh.tet(t);
        worst = std::min(worst, tetQuality(mesh.ref(k[0]), mesh.ref(k[1]), mesh.ref(k[2]), mesh.ref(k[3])).minDihedral);
    }
    return worst * 180.0 / std::numbers::pi;
}

/// Surface edges whose two triangles' normals differ by more than angleDeg (what CGAL's
/// detect_features marks as sharp).
int countSharpEdges(const TriangleSurface& s, double angleDeg) {
    std::map<std::pair<int, int>, Vec3> firstNormal;
    const double cosLimit = std::cos(angleDeg * std::numbers::pi / 180.0);
    int sharp = 0;
    for (const Tri& t : s.triangles) {
        const Vec3& a = s.positions[t[0]];
        const Vec3 n = (s.positions[t[1]] - a).cross(s.positions[t[2]] - a).normalized();
        for (int i = 0; i < 3; ++i) {
            const int u = t[i], v = t[(i + 1) % 3];
            const auto key = std::minmax(u, v);
            const auto [it, inserted] = firstNormal.try_emplace({key.first, key.second}, n);
            if (!inserted && it->second.dot(n) < cosLimit)
                ++sharp;
        }
    }
    return sharp;
}

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
    const double area = surfaceArea(surface);
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
    // A body thin for its box (a bent shaft, a stalk) gets at least about three edges
    // across: its mean thickness 3 V / A (a sphere's radius; 0.75 of a cylinder's
    // diameter) spans kEdgesPerThickness edges. Coarser, its mesh is all boundary, and
    // half the edge length gives only 3-4 times the tets (the corpus femur). The samples
    // have 2.4 (polyp) and 3.7 (myoma) edges in theirs, so the cap leaves them alone.
    const double area = surfaceArea(surface);
    const double thickness = 3.0 * std::abs(enclosedVolume(surface)) / area;
    // At most kMaxThicknessRefinement times finer than the box alone says: a thin-walled
    // part (CGAL's cheese.off) would otherwise get tens of thousands of tets.
    if (std::isfinite(thickness) && thickness > 0.0)
        h = std::max(std::min(h, thickness / kEdgesPerThickness), h / kMaxThicknessRefinement);
    if (!(h > 0.0))
        h = longest / 20.0;
    return h;
}

Status tetrahedralize(const TriangleSurface& surface, const MeshingOptions& options, TetMesh& out,
                      MeshingReport* report) {
    const auto started = std::chrono::steady_clock::now();
    out = TetMesh();
    MeshingReport local;
    MeshingReport& rep = report != nullptr ? *report : local;
    rep = MeshingReport();

    const int attempts = std::max(1, options.attempts);
    // Typical shares of an attempt's time (refinement, perturbation, exudation, volume
    // matching, quality check), measured on the samples and CGAL's scanned surfaces.
    constexpr std::array<double, 5> kShare{0.25, 0.6, 0.07, 0.05, 0.03};
    const auto announce = [&](MeshingStage stage, int attempt) {
        if (!options.progress)
            return;
        double done = 0.0;
        if (stage != MeshingStage::CheckingSurface)
            for (int i = 0; i < static_cast<int>(stage) - 1; ++i)
                done += kShare[static_cast<std::size_t>(i)];
        // Each attempt is shown as the whole work: a retry starts again from 0.
        options.progress(MeshingProgress{stage, attempt + 1, attempts, std::min(done, 1.0)});
    };
    announce(MeshingStage::CheckingSurface, 0);

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
    const double minDihedral = options.minDihedralDeg;
    if (!std::isfinite(minDihedral) || minDihedral < 0.0 || minDihedral > kMaxMinDihedralDeg)
        return Status::error("--min-dihedral must be between 0 and " + formatNumber(kMaxMinDihedralDeg) +
                             " degrees, got " + formatNumber(minDihedral));
    const double featureAngle = options.featureAngleDeg;
    if (options.protectFeatures && !(featureAngle > 0.0 && featureAngle < 180.0))
        return Status::error("--feature-angle must be between 0 and 180 degrees, got " +
                             formatNumber(featureAngle));
    // The angle the post-passes (collapses, volume matching) protect: the bound, and never
    // less than the default one, so that a lower --min-dihedral accepts worse meshes from
    // CGAL but does not let the passes make them worse.
    const double guardDeg = std::max(minDihedral, MeshingOptions{}.minDihedralDeg);
    rep.edgeLength = h;
    rep.surfaceVolume = std::abs(check.enclosedVolume);

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

        TetMesh best;
        MeshingReport bestReport = rep;
        int made = 0;
        for (int attempt = 0; attempt < attempts; ++attempt) {
            made = attempt + 1;
            const unsigned seed = options.seed + static_cast<unsigned>(attempt);
            announce(MeshingStage::Refining, attempt);
            // Reproducibility: the domain's initial rays and the refinement and
            // optimisation passes draw from these generators only.
            CGAL::Random domainRandom(seed);
            Domain domain(mesh, &domainRandom);
            int featureEdges = 0;
            if (options.protectFeatures) {
                domain.detect_features(featureAngle);
                featureEdges = countSharpEdges(surface, featureAngle);
            }

            C3t3 c3t3;
            for (const int initialPoints : {kInitialPoints, kRetryInitialPoints}) {
                CGAL::get_default_random() = CGAL::Random(seed);
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
                if (c3t3.number_of_cells_in_complex() != 0)
                    break; // else no restricted facet was found from the initial points: retry
            }
            if (c3t3.number_of_cells_in_complex() == 0)
                continue;

            // Sliver removal: perturbation moves vertices to raise the smallest dihedral
            // angles, exudation re-weights vertices so that slivers flip away (Cheng et
            // al., "Sliver exudation", 2000). Measured on the samples, the minimum radius
            // ratio rises from about 0.01-0.04 to 0.15-0.3 for 0.1-1 s.
            announce(MeshingStage::Perturbing, attempt);
            CGAL::perturb_mesh_3(c3t3, domain, p::time_limit = kPerturbTimeLimitSeconds);
            if (cancelled(options))
                return cancelledStatus();
            announce(MeshingStage::Exuding, attempt);
            CGAL::exude_mesh_3(c3t3, p::time_limit = kExudeTimeLimitSeconds);
            if (cancelled(options))
                return cancelledStatus();

            TetMesh result = extractTets(c3t3);
            if (result.empty())
                continue;
            // Collapsing short edges keeps radius ratios, not dihedral angles: where it would
            // lower the worst angle below the bound (plus a margin), the refined mesh is kept
            // as it was.
            int collapsed = 0;
            {
                TetMesh collapsedMesh = result;
                if (const int n = collapseShortEdges(collapsedMesh, h); n > 0) {
                    const double after = minDihedralDegrees(collapsedMesh);
                    if (after >= std::min(minDihedralDegrees(result), guardDeg + kCollapseMarginDeg)) {
                        result = std::move(collapsedMesh);
                        collapsed = n;
                    }
                }
            }
            // Numbered along a space-filling curve (reorder.h), before volume matching moves
            // the boundary nodes: with and without matching the mesh is numbered alike.
            if (options.reorder)
                reorderForLocality(result);
            MeshingReport r = rep;
            r.seed = seed;
            r.attempts = attempt + 1;
            r.featureEdges = featureEdges;
            r.collapsedEdges = collapsed;
            r.inscribedVolume = result.totalReferenceVolume();
            r.volume = r.inscribedVolume;
            if (options.matchVolume) {
                announce(MeshingStage::MatchingVolume, attempt);
                const auto& tree = domain.aabb_tree();
                const auto closest = [&tree](const Vec3& q) {
                    const Point c = tree.closest_point(Point(q.x(), q.y(), q.z()));
                    return Vec3(c.x(), c.y(), c.z());
                };
                const VolumeMatchResult matched = matchVolume(result, rep.surfaceVolume, closest,
                                                                guardDeg + kVolumeMatchMarginDeg);
                r.volume = matched.volumeAfter;
                r.maxBoundaryOffset = matched.maxOffset;
                r.restrainedNodes = matched.restrainedNodes;
            }
            announce(MeshingStage::CheckingQuality, attempt);
            r.minDihedralDeg = minDihedralDegrees(result);
            const bool better = best.empty() || r.minDihedralDeg > bestReport.minDihedralDeg;
            if (better) {
                best = std::move(result);
                bestReport = r;
            }
            if (bestReport.minDihedralDeg >= minDihedral)
                break;
            if (cancelled(options))
                return cancelledStatus();
        }
        rep = bestReport;
        rep.attempts = made;
        rep.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();

        if (best.empty())
            return Status::error("meshing produced no tets; --edge-length " + formatNumber(h) +
                                 " is probably too large for this surface");
        if (rep.minDihedralDeg < minDihedral)
            return Status::error(
                "no mesh reached the smallest dihedral angle of " + formatNumber(minDihedral) +
                " degrees in " + std::to_string(attempts) + " attempts (seeds " +
                std::to_string(options.seed) + " to " + std::to_string(options.seed + attempts - 1) +
                "; the best had " + formatNumber(std::round(rep.minDihedralDeg * 100.0) / 100.0) +
                " degrees); try another --edge-length or --seed, or lower --min-dihedral");
        // The surface may be inside out (negative volume); the mesh is not.
        const double relativeError = std::abs(rep.volumeError());
        if (!(relativeError <= options.maxVolumeError))
            return Status::error("the tet mesh volume " + formatNumber(rep.volume) +
                                 " differs from the surface's enclosed volume " +
                                 formatNumber(rep.surfaceVolume) + " by " +
                                 formatNumber(std::round(relativeError * 1000.0) / 10.0) +
                                 " %; try a smaller --edge-length than " + formatNumber(h));
        if (cancelled(options))
            return cancelledStatus();
        out = std::move(best);
        return Status::success();
    } catch (const std::exception& e) {
        return Status::error(std::string("meshing failed: ") + e.what());
    } catch (...) {
        return Status::error("meshing failed: unknown error in CGAL Mesh_3");
    }
}

} // namespace resect
