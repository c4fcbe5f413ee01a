#include "core/mesh/validity.h"

#include "core/mesh/predicates.h"
#include "core/mesh/topology.h"
#include "core/mesh/uniform_cells.h"

#include <Eigen/Geometry>

#include <algorithm>
#include <array>
#include <cstdint>
#include <cmath>
#include <limits>
#include <string>
#include <unordered_map>

namespace resect {
namespace {

bool finite(const Vec3& p) { return std::isfinite(p.x()) && std::isfinite(p.y()) && std::isfinite(p.z()); }

std::string tetName(int t) { return "tet " + std::to_string(t); }

} // namespace

bool hangsOn(const Vec3& p, const Vec3& a, const Vec3& b, const Vec3& c) {
    return p != a && p != b && p != c && orient3d(a, b, c, p) == 0 && inClosedTriangle(p, a, b, c);
}

bool hangsOnBoundaryFaceAt(const TetMesh& mesh, const Vec3& p, int a, int b) {
    std::vector<int> ring, sharing;
    mesh.edgeTets(a, b, ring);
    for (int t : ring) {
        for (int c : mesh.tet(t)) {
            if (c == a || c == b)
                continue;
            mesh.faceTets(a, b, c, sharing);
            if (sharing.size() == 1 && hangsOn(p, mesh.ref(a), mesh.ref(b), mesh.ref(c)))
                return true;
        }
    }
    return false;
}

std::array<double, 6> edgePositionKey(const TetMesh& mesh, int a, int b) {
    const Vec3 &pa = mesh.ref(a), &pb = mesh.ref(b);
    const bool swap = std::lexicographical_compare(pb.data(), pb.data() + 3, pa.data(), pa.data() + 3);
    const Vec3 &lo = swap ? pb : pa, &hi = swap ? pa : pb;
    return {lo.x(), lo.y(), lo.z(), hi.x(), hi.y(), hi.z()};
}

const char* toString(MeshProblem::Kind kind) {
    switch (kind) {
    case MeshProblem::Kind::NonFiniteCoordinate: return "non_finite_coordinate";
    case MeshProblem::Kind::InvertedTet: return "inverted_tet";
    case MeshProblem::Kind::ZeroVolumeTet: return "zero_volume_tet";
    case MeshProblem::Kind::InvertedCurrentTet: return "inverted_current_tet";
    case MeshProblem::Kind::OverSharedFace: return "over_shared_face";
    case MeshProblem::Kind::TJunction: return "t_junction";
    case MeshProblem::Kind::UnusedNode: return "unused_node";
    }
    return "unknown";
}

std::vector<MeshProblem> checkValidity(const TetMesh& mesh) {
    using Kind = MeshProblem::Kind;
    std::vector<MeshProblem> problems;

    std::vector<char> badNode(mesh.nodeCount(), 0);
    for (int n = 0; n < mesh.nodeCount(); ++n) {
        if (!finite(mesh.ref(n)) || !finite(mesh.pos(n))) {
            badNode[n] = 1;
            problems.push_back({Kind::NonFiniteCoordinate, n,
                                "node " + std::to_string(n) + " has a non-finite coordinate"});
        }
        if (mesh.nodeTets(n).empty())
            problems.push_back({Kind::UnusedNode, n, "node " + std::to_string(n) + " is in no tet"});
    }

    for (int t = 0; t < mesh.tetCount(); ++t) {
        const Tet& q = mesh.tet(t);
        if (badNode[q[0]] || badNode[q[1]] || badNode[q[2]] || badNode[q[3]])
            continue;  // orientation of non-finite points is meaningless
        const int o = orient3d(mesh.ref(q[0]), mesh.ref(q[1]), mesh.ref(q[2]), mesh.ref(q[3]));
        if (o < 0)
            problems.push_back({Kind::InvertedTet, t,
                                tetName(t) + " is inverted in the reference configuration"});
        else if (o == 0)
            problems.push_back({Kind::ZeroVolumeTet, t,
                                tetName(t) + " has zero volume in the reference configuration"});
        const int oc = orient3d(mesh.pos(q[0]), mesh.pos(q[1]), mesh.pos(q[2]), mesh.pos(q[3]));
        if (oc <= 0 && o > 0)
            problems.push_back({Kind::InvertedCurrentTet, t,
                                tetName(t) + " is inverted or flat in the current configuration"});
    }

    // Conformity. (1) No face in more than two tets.
    const std::vector<MeshFace> faces = allFaces(mesh);
    std::vector<const MeshFace*> boundary;
    for (const MeshFace& f : faces) {
        if (f.extraTets > 0)
            problems.push_back({Kind::OverSharedFace, f.nodes[0],
                                "face (" + std::to_string(f.nodes[0]) + ", " +
                                    std::to_string(f.nodes[1]) + ", " + std::to_string(f.nodes[2]) +
                                    ") is shared by " + std::to_string(2 + f.extraTets) + " tets"});
        if (f.tets[1] < 0)
            boundary.push_back(&f);
    }
    int reported = 0;
    // (2) T-junctions. The oriented boundary of any set of positive tets is closed (the
    // boundary of a boundary is empty), so a hanging node cannot be found topologically: it
    // is found geometrically. A node hangs when it lies on a boundary face of its own piece
    // (on an edge or inside, in the reference configuration) without being one of the
    // face's corners or coinciding with one (separated cut nodes coincide by design).
    // Candidates come from a uniform grid over the boundary faces' bounding boxes.
    if (!boundary.empty()) {
        const Components comp = connectedComponents(mesh);
        std::vector<int> boundaryNodes;
        for (const MeshFace* f : boundary)
            for (int v : f->nodes)
                boundaryNodes.push_back(v);
        std::sort(boundaryNodes.begin(), boundaryNodes.end());
        boundaryNodes.erase(std::unique(boundaryNodes.begin(), boundaryNodes.end()),
                            boundaryNodes.end());
        Vec3 lo = Vec3::Constant(std::numeric_limits<double>::infinity()), hi = -lo;
        double sizeSum = 0;
        for (const MeshFace* f : boundary) {
            for (int v : f->nodes) {
                if (badNode[v])
                    continue;
                lo = lo.cwiseMin(mesh.ref(v));
                hi = hi.cwiseMax(mesh.ref(v));
            }
            sizeSum += (mesh.ref(f->nodes[1]) - mesh.ref(f->nodes[0])).norm();
        }
        const UniformCells cells(lo, hi, std::max(sizeSum / boundary.size(), 1e-300), 1 << 10);
        std::unordered_map<std::int64_t, std::vector<int>> grid;
        for (int v : boundaryNodes)
            if (!badNode[v])
                grid[cells.index(cells.of(mesh.ref(v)))].push_back(v);
        for (const MeshFace* f : boundary) {
            const Tri& n = f->nodes;
            if (badNode[n[0]] || badNode[n[1]] || badNode[n[2]])
                continue;
            const Vec3 &pa = mesh.ref(n[0]), &pb = mesh.ref(n[1]), &pc = mesh.ref(n[2]);
            const Eigen::Array3i c0 = cells.of(pa.cwiseMin(pb).cwiseMin(pc));
            const Eigen::Array3i c1 = cells.of(pa.cwiseMax(pb).cwiseMax(pc));
            for (int z = c0.z(); z <= c1.z(); ++z)
                for (int y = c0.y(); y <= c1.y(); ++y)
                    for (int x = c0.x(); x <= c1.x(); ++x) {
                        auto it = grid.find(cells.index({x, y, z}));
                        if (it == grid.end())
                            continue;
                        for (int v : it->second) {
                            const Vec3& p = mesh.ref(v);
                            if (v == n[0] || v == n[1] || v == n[2] ||
                                comp.nodeComponent[v] != comp.nodeComponent[n[0]] || !hangsOn(p, pa, pb, pc))
                                continue;
                            if (reported++ < 1000)
                                problems.push_back(
                                    {Kind::TJunction, v,
                                     "node " + std::to_string(v) + " hangs on face (" +
                                         std::to_string(n[0]) + ", " + std::to_string(n[1]) +
                                         ", " + std::to_string(n[2]) + ") (T-junction)"});
                        }
                    }
        }
    }
    return problems;
}

MeshOverlap deepestOverlap(const TetMesh& mesh) {
    MeshOverlap worst;
    if (mesh.tetCount() == 0)
        return worst;
    std::vector<char> onBoundary(mesh.nodeCount(), 0);
    for (const BoundaryFace& f : boundaryFaces(mesh))
        for (int n : f.nodes)
            onBoundary[n] = 1;
    // A uniform grid (cells about a tet wide) holds the boundary nodes, a few; every tet is
    // checked against the nodes in the cells its box overlaps (a grid of the tets would need
    // an entry per tet and cell).
    Vec3 lo = Vec3::Constant(std::numeric_limits<double>::infinity()), hi = -lo;
    double extent = 0;
    const auto boxOf = [&](int t) {
        Eigen::AlignedBox3d box;
        for (int v : mesh.tet(t))
            box.extend(mesh.ref(v));
        return box;
    };
    for (int t = 0; t < mesh.tetCount(); ++t) {
        const Eigen::AlignedBox3d box = boxOf(t);
        if (!box.sizes().allFinite())
            continue;
        lo = lo.cwiseMin(box.min());
        hi = hi.cwiseMax(box.max());
        extent += box.sizes().maxCoeff();
    }
    if (!(lo.array() <= hi.array()).all())
        return worst;
    const UniformCells cells(lo, hi, std::max(extent / mesh.tetCount(), 1e-300), 1 << 9);
    std::unordered_map<std::int64_t, std::vector<int>> grid;  // cell -> boundary nodes, ascending
    for (int n = 0; n < mesh.nodeCount(); ++n)
        if (onBoundary[n] && finite(mesh.ref(n)))
            grid[cells.index(cells.of(mesh.ref(n)))].push_back(n);
    for (int t = 0; t < mesh.tetCount(); ++t) {
        const Eigen::AlignedBox3d box = boxOf(t);
        if (!box.sizes().allFinite())
            continue;
        const Tet& q = mesh.tet(t);
        const std::array<Vec3, 4> c = {mesh.ref(q[0]), mesh.ref(q[1]), mesh.ref(q[2]), mesh.ref(q[3])};
        // (An inverted tet, which checkValidity reports, is measured with two corners swapped.)
        const std::array<Vec3, 4> positive =
            orient3d(c[0], c[1], c[2], c[3]) >= 0 ? c : std::array<Vec3, 4>{c[1], c[0], c[2], c[3]};
        const Eigen::Array3i c0 = cells.of(box.min()), c1 = cells.of(box.max());
        for (int z = c0.z(); z <= c1.z(); ++z)
            for (int y = c0.y(); y <= c1.y(); ++y)
                for (int x = c0.x(); x <= c1.x(); ++x) {
                    const auto it = grid.find(cells.index({x, y, z}));
                    if (it == grid.end())
                        continue;
                    for (int n : it->second) {
                        const Vec3& p = mesh.ref(n);
                        if (!box.contains(p))
                            continue;  // (outside the box: outside the tet, depth <= 0)
                        bool corner = false;
                        for (int i = 0; i < 4; ++i)
                            corner = corner || q[i] == n || c[i] == p;
                        if (corner)
                            continue;
                        // The deepest wins; among equals, the lowest node, then the lowest tet.
                        const double depth = depthInside(p, positive);
                        if (depth > worst.depth ||
                            (depth == worst.depth && worst.node >= 0 && (n < worst.node || (n == worst.node && t < worst.tet))))
                            worst = {depth, n, t};
                    }
                }
    }
    return worst;
}

double depthInside(const Vec3& x, const std::array<Vec3, 4>& c) {
    if (!(orient3d(x, c[1], c[2], c[3]) > 0 && orient3d(c[0], x, c[2], c[3]) > 0 && orient3d(c[0], c[1], x, c[3]) > 0 &&
          orient3d(c[0], c[1], c[2], x) > 0))
        return 0;
    double depth = std::numeric_limits<double>::infinity();
    for (int i = 0; i < 4; ++i) {
        const Vec3 &a = c[(i + 1) % 4], &b = c[(i + 2) % 4], &d = c[(i + 3) % 4];
        const Vec3 n = (b - a).cross(d - a);
        const double len = n.norm();
        if (len > 0)
            depth = std::min(depth, std::abs(n.dot(x - a)) / len);
    }
    return std::isfinite(depth) ? depth : 0;
}

} // namespace resect
