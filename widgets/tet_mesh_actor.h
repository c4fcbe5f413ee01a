#pragma once
// TetMeshActor: rendering adapter for a TetMesh with the display modes and quality overlays
// of the studio (issue 8): the boundary surface, a wireframe of every face, or shrunk tets;
// coloured uniformly (tissue) or by a per-tet quality measure (quality_colors.h) over an
// adjustable range; a quality filter that shows only the tets worse than a threshold (drawn
// shrunk, so that they are visible inside the mesh); a clipping plane that hides whole tets
// to look inside.
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
// The mapper colours by the array of the overlay measure.

#include "core/cut/cut_types.h"
#include "core/mesh/quality.h"
#include "core/mesh/tet_mesh.h"
#include "core/mesh/topology.h"
#include "widgets/orbit_camera.h"
#include "widgets/quality_colors.h"

#include <vtkSmartPointer.h>

#include <utility>
#include <vector>

class vtkActor;
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

/// Names of the cell arrays of TetMeshActor::boundary().
inline constexpr const char* kTetIdArray = "tet";
inline constexpr const char* kRadiusRatioArray = "quality";
inline constexpr const char* kMinDihedralArray = "min_dihedral";

class TetMeshActor {
public:
    TetMeshActor();

    /// Replaces the displayed mesh (topology change: rebuilds everything); an empty mesh
    /// shows nothing. Display settings and the tet schemes are kept.
    void setMesh(const TetMesh& mesh);
    /// Moves the points to the mesh's current positions without rebuilding the cells. The
    /// mesh must have the topology of the last setMesh(); if its node or tet count differs,
    /// this falls back to setMesh() and returns false. With clipping enabled, the set of
    /// clipped tets is re-evaluated and the cells are rebuilt only if it changed.
    bool updatePositions(const TetMesh& mesh);
    void clear();

    /// Scheme that produced each tet (index = tet; Tissue::schemes()), for inspection.
    /// Kept across setMesh(); tets beyond the vector's size count as Scheme::None.
    void setTetSchemes(std::vector<Scheme> schemes);
    Scheme tetScheme(int tet) const;

    // --- display settings ---
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
    /// The triangles as displayed (current positions) with the cell arrays listed above.
    vtkPolyData* boundary() const;
    /// True when no mesh is loaded (a mesh whose tets are all clipped or filtered is not
    /// empty).
    bool empty() const { return m_tets.empty(); }
    /// Bounds of the mesh's current node positions, independent of filter and clipping, so
    /// that the camera does not jump while clipping; invalid (min > max) when empty.
    Bounds bounds() const;

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
    void updatePoints();
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

    TetDisplayMode m_mode = TetDisplayMode::Surface;
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
};

} // namespace resect
