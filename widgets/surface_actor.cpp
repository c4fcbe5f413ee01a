#include "widgets/surface_actor.h"

#include "widgets/piece_colors.h"

#include <vtkActor.h>
#include <vtkCellArray.h>
#include <vtkDataArray.h>
#include <vtkDoubleArray.h>
#include <vtkImageData.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkPolyDataMapper.h>
#include <vtkProperty.h>
#include <vtkTexture.h>

#include <algorithm>
#include <cmath>

namespace resect {

namespace {

/// The tissue's colour without a texture: pale mucosa pink.
constexpr Rgb kSurfaceColour{0.90, 0.62, 0.60};

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
            const double mottle = 0.5 + 0.25 * std::sin(3 * u + 2 * std::cos(2 * v)) +
                                  0.25 * std::sin(5 * v + std::sin(4 * u));
            const bool vessel = (x % 32) < 2 || (y % 32) < 2;
            auto* px = static_cast<unsigned char*>(image->GetScalarPointer(x, y, 0));
            const double shade = vessel ? 0.75 : 0.9 + 0.1 * mottle;
            px[0] = static_cast<unsigned char>(std::clamp(235.0 * shade, 0.0, 255.0));
            px[1] = static_cast<unsigned char>(
                std::clamp((vessel ? 120.0 : 160.0) * shade, 0.0, 255.0));
            px[2] = static_cast<unsigned char>(
                std::clamp((vessel ? 125.0 : 150.0) * shade, 0.0, 255.0));
        }
    auto texture = vtkSmartPointer<vtkTexture>::New();
    texture->SetInputData(image);
    texture->InterpolateOn();
    texture->RepeatOn();
    return texture;
}

/// The cut faces' texture: cut tissue (kCutFaceColour, lightly mottled) with a grid of lines
/// every quarter of a repeat, so that the sweep's (u, v) shows on the cut. 128 x 128 RGB.
vtkSmartPointer<vtkTexture> makeCutTexture() {
    constexpr int n = 128;
    auto image = vtkSmartPointer<vtkImageData>::New();
    image->SetDimensions(n, n, 1);
    image->AllocateScalars(VTK_UNSIGNED_CHAR, 3);
    for (int y = 0; y < n; ++y)
        for (int x = 0; x < n; ++x) {
            const double u = 2.0 * M_PI * x / n, v = 2.0 * M_PI * y / n;
            const double mottle = 0.96 + 0.04 * std::sin(7 * u + 3 * std::sin(5 * v));
            const bool line = (x % 32) < 2 || (y % 32) < 2;
            auto* px = static_cast<unsigned char*>(image->GetScalarPointer(x, y, 0));
            for (int k = 0; k < 3; ++k) {
                const double c = line ? 0.78 * kCutFaceColour[k] * (k == 0 ? 1.0 : 0.8)
                                      : kCutFaceColour[k] * mottle;
                px[k] = static_cast<unsigned char>(std::clamp(255.0 * c, 0.0, 255.0));
            }
        }
    auto texture = vtkSmartPointer<vtkTexture>::New();
    texture->SetInputData(image);
    texture->InterpolateOn();
    texture->RepeatOn();
    return texture;
}

} // namespace

SurfaceActor::SurfaceActor()
    : m_points(vtkSmartPointer<vtkPoints>::New()), m_polyData(vtkSmartPointer<vtkPolyData>::New()),
      m_mapper(vtkSmartPointer<vtkPolyDataMapper>::New()),
      m_actor(vtkSmartPointer<vtkActor>::New()), m_cutData(vtkSmartPointer<vtkPolyData>::New()),
      m_cutMapper(vtkSmartPointer<vtkPolyDataMapper>::New()),
      m_cutActor(vtkSmartPointer<vtkActor>::New()) {
    m_points->SetDataTypeToDouble();
    m_mapper->SetInputData(m_polyData);
    m_mapper->ScalarVisibilityOff();
    m_actor->SetMapper(m_mapper);
    vtkProperty* property = m_actor->GetProperty();
    property->SetColor(kSurfaceColour[0], kSurfaceColour[1], kSurfaceColour[2]);
    property->SetAmbient(0.15);
    property->SetDiffuse(0.8);
    property->SetSpecular(0.25);
    property->SetSpecularPower(30.0);
    m_actor->SetVisibility(false);

    m_cutMapper->SetInputData(m_cutData);
    m_cutMapper->ScalarVisibilityOff();
    m_cutActor->SetMapper(m_cutMapper);
    vtkProperty* cut = m_cutActor->GetProperty();
    cut->SetColor(1.0, 1.0, 1.0); // the texture's colours as they are
    cut->SetAmbient(0.2);
    cut->SetDiffuse(0.8);
    cut->SetSpecular(0.1);
    m_cutActor->SetVisibility(false);
}

