#pragma once
// TetMeshActor: rendering adapter for a TetMesh with the display modes and quality overlays
// of the studio (issue 8): the boundary surface, a wireframe of every face, or shrunk tets;
// coloured uniformly (tissue) or by a per-tet quality measure (quality_colors.h) over an
// adjustable range; a quality filter that shows only the tets worse than a threshold (drawn
// shrunk, so that they are visible inside the mesh); a clipping plane that hides whole tets
// to look inside.
//
// What a cut did (issue 19, "see the cut"), given by TissueDisplay after setMesh(): the piece
// of every tet, coloured from piecePalette() in the Piece colour mode; the nodes on a cut
// surface, whose boundary faces are drawn as cut faces (an overlay in kCutFaceColour); the
// tets the last cut touched (their drawn edges, an overlay in kTouchedColour); a picked tet
// (its six edges in kPickedColour); and a display offset per piece (the explode view: node n
// is drawn at its position plus the offset of its piece; the mesh itself never moves).
//
// Updates (STYLE.md item 8): setMesh() is a topology change and rebuilds the VTK data;
// updatePositions() only moves the points and marks them modified when the topology is
// unchanged (the simulation's per-frame path). Quality measures are taken in the reference
// configuration (core/mesh/quality.h), so they change with setMesh() only.
//
// The displayed data, boundary(), is a vtkPolyData of triangles with cell data
//   "tet"           owning tet of each triangle (int), for picking and inspection
//   "quality"       radius ratio 3 r_in / R_circ of that tet (as in .vtu files)
//   "min_dihedral"  minimum dihedral angle of that tet, degrees
//   "piece"         piece of that tet (setPieces; 0 without)
//   "piece_colour"  its piecePalette() colour, RGB bytes
//   "cut_face"      1 if the triangle is a cut face (a boundary face of the mesh whose three
//                   nodes lie on a cut surface), else 0
//   "touched"       1 if its tet was touched by the last cut, else 0
// The mapper colours by the array of the overlay measure (Quality) or by "piece_colour"
// (Piece). The overlays (cutFaces(), touchedEdges(), pickedOutline()) share the points.

#include "core/cut/cut_types.h"
#include "core/mesh/quality.h"
#include "core/mesh/tet_mesh.h"
#include "core/mesh/topology.h"
#include "widgets/orbit_camera.h"
#include "widgets/piece_colors.h"
#include "widgets/quality_colors.h"

#include <vtkSmartPointer.h>

#include <cstdint>
#include <span>
#include <utility>
#include <vector>

class vtkActor;
class vtkProp;
class vtkLookupTable;
class vtkPoints;
class vtkPolyData;
class vtkPolyDataMapper;

namespace resect {

/// How the tets are drawn.
enum class TetDisplayMode {
    Surface,    ///< boundary of the displayed tets, element edges on top
    Wireframe,  ///< every face of the displayed tets as lines
    ShrunkTets, ///< every displayed tet shrunk towards its centroid
};

/// What colours the tets.
enum class TetColorMode {
    Quality, ///< the overlay measure (or the uniform colour when it is None)
    Piece,   ///< the piece's palette colour (piece_colors.h)
};

/// Names of the cell arrays of TetMeshActor::boundary().
inline constexpr const char* kTetIdArray = "tet";
inline constexpr const char* kRadiusRatioArray = "quality";
inline constexpr const char* kMinDihedralArray = "min_dihedral";
inline constexpr const char* kPieceArray = "piece";
inline constexpr const char* kPieceColourArray = "piece_colour";
inline constexpr const char* kCutFaceArray = "cut_face";
inline constexpr const char* kTouchedArray = "touched";

class TetMeshActor {
public:
    TetMeshActor();

    /// Replaces the displayed mesh (topology change: rebuilds everything); an empty mesh
    /// shows nothing. Display settings and the tet schemes are kept; the pieces, their
    /// offsets and the cut marks are dropped (one piece, nothing marked) until set again; a
    /// picked tet stays picked if the new mesh has it.
    void setMesh(const TetMesh& mesh);
    /// Moves the points to the mesh's current positions without rebuilding the cells. The
    /// mesh must have the topology of the last setMesh(); if its node or tet count differs,
    /// this falls back to setMesh() and returns false. With clipping enabled, the set of
    /// clipped tets is re-evaluated and the cells are rebuilt only if it changed.
    bool updatePositions(const TetMesh& mesh);
    /// The same with the positions alone (#nodes of the last setMesh(); else false and
    /// nothing changes).
    bool updatePositions(std::span<const Vec3> positions);
    void clear();

    /// Scheme that produced each tet (index = tet; Tissue::schemes()), for inspection.
    /// Kept across setMesh(); tets beyond the vector's size count as Scheme::None.
    void setTetSchemes(std::vector<Scheme> schemes);
    Scheme tetScheme(int tet) const;

