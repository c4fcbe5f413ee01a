#include "core/mesh/topology.h"

#include "core/mesh/union_find.h"

#include <algorithm>
#include <unordered_map>

namespace resect {
namespace {

/// Hash of a sorted face (used as an unordered_map key).
struct TriHash {
    std::size_t operator()(const Tri& f) const {
        std::uint64_t h = static_cast<std::uint32_t>(f[0]);
        h = h * 0x9E3779B97F4A7C15ull + static_cast<std::uint32_t>(f[1]);
        h = (h ^ (h >> 29)) * 0xBF58476D1CE4E5B9ull + static_cast<std::uint32_t>(f[2]);
        return static_cast<std::size_t>(h ^ (h >> 32));
    }
};

Tri sorted(Tri f) {
    std::sort(f.begin(), f.end());
    return f;
}

} // namespace

std::vector<std::array<int, 2>> uniqueEdges(const TetMesh& mesh) {
    // Per node, collect higher-indexed neighbours through node->tets: O(sum of valences).
    std::vector<std::array<int, 2>> edges;
    edges.reserve(static_cast<std::size_t>(mesh.tetCount()) * 7 / 5 + 16);
    std::vector<int> scratch;
    for (int n = 0; n < mesh.nodeCount(); ++n) {
        scratch.clear();
        for (int t : mesh.nodeTets(n))
            for (int v : mesh.tet(t))
                if (v > n)
                    scratch.push_back(v);
        std::sort(scratch.begin(), scratch.end());
        scratch.erase(std::unique(scratch.begin(), scratch.end()), scratch.end());
        for (int v : scratch)
            edges.push_back({n, v});
    }
    return edges;
}

namespace {

/// One face of the mesh: the first two of its (tet, local face) ids, t * 4 + local face, in
/// scan order (tets ascending, then local faces), and how many there are.
struct FaceRun {
    int first, second, count;
};

/// Every face once, in the order a scan of the tets meets them (by first id). Each (tet, local
/// face) is filed under its face's smallest node (counting sort) and each node's few faces are
/// sorted by the other two, so that equal faces are neighbours: 5-10 times faster than a hash
/// map of every face. `onlyInOneTet`: the boundary faces only. False (and nothing) if a node
/// index is out of range.
bool faceRuns(const TetMesh& mesh, std::vector<FaceRun>& runs, bool onlyInOneTet = false) {
    runs.clear();
    const int tets = mesh.tetCount(), nodes = mesh.nodeCount();
    for (int t = 0; t < tets; ++t)
        for (int v : mesh.tet(t))
            if (v < 0 || v >= nodes)
                return false;
    std::vector<int> start(static_cast<std::size_t>(nodes) + 1, 0);
    for (int t = 0; t < tets; ++t) {
        const Tet& q = mesh.tet(t);
        for (const auto& lf : kTetFaces)
            ++start[static_cast<std::size_t>(std::min({q[lf[0]], q[lf[1]], q[lf[2]]})) + 1];
    }
    for (int n = 0; n < nodes; ++n)
        start[n + 1] += start[n];
    struct Entry {
        int b, c, id;  ///< the other two nodes (b <= c), and t * 4 + local face
    };
    std::vector<Entry> entries(static_cast<std::size_t>(tets) * 4);
    std::vector<int> fill(start.begin(), start.end() - 1);
    for (int t = 0; t < tets; ++t) {
        const Tet& q = mesh.tet(t);
        for (int i = 0; i < 4; ++i) {
            std::array<int, 3> f{q[kTetFaces[i][0]], q[kTetFaces[i][1]], q[kTetFaces[i][2]]};
            std::sort(f.begin(), f.end());
            entries[fill[f[0]]++] = {f[1], f[2], t * 4 + i};
        }
    }
    runs.reserve(entries.size() / 2 + 16);
    for (int n = 0; n < nodes; ++n) {
        const auto first = entries.begin() + start[n], last = entries.begin() + start[n + 1];
        std::sort(first, last, [](const Entry& x, const Entry& y) {
            return x.b != y.b ? x.b < y.b : x.c != y.c ? x.c < y.c : x.id < y.id;
        });
        for (auto it = first; it != last;) {
            auto end = it + 1;
            while (end != last && end->b == it->b && end->c == it->c)
                ++end;
            if (!onlyInOneTet || end - it == 1)
                runs.push_back({it->id, end - it > 1 ? (it + 1)->id : -1, static_cast<int>(end - it)});
            it = end;
        }
    }
    std::sort(runs.begin(), runs.end(), [](const FaceRun& x, const FaceRun& y) { return x.first < y.first; });
    return true;
}

/// Local face id % 4 of tet id / 4, oriented as in that tet.
Tri faceOf(const TetMesh& mesh, int id) {
    const Tet& q = mesh.tet(id / 4);
    const auto& lf = kTetFaces[id % 4];
    return Tri{q[lf[0]], q[lf[1]], q[lf[2]]};
}

/// allFaces through a hash map of every face: the general path (any node indices).
std::vector<MeshFace> allFacesHashed(const TetMesh& mesh) {
    std::unordered_map<Tri, int, TriHash> index;
    index.reserve(static_cast<std::size_t>(mesh.tetCount()) * 2 + 16);
    std::vector<MeshFace> faces;
    faces.reserve(static_cast<std::size_t>(mesh.tetCount()) * 2 + 16);
    for (int t = 0; t < mesh.tetCount(); ++t) {
        const Tet& q = mesh.tet(t);
        for (const auto& lf : kTetFaces) {
            const Tri f{q[lf[0]], q[lf[1]], q[lf[2]]};
            auto [it, inserted] = index.try_emplace(sorted(f), static_cast<int>(faces.size()));
            if (inserted) {
                faces.push_back({f, {t, -1}, 0});
            } else {
                MeshFace& face = faces[it->second];
                if (face.tets[1] < 0)
                    face.tets[1] = t;
                else
                    ++face.extraTets;
            }
        }
    }
    return faces;
}

} // namespace

std::vector<MeshFace> allFaces(const TetMesh& mesh) {
    std::vector<FaceRun> runs;
    if (!faceRuns(mesh, runs))
        return allFacesHashed(mesh);
    std::vector<MeshFace> faces;
    faces.reserve(runs.size());
    for (const FaceRun& r : runs)
        faces.push_back({faceOf(mesh, r.first), {r.first / 4, r.second >= 0 ? r.second / 4 : -1}, std::max(0, r.count - 2)});
    return faces;
}

std::vector<BoundaryFace> boundaryFaces(const TetMesh& mesh) {
    std::vector<BoundaryFace> result;
    std::vector<FaceRun> runs;
    if (!faceRuns(mesh, runs, true)) {
        for (const MeshFace& f : allFacesHashed(mesh))
            if (f.tets[1] < 0)
                result.push_back({f.nodes, f.tets[0]});
        return result;
    }
    result.reserve(runs.size());
    for (const FaceRun& r : runs)  // (only faces in one tet: faceRuns's onlyInOneTet)
        result.push_back({faceOf(mesh, r.first), r.first / 4});
    return result;
}

bool isBoundaryNode(const TetMesh& mesh, int n) {
    std::vector<int> scratch;
    for (int t : mesh.nodeTets(n)) {
        const Tet& q = mesh.tet(t);
        for (const auto& lf : kTetFaces) {
            const int a = q[lf[0]], b = q[lf[1]], c = q[lf[2]];
            if (a != n && b != n && c != n)
                continue;
            mesh.faceTets(a, b, c, scratch);
            if (scratch.size() == 1)
                return true;
        }
    }
    return false;
}

bool isBoundaryEdge(const TetMesh& mesh, int a, int b) {
    // Every face (a, b, v) lies in tets around the edge; it belongs to one tet only when v is
    // the third node of exactly one of them.
    std::vector<int> third;
    for (int t : mesh.nodeTets(a)) {
        const Tet& q = mesh.tet(t);
        if (std::find(q.begin(), q.end(), b) == q.end())
            continue;
        for (int v : q)
            if (v != a && v != b)
                third.push_back(v);
    }
    std::sort(third.begin(), third.end());
    for (std::size_t i = 0; i < third.size();) {
        std::size_t j = i + 1;
        while (j < third.size() && third[j] == third[i])
            ++j;
        if (j - i == 1)
            return true;
        i = j;
    }
    return false;
}

Components connectedComponents(const TetMesh& mesh) {
    // Union-find over nodes: the nodes of a tet are joined; tets inherit their nodes' set.
    // Components are numbered in the order of their lowest node.
    UnionFind sets(mesh.nodeCount());
    for (const Tet& q : mesh.tets())
        for (int i = 1; i < 4; ++i)
            sets.unite(q[i], q[0]);
    Components c;
    c.count = sets.compact(c.nodeComponent, [&](int n) { return !mesh.nodeTets(n).empty(); });
    c.tetComponent.resize(mesh.tetCount());
    for (int t = 0; t < mesh.tetCount(); ++t)
        c.tetComponent[t] = c.nodeComponent[mesh.tet(t)[0]];
    return c;
}

} // namespace resect
