#include "core/cut/decompose_tets.h"

#include "core/cut/snap_nodes.h"
#include "core/mesh/predicates.h"
#include "core/mesh/quality.h"
#include "core/mesh/validity.h"
#include "core/sweep/intersect_segment.h"

#include <Eigen/LU>

#include <algorithm>
#include <array>
#include <limits>
#include <map>
#include <string>

namespace resect {
namespace {

/// The point deepest inside every face's inner half-space of a closed polyhedron (faces
/// oriented outward, corners through `at`): the centre of the largest ball in its kernel
/// (Chebyshev centre), from the small linear programme max r subject to n_i . x + r <= n_i . p_i
/// (unit outward normals n_i), solved by trying every vertex of its feasible region (four
/// active constraints; the polyhedra of a cut tet have at most a dozen faces). False if the
/// kernel is empty or flat (the polyhedron is not star-shaped).
template <class At> bool kernelPoint(const std::vector<Tri>& faces, const At& at, Vec3& out) {
    std::vector<Eigen::Vector4d> rows;  // (n, 1) with right-hand side n . p
    std::vector<double> rhs;
    for (const Tri& f : faces) {
        Vec3 n = (at(f[1]) - at(f[0])).cross(at(f[2]) - at(f[0]));
        const double len = n.norm();
        if (!(len > 0))
            continue;
        n /= len;
        rows.emplace_back(n.x(), n.y(), n.z(), 1.0);
        rhs.push_back(n.dot(at(f[0])));
    }
    const int m = static_cast<int>(rows.size());
    double bestR = 0;
    bool found = false;
    for (int a = 0; a < m; ++a)
        for (int b = a + 1; b < m; ++b)
            for (int c = b + 1; c < m; ++c)
                for (int d = c + 1; d < m; ++d) {
                    Eigen::Matrix4d A;
                    A << rows[a].transpose(), rows[b].transpose(), rows[c].transpose(), rows[d].transpose();
                    const Eigen::Vector4d y(rhs[a], rhs[b], rhs[c], rhs[d]);
                    const Eigen::FullPivLU<Eigen::Matrix4d> lu(A);
                    if (!lu.isInvertible())
                        continue;
                    const Eigen::Vector4d x = lu.solve(y);
                    if (!(x[3] > bestR) || !x.allFinite())
                        continue;
                    bool feasible = true;
                    for (int i = 0; i < m && feasible; ++i)
                        feasible = rows[i].dot(x) <= rhs[i] + 1e-12 * (std::abs(rhs[i]) + 1);
                    if (feasible) {
                        bestR = x[3];
                        out = x.head<3>();
                        found = true;
                    }
                }
    return found;
}

struct FaceHash {
    std::size_t operator()(const Tri& f) const {
        std::uint64_t h = static_cast<std::uint32_t>(f[0]);
        h = h * 0x9E3779B97F4A7C15ull + static_cast<std::uint32_t>(f[1]);
        h = (h ^ (h >> 29)) * 0xBF58476D1CE4E5B9ull + static_cast<std::uint32_t>(f[2]);
        return static_cast<std::size_t>(h ^ (h >> 32));
    }
};

/// A boundary triangle of a side polyhedron, oriented outward, with the side it belongs to
/// and the plane it lies on: parent face 0-3, or kCutPlane for the cut polygon.
struct SideTri {
    Tri v;
    int side;
    int plane;
};
constexpr int kCutPlane = 4;

int localEdge(int x, int y) {
    for (int e = 0; e < 6; ++e)
        if ((kTetEdges[e][0] == x && kTetEdges[e][1] == y) || (kTetEdges[e][0] == y && kTetEdges[e][1] == x))
            return e;
    return -1;
}

class Decomposer {
public:
    Decomposer(TetMesh& mesh, const DecomposeOptions& options, Decomposition& out, CutChanges& changes)
        : m_mesh(mesh), m_options(options), m_out(out), m_changes(changes) {}

