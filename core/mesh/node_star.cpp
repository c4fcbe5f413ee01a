#include "core/mesh/node_star.h"

#include <algorithm>

namespace resect {

void NodeStar::gather(const TetMesh& mesh, int n) {
    m_neighbours.clear();
    if (m_seen.size() < static_cast<std::size_t>(mesh.nodeCount())) {
        m_seen.resize(mesh.nodeCount(), 0);
        m_position.resize(mesh.nodeCount());
    }
    if (++m_stamp == 0) {
        std::fill(m_seen.begin(), m_seen.end(), 0);
        m_stamp = 1;
    }
    // One pass over the star: each corner other than n gets its position among the
    // neighbours (a stamp per mesh node says whether it has one yet), and each face at n,
    // named by the positions of its other two corners, is counted in the bit masks. A face
    // in one tet only puts n on the boundary.
    bool fitsMasks = true;
    for (int t : mesh.nodeTets(n)) {
        int corner[3];
        int k = 0;
        for (int v : mesh.tet(t)) {
            if (v == n || k == 3)
                continue;
            if (m_seen[v] != m_stamp) {
                m_seen[v] = m_stamp;
                m_position[v] = static_cast<int>(m_neighbours.size());
                if (m_neighbours.size() < kMaskBits)
                    m_once[m_neighbours.size()] = m_twice[m_neighbours.size()] = 0;
                m_neighbours.push_back(v);
            }
            corner[k++] = m_position[v];
        }
        if (!fitsMasks || k < 3 || std::max({corner[0], corner[1], corner[2]}) >= kMaskBits) {
            fitsMasks = false;
            continue;
        }
        const auto count = [&](int x, int y) {
            if (x > y)
                std::swap(x, y);
            // once -> twice -> twice, branch-free (the pairs come in no predictable pattern).
            const std::uint64_t bit = std::uint64_t{1} << y;
            const std::uint64_t seenOnce = m_once[x] & bit;
            m_once[x] ^= bit & ~m_twice[x];
            m_twice[x] |= seenOnce;
        };
        count(corner[0], corner[1]);
        count(corner[0], corner[2]);
        count(corner[1], corner[2]);
    }
    if (fitsMasks)
        m_onBoundary = std::any_of(m_once, m_once + m_neighbours.size(),
                                   [](std::uint64_t m) { return m != 0; });
    else
        m_onBoundary = boundaryFromSortedFaces(mesh, n);
    std::sort(m_neighbours.begin(), m_neighbours.end());
}

bool NodeStar::boundaryFromSortedFaces(const TetMesh& mesh, int n) {
    // Stars too large for the masks: sort the faces' keys and look for one seen once.
    m_faces.clear();
    for (int t : mesh.nodeTets(n)) {
        const Tet& q = mesh.tet(t);
        for (int i = 0; i < 4; ++i)
            for (int j = i + 1; j < 4; ++j) {
                if (q[i] == n || q[j] == n)
                    continue;
                const auto a = static_cast<std::uint64_t>(std::min(q[i], q[j]));
                const auto b = static_cast<std::uint64_t>(std::max(q[i], q[j]));
                m_faces.push_back(a << 32 | b);
            }
    }
    std::sort(m_faces.begin(), m_faces.end());
    for (std::size_t i = 0; i < m_faces.size();) {
        std::size_t j = i + 1;
        while (j < m_faces.size() && m_faces[j] == m_faces[i])
            ++j;
        if (j - i == 1)
            return true;
        i = j;
    }
    return false;
}

} // namespace resect
