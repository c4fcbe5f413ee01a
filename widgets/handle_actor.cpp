#include "widgets/handle_actor.h"

#include <vtkActor.h>
#include <vtkCellArray.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkPolyDataMapper.h>
#include <vtkProperty.h>
#include <vtkUnsignedCharArray.h>

#include <cmath>

namespace resect {

HandleActor::HandleActor()
    : m_polyData(vtkSmartPointer<vtkPolyData>::New()),
      m_mapper(vtkSmartPointer<vtkPolyDataMapper>::New()),
      m_actor(vtkSmartPointer<vtkActor>::New()) {
    m_mapper->SetInputData(m_polyData);
    m_mapper->ScalarVisibilityOn();
    m_mapper->SetScalarModeToUsePointData();
    m_mapper->SetColorModeToDirectScalars();
    m_actor->SetMapper(m_mapper);
    vtkProperty* property = m_actor->GetProperty();
    property->SetRepresentationToPoints();
    property->SetPointSize(kSizePixels);
    property->RenderPointsAsSpheresOn();
    property->SetAmbient(0.3);
    property->SetSpecular(0.4);
    // Drawn in front of the tissue they sit on: a point placed on the surface would otherwise
    // be half buried, and one just behind it hidden (depth offset towards the camera).
    m_mapper->SetRelativeCoincidentTopologyPointOffsetParameter(kDepthOffsetUnits);
    m_actor->SetVisibility(false);
}

void HandleActor::setHandles(const std::vector<Vec3>& points, const std::vector<Color>& colors) {
    auto vtkPointsOut = vtkSmartPointer<vtkPoints>::New();
    vtkPointsOut->SetDataTypeToDouble();
    auto vertices = vtkSmartPointer<vtkCellArray>::New();
    auto rgb = vtkSmartPointer<vtkUnsignedCharArray>::New();
    rgb->SetName("colors");
    rgb->SetNumberOfComponents(3);
    const Color fallback = colors.empty() ? Color{1, 1, 1} : colors.front();
    for (std::size_t i = 0; i < points.size(); ++i) {
        const Vec3& p = points[i];
        if (!p.allFinite())
            continue;
        const vtkIdType id = vtkPointsOut->InsertNextPoint(p.x(), p.y(), p.z());
        vertices->InsertNextCell(1, &id);
        const Color& c = colors.size() == points.size() ? colors[i] : fallback;
        const unsigned char bytes[3] = {static_cast<unsigned char>(std::lround(255 * c[0])),
                                        static_cast<unsigned char>(std::lround(255 * c[1])),
                                        static_cast<unsigned char>(std::lround(255 * c[2]))};
        rgb->InsertNextTypedTuple(bytes);
    }
    m_polyData->Initialize();
    m_polyData->SetPoints(vtkPointsOut);
    m_polyData->SetVerts(vertices);
    m_polyData->GetPointData()->SetScalars(rgb);
    m_polyData->Modified();
    m_actor->SetVisibility(count() > 0);
}

void HandleActor::clear() {
    m_polyData->Initialize();
    m_polyData->Modified();
    m_actor->SetVisibility(false);
}

vtkActor* HandleActor::actor() const {
    return m_actor;
}

vtkPolyData* HandleActor::polyData() const {
    return m_polyData;
}

int HandleActor::count() const {
    return static_cast<int>(m_polyData->GetNumberOfPoints());
}

} // namespace resect
