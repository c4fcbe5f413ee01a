#pragma once
// Validity check of a tet mesh: returns every problem found, never throws.

#include "core/mesh/tet_mesh.h"

#include <array>
#include <string>
#include <vector>

namespace resect {

struct MeshProblem {
    enum class Kind {
        NonFiniteCoordinate,  ///< a reference or current coordinate is NaN or infinite
        InvertedTet,          ///< negative orientation in the reference configuration
        ZeroVolumeTet,        ///< exactly coplanar corners in the reference configuration
        InvertedCurrentTet,   ///< non-positive orientation in the current configuration
        OverSharedFace,       ///< a face shared by more than two tets
        TJunction,            ///< a node lying on a boundary face of its own piece without
                              ///< being (or coinciding with) one of its corners
        UnusedNode,           ///< a node in no tet
    };
    Kind kind;
    int element;          ///< the node or tet index concerned (first node for faces)
    std::string message;  ///< plain description naming the element
};

const char* toString(MeshProblem::Kind kind);

/// Whether a node at p hangs on the triangle (a, b, c) as checkValidity decides it (a
/// T-junction where the triangle is a boundary face of p's piece): p lies in the closed
/// triangle, exactly, without being at one of its corners' positions (separated cut nodes
/// coincide by design). The improvement's overlap guard refuses placements by the same test.
bool hangsOn(const Vec3& p, const Vec3& a, const Vec3& b, const Vec3& c);

/// Whether a point at p hangs on a boundary face of the mesh (a face in one tet only) that
/// has the edge (a, b), by hangsOn. Costs the tets at a.
bool hangsOnBoundaryFaceAt(const TetMesh& mesh, const Vec3& p, int a, int b);

/// The reference positions of the ends of edge (a, b), the lexicographically smaller first:
/// the same for the copies of an edge on the two walls of a crack (twins), whichever way
/// their nodes are numbered.
std::array<double, 6> edgePositionKey(const TetMesh& mesh, int a, int b);

/// Orientation decisions use exact predicates (predicates.h). Unused nodes and inverted
/// current tets are reported as problems too; the caller decides what is fatal.
std::vector<MeshProblem> checkValidity(const TetMesh& mesh);

/// Where the mesh overlaps itself most (reference configuration): the boundary node lying
/// deepest inside a tet it is not a corner of (no corner of the tet at its position either:
/// separated cut nodes coincide by design), with its depth, the distance to the tet's nearest
/// face plane. Tets that overlap have a boundary node in another tet (or edges that cross
/// faces, which this does not look for). A conforming mesh has depth 0; rounding leaves
/// points computed on a shared surface (a cut's) about 1e-16 of an edge inside their
/// neighbours. Cost: a grid over the tets, O(mesh).
struct MeshOverlap {
    double depth = 0;  ///< 0: none
    int node = -1, tet = -1;
};
MeshOverlap deepestOverlap(const TetMesh& mesh);

/// Depth of point x strictly inside the tet with corners c, which must be positively oriented
/// (orient3d(c) > 0): the distance to its nearest face plane; 0 where x is not strictly inside
/// (exact orient3d decides). deepestOverlap and the improvement's overlap guard measure with it.
double depthInside(const Vec3& x, const std::array<Vec3, 4>& c);

} // namespace resect