void SurfaceActor::setSurface(const TriangleSurface& surface) {
    if (surface.triangles.empty()) {
        clear();
        return;
    }
    m_surface = surface;
    if (m_offsets.size() != m_surface.positions.size())
        m_offsets.clear();
    rebuildCells();
}

bool SurfaceActor::updatePositions(const TriangleSurface& surface) {
    if (surface.triangleCount() != m_surface.triangleCount())
        return false;
    return updatePositions(surface.positions);
}

bool SurfaceActor::updatePositions(std::span<const Vec3> positions) {
    if (m_surface.triangles.empty() || positions.size() != m_surface.positions.size())
        return false;
    std::copy(positions.begin(), positions.end(), m_surface.positions.begin());
    updatePoints();
    return true;
}

void SurfaceActor::rebuildCells() {
    const bool hasCutUvs = m_surface.cutUvs.size() == m_surface.positions.size() &&
                           m_surface.cutFaces.size() == m_surface.triangles.size();
    const bool separateCuts = m_cutFacesVisible && hasCutUvs;
    auto polys = vtkSmartPointer<vtkCellArray>::New();
    auto cutPolys = vtkSmartPointer<vtkCellArray>::New();
    for (int f = 0; f < m_surface.triangleCount(); ++f) {
        const Tri& t = m_surface.triangles[f];
        const vtkIdType ids[3] = {t[0], t[1], t[2]};
        (separateCuts && m_surface.isCutFace(f) ? cutPolys : polys)->InsertNextCell(3, ids);
    }
    m_polyData->Initialize();
    m_polyData->SetPoints(m_points);
    m_polyData->SetPolys(polys);
    if (!m_surface.uvs.empty() && m_surface.uvs.size() == m_surface.positions.size()) {
        auto uv = vtkSmartPointer<vtkDoubleArray>::New();
        uv->SetName("uv");
        uv->SetNumberOfComponents(2);
        uv->SetNumberOfTuples(static_cast<vtkIdType>(m_surface.uvs.size()));
        for (std::size_t i = 0; i < m_surface.uvs.size(); ++i) {
            uv->SetComponent(static_cast<vtkIdType>(i), 0, m_surface.uvs[i].x());
            uv->SetComponent(static_cast<vtkIdType>(i), 1, m_surface.uvs[i].y());
        }
        m_polyData->GetPointData()->SetTCoords(uv);
    }
    m_cutData->Initialize();
    if (cutPolys->GetNumberOfCells() > 0) {
        // The sweep's (u, v) of every vertex; vertices no cut made are not corners of a cut face.
        auto uv = vtkSmartPointer<vtkDoubleArray>::New();
        uv->SetName("cut_uv");
        uv->SetNumberOfComponents(2);
        uv->SetNumberOfTuples(static_cast<vtkIdType>(m_surface.cutUvs.size()));
        for (std::size_t i = 0; i < m_surface.cutUvs.size(); ++i) {
            const Eigen::Vector2d& c = m_surface.cutUvs[i];
            const bool known = std::isfinite(c.x()) && std::isfinite(c.y());
            uv->SetComponent(static_cast<vtkIdType>(i), 0, known ? kCutTextureScale * c.x() : 0.0);
            uv->SetComponent(static_cast<vtkIdType>(i), 1, known ? kCutTextureScale * c.y() : 0.0);
        }
        m_cutData->SetPoints(m_points);
        m_cutData->SetPolys(cutPolys);
        m_cutData->GetPointData()->SetTCoords(uv);
        if (m_cutTexture == nullptr)
            m_cutTexture = makeCutTexture();
    }
    m_cutData->Modified();
    // Textured where the surface has texture coordinates (shaded in tissue colour otherwise).
    if (textured() && m_texture == nullptr)
        m_texture = makeTissueTexture();
    applyColours();
    updatePoints();
    applyVisibility();
}

