#include "widgets/tet_picker.h"

#include "widgets/tet_mesh_actor.h"
#include "widgets/vtk_viewport.h"

#include <QMouseEvent>

#include <vtkCellArray.h>
#include <vtkCellData.h>
#include <vtkDataArray.h>
#include <vtkIdList.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace resect {

namespace {

/// True if the ray meets the box (slab test).
bool rayHitsBox(const Ray& ray, const double bounds[6]) {
    double enter = 0.0;
    double leave = std::numeric_limits<double>::infinity();
    for (int axis = 0; axis < 3; ++axis) {
        const double o = ray.origin[axis];
        const double d = ray.direction[axis];
        const double lo = bounds[2 * axis];
        const double hi = bounds[2 * axis + 1];
        if (d == 0.0) {
            if (o < lo || o > hi)
                return false;
            continue;
        }
        double s0 = (lo - o) / d;
        double s1 = (hi - o) / d;
        if (s0 > s1)
            std::swap(s0, s1);
        enter = std::max(enter, s0);
        leave = std::min(leave, s1);
        if (enter > leave)
            return false;
    }
    return true;
}

/// Moller-Trumbore: the ray parameter s >= 0 of the hit with triangle (a, b, c), either
/// side, or a negative value for a miss. The tolerance on the barycentric coordinates is
/// relative (the test is scale invariant), so a ray through a shared edge hits one of the
/// two triangles.
double rayTriangle(const Ray& ray, const Vec3& a, const Vec3& b, const Vec3& c) {
    constexpr double kBarycentricTolerance = 1e-12;
    const Vec3 e1 = b - a;
    const Vec3 e2 = c - a;
    const Vec3 p = ray.direction.cross(e2);
    const double det = e1.dot(p);
    const double scale = e1.norm() * e2.norm();
    if (!(std::abs(det) > 1e-14 * scale))
        return -1.0; // parallel or degenerate
    const double inv = 1.0 / det;
    const Vec3 t = ray.origin - a;
    const double u = t.dot(p) * inv;
    if (u < -kBarycentricTolerance || u > 1.0 + kBarycentricTolerance)
        return -1.0;
    const Vec3 q = t.cross(e1);
    const double v = ray.direction.dot(q) * inv;
    if (v < -kBarycentricTolerance || u + v > 1.0 + kBarycentricTolerance)
        return -1.0;
    return e2.dot(q) * inv;
}

} // namespace

TetPicker::TetPicker(QObject* parent) : QObject(parent) {}

int TetPicker::pickTet(const VtkViewport& viewport, QPointF pixel) {
    const Ray ray = pixelRay(viewport.camera(), viewport.size(), pixel);
    return pickTet(viewport.tetMeshActor(), ray);
}

int TetPicker::pickTet(const TetMeshActor& actor, const Ray& ray, double* distance) {
    vtkPolyData* poly = actor.boundary();
    if (actor.empty() || poly == nullptr || poly->GetNumberOfCells() == 0)
        return -1;
    vtkDataArray* tetIds = poly->GetCellData()->GetArray(kTetIdArray);
    vtkPoints* points = poly->GetPoints();
    vtkCellArray* polys = poly->GetPolys();
    if (tetIds == nullptr || points == nullptr || polys == nullptr)
        return -1;
    double bounds[6];
    poly->GetBounds(bounds);
    if (!rayHitsBox(ray, bounds))
        return -1;

    int best = -1;
    double bestS = std::numeric_limits<double>::infinity();
    auto ids = vtkSmartPointer<vtkIdList>::New();
    const vtkIdType cells = polys->GetNumberOfCells();
    Vec3 corner[3];
    for (vtkIdType c = 0; c < cells; ++c) {
        polys->GetCellAtId(c, ids);
        if (ids->GetNumberOfIds() != 3)
            continue;
        for (int k = 0; k < 3; ++k)
            points->GetPoint(ids->GetId(k), corner[k].data());
        const double s = rayTriangle(ray, corner[0], corner[1], corner[2]);
        if (s >= 0.0 && s < bestS) {
            bestS = s;
            best = static_cast<int>(tetIds->GetTuple1(c));
        }
    }
    if (distance != nullptr)
        *distance = bestS;
    return best;
}

bool TetPicker::mousePress(VtkViewport& /*viewport*/, QMouseEvent* event) {
    if (event->button() != Qt::LeftButton || event->modifiers() != Qt::NoModifier)
        return false;
    m_pressed = true;
    m_moved = false;
    m_pressPos = event->position();
    return true;
}

bool TetPicker::mouseMove(VtkViewport& /*viewport*/, QMouseEvent* event) {
    if (!m_pressed)
        return false;
    const QPointF d = event->position() - m_pressPos;
    if (std::hypot(d.x(), d.y()) > kClickTolerance)
        m_moved = true;
    return true;
}

bool TetPicker::mouseRelease(VtkViewport& viewport, QMouseEvent* event) {
    if (!m_pressed)
        return false;
    m_pressed = false;
    const QPointF d = event->position() - m_pressPos;
    if (m_moved || std::hypot(d.x(), d.y()) > kClickTolerance)
        return true;
    m_lastPicked = pickTet(viewport, event->position());
    emit tetPicked(m_lastPicked);
    return true;
}

void TetPicker::deactivated(VtkViewport& /*viewport*/) {
    m_pressed = false;
    m_moved = false;
    emit toolDeactivated();
}

} // namespace resect
