#pragma once
// Step 7 of Tissue::cut (beyond the paper): local mesh improvement around what the cut touched, so
// that quality survives many cuts in a row (a whole resection, Figure 10), in the spirit of
// Klingner & Shewchuk, "Aggressive tetrahedral mesh improvement" (2007), restricted to the
// cut's neighbourhood and in time proportional to it.
//
// Four operations, repeated for a few sweeps over the region (the seed nodes and `rings` rings
// around them; anchored nodes only among themselves and within the anchored box, moveAnchored):
//  * Edge collapse. Edges shorter than `shortEdge`, and the edges of tets whose radius ratio is
//    below `badRatio`, are collapsed where the link condition holds (Dey et al.; the mesh
//    boundary is closed with a virtual vertex, so a boundary node never becomes interior nor
//    an interior node boundary, and the boundary stays a manifold). The merged node starts at
//    either end or the midpoint (on the boundary: only those on the old boundary). The volume
//    is affine in its position; on the boundary it goes to the point of the old boundary
//    nearest to the start where the volume is exactly what it was, so it stays on the body's
//    surface or the cut surface. Where no such point exists it may move along the volume
//    gradient instead, within maxDeviation local edge lengths of the old boundary (offSurface).
//    A placement is allowed only if every remaining tet is positively oriented in both
//    configurations (exact orient3d) and the old boundary nodes stay within maxDeviation of
//    the new boundary. A short edge is collapsed when the worst tet around it does not fall
//    below min(badRatio, its value before); an edge of a bad tet only when the worst tet
//    improves. A short edge whose best placement is not good enough gets the merged node
//    smoothed (below) among the tets that remain, and goes if that is.
//  * Flips: 2-3 flips and edge removal (3-2 and rings of up to 7 tets) of bad tets, where the
//    worst tet improves.
//  * Smoothing. A node whose worst tet is below `badRatio` or whose shortest edge is below
//    `shortEdge` moves to raise the smaller of the two (each against its bound): ascent along
//    the gradient of the limiting term with a line search (for the ratio, the direction that
//    raises the tets within 0.02 of the worst together, as Klingner & Shewchuk's smoothing
//    does: the point of their gradients' convex hull nearest to zero); interior nodes first
//    try their neighbours' centroid. Interior nodes move freely; a boundary node's trial
//    position is taken back onto its old boundary where the volume is unchanged (else, with
//    offSurface, kept across the volume gradient within maxDeviation of the old boundary).
//    Every move keeps all tets positive in both configurations (exact) and raises the node's
//    score.
//  * Edge split (vertex insertion, `split`): a tet still bad after the others gets a new node
//    on one of its two longest edges, placed by smoothing among the tets the split makes,
//    where that raises the worst tet around the edge by 0.01. The split tets fill the space of
//    the old ones (on the boundary the new node starts on the old boundary), so the volume
//    is kept as smoothing keeps it.
// The body's surface (`body`, with the cut marks `cutSurfaceNodes`; issue 16: no node may leave
// it): no boundary node is placed outside the body as it was before any cut, and a boundary
// node on no cut's surface that lies on the body's surface (a node of the body's surface alone)
// is placed only on its old boundary and on the body's surface, so it never leaves it. Nodes of
// a cut's surface keep the freedom above (a rim node, on both, may go into the body along the
// cut, never out of it). Both up to rounding and to the chordal slack of smooth curved patches
// (BodySurface::side): exact on flat patches and at sharp edges.
// Glued cracks (glueCracks; issue 16): where both walls of a crack are in the region (a cut
// partway in, a piece kept), each pair of coincident copies is glued into one node for the
// pass and the paired wall faces become inner "crack faces" that no flip or split removes, so
// whatever the pass does to a crack it does to both walls, and neither goes into the other. A
// node on the crack slides along it keeping the volume of each side; a rim node (crack and
// body's surface) keeps the body's and each side's (it moves along the line where both are
// unchanged); a front node (the crack ends at it) moves as any boundary node; where cracks
// meet a node stays. No node of a crack goes farther than maxCrackDrift from the cuts' sweeps
// (cutDistance). A collapse may join the walls at a node only on a crack that ends inside the
// tissue somewhere (so it cannot join two pieces). Afterwards every node gets one copy per side
// of the crack around it again. Where the region is still below weakRatio or weakEdge, the
// sweeps run once more with the walls on their own, which may push one into the other there.
// Overlap guard (overlapGuard; issue 16): where walls are not glued (triangulated differently,
// cracks meeting), a placement by smoothing or a collapse of a node whose tets meet the mesh's
// boundary (not a glued crack alone) is refused where the mesh around it would reach deeper
// into itself (a node strictly inside a tet it is not a corner of, reference positions, exact
// orient3d) than it did and than overlapSlack of the longest edge around it.
// A moved node's current position and velocity come from the tet of its old neighbourhood that
// contains its new reference position (the deformation is carried over, not reset). Masses
// follow Eq. 3 for every node whose tets changed. The volume of the mesh, hence its mass, is
// unchanged up to rounding. Collapses and moves stay within the pieces they start in; where
// both walls of a crack stay, see "glued cracks" above for how far they keep apart.

