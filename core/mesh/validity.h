#pragma once
// Validity check of a tet mesh: returns every problem found, never throws.

#include "core/mesh/tet_mesh.h"

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

/// Orientation decisions use exact predicates (predicates.h). Unused nodes and inverted
/// current tets are reported as problems too; the caller decides what is fatal.
std::vector<MeshProblem> checkValidity(const TetMesh& mesh);

} // namespace resect
