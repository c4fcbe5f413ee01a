#include "widgets/tet_mesh_actor.h"

#include <vtkActor.h>
#include <vtkCellArray.h>
#include <vtkCellData.h>
#include <vtkDoubleArray.h>
#include <vtkIntArray.h>
#include <vtkLookupTable.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkPolyDataMapper.h>
#include <vtkProperty.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace resect {

namespace {

/// Colour of tissue without an overlay (the surface actor's mucosa pink).
constexpr double kTissueColour[3] = {0.90, 0.62, 0.60};

} // namespace

TetMeshActor::TetMeshActor()
    : m_boundary(vtkSmartPointer<vtkPolyData>::New()), m_points(vtkSmartPointer<vtkPoints>::New()),
      m_lut(makeQualityLookupTable()), m_mapper(vtkSmartPointer<vtkPolyDataMapper>::New()),
      m_actor(vtkSmartPointer<vtkActor>::New()) {
    m_points->SetDataTypeToDouble();
    m_mapper->SetInputData(m_boundary);
    m_mapper->SetLookupTable(m_lut);
    m_mapper->UseLookupTableScalarRangeOff();
    m_mapper->SetScalarModeToUseCellFieldData();
    m_mapper->SetColorModeToMapScalars();

    m_actor->SetMapper(m_mapper);
    vtkProperty* property = m_actor->GetProperty();
    property->SetEdgeColor(0.12, 0.12, 0.14);
    property->SetLineWidth(1.0);
    property->SetAmbient(0.15);
    property->SetDiffuse(0.8);
    property->SetSpecular(0.15);
    property->SetSpecularPower(20.0);
    property->SetColor(kTissueColour[0], kTissueColour[1], kTissueColour[2]);
    m_actor->SetVisibility(false);
    applyColouring();
    applyRepresentation();
}

void TetMeshActor::setMesh(const TetMesh& mesh) {
    if (mesh.empty()) {
        clear();
        return;
    }
    m_pos.assign(mesh.positions().begin(), mesh.positions().end());
    m_tets = mesh.tets();
    m_faces = allFaces(mesh);
    m_quality = resect::tetQualities(mesh);
    computeClipped(m_clipped);
    rebuildCells();
}

bool TetMeshActor::updatePositions(const TetMesh& mesh) {
    if (m_tets.empty() || mesh.nodeCount() != static_cast<int>(m_pos.size()) ||
        mesh.tetCount() != static_cast<int>(m_tets.size())) {
        setMesh(mesh);
        return false;
    }
    m_pos.assign(mesh.positions().begin(), mesh.positions().end());
    if (m_clipEnabled && computeClipped(m_clipped)) {
        rebuildCells();
        return true;
    }
    updatePoints();
    ++m_pointUpdates;
    return true;
}

void TetMeshActor::clear() {
    m_pos.clear();
    m_tets.clear();
    m_faces.clear();
    m_quality.clear();
    m_clipped.clear();
    m_displayed.clear();
    m_points->Initialize();
    m_boundary->Initialize();
    m_boundary->Modified();
    m_actor->SetVisibility(false);
}

void TetMeshActor::setTetSchemes(std::vector<Scheme> schemes) {
    m_schemes = std::move(schemes);
}

Scheme TetMeshActor::tetScheme(int tet) const {
    return tet >= 0 && tet < static_cast<int>(m_schemes.size()) ? m_schemes[tet] : Scheme::None;
}

void TetMeshActor::setDisplayMode(TetDisplayMode mode) {
    if (mode == m_mode)
        return;
    m_mode = mode;
    applyRepresentation();
    rebuildCells();
}

void TetMeshActor::setOverlayMeasure(QualityMeasure measure) {
    const QualityMeasure oldFilterMeasure = filterMeasure();
    m_measure = measure;
    m_range = defaultQualityRange(measure);
    applyColouring();
    if (m_filterEnabled && filterMeasure() != oldFilterMeasure)
        rebuildCells();
}

void TetMeshActor::setColorRange(double lo, double hi) {
    if (!std::isfinite(lo) || !std::isfinite(hi) || !(lo < hi))
        return;
    m_range = {lo, hi};
    applyColouring();
}

std::pair<double, double> TetMeshActor::autoRange() const {
    const QualityMeasure measure = filterMeasure();
    double lo = std::numeric_limits<double>::infinity();
    double hi = -lo;
    for (const TetQuality& q : m_quality) {
        const double v = qualityMeasureValue(measure, q);
        if (!std::isfinite(v))
            continue;
        lo = std::min(lo, v);
        hi = std::max(hi, v);
    }
    if (!(lo < hi))
        return defaultQualityRange(measure);
    return {lo, hi};
}