#include "core/mesh/renumbering.h"
#include "core/mesh/tet_mesh.h"

#include <array>
#include <cstdint>
#include <functional>
#include <optional>
#include <span>
#include <vector>

namespace resect {

class BodySurface;
class TetGrid;

/// Accepted ranges of ImproveOptions (messages print them).
struct ImproveLimits {
    static constexpr int kMaxRings = 5;            ///< rings in [1, this]
    static constexpr int kMaxSweeps = 20;          ///< sweeps in [0, this]
    static constexpr double kMaxDeviation = 0.5;   ///< maxDeviation in [0, this]
};

struct ImproveOptions {
    double badRatio = 0;        ///< radius ratio (3 r_in / R) below which a tet is improved; in [0, 1]
    double shortEdge = 0;       ///< reference length below which an edge is collapsed; >= 0
    /// Coarsening: edges shorter than this are collapsed too where the worst tet around them
    /// does not fall below min(badRatio, its value before) and no edge grows beyond maxEdge
    /// (0: off), so that repeated cuts do not keep adding tets.
    double coarsenEdge = 0;
    double maxEdge = 0;
    /// Floors: an edge shorter than floorEdge is collapsed even where the tets around it get
    /// worse, as long as none falls below floorRatio (0: no floor).
    double floorEdge = 0;
    double floorRatio = 0;
    int rings = 2;              ///< size of the region around the seeds
    int sweeps = 3;             ///< collapse + smoothing sweeps over the region
    /// Largest distance a boundary node may move off the boundary it was on, as a fraction of
    /// its mean boundary edge length.
    double maxDeviation = 0.1;
    /// Where no placement on the old boundary keeps the volume (or, for smoothing, raises the
    /// node's score), allow one off it within maxDeviation (along the volume gradient for a
    /// collapse, across it for smoothing). Without it, the myoma's shortest edge falls to 0.22
    /// times its input's over 20 scoops (the rims where cuts meet the surface at an acute angle).
    bool offSurface = true;
    /// Edge splits (vertex insertion): a bad tet that the other operations leave bad gets a
    /// new node on one of its longest edges where that raises the worst tet around the edge.
    bool split = true;
    /// The body's surface before any cut (Tissue keeps it), or null. With it no node may leave
    /// the body's surface: no boundary node is placed outside the body, and a node whose
    /// boundary faces all lie on the body's surface (not on a cut's) is placed off its old
    /// boundary only where that is on the body's surface too (on a flat patch, within it).
    const BodySurface* body = nullptr;
    /// Per node (indices at the start of the pass), nonzero where the node lies on a cut's
    /// surface (Tissue::onCutSurface). With `body`, a boundary node on no cut's surface that
    /// lies on the body's surface is a node of that surface alone and stays on it; a node on a
    /// cut's surface that is on the body too (a rim node) may go into the body along the cut,
    /// never out of it. Empty: no node is on a cut's surface.
    std::span<const std::uint8_t> cutSurfaceNodes;
    /// Glue the walls of cracks in the region for the pass (both walls of a crack change
    /// together, so neither goes into the other; see "glued cracks" in improve_mesh.cpp).
    bool glueCracks = true;
    /// The mesh's spatial index (current positions), where glueCracks finds the other wall of
    /// a crack beyond the region; null: only walls within the region are glued.
    const TetGrid* grid = nullptr;
    /// Distance of a reference point from the cuts' sweeps (null: none known). A node of a glued
    /// crack is never placed farther from them than maxCrackDrift or than it already was, so
    /// a crack stays where its cut was made over many passes (the sweeps were made on the
    /// tissue as it was deformed then: exact where it was at rest).
    std::function<double(const Vec3&)> cutDistance;
    double maxCrackDrift = 0;
    /// After a pass with glued cracks, where a tet of the region is still below weakRatio or an
    /// edge below weakEdge, the sweeps again with the walls on their own (0: never).
    double weakRatio = 0;
    double weakEdge = 0;
    /// Refuse a placement (smoothing, also of a split's new node; a collapse's merged node) of a
    /// node whose tets meet the mesh's boundary that makes the mesh overlap itself more deeply
    /// around it (a node strictly inside a tet it is not a corner
    /// of; reference positions), so that walls of a crack that are not glued do not go into
    /// each other.
    bool overlapGuard = true;
    /// The guard lets a placement reach this far into the tissue around it (as a fraction of the
    /// longest edge of the tets around the node), or as far as it reached before, whichever is
    /// more; in [0, 1]. With 0 the stability suite's ten box scoops fall to 0.46 times the input's
    /// worst ratio; with 0.02 they keep 0.58 times, and the overlap left is at most 0.03 mean
    /// edges on test_resection_quality's stroke rows (0.1 without the guard).
    double overlapSlack = 0.02;
    double density = 1e-3;      ///< g/mm^3, for the masses of Eq. 3
    /// A box no free node may move into (the anchored region, whose new nodes are anchored by
    /// position; reference positions).
    std::optional<std::array<Vec3, 2>> keepOut;
    /// The region's fixed nodes (ImproveRegion::fixed) that lie in keepOut may be moved and
    /// merged among themselves, within keepOut, so that they stay fixed (anchored by position)
    /// where they go. Cuts that reach into the anchored region leave slivers there that nothing
    /// else mends (issue 16: twenty partial strokes, where the worst tets of every run below
    /// the bound had only anchored nodes). Without keepOut the fixed nodes stay where they are.
    bool moveAnchored = true;
    /// With moveAnchored, a free node may also merge with an anchored one, the merged node placed
    /// in keepOut (it is anchored there, by position): a short edge across the box's border,
    /// which neither kind can mend alone (issue 16: the myoma's seed 8 partial strokes with near
    /// nodes; the lattice box's seed 7 partial strokes rise from 0.12 to 0.41 times the input's
    /// worst ratio). Off by default (README "Pits and the anchored box's border").
    bool mergeFreeIntoAnchored = false;
    /// Fill pits for a collapse (issue 16; off by default, README "Pits and the anchored box's
    /// border"): a short edge (a, b) of the boundary whose collapse the link condition refuses
    /// only because the edge is the mouth of a pit (a void the shape of one tet (x, a, b, c):
    /// boundary faces (a, b, x), (a, x, c) and (b, x, c), none a glued crack face, and no tet
    /// with a, b and c) is collapsed with the pit filled first, the merged node placed to keep
    /// the volume the mesh had (the pit's is not added). Where crack walls meet at a junction,
    /// independent collapses on the walls leave such pits, and the link condition then keeps
    /// their short mouths for good (the myoma's seed 7 stroke row with near nodes, pass 15).
    bool fillPits = false;
};

/// The nodes the pass may move (seeds and their rings, minus fixed nodes), the fixed nodes among
/// them, and the tets that may change (those of both).
struct ImproveRegion {
    std::vector<int> nodes;
    std::vector<int> fixed;  ///< fixed nodes within the rings: their tets may be flipped (moved: moveAnchored)
    std::vector<int> tets;   ///< the tets of both
};
ImproveRegion improveRegion(const TetMesh& mesh, const std::vector<int>& seeds, const std::vector<int>& fixedNodes,
                            int rings);

struct ImproveResult {
    int collapses = 0;         ///< edges collapsed
    int smoothed = 0;          ///< nodes moved by smoothing
    int flips = 0;             ///< 2-3 and 3-2 flips
    int splits = 0;            ///< edges split (nodes added)
    int removedTets = 0, removedNodes = 0;
    int gluedNodes = 0;        ///< copies glued to their twins for the pass (see glueCracks)
    int ungluedPasses = 0;     ///< passes that ran the sweeps again unglued (weakRatio, weakEdge)
    int ungluedNodes = 0;      ///< copies given back to a side of a crack after it
    int pitsFilled = 0;        ///< collapses through a filled pit (fillPits)
    double worstBefore = 1, worstAfter = 1;  ///< smallest radius ratio over the region's tets
    /// Final indices of the nodes that moved (smoothing, merged nodes) and of every node whose
    /// tets changed (their masses were updated); sorted.
    std::vector<int> movedNodes, touchedNodes;
    /// Only when tets changed (else empty): the indices that changed (core/mesh/renumbering.h).
    /// Tets: old -> new, -1 for a tet removed or replaced by a flip; nodes: old -> new, a
    /// collapsed node -> the new index of the node it merged into. Removal lets the last tets
    /// and nodes take the freed indices, so the lists are as long as the pass's changes.
    MeshRenumbering renumbering;
    /// The indices (after the pass) of the tets the flips and splits created, sorted. Nodes
    /// the splits added take the indices after the surviving ones (none had an index before).
    std::vector<int> createdTets;
    /// Final indices of the nodes the pass put on a cut's surface, sorted: split points of edges
    /// whose ends both were, and merged nodes of which either end was (the renumbering passes
    /// a merged node's mark on only where that node had an index at the start).
    std::vector<int> addedOnCutSurface;
    bool renumbered() const { return !renumbering.empty(); }
};

/// Improves the region (see the top of this file). Cost: in proportion to the region.
ImproveResult improveMesh(TetMesh& mesh, const ImproveRegion& region, const ImproveOptions& options);

/// The point of the convex hull of `g` (one to four vectors) nearest to the origin; zero for
/// an empty or longer list. Smoothing moves a node along it: the direction that raises all the
/// tets near the worst at once (the gradients of their radius ratios), where the worst tet's
/// gradient alone would lower its near-tie.
Vec3 nearestToZeroInHull(const std::vector<Vec3>& g);

/// Distance from p to the triangle (a, b, c).
double pointTriangleDistance(const Vec3& p, const Vec3& a, const Vec3& b, const Vec3& c);

} // namespace resect