    // --- what a cut did (issue 19) ---
    /// The piece of every tet (#tets of the mesh, each >= 0; its palette index). Anything
    /// else (an empty vector) makes every tet piece 0.
    void setPieces(std::vector<int> tetPiece);
    int tetPiece(int tet) const;
    /// Pieces: 1 + the largest piece index (1 without pieces, 0 when empty).
    int pieceCount() const;
    /// The cut marks: per node, whether it lies on a cut surface (Tissue::onCutSurface); per
    /// tet, whether the last cut touched it. Vectors of another size count as all zero.
    void setCutMarks(std::vector<std::uint8_t> onCutSurface, std::vector<std::uint8_t> touchedTets);
    /// Display offset of every piece (index = piece; missing ones are zero): node n is drawn
    /// at its current position plus the offset of its piece. Only moves points.
    void setPieceOffsets(std::vector<Vec3> offsets);
    const std::vector<Vec3>& pieceOffsets() const { return m_pieceOffsets; }
    /// The tet whose edges are outlined (-1: none; an index outside the mesh: none).
    void setPickedTet(int tet);
    int pickedTet() const { return m_picked; }

    // --- display settings ---
    void setColorMode(TetColorMode mode);
    TetColorMode colorMode() const { return m_colorMode; }
    /// Whether the cut faces and the last cut's touched tets are drawn (default: both).
    void setCutFacesVisible(bool visible);
    bool cutFacesVisible() const { return m_cutFacesVisible; }
    void setTouchedVisible(bool visible);
    bool touchedVisible() const { return m_touchedVisible; }
    /// Shows or hides everything this actor draws (it draws nothing without triangles).
    void setVisible(bool visible);
    bool visible() const { return m_visible; }
    /// Fades the piece colours, the uniform colour and the overlays towards `towards` (the
    /// view's background) by `amount` in [0, 1] (0 by default): the tets recede without the
    /// cost and the artefacts of translucency. Quality colours are never faded.
    void setFade(double amount, const Rgb& towards);
    double fade() const { return m_fade; }
    /// The colour of the tets when the overlay measure is None (tissue pink by default).
    void setUniformColor(const Rgb& colour);

    void setDisplayMode(TetDisplayMode mode);
    TetDisplayMode displayMode() const { return m_mode; }

    /// Sets the overlay and resets the colour range to defaultQualityRange(measure).
    void setOverlayMeasure(QualityMeasure measure);
    QualityMeasure overlayMeasure() const { return m_measure; }
    /// Colour range of the overlay (values outside are clamped to the end colours). lo >= hi
    /// or non-finite values are ignored.
    void setColorRange(double lo, double hi);
    std::pair<double, double> colorRange() const { return m_range; }
    /// The range of the overlay measure (filterMeasure() when the overlay is None) over all
    /// tets of the mesh; defaultQualityRange() when there are none or all values are equal.
    std::pair<double, double> autoRange() const;
    /// The lookup table the mapper colours with (range = colorRange()).
    vtkLookupTable* lookupTable() const;

    /// Shows only the tets whose filterMeasure() is below `threshold`, drawn shrunk.
    void setQualityFilter(bool enabled, double threshold);
    bool qualityFilterEnabled() const { return m_filterEnabled; }
    double qualityFilterThreshold() const { return m_filterThreshold; }
    /// The measure the filter compares: the overlay measure, or the radius ratio when the
    /// overlay is None.
    QualityMeasure filterMeasure() const;

    /// Hides every tet whose four current node positions p all lie on the positive side of
    /// the plane or on it, dot(p - origin, normal) >= 0 (so a plane through the mesh's
    /// lowest point hides every tet, one through its highest none). A zero normal disables
    /// clipping.
    void setClipPlane(bool enabled, const Vec3& origin, const Vec3& normal);
    bool clipEnabled() const { return m_clipEnabled; }
    Vec3 clipOrigin() const { return m_clipOrigin; }
    Vec3 clipNormal() const { return m_clipNormal; }

    /// Scale of a shrunk tet about its centroid, in (0, 1]; default 0.75.
    void setShrinkFactor(double factor);
    double shrinkFactor() const { return m_shrink; }

    // --- data ---
    vtkActor* actor() const;
    /// Everything to add to a renderer: actor() and the overlays' actors.
    std::vector<vtkProp*> props() const;
    /// The overlays (points shared with boundary()): the cut faces as triangles, the edges of
    /// the touched tets' drawn triangles as lines, the picked tet's six edges as lines (its
    /// own four points). Empty when there is nothing to draw; their actors are hidden then or
    /// when switched off.
    vtkPolyData* cutFaces() const;
    vtkPolyData* touchedEdges() const;
    vtkPolyData* pickedOutline() const;
    vtkActor* cutFacesActor() const;
    vtkActor* touchedActor() const;
    vtkActor* pickedActor() const;
    /// The triangles as displayed (current positions) with the cell arrays listed above.
    vtkPolyData* boundary() const;
    /// True when no mesh is loaded (a mesh whose tets are all clipped or filtered is not
    /// empty).
    bool empty() const { return m_tets.empty(); }
    /// Bounds of the mesh's nodes as drawn (current positions plus piece offsets),
    /// independent of filter and clipping, so that the camera does not jump while clipping;
    /// invalid (min > max) when empty.
    Bounds bounds() const;
    /// Where node n is drawn: its current position plus its piece's offset.
    Vec3 displayedPosition(int node) const;

