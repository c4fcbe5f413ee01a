#pragma once
// Step 4 of the cut (section 4.4): decompose every intersected tet into sub-tets that lie on
// one side of the cut.
//
// Faces first: each tet face is triangulated from the split points on its edges alone, so
// the two tets sharing a face always agree (conforming). A face with two split edges is a
// corner triangle plus a quadrilateral (the "face prism"); the quadrilateral is split by a
// diagonal chosen from global node indices (standard triangulation, Figure 5a) or fanned
// around a face node at the mean of its four corners, reference and current positions alike
// (the paper's enhanced symmetric triangulation, Figure 5b). In enhanced mode a face takes the
// face node only where that gives clearly better triangles than the better of the two
// diagonals, and the better diagonal otherwise; faces of partially cut tets, and faces where
// a curved sweep bulges into the prism, keep the standard diagonal.
//
// Then each side of a completely cut tet (or the whole of a partially cut one) is a
// polyhedron bounded by those face triangles and the cut polygon; it is split into tets by a
// cone from one of its vertices. The apex is chosen so that every tet is positively oriented
// in both the reference and the current configuration (exact predicates), with the fewest
// tets and then the best worst radius ratio. If no vertex will do, an interior point at the
// vertices' mean is added (counted as a Steiner point).

#include "core/cut/cut_types.h"
#include "core/status.h"
#include "core/sweep/sweep_surface.h"

namespace resect {

struct DecomposeOptions {
    bool symmetricFaces = true;  ///< enhanced (Figure 5b) or standard (Figure 5a) faces
    /// The sweep, used to put the apex of a partially cut tet on it (may be null).
    const SweepSurface* sweep = nullptr;
    /// An interior point placed on the sweep in a partially cut tet is used if every tet it
    /// makes has at least this radius ratio (or, failing that, a twentieth of it); otherwise
    /// a vertex of the tet is the apex.
    double minSteinerRadiusRatio = 0.02;
    /// Enhanced faces: the face node is used only where the worst of its four triangles is at
    /// least this many times better shaped than the worst triangle of the better diagonal;
    /// otherwise the better diagonal is used. (Measured on the samples: 1.5 keeps the worst
    /// element of a cut at half the input's or better; the plain symmetric rule does not.)
    double faceNodeAdvantage = 1.5;
    /// Choose the cone apex for the best worst radius ratio (true) or for the fewest tets
    /// first (false).
    bool apexByQuality = true;
};

struct Decomposition {
    std::unordered_map<std::uint64_t, int> edgePoint;  ///< cut edge key -> node at the crossing
    std::unordered_map<int, std::int8_t> tetSide;       ///< tet -> side (+1/-1; 0 inside a
                                                        ///< partially cut tet)
    std::vector<int> sweepPoints;  ///< interior points of partially cut tets, on the sweep
    int decomposedTets = 0;
    int steinerPoints = 0;
    int faceNodes = 0;
};

/// Edits the mesh in place (sub-tets replace their parent; extra ones are appended) and
/// records what changed. On failure (a polyhedron that no apex can decompose into valid
/// tets) the caller must roll back the edits recorded in `changes`.
Status decomposeTets(TetMesh& mesh, const CutSelection& selection, const DecomposeOptions& options,
                     Decomposition& out, CutChanges& changes);

} // namespace resect
