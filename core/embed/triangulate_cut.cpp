#include "core/embed/triangulate_cut.h"

#include <CGAL/Constrained_Delaunay_triangulation_2.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Triangulation_face_base_with_info_2.h>
#include <CGAL/Triangulation_vertex_base_with_info_2.h>

#include <list>
#include <string>

namespace resect {
namespace {

using K = CGAL::Exact_predicates_inexact_constructions_kernel;
using Vb = CGAL::Triangulation_vertex_base_with_info_2<int, K>;
struct FaceInfo {
    int depth = -1;  ///< nesting depth of the region the face lies in
};
using Fbb = CGAL::Triangulation_face_base_with_info_2<FaceInfo, K>;
using Fb = CGAL::Constrained_triangulation_face_base_2<K, Fbb>;
using Tds = CGAL::Triangulation_data_structure_2<Vb, Fb>;
using Cdt = CGAL::Constrained_Delaunay_triangulation_2<K, Tds, CGAL::Exact_predicates_tag>;

/// Flood fill from the infinite face: crossing a constrained edge increases the depth.
void markDepths(Cdt& cdt) {
    std::list<Cdt::Face_handle> border{cdt.infinite_face()};
    int depth = 0;
    while (!border.empty()) {
        std::list<Cdt::Face_handle> next;
        for (Cdt::Face_handle start : border) {
            if (start->info().depth != -1)
                continue;
            std::list<Cdt::Face_handle> queue{start};
            while (!queue.empty()) {
                Cdt::Face_handle f = queue.front();
                queue.pop_front();
                if (f->info().depth != -1)
                    continue;
                f->info().depth = depth;
                for (int i = 0; i < 3; ++i) {
                    Cdt::Face_handle n = f->neighbor(i);
                    if (n->info().depth != -1)
                        continue;
                    if (cdt.is_constrained(Cdt::Edge(f, i)))
                        next.push_back(n);
                    else
                        queue.push_back(n);
                }
            }
        }
        border = std::move(next);
        ++depth;
    }
}

} // namespace

Status triangulateInPlane(const std::vector<Vec2>& points, const std::vector<std::vector<int>>& loops,
                          std::vector<std::array<int, 3>>& triangles) {
    triangles.clear();
    try {
        Cdt cdt;
        std::vector<Cdt::Vertex_handle> handle(points.size());
        for (const auto& loop : loops)
            for (int i : loop)
                if (handle[i] == Cdt::Vertex_handle()) {
                    const std::size_t before = cdt.number_of_vertices();
                    handle[i] = cdt.insert(K::Point_2(points[i].x(), points[i].y()));
                    if (cdt.number_of_vertices() == before)
                        return Status::error("two cut-boundary points map to the same (u, v)");
                    handle[i]->info() = i;
                }
        const std::size_t inserted = cdt.number_of_vertices();
        for (const auto& loop : loops)
            for (std::size_t k = 0; k < loop.size(); ++k) {
                const auto a = handle[loop[k]], b = handle[loop[(k + 1) % loop.size()]];
                if (a != b)
                    cdt.insert_constraint(a, b);
            }
        if (cdt.number_of_vertices() != inserted)
            return Status::error("cut boundary crosses itself in the parameter plane");
        for (auto f = cdt.all_faces_begin(); f != cdt.all_faces_end(); ++f)
            f->info().depth = -1;
        markDepths(cdt);
        for (auto f = cdt.finite_faces_begin(); f != cdt.finite_faces_end(); ++f) {
            if (f->info().depth % 2 == 0)
                continue;
            triangles.push_back({f->vertex(0)->info(), f->vertex(1)->info(), f->vertex(2)->info()});
        }
    } catch (const std::exception& e) {
        return Status::error(std::string("triangulating the cut face failed: ") + e.what());
    }
    return Status::success();
}

} // namespace resect
