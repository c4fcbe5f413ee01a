#include "widgets/sweep_actor.h"

#include <vtkActor.h>
#include <vtkCellArray.h>
#include <vtkCellData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkPolyDataMapper.h>
#include <vtkProperty.h>
#include <vtkUnsignedCharArray.h>

#include <cmath>

namespace resect {

namespace {

std::array<unsigned char, 3> toBytes(const std::array<double, 3>& rgb) {
    std::array<unsigned char, 3> out{};
    for (int i = 0; i < 3; ++i)
        out[i] = static_cast<unsigned char>(std::lround(255.0 * rgb[i]));
    return out;
}

} // namespace

SweepActor::SweepActor()
    : m_surface(vtkSmartPointer<vtkPolyData>::New()),
      m_surfaceMapper(vtkSmartPointer<vtkPolyDataMapper>::New()),
      m_surfaceActor(vtkSmartPointer<vtkActor>::New()),
      m_curves(vtkSmartPointer<vtkPolyData>::New()),
      m_curveMapper(vtkSmartPointer<vtkPolyDataMapper>::New()),
      m_curveActor(vtkSmartPointer<vtkActor>::New()) {
    m_surfaceMapper->SetInputData(m_surface);
    m_surfaceMapper->ScalarVisibilityOff();
    m_surfaceActor->SetMapper(m_surfaceMapper);
    vtkProperty* surface = m_surfaceActor->GetProperty();
    surface->SetColor(kSurfaceColor[0], kSurfaceColor[1], kSurfaceColor[2]);
    surface->SetOpacity(kOpacity);
    surface->SetAmbient(0.3);
    surface->SetDiffuse(0.7);
    surface->SetSpecular(0.1);
    surface->BackfaceCullingOff();
    m_surfaceActor->SetVisibility(false);

    m_curveMapper->SetInputData(m_curves);
    m_curveMapper->ScalarVisibilityOn();
    m_curveMapper->SetScalarModeToUseCellData();
    m_curveMapper->SetColorModeToDirectScalars();
    m_curveActor->SetMapper(m_curveMapper);
    vtkProperty* curves = m_curveActor->GetProperty();
    curves->SetLineWidth(2.5);
    curves->LightingOff();
    m_curveActor->SetVisibility(false);
}

void SweepActor::setSweep(const SweepSurface& sweep) {
    setCurves(sweep.curves());
}

void SweepActor::setCurves(const std::vector<std::vector<Vec3>>& curves) {
    auto points = vtkSmartPointer<vtkPoints>::New();
    points->SetDataTypeToDouble();
    // VTK point id of curve i, point j; -1 for a non-finite point.
    std::vector<std::vector<vtkIdType>> ids(curves.size());
    for (std::size_t i = 0; i < curves.size(); ++i)
        for (const Vec3& p : curves[i])
            ids[i].push_back(p.allFinite() ? points->InsertNextPoint(p.x(), p.y(), p.z()) : -1);

    auto lines = vtkSmartPointer<vtkCellArray>::New();
    auto colors = vtkSmartPointer<vtkUnsignedCharArray>::New();
    colors->SetName("colors");
    colors->SetNumberOfComponents(3);
    for (std::size_t i = 0; i < ids.size(); ++i) {
        const auto rgb = toBytes(i == 0                ? kStartColor
                                 : i + 1 == ids.size() ? kEndColor
                                                       : kCurveColor);
        for (std::size_t j = 0; j + 1 < ids[i].size(); ++j) {
            if (ids[i][j] < 0 || ids[i][j + 1] < 0)
                continue;
            const vtkIdType segment[2] = {ids[i][j], ids[i][j + 1]};
            lines->InsertNextCell(2, segment);
            colors->InsertNextTypedTuple(rgb.data());
        }
    }

    auto triangles = vtkSmartPointer<vtkCellArray>::New();
    for (std::size_t i = 0; i + 1 < ids.size(); ++i) {
        const auto& a = ids[i];
        const auto& b = ids[i + 1];
        if (a.size() != b.size() || a.size() < 2)
            continue;
        for (std::size_t j = 0; j + 1 < a.size(); ++j) {
            // Quad (i, j) as in SweepSurface: (P(i,j), P(i,j+1), P(i+1,j+1)) and
            // (P(i,j), P(i+1,j+1), P(i+1,j)).
            const vtkIdType t0[3] = {a[j], a[j + 1], b[j + 1]};
            const vtkIdType t1[3] = {a[j], b[j + 1], b[j]};
            for (const vtkIdType* t : {t0, t1})
                if (t[0] >= 0 && t[1] >= 0 && t[2] >= 0)
                    triangles->InsertNextCell(3, t);
        }
    }

    m_curves->Initialize();
    m_curves->SetPoints(points);
    m_curves->SetLines(lines);
    m_curves->GetCellData()->SetScalars(colors);
    m_curves->Modified();
    m_surface->Initialize();
    m_surface->SetPoints(points);
    m_surface->SetPolys(triangles);
    m_surface->Modified();
    m_curveActor->SetVisibility(m_curves->GetNumberOfCells() > 0);
    m_surfaceActor->SetVisibility(m_surface->GetNumberOfCells() > 0);
}

void SweepActor::clear() {
    m_surface->Initialize();
    m_surface->Modified();
    m_curves->Initialize();
    m_curves->Modified();
    m_surfaceActor->SetVisibility(false);
    m_curveActor->SetVisibility(false);
}

std::vector<vtkProp*> SweepActor::props() const {
    return {m_surfaceActor, m_curveActor};
}

vtkActor* SweepActor::surfaceActor() const {
    return m_surfaceActor;
}

vtkActor* SweepActor::curveActor() const {
    return m_curveActor;
}

vtkPolyData* SweepActor::surface() const {
    return m_surface;
}

vtkPolyData* SweepActor::curves() const {
    return m_curves;
}

bool SweepActor::empty() const {
    return m_surface->GetNumberOfCells() == 0 && m_curves->GetNumberOfCells() == 0;
}

} // namespace resect