    Status decompose(const TetCut& tc);
    /// Faces of partially cut tets keep the standard diagonal (no face node): there the
    /// sweep ends inside the tet and a face node off the sweep could only be reached across it.
    void excludeFaceNodes(const TetMesh& mesh, const TetCut& tc) {
        const Tet& q = mesh.tet(tc.tet);
        for (const auto& lf : kTetFaces) {
            Tri key{q[lf[0]], q[lf[1]], q[lf[2]]};
            std::sort(key.begin(), key.end());
            m_faceNodes.emplace(key, -1);
        }
    }

private:
    int faceNode(const Tri& corners, const std::array<int, 4>& quad);
    Status triangulateFace(const TetCut& tc, const std::array<int, 6>& ep, int f,
                           std::vector<SideTri>& out);
    Status cutPolygon(const TetCut& tc, const std::array<int, 6>& ep, std::vector<Tri>& out);
    /// With avoidCrossing, an apex is only used if none of its new edges crosses the sweep.
    Status cone(const std::vector<SideTri>& tris, std::vector<Tet>& tets, bool avoidCrossing = false);
    bool coneFrom(const std::vector<SideTri>& tris, const Vec3& ref, const Vec3& pos, int node,
                  std::vector<Tet>& tets, double minRadiusRatio = 0);
    /// Whether `node` may be the apex for triangle t: never when it lies on t's plane
    /// without being a corner of t. Decided from the construction (which parent faces, or
    /// the cut polygon, a vertex lies on), not from rounded coordinates, where a constructed
    /// point is only nearly coplanar and would give an almost flat tet.
    bool onPlaneOf(int node, const SideTri& t) const { return planesOf(node) >> t.plane & 1; }
    /// Planes a vertex of the current tet lies on (0 for a vertex not listed).
    std::uint8_t planesOf(int node) const {
        for (const auto& [v, mask] : m_planes)
            if (v == node)
                return mask;
        return 0;
    }
    void setPlanes(int node, std::uint8_t mask) {
        for (auto& [v, m] : m_planes)
            if (v == node) {
                m = mask;
                return;
            }
        m_planes.push_back({node, mask});
    }
    int sideOfVertex(const TetCut& tc, int node) const;

