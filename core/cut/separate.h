#pragma once
// Step 5 of the cut (sections 4.3-4.4): separate the two sides. Every cut vertex (a cut node
// or a split point) is duplicated once for each group of its incident tets that remain
// connected through faces containing it that are not cut faces. A cut face is a face shared
// by tets on opposite sides whose corners are all cut vertices. Purely topological, so it is
// exact: at the border of a partial cut the tets around a split point stay connected
// (through the partially cut tets) and the point is not duplicated.

#include "core/cut/cut_types.h"
#include "core/cut/decompose_tets.h"

namespace resect {

struct Separation {
    int duplicatedNodes = 0;
    int separatedTets = 0;  ///< tets re-attached to a duplicated node
};

Separation separate(TetMesh& mesh, const CutSelection& selection, const Decomposition& decomposition,
                    CutChanges& changes);

} // namespace resect
