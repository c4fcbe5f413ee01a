#include "core/cut/separate.h"

#include "core/mesh/edge_key_table.h"
#include "core/mesh/index_marks.h"
#include "core/mesh/union_find.h"

#include <algorithm>

namespace resect {

Separation separate(TetMesh& mesh, const CutSelection& selection, const Decomposition& decomposition,
                    CutChanges& changes) {
    Separation result;
    std::vector<int> cutVertices = selection.cutNodes;
    for (const auto& [key, node] : decomposition.edgePoint)
        cutVertices.push_back(node);
    std::sort(cutVertices.begin(), cutVertices.end());
    const auto isCut = [&](int v) {
        return std::binary_search(cutVertices.begin(), cutVertices.end(), v);
    };
    // Sides by tet (0 where the decomposition gave none), read for every tet of every star;
    // marks kept between cuts on this thread (see "Marks" at HybridCutter::cut).
    thread_local IndexMarks<std::int8_t> sideOfTet;
    const auto scope = sideOfTet.use(mesh.tetCount());
    for (const auto& [t, s] : decomposition.tetSide)
        if (t < mesh.tetCount())
            sideOfTet.set(t, s);

    // Reused from vertex to vertex: the star, its tets' sides, its faces, its groups.
    std::vector<int> star, side, separatedTets;
    EdgeKeyTable firstTetOfFace;
    UnionFind groups;
    std::vector<std::pair<int, int>> nodeOfGroup; // (group representative, node), a few
    for (int v : cutVertices) {
        star.assign(mesh.nodeTets(v).begin(), mesh.nodeTets(v).end());
        const int n = static_cast<int>(star.size());
        side.resize(n);
        for (int k = 0; k < n; ++k)
            side[k] = sideOfTet[star[k]];
        groups.reset(n); // over the positions k of star
        // Faces containing v, keyed by their other two nodes: a face's tets are joined unless
        // it is a cut face.
        firstTetOfFace.clear();
        for (int k = 0; k < n; ++k) {
            const Tet& q = mesh.tet(star[k]);
            for (int i = 0; i < 4; ++i) {
                if (q[i] == v)
                    continue;
                for (int j = i + 1; j < 4; ++j) {
                    if (q[j] == v)
                        continue;
                    const auto [other, inserted] = firstTetOfFace.tryInsert(edgeKey(q[i], q[j]), k);
                    if (inserted)
                        continue;
                    const int s1 = side[k], s2 = side[other];
                    const bool cutFace =
                        s1 != 0 && s2 != 0 && s1 != s2 && isCut(q[i]) && isCut(q[j]);
                    if (!cutFace)
                        groups.unite(k, other);
                }
            }
        }
        // One copy of v per extra group; the group of the first tet on the + side keeps v.
        int keeper = -1;
        for (int k = 0; k < n && keeper < 0; ++k)
            if (side[k] > 0)
                keeper = groups.find(k);
        if (keeper < 0)
            keeper = groups.find(0);
        nodeOfGroup.assign(1, {keeper, v});
        for (int k = 0; k < n; ++k) {
            const int g = groups.find(k);
            auto it = std::find_if(nodeOfGroup.begin(), nodeOfGroup.end(),
                                   [&](const auto& e) { return e.first == g; });
            int node;
            if (it == nodeOfGroup.end()) {
                node = mesh.addNode(mesh.ref(v), mesh.pos(v));
                mesh.velocities()[node] = mesh.velocities()[v];
                nodeOfGroup.push_back({g, node});
                changes.duplicatedNodes.push_back({v, node});
                ++result.duplicatedNodes;
            } else {
                node = it->second;
            }
            if (node == v)
                continue;
            Tet q = mesh.tet(star[k]);
            std::replace(q.begin(), q.end(), v, node);
            mesh.replaceTet(star[k], q);
            separatedTets.push_back(star[k]);
            if (star[k] < changes.firstNewTet)
                changes.modifiedTets.push_back(star[k]);
        }
    }
    std::sort(separatedTets.begin(), separatedTets.end());
    result.separatedTets = static_cast<int>(
        std::unique(separatedTets.begin(), separatedTets.end()) - separatedTets.begin());
    return result;
}

} // namespace resect
