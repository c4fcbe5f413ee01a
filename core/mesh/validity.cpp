#include "core/mesh/validity.h"

#include "core/mesh/predicates.h"
#include "core/mesh/topology.h"

#include <algorithm>
#include <cmath>
#include <string>
#include <unordered_map>

namespace resect {
namespace {

bool finite(const Vec3& p) { return std::isfinite(p.x()) && std::isfinite(p.y()) && std::isfinite(p.z()); }

std::uint64_t directedKey(int a, int b) {
    return (static_cast<std::uint64_t>(static_cast<std::uint32_t>(a)) << 32) |
           static_cast<std::uint32_t>(b);
}

std::string tetName(int t) { return "tet " + std::to_string(t); }

/// Dominant axis of a normal, dropped when projecting a face to 2-D.
int dominantAxis(const Vec3& n) {
    const Vec3 a = n.cwiseAbs();
    return a.x() >= a.y() ? (a.x() >= a.z() ? 0 : 2) : (a.y() >= a.z() ? 1 : 2);
}

/// True if p lies strictly inside triangle (a, b, c) (coplanarity already established).
bool strictlyInsideTriangle(const Vec3& p, const Vec3& a, const Vec3& b, const Vec3& c) {
    const int drop = dominantAxis((b - a).cross(c - a));
    const int s = orient2dProjected(a, b, c, drop);
    if (s == 0)
        return false;
    return orient2dProjected(a, b, p, drop) == s && orient2dProjected(b, c, p, drop) == s &&
           orient2dProjected(c, a, p, drop) == s;
}

} // namespace

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
    // (2) The boundary of a conforming mesh is closed: every directed boundary half-edge
    // a->b is matched by b->a. A node hanging on an edge leaves that edge unmatched.
    std::unordered_map<std::uint64_t, int> halfEdges;
    halfEdges.reserve(boundary.size() * 3);
    for (const MeshFace* f : boundary)
        for (int i = 0; i < 3; ++i)
            halfEdges[directedKey(f->nodes[i], f->nodes[(i + 1) % 3])] += 1;
    int reported = 0;
    for (const auto& [key, count] : halfEdges) {
        const int a = static_cast<int>(key >> 32), b = static_cast<int>(key & 0xffffffffu);
        auto it = halfEdges.find(directedKey(b, a));
        const int opposite = it == halfEdges.end() ? 0 : it->second;
        if (count != opposite && (count > opposite || a < b) && reported < 1000) {
            ++reported;
            problems.push_back({Kind::TJunction, a,
                                "boundary edge (" + std::to_string(a) + ", " + std::to_string(b) +
                                    ") is not closed: a node hangs on it (T-junction)"});
        }
    }
    // (3) A node hanging inside a face: the boundary faces around it close up, but fold
    // back onto the face they should match. Detected across each boundary edge: the face on
    // the other side is coplanar and its far corner lies strictly inside this face.
    std::unordered_map<std::uint64_t, const MeshFace*> faceOfHalfEdge;
    faceOfHalfEdge.reserve(boundary.size() * 3);
    for (const MeshFace* f : boundary)
        for (int i = 0; i < 3; ++i)
            faceOfHalfEdge.emplace(directedKey(f->nodes[i], f->nodes[(i + 1) % 3]), f);
    for (const MeshFace* f : boundary) {
        const Tri& n = f->nodes;
        if (badNode[n[0]] || badNode[n[1]] || badNode[n[2]])
            continue;
        for (int i = 0; i < 3; ++i) {
            auto it = faceOfHalfEdge.find(directedKey(n[(i + 1) % 3], n[i]));
            if (it == faceOfHalfEdge.end())
                continue;
            const Tri& g = it->second->nodes;
            int far = -1;
            for (int v : g)
                if (v != n[i] && v != n[(i + 1) % 3])
                    far = v;
            if (far < 0 || badNode[far] || far == n[(i + 2) % 3])
                continue;
            const Vec3& p = mesh.ref(far);
            if (orient3d(mesh.ref(n[0]), mesh.ref(n[1]), mesh.ref(n[2]), p) == 0 &&
                strictlyInsideTriangle(p, mesh.ref(n[0]), mesh.ref(n[1]), mesh.ref(n[2])) &&
                reported < 1000) {
                ++reported;
                problems.push_back({Kind::TJunction, far,
                                    "node " + std::to_string(far) + " hangs inside face (" +
                                        std::to_string(n[0]) + ", " + std::to_string(n[1]) + ", " +
                                        std::to_string(n[2]) + ") (T-junction)"});
            }
        }
    }
    return problems;
}

} // namespace resect