    int tetCount() const { return static_cast<int>(m_tets.size()); }
    /// The tets currently drawn (after filter and clipping), ascending.
    const std::vector<int>& displayedTets() const { return m_displayed; }
    bool isTetDisplayed(int tet) const;
    /// Measures of every tet (reference configuration), index = tet.
    const std::vector<TetQuality>& tetQualities() const { return m_quality; }
    /// Value of `measure` for one tet (qualityMeasureValue).
    double tetMeasure(QualityMeasure measure, int tet) const;

    /// Times setMesh()/the display settings rebuilt the cells, and times updatePositions()
    /// only moved points: lets tests check that the fast path is taken.
    int cellRebuilds() const { return m_cellRebuilds; }
    int pointUpdates() const { return m_pointUpdates; }

private:
    void rebuildCells();
    /// The per-cell arrays and overlays that depend on pieces and cut marks (not the cells).
    void rebuildMarks();
    void rebuildPicked();
    void applyVisibility();
    void updatePoints();
    Vec3 offsetOfNode(int node) const;
    bool computeClipped(std::vector<char>& clipped) const;
    void applyColouring();
    void applyRepresentation();
    Vec3 shrunkCorner(int tet, int local) const;

    // Copy of what is displayed: per-node current positions, the tets, their faces, their
    // measures. Reference positions are not needed for drawing.
    std::vector<Vec3> m_pos;
    std::vector<Tet> m_tets;
    std::vector<MeshFace> m_faces;
    std::vector<TetQuality> m_quality;
    std::vector<Scheme> m_schemes;
    std::vector<char> m_clipped; ///< per tet: hidden by the clipping plane
    std::vector<int> m_displayed;
    bool m_pointsAreNodes = true; ///< point i is node i (else four points per shown tet)
    /// Per tet: bit f set if its local face f (kTetFaces) is on the mesh's boundary.
    std::vector<std::uint8_t> m_boundaryFaces;
    // Per drawn triangle (cell): its tet, its nodes, whether it is a boundary face.
    std::vector<int> m_cellTet;
    std::vector<Tri> m_cellNodes;
    std::vector<char> m_cellOnBoundary;
    // What a cut did (setPieces, setCutMarks, setPieceOffsets, setPickedTet).
    std::vector<int> m_tetPiece;         ///< per tet, or empty
    std::vector<int> m_nodePiece;        ///< per node, or empty
    std::vector<std::uint8_t> m_onCut;   ///< per node, or empty
    std::vector<std::uint8_t> m_touched; ///< per tet, or empty
    std::vector<Vec3> m_pieceOffsets;
    int m_picked = -1;

    TetDisplayMode m_mode = TetDisplayMode::Surface;
    TetColorMode m_colorMode = TetColorMode::Quality;
    bool m_cutFacesVisible = true;
    bool m_touchedVisible = true;
    bool m_visible = true;
    double m_fade = 0.0;
    Rgb m_fadeTowards{0, 0, 0};
    Rgb m_uniformColour{0.90, 0.62, 0.60};
    /// Colours of the actor and the overlays with the fade applied.
    void applyFade();
    QualityMeasure m_measure = QualityMeasure::RadiusRatio;
    std::pair<double, double> m_range{kQualityScaleMin, kQualityScaleMax};
    bool m_filterEnabled = false;
    double m_filterThreshold = 0.3;
    bool m_clipEnabled = false;
    Vec3 m_clipOrigin = Vec3::Zero();
    Vec3 m_clipNormal = Vec3::UnitX();
    double m_shrink = 0.75;
    int m_cellRebuilds = 0;
    int m_pointUpdates = 0;

    vtkSmartPointer<vtkPolyData> m_boundary;
    vtkSmartPointer<vtkPoints> m_points;
    vtkSmartPointer<vtkLookupTable> m_lut;
    vtkSmartPointer<vtkPolyDataMapper> m_mapper;
    vtkSmartPointer<vtkActor> m_actor;
    /// An overlay: its data, mapper and actor.
    struct Overlay {
        vtkSmartPointer<vtkPolyData> data;
        vtkSmartPointer<vtkPolyDataMapper> mapper;
        vtkSmartPointer<vtkActor> actor;
    };
    Overlay m_cutOverlay, m_touchedOverlay, m_pickedOverlay;
    vtkSmartPointer<vtkPoints> m_pickedPoints;
};

} // namespace resect