void SurfaceActor::updatePoints() {
    const bool offsets = m_offsets.size() == m_surface.positions.size();
    m_points->SetNumberOfPoints(static_cast<vtkIdType>(m_surface.positions.size()));
    for (std::size_t i = 0; i < m_surface.positions.size(); ++i) {
        const Vec3 p =
            offsets ? Vec3(m_surface.positions[i] + m_offsets[i]) : m_surface.positions[i];
        m_points->SetPoint(static_cast<vtkIdType>(i), p.data());
    }
    m_points->Modified();
    m_polyData->Modified();
    m_cutData->Modified();
}

void SurfaceActor::setVertexOffsets(std::vector<Vec3> offsets) {
    if (offsets == m_offsets)
        return;
    m_offsets = std::move(offsets);
    if (!m_surface.triangles.empty())
        updatePoints();
}

void SurfaceActor::setVisible(bool visible) {
    m_visible = visible;
    applyVisibility();
}

void SurfaceActor::setCutFacesVisible(bool visible) {
    if (visible == m_cutFacesVisible)
        return;
    m_cutFacesVisible = visible;
    if (!m_surface.triangles.empty())
        rebuildCells();
}

void SurfaceActor::setFade(double amount, const std::array<double, 3>& towards) {
    m_fade = std::clamp(amount, 0.0, 1.0);
    m_fadeTowards = towards;
    applyColours();
}

void SurfaceActor::applyColours() {
    const Rgb tissue = mixColours(kSurfaceColour, m_fadeTowards, m_fade);
    m_actor->GetProperty()->SetColor(tissue[0], tissue[1], tissue[2]);
    // The cut's texture is drawn as it is (white), a faded cut in its plain colour.
    const Rgb cut =
        m_fade > 0 ? mixColours(kCutFaceColour, m_fadeTowards, m_fade) : Rgb{1.0, 1.0, 1.0};
    m_cutActor->GetProperty()->SetColor(cut[0], cut[1], cut[2]);
    m_actor->SetTexture(m_fade == 0 && textured() ? m_texture.Get() : nullptr);
    m_cutActor->SetTexture(m_fade == 0 ? m_cutTexture.Get() : nullptr);
}

void SurfaceActor::applyVisibility() {
    m_actor->SetVisibility(m_visible && m_polyData->GetNumberOfCells() > 0);
    m_cutActor->SetVisibility(m_visible && m_cutData->GetNumberOfCells() > 0);
}

bool SurfaceActor::textured() const {
    return m_polyData->GetPointData() != nullptr &&
           m_polyData->GetPointData()->GetTCoords() != nullptr &&
           m_polyData->GetPointData()->GetTCoords()->GetNumberOfTuples() ==
               m_polyData->GetNumberOfPoints();
}

void SurfaceActor::clear() {
    m_surface = {};
    m_offsets.clear();
    m_actor->SetTexture(nullptr);
    m_points->Initialize();
    m_polyData->Initialize();
    m_polyData->Modified();
    m_cutData->Initialize();
    m_cutData->Modified();
    applyVisibility();
}

vtkActor* SurfaceActor::actor() const {
    return m_actor;
}

vtkActor* SurfaceActor::cutActor() const {
    return m_cutActor;
}

vtkPolyData* SurfaceActor::cutPolyData() const {
    return m_cutData;
}

std::vector<vtkProp*> SurfaceActor::props() const {
    return {m_actor, m_cutActor};
}

vtkPolyData* SurfaceActor::polyData() const {
    return m_polyData;
}

bool SurfaceActor::empty() const {
    return m_surface.triangles.empty();
}

Bounds SurfaceActor::bounds() const {
    Bounds b{1, -1, 1, -1, 1, -1};
    if (!empty())
        m_points->GetBounds(b.data());
    return b;
}

} // namespace resect
