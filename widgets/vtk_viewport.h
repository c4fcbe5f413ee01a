#pragma once
// VtkViewport: a 3-D view of the loaded meshes.
//
// With OpenGL it hosts a VtkGlWidget rendering the scene with VTK; without (the `offscreen`
// platform, a failed context, RESECT_NO_OPENGL) it shows a placeholder label instead and
// everything else keeps working: the scene's VTK data, the bounds and the camera model
// (OrbitCamera), which the mouse drives in both cases.
//
// Mouse: left drag orbits, middle drag or Shift+left pans, right drag or Ctrl+left zooms,
// the wheel zooms.

#include "core/mesh/tet_mesh.h"
#include "core/mesh/triangle_surface.h"
#include "widgets/orbit_camera.h"
#include "widgets/surface_actor.h"
#include "widgets/tet_mesh_actor.h"

#include <QImage>
#include <QPoint>
#include <QString>
#include <QWidget>

#include <array>
#include <vector>

class QLabel;
class QVBoxLayout;
class vtkCamera;
class vtkProp;

namespace resect {

class VtkGlWidget;
class ViewportTool;

class VtkViewport : public QWidget {
    Q_OBJECT

public:
    explicit VtkViewport(QWidget* parent = nullptr);
    ~VtkViewport() override;

    /// Shows the mesh's boundary coloured by the radius ratio of the owning tet, with the
    /// element edges; with `frame`, frames it (resetCamera()), else keeps the camera (a cut
    /// or a simulation step). An empty mesh clears it from the view.
    void setTetMesh(const TetMesh& mesh, bool frame = true);
    /// Shows a triangle surface in tissue colour; with `frame`, frames the scene if nothing
    /// else is shown.
    void setSurface(const TriangleSurface& surface, bool frame = true);
    /// Removes the meshes from the view (extra props stay).
    void clear();

    /// The rendering adapters, for display options (overlays, clipping, ...).
    TetMeshActor& tetMeshActor() { return m_tetMesh; }
    const TetMeshActor& tetMeshActor() const { return m_tetMesh; }
    SurfaceActor& surfaceActor() { return m_surface; }
    /// The resected chips (Tissue::chips()) as tets and as surfaces, drawn apart from the
    /// tissue (TissueDisplay fills them); in the scene's bounds.
    TetMeshActor& chipsActor() { return m_chips; }
    const TetMeshActor& chipsActor() const { return m_chips; }
    SurfaceActor& chipSurfacesActor() { return m_chipSurfaces; }

    /// Adds a prop (sweep surface, tool, handles, legend, ...) to the scene; not owned, the
    /// caller keeps it alive until removeProp(). Works without rendering too (kept for when
    /// a renderer exists). Adding a prop twice adds it once.
    void addProp(vtkProp* prop);
    void removeProp(vtkProp* prop);

    /// The interaction tool that gets mouse events first (viewport_tool.h); not owned.
    /// Null: camera navigation only. Setting another tool deactivates the previous one.
    void setTool(ViewportTool* tool);
    ViewportTool* tool() const { return m_tool; }

    /// Frames the bounds of everything shown, keeping the view direction (clear of a visible
    /// colour legend on the right).
    void resetCamera();
    /// The starting view (the oblique default direction, z up), framing the scene: what
    /// View > Reset camera does. resetCamera() keeps the current direction.
    void restoreStartingView();
    /// The scene's extent changed without a new mesh (e.g. exploded pieces): fits the camera's
    /// clipping range to it, without moving the camera, and renders.
    void sceneExtentChanged();
    /// The camera used for rendering and for the camera maths (picking, strokes).
    vtkCamera* camera() const { return m_camera.camera(); }
    /// Bounds of everything shown; invalid (min > max) when the scene is empty.
    Bounds sceneBounds() const;

    /// True while the view renders with OpenGL; false when the placeholder is shown.
    bool hasRendering() const;
    /// Why there is no rendering (empty while hasRendering()).
    QString renderingUnavailableReason() const { return m_unavailableReason; }
    /// The view as an image: the rendered frame, or a grab of the placeholder.
    QImage grabImage();
    /// Schedules a frame (no-op without rendering).
    void requestRender();

    /// Background colour of the 3-D view (RGB in [0, 1]).
    static constexpr std::array<double, 3> kBackground{0.11, 0.13, 0.17};

signals:
    /// A frame has been rendered (only with rendering).
    void frameRendered();
    /// The camera moved (mouse interaction or reset).
    void cameraChanged();
    /// Rendering was lost and the placeholder is now shown.
    void renderingUnavailable(const QString& reason);

protected:
    void mousePressEvent(QMouseEvent* event) override;
    void mouseMoveEvent(QMouseEvent* event) override;
    void mouseReleaseEvent(QMouseEvent* event) override;
    void wheelEvent(QWheelEvent* event) override;

private:
    enum class Drag { None, Orbit, Pan, Zoom };

    void createGlWidget();
    void showPlaceholder(const QString& reason);
    void updatePlaceholderText();
    void onGlInitializationFailed(const QString& reason);
    void cameraMoved();

    OrbitCamera m_camera;
    TetMeshActor m_tetMesh;
    SurfaceActor m_surface;
    TetMeshActor m_chips;
    SurfaceActor m_chipSurfaces;
    int m_nodeCount = 0;
    int m_tetCount = 0;
    int m_triangleCount = 0;

    QVBoxLayout* m_layout = nullptr;
    VtkGlWidget* m_glWidget = nullptr;
    QLabel* m_placeholder = nullptr;
    QString m_unavailableReason;

    Drag m_drag = Drag::None;
    QPoint m_lastPos;
    ViewportTool* m_tool = nullptr;
    bool m_toolGrab = false; ///< the tool consumed the press: it gets the move/release too
    std::vector<vtkProp*> m_props;
};

} // namespace resect
