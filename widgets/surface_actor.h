#pragma once
// SurfaceActor: rendering adapter for a TriangleSurface (anatomy or the embedded visual
// surface), drawn in a uniform tissue colour, or with a procedural tissue texture where the
// surface has texture coordinates.
//
// Cut faces (TriangleSurface::cutFaces, the caps that close a cut, section 5.2) are drawn by
// a second actor, cutActor(), with a procedural "cut tissue" texture mapped by the (u, v) of
// the sweep (TriangleSurface::cutUvs), so that the cut stands out from the outer surface and
// shows the sweep's parameterisation (Figure 6). Both share the points.
//
// Updates (STYLE.md item 8): setSurface() rebuilds; updatePositions() only moves the points of
// a surface with the same vertices (a simulation step). Per-vertex display offsets (the explode
// view, setVertexOffsets) are added to the positions drawn; the surface itself never moves.

#include "core/mesh/triangle_surface.h"
#include "widgets/orbit_camera.h"

#include <vtkSmartPointer.h>

#include <array>
#include <span>
#include <vector>

class vtkActor;
class vtkPoints;
class vtkPolyData;
class vtkPolyDataMapper;
class vtkProp;
class vtkTexture;

namespace resect {

class SurfaceActor {
public:
    SurfaceActor();

    /// Replaces the displayed surface; an empty surface shows nothing. Vertex offsets of
    /// another vertex count are dropped.
    void setSurface(const TriangleSurface& surface);
    /// Moves the points to the surface's positions if it has the vertex and triangle counts of
    /// the last setSurface() (its triangles are assumed unchanged); else false and nothing
    /// changes.
    bool updatePositions(const TriangleSurface& surface);
    /// The same with the positions alone (#vertices of the last setSurface(); else false).
    bool updatePositions(std::span<const Vec3> positions);
    void clear();

    /// Display offset of every vertex (#vertices; empty: none), added to the drawn positions.
    void setVertexOffsets(std::vector<Vec3> offsets);
    /// Shows or hides everything this actor draws (it draws nothing without triangles).
    void setVisible(bool visible);
    bool visible() const { return m_visible; }
    /// Whether the cut faces are drawn in their own texture (default) or like the rest.
    void setCutFacesVisible(bool visible);
    bool cutFacesVisible() const { return m_cutFacesVisible; }
    /// Fades the colours towards `towards` (the view's background) by `amount` in [0, 1] (0 by
    /// default); a faded surface is drawn without its textures.
    void setFade(double amount, const std::array<double, 3>& towards);

    vtkActor* actor() const;
    /// The cut faces' actor and data (triangles of the cut faces; points shared with
    /// polyData(); texture coordinates: the sweep's (u, v)).
    vtkActor* cutActor() const;
    vtkPolyData* cutPolyData() const;
    /// Everything to add to a renderer: actor() and cutActor().
    std::vector<vtkProp*> props() const;
    /// The triangles drawn by actor(): every triangle, or all but the cut faces while those
    /// are drawn by cutActor().
    vtkPolyData* polyData() const;
    bool empty() const;
    /// True when the shown surface has texture coordinates: it is then drawn with a
    /// procedural tissue texture.
    bool textured() const;
    /// Bounds of the displayed surface; invalid (min > max) when empty.
    Bounds bounds() const;

    /// Repeats of the cut texture's grid per unit of the sweep's u and v.
    static constexpr double kCutTextureScale = 4.0;

private:
    void rebuildCells();
    void updatePoints();
    void applyVisibility();

    TriangleSurface m_surface; ///< what is shown (positions as last updated)
    std::vector<Vec3> m_offsets;
    bool m_visible = true;
    bool m_cutFacesVisible = true;
    double m_fade = 0;
    std::array<double, 3> m_fadeTowards{0, 0, 0};
    void applyColours();
    vtkSmartPointer<vtkPoints> m_points;
    vtkSmartPointer<vtkPolyData> m_polyData;
    vtkSmartPointer<vtkPolyDataMapper> m_mapper;
    vtkSmartPointer<vtkActor> m_actor;
    vtkSmartPointer<vtkTexture> m_texture; ///< made on first use
    vtkSmartPointer<vtkPolyData> m_cutData;
    vtkSmartPointer<vtkPolyDataMapper> m_cutMapper;
    vtkSmartPointer<vtkActor> m_cutActor;
    vtkSmartPointer<vtkTexture> m_cutTexture; ///< made on first use
};

} // namespace resect
