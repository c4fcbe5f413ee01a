#pragma once
// Global derived topology of a TetMesh, built on demand (O(mesh)): the unique edge list,
// faces with their tets, boundary faces and connected components ("pieces").

#include "core/mesh/tet_mesh.h"

#include <vector>

namespace resect {

/// Every edge of the mesh once, as (a, b) with a < b, sorted lexicographically.
std::vector<std::array<int, 2>> uniqueEdges(const TetMesh& mesh);

/// A face and the tets that share it (tets[1] = -1 on the boundary).
struct MeshFace {
    Tri nodes;                 ///< oriented outward from tets[0]
    std::array<int, 2> tets;   ///< tets[1] == -1 for a boundary face
    int extraTets = 0;         ///< tets beyond two sharing this face (non-conforming if > 0)
};

/// Every face of the mesh once.
std::vector<MeshFace> allFaces(const TetMesh& mesh);

/// Boundary faces (in exactly one tet), oriented outward, with the owning tet.
struct BoundaryFace {
    Tri nodes;
    int tet;
};
std::vector<BoundaryFace> boundaryFaces(const TetMesh& mesh);

/// True if node n has an incident face that belongs to one tet only (O(valence^2)).
bool isBoundaryNode(const TetMesh& mesh, int n);

/// True if edge (a, b), a != b, has an incident face that belongs to one tet only: the edge
/// lies on the mesh boundary (the original surface or an earlier cut). False if no tet
/// contains the edge. O(v log v) for v the valence of a.
bool isBoundaryEdge(const TetMesh& mesh, int a, int b);

/// Connected components: tets are connected when they share a node (nodes separated by a
/// cut are distinct, so each piece of a cut mesh is one component).
struct Components {
    int count = 0;
    std::vector<int> tetComponent;   ///< #tets, component of each tet
    std::vector<int> nodeComponent;  ///< #nodes, component of each node, -1 for unused nodes
};
Components connectedComponents(const TetMesh& mesh);

} // namespace resect
