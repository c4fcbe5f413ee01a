#pragma once
// Step 7 of the cut (section 4.6): local mesh relaxation around the cut.
//
// The node set S is the k-ring (k = 2 or 3) neighbourhood of the nodes on the cut. Interior
// nodes move freely; nodes on the sweep move only within it (projected back after each
// move; separated copies move together); nodes that were on the mesh boundary before the cut
// (the original surface or earlier cuts) are fixed. Forces follow Eq. 2: springs on the edges
// at movable nodes with rest length equal to the mean of those edges, plus Lennard-Jones
// forces between neighbours (equilibrium at the same length), weighted by w_spring and
// w_particle, equal masses. The rest length is the mean length of all edges at movable nodes
// of S. With heavy damping the motion is first order, x <- x + h F / c, which is what is
// integrated here (explicitly, one node after another).
// A move is kept only if no tet around the node inverts (exact, both configurations) and the
// smallest radius ratio around the node does not drop, so relaxation never lowers the
// mesh's minimum radius ratio. New reference positions come from barycentric coordinates in
// the tet containing the new position, as in snapping.
// Cost: a trial move computes the radius ratios of the tets around the node only (the others'
// are kept from the moves that changed them), and a node whose copies and neighbours have not
// moved since its last trial is not tried again (the trial would end as that one did).

#include "core/cut/cut_types.h"
#include "core/sweep/sweep_surface.h"

#include <vector>

namespace resect {

struct RelaxOptions {
    int steps = 10;            ///< relaxation sweeps over S
    double wSpring = 1.0;      ///< weight of the spring forces (Eq. 2)
    double wParticle = 0.2;    ///< weight of the Lennard-Jones forces (Eq. 2)
    /// Damping c of Eq. 2 (unit masses, unit time step): heavily damped motion moves a node by
    /// F / c per step, in units of the rest length.
    double damping = 10.0;
    int rings = 2;             ///< size of the neighbourhood S
};

struct RelaxResult {
    int movable = 0;       ///< interior nodes in S
    int onSweep = 0;       ///< nodes (groups of copies) in S moving within the sweep
    int fixed = 0;         ///< boundary nodes in S
    int acceptedMoves = 0;
    int rejectedMoves = 0;
    std::vector<int> movedNodes;  ///< every node moved at least once (all copies)
};

/// `fixedNodes`: nodes on the boundary before the cut (they, and their copies, never move).
RelaxResult relaxNodes(TetMesh& mesh, const SweepSurface& sweep, const CutChanges& changes,
                       const std::vector<int>& fixedNodes, const RelaxOptions& options);

} // namespace resect
