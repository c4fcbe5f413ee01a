#include "core/cut/separate.h"

#include "core/mesh/union_find.h"

#include <algorithm>
#include <unordered_map>
#include <unordered_set>

namespace resect {

Separation separate(TetMesh& mesh, const CutSelection& selection, const Decomposition& decomposition,
                    CutChanges& changes) {
    Separation result;
    std::vector<int> cutVertices = selection.cutNodes;
    for (const auto& [key, node] : decomposition.edgePoint)
        cutVertices.push_back(node);
    std::sort(cutVertices.begin(), cutVertices.end());
    const std::unordered_set<int> isCut(cutVertices.begin(), cutVertices.end());
    const auto sideOfTet = [&](int t) {
        auto it = decomposition.tetSide.find(t);
        return it == decomposition.tetSide.end() ? 0 : static_cast<int>(it->second);
    };

    std::unordered_set<int> separatedTets;
    for (int v : cutVertices) {
        const std::vector<int> star(mesh.nodeTets(v).begin(), mesh.nodeTets(v).end());
        const int n = static_cast<int>(star.size());
        UnionFind groups(n);  // over the positions k of star
        // Faces containing v, keyed by their other two nodes.
        std::unordered_map<std::uint64_t, int> firstTetOfFace;
        for (int k = 0; k < n; ++k) {
            const Tet& q = mesh.tet(star[k]);
            for (int i = 0; i < 4; ++i) {
                if (q[i] == v)
                    continue;
                for (int j = i + 1; j < 4; ++j) {
                    if (q[j] == v)
                        continue;
                    const std::uint64_t key = edgeKey(q[i], q[j]);
                    auto [it, inserted] = firstTetOfFace.try_emplace(key, k);
                    if (inserted)
                        continue;
                    const int other = it->second;
                    const int s1 = sideOfTet(star[k]), s2 = sideOfTet(star[other]);
                    const bool cutFace = s1 != 0 && s2 != 0 && s1 != s2 && isCut.count(q[i]) &&
                                         isCut.count(q[j]);
                    if (!cutFace)
                        groups.unite(k, other);
                }
            }
        }
        // One copy of v per extra group; the group of the first tet on the + side keeps v.
        std::unordered_map<int, int> nodeOfGroup;
        int keeper = -1;
        for (int k = 0; k < n && keeper < 0; ++k)
            if (sideOfTet(star[k]) > 0)
                keeper = groups.find(k);
        if (keeper < 0)
            keeper = groups.find(0);
        nodeOfGroup[keeper] = v;
        for (int k = 0; k < n; ++k) {
            const int g = groups.find(k);
            auto it = nodeOfGroup.find(g);
            int node;
            if (it == nodeOfGroup.end()) {
                node = mesh.addNode(mesh.ref(v), mesh.pos(v));
                mesh.velocities()[node] = mesh.velocities()[v];
                nodeOfGroup.emplace(g, node);
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
            separatedTets.insert(star[k]);
            if (star[k] < changes.firstNewTet)
                changes.modifiedTets.push_back(star[k]);
        }
    }
    result.separatedTets = static_cast<int>(separatedTets.size());
    return result;
}

} // namespace resect