vtkLookupTable* TetMeshActor::lookupTable() const {
    return m_lut;
}

void TetMeshActor::setQualityFilter(bool enabled, double threshold) {
    if (enabled == m_filterEnabled && threshold == m_filterThreshold)
        return;
    const bool rebuild = enabled || m_filterEnabled;
    m_filterEnabled = enabled;
    m_filterThreshold = threshold;
    if (rebuild)
        rebuildCells();
}

QualityMeasure TetMeshActor::filterMeasure() const {
    return m_measure == QualityMeasure::None ? QualityMeasure::RadiusRatio : m_measure;
}

void TetMeshActor::setClipPlane(bool enabled, const Vec3& origin, const Vec3& normal) {
    const double length = normal.norm();
    m_clipEnabled = enabled && length > 0 && std::isfinite(length) && origin.allFinite();
    if (m_clipEnabled) {
        m_clipOrigin = origin;
        m_clipNormal = normal / length;
    }
    computeClipped(m_clipped);
    rebuildCells();
}

void TetMeshActor::setShrinkFactor(double factor) {
    if (!(factor > 0.0 && factor <= 1.0) || factor == m_shrink)
        return;
    m_shrink = factor;
    if (!m_pointsAreNodes)
        updatePoints();
}

vtkActor* TetMeshActor::actor() const {
    return m_actor;
}

vtkPolyData* TetMeshActor::boundary() const {
    return m_boundary;
}

Bounds TetMeshActor::bounds() const {
    Bounds b{1, -1, 1, -1, 1, -1};
    if (m_pos.empty())
        return b;
    Vec3 lo = m_pos.front(), hi = m_pos.front();
    for (const Vec3& p : m_pos) {
        lo = lo.cwiseMin(p);
        hi = hi.cwiseMax(p);
    }
    return {lo.x(), hi.x(), lo.y(), hi.y(), lo.z(), hi.z()};
}

bool TetMeshActor::isTetDisplayed(int tet) const {
    return std::binary_search(m_displayed.begin(), m_displayed.end(), tet);
}

double TetMeshActor::tetMeasure(QualityMeasure measure, int tet) const {
    return qualityMeasureValue(measure, m_quality[tet]);
}

bool TetMeshActor::computeClipped(std::vector<char>& clipped) const {
    std::vector<char> next(m_tets.size(), 0);
    if (m_clipEnabled) {
        for (std::size_t t = 0; t < m_tets.size(); ++t) {
            bool allPositive = true;
            for (int n : m_tets[t])
                allPositive = allPositive && (m_pos[n] - m_clipOrigin).dot(m_clipNormal) >= 0.0;
            next[t] = allPositive ? 1 : 0;
        }
    }
    const bool changed = next != clipped;
    clipped = std::move(next);
    return changed;
}

Vec3 TetMeshActor::shrunkCorner(int tet, int local) const {
    const Tet& nodes = m_tets[tet];
    const Vec3 centroid =
        0.25 * (m_pos[nodes[0]] + m_pos[nodes[1]] + m_pos[nodes[2]] + m_pos[nodes[3]]);
    return centroid + m_shrink * (m_pos[nodes[local]] - centroid);
}

