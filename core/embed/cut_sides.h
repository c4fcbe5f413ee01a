#pragma once
// What re-binding after a cut asks about the tets again and again (section 5.1), answered once
// per cut: the side of the sweep each tet lies on, and the tets around a few tets including the
// stars of the nodes the cut separated. Scratch state that SurfaceBinding keeps between cuts:
// per-tet and per-node marks (flat_marks.h), so that starting a cut costs in proportion to its
// change list, not to the mesh, and no hash set is built per query.

#include "core/cut/cut_types.h"
#include "core/embed/flat_marks.h"
#include "core/sweep/sweep_surface.h"

#include <span>
#include <vector>

namespace resect {

class CutSides {
public:
    /// Starts answering for one cut (the mesh after it, its change list and its sweep; all three
    /// must outlive the queries). O(change list).
    void begin(const TetMesh& mesh, const CutChanges& changes, const SweepSurface& sweep);

    /// Side of tet t relative to the sweep: from the cut where it made the tet
    /// (CutChanges::tetSide, 0 for pieces of partially cut tets); else from its first node off
    /// the cut surface that is off the sweep (a tet touching the cut at nodes that stayed off the
    /// sweep may have its centre across it); else from its centre. Computed once per cut.
    int tetSide(int t);
    /// SweepSurface::sideOf of node n's position, computed once per cut.
    int nodeSide(int n);

    /// The tets sharing a node with any of `tets`, including the stars of the copies the cut
    /// separated from those nodes (CutChanges::duplicatedNodes, read in order in one pass as a
    /// list: a pair joins when either of its nodes is already in), each once, in no particular
    /// order (appended to out, cleared first). O(the ring).
    void ring(std::span<const int> tets, std::vector<int>& out);
    /// True if t is in the ring of the last ring() call.
    bool inRing(int t) const { return t >= 0 && m_ringTet.has(t); }

private:
    const TetMesh* m_mesh = nullptr;
    const CutChanges* m_changes = nullptr;
    const SweepSurface* m_sweep = nullptr;
    // Per cut (begin() clears them):
    StampedMarks m_tetSides, m_nodeSides;  ///< computed sides
    StampedMarks m_onCut;                  ///< the cut-surface nodes
    /// Duplicated-node pairs by node: node -> its slot, CSR of the pairs (ascending) per slot.
    StampedMarks m_pairSlot;
    std::vector<int> m_pairStart, m_pairIndex;
    // Per ring() call:
    StampedMarks m_ringNode, m_ringTet;
    std::vector<int> m_ringNodes, m_pending;
};

} // namespace resect
