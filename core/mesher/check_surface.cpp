// Surface checks and repairs. CGAL's Polygon Mesh Processing (self-intersection test,
// hole filling) is confined to this translation unit.

// Hole fairing solves a sparse linear system; CGAL uses Eigen for it when this is defined.
#ifndef CGAL_EIGEN3_ENABLED
#define CGAL_EIGEN3_ENABLED
#endif

#include "core/mesher/check_surface.h"

#include "core/mesh/union_find.h"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_mesh_processing/self_intersections.h>
#include <CGAL/Polygon_mesh_processing/triangulate_hole.h>
#include <CGAL/Surface_mesh.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <exception>
#include <iterator>
#include <numeric>
#include <string>
#include <vector>

namespace resect {

namespace {

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Point = Kernel::Point_3;
using Mesh = CGAL::Surface_mesh<Point>;
namespace PMP = CGAL::Polygon_mesh_processing;

bool isFinite(const Vec3& p) {
    return p.allFinite();
}

Point toPoint(const Vec3& p) {
    return Point(p.x(), p.y(), p.z());
}

/// "1 edge" / "3 edges".
std::string count(int n, const char* singular, const char* plural) {
    return std::to_string(n) + " " + (n == 1 ? singular : plural);
}

/// True if the triangle's indices are in range and pairwise distinct.
bool goodIndices(const Tri& t, int vertexCount) {
    for (int i : t)
        if (i < 0 || i >= vertexCount)
            return false;
    return t[0] != t[1] && t[1] != t[2] && t[0] != t[2];
}

/// Counts the vertices whose incident triangles do not form a single edge-connected
/// fan (two cones touching at a vertex, a "bow tie"). `good` marks the triangles with
/// valid indices; only those are considered.
int countNonManifoldVertices(const TriangleSurface& s, const std::vector<char>& good) {
    const int nv = s.vertexCount();
    // Vertex -> incident triangles, compressed rows.
    std::vector<int> start(static_cast<std::size_t>(nv) + 1, 0);
    for (int f = 0; f < s.triangleCount(); ++f)
        if (good[f])
            for (int v : s.triangles[f])
                ++start[v + 1];
    std::partial_sum(start.begin(), start.end(), start.begin());
    std::vector<int> incident(static_cast<std::size_t>(start.back()));
    std::vector<int> fill(start.begin(), start.end() - 1);
    for (int f = 0; f < s.triangleCount(); ++f)
        if (good[f])
            for (int v : s.triangles[f])
                incident[fill[v]++] = f;

    int bad = 0;
    UnionFind uf;
    std::vector<std::pair<int, int>> spokes; // (other vertex, local triangle index)
    for (int v = 0; v < nv; ++v) {
        const int n = start[v + 1] - start[v];
        if (n <= 1)
            continue;
        uf.reset(n);
        spokes.clear();
        for (int i = 0; i < n; ++i) {
            const Tri& t = s.triangles[incident[start[v] + i]];
            for (int w : t)
                if (w != v)
                    spokes.emplace_back(w, i);
        }
        // Triangles sharing a spoke (an edge v-w) belong to the same fan.
        std::sort(spokes.begin(), spokes.end());
        for (std::size_t k = 1; k < spokes.size(); ++k)
            if (spokes[k].first == spokes[k - 1].first)
                uf.unite(spokes[k].second, spokes[k - 1].second);
        if (uf.setCount() > 1)  // more than one fan
            ++bad;
    }
    return bad;
}

/// Builds a CGAL Surface_mesh holding every vertex (same indices) and every triangle.
/// Returns false if CGAL refuses a face (only possible for non-manifold or inconsistently
/// oriented input, which the callers exclude beforehand).
bool buildSurfaceMesh(const TriangleSurface& s, Mesh& mesh) {
    mesh.clear();
    mesh.reserve(static_cast<Mesh::size_type>(s.vertexCount()),
                 static_cast<Mesh::size_type>(3 * s.triangleCount() / 2),
                 static_cast<Mesh::size_type>(s.triangleCount()));
    std::vector<Mesh::Vertex_index> vertex;
    vertex.reserve(s.positions.size());
    for (const Vec3& p : s.positions)
        vertex.push_back(mesh.add_vertex(toPoint(p)));
    for (const Tri& t : s.triangles) {
        if (mesh.add_face(vertex[t[0]], vertex[t[1]], vertex[t[2]]) == Mesh::null_face())
            return false;
    }
    return true;
}

} // namespace

SurfaceCheck checkSurface(const TriangleSurface& surface, const SurfaceCheckOptions& options) {
    SurfaceCheck c;
    c.vertices = surface.vertexCount();
    c.triangles = surface.triangleCount();

    std::vector<char> finite(surface.positions.size());
    for (std::size_t i = 0; i < surface.positions.size(); ++i) {
        finite[i] = isFinite(surface.positions[i]);
        if (!finite[i])
            ++c.nonFiniteVertices;
    }

    // Triangles with valid indices take part in the topological checks.
    std::vector<char> good(surface.triangles.size());
    for (std::size_t f = 0; f < surface.triangles.size(); ++f) {
        const Tri& t = surface.triangles[f];
        good[f] = goodIndices(t, c.vertices);
        if (!good[f]) {
            ++c.badIndexTriangles;
            continue;
        }
        if (finite[t[0]] && finite[t[1]] && finite[t[2]] &&
            CGAL::collinear(toPoint(surface.positions[t[0]]), toPoint(surface.positions[t[1]]),
                            toPoint(surface.positions[t[2]])))
            ++c.degenerateTriangles; // exact predicate: zero area, not merely small
    }

    // Directed half-edges, grouped by undirected edge. Key = (min << 32 | max); the flag
    // says whether the triangle traverses the edge from min to max.
    struct HalfEdge {
        std::uint64_t key;
        bool forward;
        bool operator<(const HalfEdge& o) const {
            return key != o.key ? key < o.key : forward < o.forward;
        }
    };
    std::vector<HalfEdge> halfEdges;
    halfEdges.reserve(3 * surface.triangles.size());
    for (std::size_t f = 0; f < surface.triangles.size(); ++f) {
        if (!good[f])
            continue;
        const Tri& t = surface.triangles[f];
        for (int e = 0; e < 3; ++e) {
            const auto a = static_cast<std::uint64_t>(t[e]);
            const auto b = static_cast<std::uint64_t>(t[(e + 1) % 3]);
            halfEdges.push_back({std::min(a, b) << 32 | std::max(a, b), a < b});
        }
    }
    std::sort(halfEdges.begin(), halfEdges.end());
    for (std::size_t i = 0; i < halfEdges.size();) {
        std::size_t j = i;
        int forward = 0;
        while (j < halfEdges.size() && halfEdges[j].key == halfEdges[i].key) {
            forward += halfEdges[j].forward ? 1 : 0;
            ++j;
        }
        const int n = static_cast<int>(j - i);
        if (n == 1)
            ++c.borderEdges;
        else if (n > 2)
            ++c.nonManifoldEdges;
        else if (forward != 1)
            ++c.orientationErrors; // both triangles traverse the edge the same way
        i = j;
    }
    c.nonManifoldVertices = countNonManifoldVertices(surface, good);

    const bool indexable = c.nonFiniteVertices == 0 && c.badIndexTriangles == 0;
    if (indexable)
        c.enclosedVolume = enclosedVolume(surface);

    // PMP needs a valid halfedge structure: finite, indexable, manifold and consistently
    // oriented (border edges are fine).
    const bool buildable = indexable && c.nonManifoldEdges == 0 && c.nonManifoldVertices == 0 &&
                           c.orientationErrors == 0 && c.triangles > 0;
    if (options.testSelfIntersection && buildable) {
        try {
            Mesh mesh;
            if (buildSurfaceMesh(surface, mesh))
                c.selfIntersecting = PMP::does_self_intersect(mesh);
        } catch (const std::exception&) {
            // CGAL precondition failure on input we could not foresee: report the surface
            // as unfit rather than crash.
            c.selfIntersecting = true;
        }
    }
    return c;
}

Status surfaceProblem(const SurfaceCheck& c) {
    if (c.triangles == 0)
        return Status::error("surface has no triangles");
    if (c.nonFiniteVertices > 0)
        return Status::error(count(c.nonFiniteVertices, "vertex has", "vertices have") +
                             " non-finite coordinates (NaN or infinite)");
    if (c.badIndexTriangles > 0)
        return Status::error(count(c.badIndexTriangles, "triangle has", "triangles have") +
                             " an out-of-range or repeated vertex index");
    if (c.nonManifoldEdges > 0)
        return Status::error("non-manifold surface: " + count(c.nonManifoldEdges, "edge", "edges") +
                             " shared by more than two triangles");
    if (c.nonManifoldVertices > 0)
        return Status::error("non-manifold surface: " +
                             count(c.nonManifoldVertices, "vertex joins", "vertices join") +
                             " separate sheets of triangles (surfaces touching at a point)");
    if (c.orientationErrors > 0)
        return Status::error("inconsistent triangle orientation: " +
                             count(c.orientationErrors, "edge is", "edges are") +
                             " traversed in the same direction by both of its triangles");
    if (c.borderEdges > 0)
        return Status::error(
            "open surface: " + count(c.borderEdges, "border edge", "border edges") +
            " (try --repair to fill holes)");
    if (c.degenerateTriangles > 0)
        return Status::error("degenerate surface: " +
                             count(c.degenerateTriangles, "triangle has", "triangles have") +
                             " zero area (collinear corners)");
    if (c.selfIntersecting)
        return Status::error("self-intersecting surface: some triangles cross each other");
    // An inside-out surface (negative volume) is fit for meshing: Mesh_3 decides inside
    // and outside by ray parity, and orientOutward() repairs it for display.
    if (!(c.enclosedVolume != 0.0))
        return Status::error("surface encloses no volume");
    return Status::success();
}

Status fillHoles(TriangleSurface& surface, int* holesFilled) {
    if (holesFilled)
        *holesFilled = 0;
    SurfaceCheckOptions noSelfIntersection;
    noSelfIntersection.testSelfIntersection = false;
    const SurfaceCheck c = checkSurface(surface, noSelfIntersection);
    if (c.borderEdges == 0)
        return Status::success();
    // Hole filling works on a halfedge structure: the rest of the surface must be sound.
    if (c.nonFiniteVertices > 0 || c.badIndexTriangles > 0 || c.nonManifoldEdges > 0 ||
        c.nonManifoldVertices > 0 || c.orientationErrors > 0) {
        const Status why = surfaceProblem(c);
        return Status::error("cannot fill holes: " + why.message());
    }

    try {
        Mesh mesh;
        if (!buildSurfaceMesh(surface, mesh))
            return Status::error("cannot fill holes: the surface is not a valid halfedge mesh");

        // One border halfedge per hole (a border cycle).
        std::vector<Mesh::Halfedge_index> holes;
        std::vector<char> seen(mesh.number_of_halfedges(), 0);
        for (Mesh::Halfedge_index h : mesh.halfedges()) {
            if (!mesh.is_border(h) || seen[h.idx()])
                continue;
            holes.push_back(h);
            Mesh::Halfedge_index g = h;
            do {
                seen[g.idx()] = 1;
                g = mesh.next(g);
            } while (g != h);
        }

        const bool haveUvs = surface.uvs.size() == surface.positions.size();
        std::vector<Eigen::Vector2d> uvs = surface.uvs;
        int filled = 0;
        for (Mesh::Halfedge_index h : holes) {
            // The mean texture coordinate of the hole's rim, for the new vertices.
            Eigen::Vector2d rimUv = Eigen::Vector2d::Zero();
            if (haveUvs) {
                int n = 0;
                for (Mesh::Halfedge_index g : CGAL::halfedges_around_face(h, mesh)) {
                    rimUv += uvs[mesh.target(g).idx()];
                    ++n;
                }
                rimUv /= std::max(n, 1);
            }
            const std::size_t rimEdges = CGAL::halfedges_around_face(h, mesh).size();
            std::vector<Mesh::Face_index> newFaces;
            std::vector<Mesh::Vertex_index> newVertices;
            // Triangulate (minimum-weight, Delaunay search space), refine to the rim's
            // density, then fair (tangent-continuous); Liepa 2003 as implemented by CGAL.
            PMP::triangulate_refine_and_fair_hole(mesh, h, std::back_inserter(newFaces),
                                                  std::back_inserter(newVertices));
            if (newFaces.empty())
                return Status::error("cannot fill holes: no triangulation found for a hole "
                                     "with " +
                                     std::to_string(rimEdges) + " border edges");
            if (haveUvs)
                uvs.resize(mesh.number_of_vertices(), rimUv);
            ++filled;
        }

        // Copy back: vertex indices are preserved (no vertex was removed), new vertices
        // follow the old ones.
        TriangleSurface out;
        out.positions.reserve(mesh.number_of_vertices());
        for (Mesh::Vertex_index v : mesh.vertices()) {
            const Point& p = mesh.point(v);
            out.positions.emplace_back(p.x(), p.y(), p.z());
        }
        out.triangles.reserve(mesh.number_of_faces());
        for (Mesh::Face_index f : mesh.faces()) {
            Tri t{};
            int k = 0;
            for (Mesh::Vertex_index v : CGAL::vertices_around_face(mesh.halfedge(f), mesh))
                if (k < 3)
                    t[k++] = static_cast<int>(v.idx());
            out.triangles.push_back(t);
        }
        if (haveUvs) {
            uvs.resize(out.positions.size(), Eigen::Vector2d::Zero());
            out.uvs = std::move(uvs);
        }
        surface = std::move(out);
        if (holesFilled)
            *holesFilled = filled;
        return Status::success();
    } catch (const std::exception& e) {
        return Status::error(std::string("cannot fill holes: ") + e.what());
    }
}

void orientOutward(TriangleSurface& surface) {
    for (const Tri& t : surface.triangles)
        if (!goodIndices(t, surface.vertexCount()))
            return; // enclosedVolume would index out of range
    if (enclosedVolume(surface) < 0.0)
        for (Tri& t : surface.triangles)
            std::swap(t[1], t[2]);
}

} // namespace resect
