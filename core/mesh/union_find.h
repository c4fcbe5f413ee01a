#pragma once
// UnionFind: disjoint sets over the indices 0 .. size()-1, the one union-find of the core
// (connected components, fans around a vertex, groups of tet nodes, separation of cut
// vertices, cut-face caps).
//
// find() halves paths (every node on the way points to its grandparent), so a sequence of
// operations costs nearly O(1) each. unite(a, b) always puts the root of a's set under the
// root of b's set: the representative of the union is find(b) as it was before the call.
// Callers that use representatives as keys (and iterate over them in order) rely on this
// rule; path halving never changes which element is a root, only how fast it is reached.

#include <numeric>
#include <vector>

namespace resect {

class UnionFind {
public:
    UnionFind() = default;
    /// n singletons {0}, {1}, ..., {n-1}.
    explicit UnionFind(int n) { reset(n); }

    /// Back to n singletons (reuses the storage).
    void reset(int n) {
        m_parent.resize(static_cast<std::size_t>(n));
        std::iota(m_parent.begin(), m_parent.end(), 0);
        m_sets = n;
    }

    int size() const { return static_cast<int>(m_parent.size()); }
    /// Number of disjoint sets.
    int setCount() const { return m_sets; }

    /// Representative (root) of x's set, with path halving.
    int find(int x) {
        while (m_parent[x] != x) {
            m_parent[x] = m_parent[m_parent[x]];
            x = m_parent[x];
        }
        return x;
    }

    /// Joins the sets of a and b; the root of b's set becomes the root of the union.
    /// Returns false if they were already one set.
    bool unite(int a, int b) {
        const int ra = find(a), rb = find(b);
        if (ra == rb)
            return false;
        m_parent[ra] = rb;
        --m_sets;
        return true;
    }

    /// Dense set labels 0 .. k-1 for the elements i with keep(i), numbered in the order of
    /// each set's first kept element (so independent of which element is the root); -1 for
    /// the others. `label` is resized to size(); returns k.
    template <class Keep> int compact(std::vector<int>& label, Keep keep) {
        label.assign(m_parent.size(), -1);
        std::vector<int> ofRoot(m_parent.size(), -1);
        int count = 0;
        for (int i = 0; i < size(); ++i) {
            if (!keep(i))
                continue;
            int& l = ofRoot[find(i)];
            if (l < 0)
                l = count++;
            label[i] = l;
        }
        return count;
    }
    /// Dense labels for every element.
    int compact(std::vector<int>& label) {
        return compact(label, [](int) { return true; });
    }

private:
    std::vector<int> m_parent;
    int m_sets = 0;
};

} // namespace resect
