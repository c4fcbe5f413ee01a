#pragma once
// Literal inputs for the tests of single cut steps (test_intersect_edges, test_select_cut_nodes,
// test_decompose_tets, test_separate, ...): planar sweeps in the plane z = 0 and the
// crossings such a sweep makes, given literally instead of computed by intersectEdges, so
// that each step is tested alone.
#include "core/cut/cut_types.h"
#include "core/sweep/sweep_surface.h"

#include <QtGlobal>

#include <algorithm>
#include <vector>

namespace resect::testing {

/// The rectangle [x0, x1] x [y0, y1] of the plane z = 0 as a sweep (two curves of two points).
inline SweepSurface planeZ0(double x0, double x1, double y0, double y1) {
    SweepSurface s;
    const Status st = SweepSurface::fromStartEnd({Vec3(x0, y0, 0), Vec3(x1, y0, 0)},
                                                 {Vec3(x0, y1, 0), Vec3(x1, y1, 0)}, s);
    if (!st.ok())
        qFatal("%s", st.message().c_str());
    return s;
}

/// The crossing of edge (a, b) with a sweep in the plane z = 0, as intersectEdges reports it:
/// ordered a < b, t = z_a / (z_a - z_b) from a, the point at t, sideP the side of a.
inline EdgeCrossing crossingOfZ0(const TetMesh& mesh, const SweepSurface& sweep, int a, int b) {
    if (a > b)
        std::swap(a, b);
    EdgeCrossing c;
    c.a = a;
    c.b = b;
    const double za = mesh.pos(a).z(), zb = mesh.pos(b).z();
    c.hit.t = za / (za - zb);
    c.hit.point = mesh.pos(a) + c.hit.t * (mesh.pos(b) - mesh.pos(a));
    c.hit.sideP = sweep.sideOf(mesh.pos(a));
    c.hit.triangle = sweep.closestPoint(c.hit.point).triangle;
    return c;
}

/// Step 2's output given literally: the listed edges crossed once (in this order) and the
/// listed nodes on the sweep.
inline IntersectedEdges crossingsOfZ0(const TetMesh& mesh, const SweepSurface& sweep,
                                      const std::vector<std::array<int, 2>>& edges,
                                      std::vector<int> onSweep = {}) {
    IntersectedEdges x;
    for (const auto& e : edges) {
        x.index.emplace(edgeKey(e[0], e[1]), static_cast<int>(x.edges.size()));
        x.edges.push_back(crossingOfZ0(mesh, sweep, e[0], e[1]));
    }
    std::sort(onSweep.begin(), onSweep.end());
    x.onSweepNodes = onSweep;
    for (int t = 0; t < mesh.tetCount(); ++t)
        x.candidateTets.push_back(t);
    return x;
}

/// The unit tet (0,0,0), (1,0,0), (0,1,0), (0,0,1): local edge e of kTetEdges joins the
/// same global nodes.
inline TetMesh unitTet() {
    return TetMesh::fromArrays({Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0), Vec3(0, 0, 1)},
                               {{0, 1, 2, 3}});
}

} // namespace resect::testing
