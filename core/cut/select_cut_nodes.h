#pragma once
// Step 3 of the cut (section 4.3, Figure 3): cut nodes, cut edges and per-tet codes.
//
// For every crossed edge the end node nearer to the crossing becomes a cut node if its
// distance to the sweep is below d; crossed edges incident to a cut node are not split.
// Rules beyond the paper's text, documented here:
//  * A node lying exactly on the sweep is always a cut node (distance 0), with every method:
//    splitting an edge at its end node would create a zero-volume tet.
//  * Nodes of partially cut tets are never cut nodes (section 4.4). A tet is completely cut
//    when its crossed edges are exactly the edges between two groups of its nodes (cut
//    nodes aside); otherwise it is partially cut. Because a node on the sweep that cannot be
//    a cut node makes its tets partial too, this is iterated to a fixed point.
//  * Nominations are independent of edge order: every crossed edge nominates its nearer
//    end; nominees are accepted nearest first unless a tet would get four cut nodes.
//  * Near nodes (only with nearFraction > 0; off by default, see SelectOptions): an end of a
//    crossed edge closer to the sweep than nearFraction * d (but not on it) counts as a cut
//    node when tets are classified: its crossed edges are not splits, so a
//    tet that the sweep crosses only near such nodes is completely cut, not partially. Where a
//    later sweep runs within a hair of an earlier cut's wall, it crosses the wall back and forth;
//    under the rule above every tet there was partial, no wall node could be a cut node, and the
//    edges were split a hundredth of an edge from their ends (issue 16: random pulls on a
//    scanned surface; a knife-edge sliver of 0.009 radius ratio). A near node that then cannot
//    become a cut node (a fourth in a tet; its twin across a crack cannot be one) is dropped and
//    the selection made again without it.
//  * A crossing closer than minEdgeFraction of the edge to an end node is moved to that
//    fraction (only possible where that node cannot be a cut node), so that no zero-volume
//    tet is ever created.

#include "core/cut/cut_types.h"
#include "core/sweep/sweep_surface.h"

namespace resect {

struct SelectOptions {
    double d = 0;                    ///< absolute distance threshold (0: no cut nodes by distance)
    bool allowCutNodes = true;       ///< false for the subdivision baseline
    double minEdgeFraction = 1e-6;   ///< smallest edge fraction a split may cut off
    /// Near nodes (hybrid only): an end of a crossed edge closer to the sweep than this times d
    /// counts as a cut node when deciding which tets are partially cut (see above). Off (0) by
    /// default: measured in issue 16 at 0.1, it lifts the random pull it was made for and the
    /// lattice box's partial strokes, but one stroke row of test_resection_quality (myoma, seed 7,
    /// pass 15) then keeps an edge of 0.2 times the input's shortest for one pass.
    double nearFraction = 0;
};

CutSelection selectCutNodes(const TetMesh& mesh, const SweepSurface& sweep,
                            const IntersectedEdges& crossed, const SelectOptions& options);

} // namespace resect
