#pragma once
// SurfaceActor: rendering adapter for a TriangleSurface (anatomy or the embedded visual
// surface), drawn in a uniform tissue colour.

#include "core/mesh/triangle_surface.h"
#include "widgets/orbit_camera.h"

#include <vtkSmartPointer.h>

class vtkActor;
class vtkPolyData;
class vtkPolyDataMapper;
class vtkTexture;

namespace resect {

class SurfaceActor {
public:
    SurfaceActor();

    /// Replaces the displayed surface; an empty surface shows nothing.
    void setSurface(const TriangleSurface& surface);
    void clear();

    vtkActor* actor() const;
    vtkPolyData* polyData() const;
    bool empty() const;
    /// True when the shown surface has texture coordinates: it is then drawn with a
    /// procedural tissue texture.
    bool textured() const;
    /// Bounds of the displayed surface; invalid (min > max) when empty.
    Bounds bounds() const;

private:
    vtkSmartPointer<vtkPolyData> m_polyData;
    vtkSmartPointer<vtkPolyDataMapper> m_mapper;
    vtkSmartPointer<vtkActor> m_actor;
    vtkSmartPointer<vtkTexture> m_texture; ///< made on first use
};

} // namespace resect