void TetMeshActor::rebuildCells() {
    ++m_cellRebuilds;
    m_displayed.clear();
    if (m_tets.empty()) {
        clear();
        return;
    }
    const QualityMeasure fm = filterMeasure();
    std::vector<char> shown(m_tets.size(), 0);
    for (std::size_t t = 0; t < m_tets.size(); ++t) {
        if (m_clipped[t])
            continue;
        if (m_filterEnabled && !(qualityMeasureValue(fm, m_quality[t]) < m_filterThreshold))
            continue;
        shown[t] = 1;
        m_displayed.push_back(static_cast<int>(t));
    }

    // The triangles to draw, each with its owning tet.
    std::vector<Tri> triangles;
    std::vector<int> owners;
    m_pointsAreNodes = !(m_filterEnabled || m_mode == TetDisplayMode::ShrunkTets);
    if (!m_pointsAreNodes) {
        // Four points per shown tet, its four outward faces.
        triangles.reserve(4 * m_displayed.size());
        for (std::size_t i = 0; i < m_displayed.size(); ++i) {
            const int base = static_cast<int>(4 * i);
            for (const auto& f : kTetFaces) {
                triangles.push_back({base + f[0], base + f[1], base + f[2]});
                owners.push_back(m_displayed[i]);
            }
        }
    } else {
        const bool allFacesMode = m_mode == TetDisplayMode::Wireframe;
        for (const MeshFace& face : m_faces) {
            const bool a = shown[face.tets[0]] != 0;
            const bool b = face.tets[1] >= 0 && shown[face.tets[1]] != 0;
            if (allFacesMode ? (a || b) : (a != b)) {
                if (a) {
                    triangles.push_back(face.nodes);
                    owners.push_back(face.tets[0]);
                } else {
                    // Seen from the shown tet on the other side: reverse the orientation.
                    triangles.push_back({face.nodes[0], face.nodes[2], face.nodes[1]});
                    owners.push_back(face.tets[1]);
                }
            }
        }
    }

    auto polys = vtkSmartPointer<vtkCellArray>::New();
    polys->AllocateExact(static_cast<vtkIdType>(triangles.size()),
                         static_cast<vtkIdType>(3 * triangles.size()));
    for (const Tri& tri : triangles) {
        const vtkIdType ids[3] = {tri[0], tri[1], tri[2]};
        polys->InsertNextCell(3, ids);
    }
    auto tetIds = vtkSmartPointer<vtkIntArray>::New();
    tetIds->SetName(kTetIdArray);
    auto radiusRatio = vtkSmartPointer<vtkDoubleArray>::New();
    radiusRatio->SetName(kRadiusRatioArray);
    auto minDihedral = vtkSmartPointer<vtkDoubleArray>::New();
    minDihedral->SetName(kMinDihedralArray);
    const auto count = static_cast<vtkIdType>(owners.size());
    tetIds->SetNumberOfValues(count);
    radiusRatio->SetNumberOfValues(count);
    minDihedral->SetNumberOfValues(count);
    for (vtkIdType c = 0; c < count; ++c) {
        const int t = owners[static_cast<std::size_t>(c)];
        tetIds->SetValue(c, t);
        radiusRatio->SetValue(c, qualityMeasureValue(QualityMeasure::RadiusRatio, m_quality[t]));
        minDihedral->SetValue(c, qualityMeasureValue(QualityMeasure::MinDihedral, m_quality[t]));
    }

    m_boundary->Initialize();
    updatePoints();
    m_boundary->SetPoints(m_points);
    m_boundary->SetPolys(polys);
    m_boundary->GetCellData()->AddArray(tetIds);
    m_boundary->GetCellData()->AddArray(radiusRatio);
    m_boundary->GetCellData()->AddArray(minDihedral);
    m_boundary->Modified();
    m_actor->SetVisibility(count > 0);
}

void TetMeshActor::updatePoints() {
    if (m_pointsAreNodes) {
        m_points->SetNumberOfPoints(static_cast<vtkIdType>(m_pos.size()));
        for (std::size_t n = 0; n < m_pos.size(); ++n)
            m_points->SetPoint(static_cast<vtkIdType>(n), m_pos[n].data());
    } else {
        m_points->SetNumberOfPoints(static_cast<vtkIdType>(4 * m_displayed.size()));
        for (std::size_t i = 0; i < m_displayed.size(); ++i)
            for (int k = 0; k < 4; ++k)
                m_points->SetPoint(static_cast<vtkIdType>(4 * i + k),
                                   shrunkCorner(m_displayed[i], k).data());
    }
    m_points->Modified();
    m_boundary->Modified();
}

void TetMeshActor::applyColouring() {
    m_lut->SetTableRange(m_range.first, m_range.second);
    m_mapper->SetScalarRange(m_range.first, m_range.second);
    switch (m_measure) {
    case QualityMeasure::None:
        m_mapper->ScalarVisibilityOff();
        break;
    case QualityMeasure::RadiusRatio:
        m_mapper->SelectColorArray(kRadiusRatioArray);
        m_mapper->ScalarVisibilityOn();
        break;
    case QualityMeasure::MinDihedral:
        m_mapper->SelectColorArray(kMinDihedralArray);
        m_mapper->ScalarVisibilityOn();
        break;
    }
    m_mapper->Modified();
}

void TetMeshActor::applyRepresentation() {
    vtkProperty* property = m_actor->GetProperty();
    if (m_mode == TetDisplayMode::Wireframe) {
        property->SetRepresentationToWireframe();
        property->EdgeVisibilityOff();
    } else {
        property->SetRepresentationToSurface();
        property->EdgeVisibilityOn();
    }
}

} // namespace resect
