#pragma once
// The star of a node (its incident tets), read once for the two things the steps of a cut
// ask of every node near the cut: its neighbours and whether it lies on the mesh boundary.
// The answers are those of TetMesh::nodeNeighbours and isBoundaryNode (topology.h); this
// reads the star once for both, in O(valence), and reuses its buffers from node to node
// (they include an array over the mesh's nodes, allocated by the first gather).

#include "core/mesh/tet_mesh.h"

#include <cstdint>
#include <span>
#include <vector>

namespace resect {

class NodeStar {
public:
    /// Reads the star of node n (replacing the previous one).
    void gather(const TetMesh& mesh, int n);
    /// Nodes sharing an edge with n, sorted, without duplicates.
    std::span<const int> neighbours() const { return m_neighbours; }
    /// True if a face at n belongs to one tet only (the node is on the boundary).
    bool onBoundary() const { return m_onBoundary; }

private:
    bool boundaryFromSortedFaces(const TetMesh& mesh, int n);

    std::vector<int> m_neighbours;
    /// Per mesh node: its position in m_neighbours, valid where m_seen holds this gather's
    /// stamp (grown to the mesh once, then each gather touches only its star).
    std::vector<int> m_position;
    std::vector<std::uint32_t> m_seen;
    std::uint32_t m_stamp = 0;
    /// Faces at the node by their other two corners (positions x < y in m_neighbours before
    /// sorting): bit y of once[x] / twice[x] is set when the face was seen once / more often.
    static constexpr int kMaskBits = 64;
    std::uint64_t m_once[kMaskBits], m_twice[kMaskBits];
    std::vector<std::uint64_t> m_faces; ///< for stars of more than 64 neighbours
    bool m_onBoundary = false;
};

} // namespace resect
