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
};

CutSelection selectCutNodes(const TetMesh& mesh, const SweepSurface& sweep,
                            const IntersectedEdges& crossed, const SelectOptions& options);

} // namespace resect