    TetMesh& m_mesh;
    const DecomposeOptions& m_options;
    Decomposition& m_out;
    CutChanges& m_changes;
    std::unordered_map<Tri, int, FaceHash> m_faceNodes;
    std::unordered_map<Tri, int, FaceHash> m_faceDiagonal;  ///< face -> a node on its chosen diagonal
    /// Planes each vertex of the current tet lies on: its four nodes, split points and face
    /// nodes, a dozen at most, so a list.
    std::vector<std::pair<int, std::uint8_t>> m_planes;
    /// The orientation of the tet being decomposed in the current configuration: 1, or -1
    /// where the simulation has turned it inside out. Its sub-tets take it too: the current
    /// positions of every vertex of a cut tet (nodes, split points, face nodes) are the same
    /// affine map of their reference positions, which keeps or reverses every orientation.
    int m_currentSign = 1;
    Tet m_parent{};
    std::vector<int> m_scratch;
    // Buffers reused from tet to tet (a cut decomposes a hundred tets or more).
    std::vector<SideTri> m_faceTris, m_sideTris;
    std::vector<Tri> m_cutTris;
    std::vector<Tet> m_tets;
    std::vector<std::pair<Tet, int>> m_result;
    std::vector<int> m_coneVerts, m_coneTris;
    std::vector<std::pair<int, int>> m_candidates;
};

/// Shape quality of a triangle: 4 sqrt(3) area / (sum of squared edges), 1 if equilateral.
double triangleQuality(const Vec3& a, const Vec3& b, const Vec3& c) {
    const double l2 = (b - a).squaredNorm() + (c - b).squaredNorm() + (a - c).squaredNorm();
    return l2 > 0 ? 2.0 * std::sqrt(3.0) * (b - a).cross(c - a).norm() / l2 : 0.0;
}

int Decomposer::faceNode(const Tri& corners, const std::array<int, 4>& quad) {
    Tri key = corners;
    std::sort(key.begin(), key.end());
    auto it = m_faceNodes.find(key);
    if (it != m_faceNodes.end())
        return it->second;
    // Section 4.4: the mean of the four corners of the face prism, in both configurations.
    Vec3 ref = Vec3::Zero(), pos = Vec3::Zero(), vel = Vec3::Zero();
    for (int v : quad) {
        ref += m_mesh.ref(v) / 4.0;
        pos += m_mesh.pos(v) / 4.0;
        vel += m_mesh.velocities()[v] / 4.0;
    }
    // The face node is used where its four triangles are clearly better shaped than the two
    // of the better diagonal (both tets sharing the face compute the same, from the face
    // alone); otherwise the better diagonal is used.
    {
        const auto R = [&](int v) -> const Vec3& { return m_mesh.ref(v); };
        double fan = 1, diag02 = 1, diag13 = 1;
        for (int k = 0; k < 4; ++k)
            fan = std::min(fan, triangleQuality(R(quad[k]), R(quad[(k + 1) % 4]), ref));
        diag02 = std::min(triangleQuality(R(quad[0]), R(quad[1]), R(quad[2])),
                          triangleQuality(R(quad[0]), R(quad[2]), R(quad[3])));
        diag13 = std::min(triangleQuality(R(quad[1]), R(quad[2]), R(quad[3])),
                          triangleQuality(R(quad[1]), R(quad[3]), R(quad[0])));
        if (fan < m_options.faceNodeAdvantage * std::max(diag02, diag13)) {
            // Remember the diagonal by a node on it: the neighbour walks the face the other
            // way round, so a position in the quad would not mean the same diagonal.
            m_faceDiagonal.emplace(key, diag02 >= diag13 ? quad[0] : quad[1]);
            m_faceNodes.emplace(key, -2);
            return -2;
        }
    }
    // A curved sweep may bulge past the chord between the split points into the prism; a
    // face node whose spokes would cross it is not used (the face gets the diagonal).
    if (m_options.sweep) {
        SegmentQuery query;
        for (int v : quad) {
            intersectSegment(*m_options.sweep, pos, m_mesh.pos(v), query, m_scratch);
            if (query.hits.size() % 2 == 1) {
                m_faceNodes.emplace(key, -1);
                return -1;
            }
        }
    }
    const int n = m_mesh.addNode(ref, pos);
    m_mesh.velocities()[n] = vel;
    m_faceNodes.emplace(key, n);
    ++m_out.faceNodes;
    return n;
}

int Decomposer::sideOfVertex(const TetCut& tc, int node) const {
    const Tet& q = m_mesh.tet(tc.tet);
    for (int i = 0; i < 4; ++i)
        if (q[i] == node)
            return tc.side[i];
    return 0;
}

Status Decomposer::triangulateFace(const TetCut& tc, const std::array<int, 6>& ep, int f,
                                   std::vector<SideTri>& out) {
    const Tet& q = m_mesh.tet(tc.tet);
    const auto& lf = kTetFaces[f];
    // The face's boundary cycle in outward order, with split points inserted.
    std::array<int, 6> cycle;
    std::array<char, 6> original;
    int n = 0;
    for (int s = 0; s < 3; ++s) {
        const int x = lf[s], y = lf[(s + 1) % 3];
        cycle[n] = q[x];
        original[n++] = 1;
        const int p = ep[localEdge(x, y)];
        if (p >= 0) {
            cycle[n] = p;
            original[n++] = 0;
        }
    }
    const auto at = [&](int i) { return cycle[((i % n) + n) % n]; };
    const auto isOriginal = [&](int i) { return original[((i % n) + n) % n] != 0; };
    // Side of a triangle in a completely cut tet: that of its first non-cut original node.
    const auto sideOf = [&](const Tri& t) {
        if (tc.partial)
            return 0;
        for (int v : t) {
            const int s = sideOfVertex(tc, v);
            if (s != 0)
                return s;
        }
        return 0;
    };
    const auto emit = [&](const Tri& t, int side) { out.push_back({t, side, f}); };

    switch (n) {
    case 3:
        emit({cycle[0], cycle[1], cycle[2]}, sideOf({cycle[0], cycle[1], cycle[2]}));
        break;
    case 4: {  // one split edge: fan from the opposite corner
        int ip = 0;
        while (isOriginal(ip))
            ++ip;
        const Tri t1{at(ip + 2), at(ip - 1), at(ip)}, t2{at(ip + 2), at(ip), at(ip + 1)};
        emit(t1, sideOf(t1));
        emit(t2, sideOf(t2));
        break;
    }
    case 5: {  // two split edges: corner triangle plus the face prism (a quadrilateral)
        int c = 0;
        while (!(isOriginal(c) && !isOriginal(c - 1) && !isOriginal(c + 1)))
            ++c;
        const Tri corner{at(c - 1), at(c), at(c + 1)};
        const std::array<int, 4> quad{at(c + 1), at(c + 2), at(c + 3), at(c + 4)};
        const int quadSide = tc.partial ? 0 : sideOfVertex(tc, quad[1]);
        emit(corner, tc.partial ? 0 : sideOfVertex(tc, corner[1]));
        // fn >= 0: face node; -2: the diagonal chosen for shape (enhanced mode); -1: the
        // standard rule.
        const int fn = m_options.symmetricFaces ? faceNode({q[lf[0]], q[lf[1]], q[lf[2]]}, quad) : -1;
        if (fn >= 0) {
            setPlanes(fn, static_cast<std::uint8_t>(1 << f));
            for (int k = 0; k < 4; ++k)
                emit({quad[k], quad[(k + 1) % 4], fn}, quadSide);
        } else {
            // Standard: the diagonal through the quad's smallest global index; both tets
            // sharing the face see the same indices, so they choose the same diagonal.
            const int smallest = static_cast<int>(std::min_element(quad.begin(), quad.end()) - quad.begin());
            int d = smallest % 2;
            if (fn == -2) {
                Tri key{q[lf[0]], q[lf[1]], q[lf[2]]};
                std::sort(key.begin(), key.end());
                const int onDiagonal = m_faceDiagonal.at(key);
                d = static_cast<int>(std::find(quad.begin(), quad.end(), onDiagonal) - quad.begin()) % 2;
            }
            emit({quad[d], quad[d + 1], quad[(d + 2) % 4]}, quadSide);
            emit({quad[d], quad[(d + 2) % 4], quad[(d + 3) % 4]}, quadSide);
        }
        break;
    }
    case 6: {  // all three edges split (only in partially cut tets): four triangles
        if (!tc.partial)
            return Status::error("tet " + std::to_string(tc.tet) + ": a face has three split edges in a complete cut");
        int s = 0;
        while (!isOriginal(s))
            ++s;
        emit({at(s), at(s + 1), at(s + 5)}, 0);
        emit({at(s + 1), at(s + 2), at(s + 3)}, 0);
        emit({at(s + 3), at(s + 4), at(s + 5)}, 0);
        emit({at(s + 1), at(s + 3), at(s + 5)}, 0);
        break;
    }
    default:
        return Status::error("tet " + std::to_string(tc.tet) + ": bad face cycle");
    }
    return Status::success();
}

Status Decomposer::cutPolygon(const TetCut& tc, const std::array<int, 6>& ep, std::vector<Tri>& out) {
    const Tet& q = m_mesh.tet(tc.tet);
    // Cut vertices and the faces they lie on: a cut node lies on the three faces that
    // contain it, a split point on the two faces containing its edge.
    std::vector<int> verts;
    std::vector<std::array<bool, 4>> onFace;
    for (int i = 0; i < 4; ++i)
        if (tc.nodeCode >> i & 1) {
            verts.push_back(q[i]);
            std::array<bool, 4> f{true, true, true, true};
            f[i] = false;
            onFace.push_back(f);
        }
    for (int e = 0; e < 6; ++e)
        if (ep[e] >= 0) {
            verts.push_back(ep[e]);
            std::array<bool, 4> f{true, true, true, true};
            f[kTetEdges[e][0]] = f[kTetEdges[e][1]] = false;
            onFace.push_back(f);
        }
    const int n = static_cast<int>(verts.size());
    if (n < 3 || n > 4)
        return Status::error("tet " + std::to_string(tc.tet) + ": cut polygon with " + std::to_string(n) + " corners");
    // Polygon edges: pairs of cut vertices sharing a face.
    std::vector<std::vector<int>> adj(n);
    for (int f = 0; f < 4; ++f) {
        std::vector<int> on;
        for (int k = 0; k < n; ++k)
            if (onFace[k][f])
                on.push_back(k);
        if (on.size() > 2)
            return Status::error("tet " + std::to_string(tc.tet) + ": face with more than two cut vertices");
        if (on.size() == 2) {
            auto& a = adj[on[0]];
            if (std::find(a.begin(), a.end(), on[1]) == a.end()) {
                a.push_back(on[1]);
                adj[on[1]].push_back(on[0]);
            }
        }
    }
    std::vector<int> order{0};
    for (int prev = -1, cur = 0; static_cast<int>(order.size()) < n;) {
        if (adj[cur].size() != 2)
            return Status::error("tet " + std::to_string(tc.tet) + ": cut polygon is not a cycle");
        const int next = adj[cur][0] != prev ? adj[cur][0] : adj[cur][1];
        prev = cur;
        cur = next;
        order.push_back(cur);
    }
    if (n == 3) {
        out.push_back({verts[order[0]], verts[order[1]], verts[order[2]]});
    } else {
        const int c0 = verts[order[0]], c1 = verts[order[1]], c2 = verts[order[2]], c3 = verts[order[3]];
        const double d02 = (m_mesh.ref(c0) - m_mesh.ref(c2)).squaredNorm();
        const double d13 = (m_mesh.ref(c1) - m_mesh.ref(c3)).squaredNorm();
        if (d02 <= d13) {
            out.push_back({c0, c1, c2});
            out.push_back({c0, c2, c3});
        } else {
            out.push_back({c1, c2, c3});
            out.push_back({c1, c3, c0});
        }
    }
    return Status::success();
}

Status Decomposer::cone(const std::vector<SideTri>& tris, std::vector<Tet>& tets, bool avoidCrossing) {
    // The polyhedron's vertices, sorted (a dozen at most: deduplicated as they come).
    std::vector<int>& verts = m_coneVerts;
    verts.clear();
    for (const SideTri& t : tris)
        for (int x : t.v)
            if (std::find(verts.begin(), verts.end(), x) == verts.end())
                verts.push_back(x);
    std::sort(verts.begin(), verts.end());

    const auto behind = [&](const Tri& t, const Vec3& cr, const Vec3& cp) {
        return orient3d(m_mesh.ref(t[0]), m_mesh.ref(t[1]), m_mesh.ref(t[2]), cr) < 0 &&
               m_currentSign * orient3d(m_mesh.pos(t[0]), m_mesh.pos(t[1]), m_mesh.pos(t[2]), cp) < 0;
    };
    const auto contains = [](const Tri& t, int v) { return t[0] == v || t[1] == v || t[2] == v; };

    // Candidates ordered by how many tets their cone makes.
    std::vector<std::pair<int, int>>& candidates = m_candidates; // (count, vertex)
    candidates.clear();
    for (int v : verts) {
        int count = 0;
        for (const SideTri& t : tris)
            count += contains(t.v, v) ? 0 : 1;
        candidates.push_back({count, v});
    }
    std::sort(candidates.begin(), candidates.end());
    int best = -1, bestCount = std::numeric_limits<int>::max();
    double bestQuality = -1;
    for (const auto& [count, candidate] : candidates) {
        const int v = candidate; // (a structured binding cannot be captured by clang 14's lambdas)
        if (m_options.apexByQuality ? false : count > bestCount)
            break;
        // Every tet of the cone positive in both configurations (exact, and cheap)...
        bool valid = true;
        const std::uint8_t planes = planesOf(v);
        std::vector<int>& coneTris = m_coneTris; // positions in tris of the cone's bases
        coneTris.clear();
        for (int k = 0; k < static_cast<int>(tris.size()) && valid; ++k) {
            const SideTri& st = tris[k];
            if (contains(st.v, v))
                continue;
            valid = !(planes >> st.plane & 1) && behind(st.v, m_mesh.ref(v), m_mesh.pos(v));
            coneTris.push_back(k);
        }
        if (!valid)
            continue;
        // ... then their worst radius ratio, two tets at a time. The worst only gets worse: once
        // no better than the best apex so far, this vertex cannot replace it.
        const auto tetCorners = [&](int k) {
            const Tri& t = tris[k].v;
            return std::array<Vec3, 4>{m_mesh.ref(t[0]), m_mesh.ref(t[2]), m_mesh.ref(t[1]),
                                       m_mesh.ref(v)};
        };
        double quality = std::numeric_limits<double>::infinity();
        std::size_t i = 0;
        for (; i + 1 < coneTris.size() && quality > bestQuality; i += 2) {
            const auto [first, second] =
                radiusRatioPair(tetCorners(coneTris[i]), tetCorners(coneTris[i + 1]));
            quality = std::min(quality, first);
            quality = std::min(quality, second);
        }
        if (i < coneTris.size() && quality > bestQuality) {
            const auto c = tetCorners(coneTris[i]);
            quality = std::min(quality, radiusRatio(c[0], c[1], c[2], c[3]));
        }
        if (!(quality > bestQuality))
            continue;
        if (avoidCrossing && m_options.sweep) {
            SegmentQuery query;
            for (int u : verts) {
                if (u == v)
                    continue;
                intersectSegment(*m_options.sweep, m_mesh.pos(v), m_mesh.pos(u), query, m_scratch);
                if (query.hits.size() % 2 == 1) {
                    valid = false;
                    break;
                }
            }
        }
        if (valid && quality > bestQuality) {
            best = v;
            bestCount = count;
            bestQuality = quality;
        }
    }
    int apex = best;
    if (apex < 0 && avoidCrossing)
        return Status::error("no apex avoids the sweep");
    if (apex < 0) {
        // No vertex sees every face: an interior point at the vertices' mean.
        Vec3 ref = Vec3::Zero(), pos = Vec3::Zero(), vel = Vec3::Zero();
        for (int v : verts) {
            ref += m_mesh.ref(v);
            pos += m_mesh.pos(v);
            vel += m_mesh.velocities()[v];
        }
        ref /= static_cast<double>(verts.size());
        pos /= static_cast<double>(verts.size());
        vel /= static_cast<double>(verts.size());
        const auto seesAll = [&](const Vec3& r, const Vec3& p) {
            for (const SideTri& t : tris)
                if (!behind(t.v, r, p))
                    return false;
            return true;
        };
        if (!seesAll(ref, pos)) {
            // A curved cut can leave a side whose vertex mean does not see every face: the
            // centre of its kernel (the intersection of the faces' inner half-spaces), found in
            // each configuration.
            std::vector<Tri> faces;
            for (const SideTri& t : tris)
                faces.push_back(t.v);
            bool found = kernelPoint(faces, [&](int v) -> const Vec3& { return m_mesh.ref(v); }, ref);
            if (found && m_currentSign > 0)
                found = kernelPoint(faces, [&](int v) -> const Vec3& { return m_mesh.pos(v); }, pos);
            else if (found)
                pos = currentInTet(m_mesh, m_parent, ref);  // (the kernel's image: the faces face the other way there)
            if (!found || !seesAll(ref, pos))
                return Status::error("a cut polyhedron cannot be split into positive tets");
        }
        apex = m_mesh.addNode(ref, pos);
        m_mesh.velocities()[apex] = vel;
        ++m_out.steinerPoints;
    }
    for (const SideTri& t : tris)
        if (!contains(t.v, apex))
            tets.push_back({t.v[0], t.v[2], t.v[1], apex});
    return Status::success();
}

bool Decomposer::coneFrom(const std::vector<SideTri>& tris, const Vec3& ref, const Vec3& pos, int node,
                          std::vector<Tet>& tets, double minRadiusRatio) {
    for (const SideTri& st : tris) {
        const Tri& t = st.v;
        if (t[0] == node || t[1] == node || t[2] == node)
            continue;
        if ((node >= 0 && onPlaneOf(node, st)) ||
            !(orient3d(m_mesh.ref(t[0]), m_mesh.ref(t[1]), m_mesh.ref(t[2]), ref) < 0 &&
              m_currentSign * orient3d(m_mesh.pos(t[0]), m_mesh.pos(t[1]), m_mesh.pos(t[2]), pos) < 0))
            return false;
        if (minRadiusRatio > 0 &&
            radiusRatio(m_mesh.ref(t[0]), m_mesh.ref(t[2]), m_mesh.ref(t[1]), ref) < minRadiusRatio)
            return false;
    }
    if (node < 0) {
        node = m_mesh.addNode(ref, pos);
        ++m_out.steinerPoints;
    }
    for (const SideTri& st : tris) {
        const Tri& t = st.v;
        if (t[0] != node && t[1] != node && t[2] != node)
            tets.push_back({t[0], t[2], t[1], node});
    }
    return true;
}

Status Decomposer::decompose(const TetCut& tc) {
    const Tet parent = m_mesh.tet(tc.tet);
    if (tc.scheme == Scheme::Z || tc.scheme == Scheme::Touch) {
        int side = 0;
        for (int i = 0; i < 4 && side == 0; ++i)
            side = tc.side[i];
        m_out.tetSide[tc.tet] = static_cast<std::int8_t>(side);
        return Status::success();
    }
    m_parent = parent;
    const int current = orient3d(m_mesh.pos(parent[0]), m_mesh.pos(parent[1]), m_mesh.pos(parent[2]), m_mesh.pos(parent[3]));
    if (current == 0)
        return Status::error("tet " + std::to_string(tc.tet) + " is flat in the current configuration");
    m_currentSign = current > 0 ? 1 : -1;
    std::array<int, 6> ep;
    for (int e = 0; e < 6; ++e) {
        ep[e] = -1;
        if (tc.edgeCode >> e & 1)
            ep[e] = m_out.edgePoint.at(edgeKey(parent[kTetEdges[e][0]], parent[kTetEdges[e][1]]));
    }
    // Planes each vertex lies on: node i on the three faces other than face i, a split point
    // on the two faces containing its edge; cut nodes and (in complete cuts) split points
    // also on the cut polygon. Face nodes are added as they are made.
    m_planes.clear();
    for (int i = 0; i < 4; ++i) {
        std::uint8_t mask = static_cast<std::uint8_t>(0xF & ~(1 << i));
        if (tc.nodeCode >> i & 1)
            mask |= 1 << kCutPlane;
        setPlanes(parent[i], mask);
    }
    for (int e = 0; e < 6; ++e)
        if (ep[e] >= 0)
            setPlanes(ep[e], static_cast<std::uint8_t>(
                                 (0xF & ~(1 << kTetEdges[e][0]) & ~(1 << kTetEdges[e][1])) |
                                 (tc.partial ? 0 : 1 << kCutPlane)));
    std::vector<SideTri>& faceTris = m_faceTris;
    faceTris.clear();
    for (int f = 0; f < 4; ++f)
        if (Status s = triangulateFace(tc, ep, f, faceTris); !s.ok())
            return s;

    std::vector<std::pair<Tet, int>>& result = m_result; // sub-tet and its side
    result.clear();
    if (tc.partial) {
        const std::vector<SideTri>& tris = faceTris;
        // The sweep ends inside this tet and the crack stays closed here. The cone apex is
        // put on the sweep, so that no new edge crosses it.
        std::vector<int> points;
        for (int e = 0; e < 6; ++e)
            if (ep[e] >= 0)
                points.push_back(ep[e]);
        std::vector<Tet>& tets = m_tets;
        tets.clear();
        bool done = false;
        if (points.size() == 1)
            done = coneFrom(tris, m_mesh.ref(points[0]), m_mesh.pos(points[0]), points[0], tets);
        // Otherwise a new interior point on the sweep: tried at the mean of the split points,
        // then half-way towards the tet's centre and at the centre (each projected onto the
        // sweep; its reference position from barycentric coordinates in the parent tet).
        Vec3 meanPos = Vec3::Zero(), centre = Vec3::Zero(), vel = Vec3::Zero();
        for (int p : points) {
            meanPos += m_mesh.pos(p) / static_cast<double>(points.size());
            vel += m_mesh.velocities()[p] / static_cast<double>(points.size());
        }
        for (int v : parent)
            centre += m_mesh.pos(v) / 4.0;
        for (const double floor : {m_options.minSteinerRadiusRatio, m_options.minSteinerRadiusRatio / 20})
            for (const Vec3& guess : {meanPos, Vec3(0.5 * (meanPos + centre)), centre}) {
                if (done || points.size() < 2)
                    break;
                const Vec3 onSweep = m_options.sweep ? m_options.sweep->closestPoint(guess).point : guess;
                const Vec3 ref = referenceInTet(m_mesh, parent, onSweep);
                if (!ref.allFinite())
                    continue;
                const int before = m_mesh.nodeCount();
                if (coneFrom(tris, ref, onSweep, -1, tets, floor)) {
                    done = true;
                    m_mesh.velocities()[before] = vel;
                    m_out.sweepPoints.push_back(before);
                }
            }
        if (!done)
            done = cone(tris, tets, /*avoidCrossing=*/true).ok();
        if (!done)
            if (Status s = cone(tris, tets); !s.ok())
                return Status::error("tet " + std::to_string(tc.tet) + ": " + s.message());
        for (const Tet& t : tets)
            result.push_back({t, 0});
    } else {
        std::vector<Tri>& cut = m_cutTris;
        cut.clear();
        if (Status s = cutPolygon(tc, ep, cut); !s.ok())
            return s;
        for (int side : {1, -1}) {
            int representative = -1;
            for (int i = 0; i < 4; ++i)
                if (tc.side[i] == side)
                    representative = parent[i];
            if (representative < 0)
                return Status::error("tet " + std::to_string(tc.tet) + ": a side without nodes");
            std::vector<SideTri>& tris = m_sideTris;
            tris.clear();
            for (const SideTri& t : faceTris) {
                if (t.side == 0)
                    return Status::error("tet " + std::to_string(tc.tet) + ": a face triangle on no side");
                if (t.side == side)
                    tris.push_back(t);
            }
            for (Tri t : cut) {
                const int o = orient3d(m_mesh.ref(t[0]), m_mesh.ref(t[1]), m_mesh.ref(t[2]),
                                       m_mesh.ref(representative));
                if (o == 0)
                    return Status::error("tet " + std::to_string(tc.tet) + ": flat cut polygon");
                if (o > 0)
                    std::swap(t[1], t[2]);
                tris.push_back({t, side, kCutPlane});
            }
            std::vector<Tet>& tets = m_tets;
            tets.clear();
            if (Status s = cone(tris, tets); !s.ok())
                return Status::error("tet " + std::to_string(tc.tet) + ": " + s.message());
            for (const Tet& t : tets)
                result.push_back({t, side});
        }
    }
    // The first sub-tet takes the parent's place; the others are appended.
    m_changes.modifiedTets.push_back(tc.tet);
    m_mesh.replaceTet(tc.tet, result[0].first);
    m_out.tetSide[tc.tet] = static_cast<std::int8_t>(result[0].second);
    for (std::size_t k = 1; k < result.size(); ++k) {
        const int t = m_mesh.addTet(result[k].first);
        m_changes.parentOfNewTet.push_back(tc.tet);
        m_out.tetSide[t] = static_cast<std::int8_t>(result[k].second);
    }
    ++m_out.decomposedTets;
    return Status::success();
}

} // namespace

Status decomposeTets(TetMesh& mesh, const CutSelection& selection, const DecomposeOptions& options,
                     Decomposition& out, CutChanges& changes) {
    // Split points on the cut edges: Eq. 1, the crossing parameter t of the deformed
    // configuration applied to the reference positions (and velocities).
    // The two walls of an earlier crack have edges at the same reference positions (twins, by
    // different nodes). Computed from opposite ends, their split points can land a rounding
    // apart, and one wall's new node then hangs on the other wall's face (a T-junction, traced
    // on the lattice box with twenty partial strokes before the improvement's guard refused
    // hanging nodes; issue 16). Where it would, the second twin takes the first one's point.
    std::map<std::array<double, 6>, std::pair<int, std::array<int, 2>>> firstOfTwins;
    for (const EdgeCrossing& c : selection.cutEdges) {
        const double t = c.hit.t;
        Vec3 ref = mesh.ref(c.a) + t * (mesh.ref(c.b) - mesh.ref(c.a));
        const Vec3 pos = mesh.pos(c.a) + t * (mesh.pos(c.b) - mesh.pos(c.a));
        const auto [twin, first] =
            firstOfTwins.try_emplace(edgePositionKey(mesh, c.a, c.b), mesh.nodeCount(), std::array<int, 2>{c.a, c.b});
        if (!first) {
            const Vec3& other = mesh.ref(twin->second.first);
            const auto [ta, tb] = twin->second.second;
            if (other != ref && (hangsOnBoundaryFaceAt(mesh, ref, ta, tb) || hangsOnBoundaryFaceAt(mesh, other, c.a, c.b)))
                ref = other;
        }
        const int n = mesh.addNode(ref, pos);
        mesh.velocities()[n] = (1 - t) * mesh.velocities()[c.a] + t * mesh.velocities()[c.b];
        out.edgePoint.emplace(edgeKey(c.a, c.b), n);
    }
    Decomposer decomposer(mesh, options, out, changes);
    for (const TetCut& tc : selection.tets)
        if (tc.partial)
            decomposer.excludeFaceNodes(mesh, tc);
    for (const TetCut& tc : selection.tets)
        if (Status s = decomposer.decompose(tc); !s.ok())
            return s;
    return Status::success();
}

} // namespace resect
