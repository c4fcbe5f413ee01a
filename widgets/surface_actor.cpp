#include "widgets/surface_actor.h"

#include <vtkDataArray.h>
#include <vtkImageData.h>
#include <vtkPointData.h>
#include <vtkTexture.h>

#include <algorithm>
#include <cmath>

#include "scenario/vtk_convert.h"

#include <vtkActor.h>
#include <vtkPolyData.h>
#include <vtkPolyDataMapper.h>
#include <vtkProperty.h>

namespace resect {

SurfaceActor::SurfaceActor()
    : m_polyData(vtkSmartPointer<vtkPolyData>::New()),
      m_mapper(vtkSmartPointer<vtkPolyDataMapper>::New()),
      m_actor(vtkSmartPointer<vtkActor>::New()) {
    m_mapper->SetInputData(m_polyData);
    m_mapper->ScalarVisibilityOff();
    m_actor->SetMapper(m_mapper);
    vtkProperty* property = m_actor->GetProperty();
    property->SetColor(0.90, 0.62, 0.60); // pale mucosa pink
    property->SetAmbient(0.15);
    property->SetDiffuse(0.8);
    property->SetSpecular(0.25);
    property->SetSpecularPower(30.0);
    m_actor->SetVisibility(false);
}

namespace {

/// A procedural tissue texture (soft mottled mucosa with a faint vessel grid), 256 x 256 RGB,
/// so that a surface's texture coordinates show without shipping an image.
vtkSmartPointer<vtkTexture> makeTissueTexture() {
    constexpr int n = 256;
    auto image = vtkSmartPointer<vtkImageData>::New();
    image->SetDimensions(n, n, 1);
    image->AllocateScalars(VTK_UNSIGNED_CHAR, 3);
    for (int y = 0; y < n; ++y)
        for (int x = 0; x < n; ++x) {
            const double u = 2.0 * M_PI * x / n, v = 2.0 * M_PI * y / n;
            const double mottle = 0.5 + 0.25 * std::sin(3 * u + 2 * std::cos(2 * v)) + 0.25 * std::sin(5 * v + std::sin(4 * u));
            const bool vessel = (x % 32) < 2 || (y % 32) < 2;
            auto* px = static_cast<unsigned char*>(image->GetScalarPointer(x, y, 0));
            const double shade = vessel ? 0.75 : 0.9 + 0.1 * mottle;
            px[0] = static_cast<unsigned char>(std::clamp(235.0 * shade, 0.0, 255.0));
            px[1] = static_cast<unsigned char>(std::clamp((vessel ? 120.0 : 160.0) * shade, 0.0, 255.0));
            px[2] = static_cast<unsigned char>(std::clamp((vessel ? 125.0 : 150.0) * shade, 0.0, 255.0));
        }
    auto texture = vtkSmartPointer<vtkTexture>::New();
    texture->SetInputData(image);
    texture->InterpolateOn();
    texture->RepeatOn();
    return texture;
}

} // namespace

void SurfaceActor::setSurface(const TriangleSurface& surface) {
    if (surface.triangles.empty()) {
        clear();
        return;
    }
    vtkSmartPointer<vtkPolyData> polyData = toPolyData(surface);
    if (polyData == nullptr) {
        clear();
        return;
    }
    m_polyData->ShallowCopy(polyData);
    m_polyData->Modified();
    // Textured where the surface has texture coordinates (shaded in tissue colour otherwise).
    if (textured()) {
        if (m_texture == nullptr)
            m_texture = makeTissueTexture();
        m_actor->SetTexture(m_texture);
    } else {
        m_actor->SetTexture(nullptr);
    }
    m_actor->SetVisibility(m_polyData->GetNumberOfCells() > 0);
}

bool SurfaceActor::textured() const {
    return m_polyData->GetPointData() != nullptr && m_polyData->GetPointData()->GetTCoords() != nullptr &&
           m_polyData->GetPointData()->GetTCoords()->GetNumberOfTuples() == m_polyData->GetNumberOfPoints();
}

void SurfaceActor::clear() {
    m_actor->SetTexture(nullptr);
    m_polyData->Initialize();
    m_polyData->Modified();
    m_actor->SetVisibility(false);
}

vtkActor* SurfaceActor::actor() const {
    return m_actor;
}

vtkPolyData* SurfaceActor::polyData() const {
    return m_polyData;
}

bool SurfaceActor::empty() const {
    return m_polyData->GetNumberOfCells() == 0;
}

Bounds SurfaceActor::bounds() const {
    Bounds b{1, -1, 1, -1, 1, -1};
    if (!empty())
        m_polyData->GetBounds(b.data());
    return b;
}

} // namespace resect
