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
#include <vtkUnsignedCharArray.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <unordered_set>

namespace resect {

namespace {

/// Width of the touched tets' edges and of the picked tet's outline, in pixels.
constexpr double kTouchedLineWidth = 2.5;
constexpr double kPickedLineWidth = 4.0;

/// An overlay drawn over coincident geometry of the tets: pulled towards the camera by a
/// polygon or line offset so that it wins the depth test.
void makeOverlay(vtkSmartPointer<vtkPolyData>& data, vtkSmartPointer<vtkPolyDataMapper>& mapper,
                 vtkSmartPointer<vtkActor>& actor, const Rgb& colour) {
    data = vtkSmartPointer<vtkPolyData>::New();
    mapper = vtkSmartPointer<vtkPolyDataMapper>::New();
    actor = vtkSmartPointer<vtkActor>::New();
    mapper->SetInputData(data);
    mapper->ScalarVisibilityOff();
    mapper->SetRelativeCoincidentTopologyPolygonOffsetParameters(-1.0, -4.0);
    mapper->SetRelativeCoincidentTopologyLineOffsetParameters(0.0, -40.0);
    actor->SetMapper(mapper);
    actor->PickableOff();
    vtkProperty* property = actor->GetProperty();
    property->SetColor(colour[0], colour[1], colour[2]);
    property->SetAmbient(0.25);
    property->SetDiffuse(0.75);
    actor->SetVisibility(false);
}

std::uint64_t lineKey(vtkIdType a, vtkIdType b) {
    if (a > b)
        std::swap(a, b);
    return (static_cast<std::uint64_t>(a) << 32) | static_cast<std::uint64_t>(b);
}

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
    m_actor->SetVisibility(false);

    // The overlays' relative offsets take effect only with VTK's polygon-offset resolution of
    // coincident topology (off by default; with its default parameters it moves nothing else).
    vtkMapper::SetResolveCoincidentTopologyToPolygonOffset();
    m_pickedPoints = vtkSmartPointer<vtkPoints>::New();
    m_pickedPoints->SetDataTypeToDouble();
    makeOverlay(m_cutOverlay.data, m_cutOverlay.mapper, m_cutOverlay.actor, kCutFaceColour);
    m_cutOverlay.actor->GetProperty()->SetEdgeColor(0.12, 0.12, 0.14);
    makeOverlay(m_touchedOverlay.data, m_touchedOverlay.mapper, m_touchedOverlay.actor,
                kTouchedColour);
    m_touchedOverlay.actor->GetProperty()->SetLineWidth(kTouchedLineWidth);
    m_touchedOverlay.actor->GetProperty()->LightingOff();
    makeOverlay(m_pickedOverlay.data, m_pickedOverlay.mapper, m_pickedOverlay.actor, kPickedColour);
    m_pickedOverlay.actor->GetProperty()->SetLineWidth(kPickedLineWidth);
    m_pickedOverlay.actor->GetProperty()->SetPointSize(2.0 * kPickedLineWidth);
    m_pickedOverlay.actor->GetProperty()->LightingOff();
    m_pickedOverlay.actor->GetProperty()->RenderLinesAsTubesOn();
    m_pickedOverlay.actor->GetProperty()->RenderPointsAsSpheresOn();
    m_touchedOverlay.actor->GetProperty()->RenderLinesAsTubesOn();
    applyFade();
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
    // Which local faces of each tet are boundary faces (face f is opposite local node f).
    m_boundaryFaces.assign(m_tets.size(), 0);
    for (const MeshFace& face : m_faces) {
        if (face.tets[1] >= 0)
            continue;
        const Tet& q = m_tets[face.tets[0]];
        for (int f = 0; f < 4; ++f)
            if (q[f] != face.nodes[0] && q[f] != face.nodes[1] && q[f] != face.nodes[2])
                m_boundaryFaces[face.tets[0]] |= static_cast<std::uint8_t>(1u << f);
    }
    m_tetPiece.clear();
    m_nodePiece.clear();
    m_onCut.clear();
    m_touched.clear();
    m_pieceOffsets.clear();
    if (m_picked >= static_cast<int>(m_tets.size()))
        m_picked = -1;
    computeClipped(m_clipped);
    rebuildCells();
}

bool TetMeshActor::updatePositions(const TetMesh& mesh) {
    if (m_tets.empty() || mesh.nodeCount() != static_cast<int>(m_pos.size()) ||
        mesh.tetCount() != static_cast<int>(m_tets.size())) {
        setMesh(mesh);
        return false;
    }
    return updatePositions(mesh.positions());
}

bool TetMeshActor::updatePositions(std::span<const Vec3> positions) {
    if (m_tets.empty() || positions.size() != m_pos.size())
        return false;
    m_pos.assign(positions.begin(), positions.end());
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
    m_boundaryFaces.clear();
    m_cellTet.clear();
    m_cellNodes.clear();
    m_cellOnBoundary.clear();
    m_tetPiece.clear();
    m_nodePiece.clear();
    m_onCut.clear();
    m_touched.clear();
    m_pieceOffsets.clear();
    m_picked = -1;
    m_points->Initialize();
    m_boundary->Initialize();
    m_boundary->Modified();
    for (Overlay* o : {&m_cutOverlay, &m_touchedOverlay, &m_pickedOverlay}) {
        o->data->Initialize();
        o->data->Modified();
    }
    applyVisibility();
}

void TetMeshActor::setPieces(std::vector<int> tetPiece) {
    const bool valid = tetPiece.size() == m_tets.size() && !tetPiece.empty() &&
                       *std::min_element(tetPiece.begin(), tetPiece.end()) >= 0;
    m_tetPiece = valid ? std::move(tetPiece) : std::vector<int>{};
    m_nodePiece.assign(valid ? m_pos.size() : 0, 0);
    for (std::size_t t = 0; t < m_tetPiece.size(); ++t)
        for (int n : m_tets[t])
            m_nodePiece[n] = m_tetPiece[t];
    rebuildMarks();
    if (!m_pieceOffsets.empty())
        updatePoints();
}

int TetMeshActor::tetPiece(int tet) const {
    return tet >= 0 && tet < static_cast<int>(m_tetPiece.size()) ? m_tetPiece[tet] : 0;
}

int TetMeshActor::pieceCount() const {
    if (m_tets.empty())
        return 0;
    return m_tetPiece.empty() ? 1 : 1 + *std::max_element(m_tetPiece.begin(), m_tetPiece.end());
}

void TetMeshActor::setCutMarks(std::vector<std::uint8_t> onCutSurface,
                               std::vector<std::uint8_t> touchedTets) {
    m_onCut =
        onCutSurface.size() == m_pos.size() ? std::move(onCutSurface) : std::vector<std::uint8_t>{};
    m_touched =
        touchedTets.size() == m_tets.size() ? std::move(touchedTets) : std::vector<std::uint8_t>{};
    rebuildMarks();
}

void TetMeshActor::setPieceOffsets(std::vector<Vec3> offsets) {
    if (offsets == m_pieceOffsets)
        return;
    m_pieceOffsets = std::move(offsets);
    if (!m_tets.empty())
        updatePoints();
}

void TetMeshActor::setPickedTet(int tet) {
    m_picked = tet >= 0 && tet < static_cast<int>(m_tets.size()) ? tet : -1;
    rebuildPicked();
    applyVisibility();
}

void TetMeshActor::setColorMode(TetColorMode mode) {
    if (mode == m_colorMode)
        return;
    m_colorMode = mode;
    applyColouring();
}

void TetMeshActor::setCutFacesVisible(bool visible) {
    m_cutFacesVisible = visible;
    applyVisibility();
}

void TetMeshActor::setTouchedVisible(bool visible) {
    m_touchedVisible = visible;
    applyVisibility();
}

void TetMeshActor::setVisible(bool visible) {
    m_visible = visible;
    applyVisibility();
}

void TetMeshActor::setFade(double amount, const Rgb& towards) {
    const double a = std::clamp(amount, 0.0, 1.0);
    if (a == m_fade && towards == m_fadeTowards)
        return;
    m_fade = a;
    m_fadeTowards = towards;
    applyFade();
    rebuildMarks(); // the piece colours
}

void TetMeshActor::setUniformColor(const Rgb& colour) {
    m_uniformColour = colour;
    applyFade();
}

void TetMeshActor::applyFade() {
    const Rgb uniform = mixColours(m_uniformColour, m_fadeTowards, m_fade);
    m_actor->GetProperty()->SetColor(uniform[0], uniform[1], uniform[2]);
    const Rgb cut = mixColours(kCutFaceColour, m_fadeTowards, m_fade);
    m_cutOverlay.actor->GetProperty()->SetColor(cut[0], cut[1], cut[2]);
    const Rgb touched = mixColours(kTouchedColour, m_fadeTowards, m_fade);
    m_touchedOverlay.actor->GetProperty()->SetColor(touched[0], touched[1], touched[2]);
}

void TetMeshActor::applyVisibility() {
    const bool shown = m_visible && m_boundary->GetNumberOfCells() > 0;
    m_actor->SetVisibility(shown);
    m_cutOverlay.actor->SetVisibility(shown && m_cutFacesVisible &&
                                      m_cutOverlay.data->GetNumberOfCells() > 0);
    m_touchedOverlay.actor->SetVisibility(shown && m_touchedVisible &&
                                          m_touchedOverlay.data->GetNumberOfCells() > 0);
    m_pickedOverlay.actor->SetVisibility(m_visible && m_picked >= 0 &&
                                         m_pickedOverlay.data->GetNumberOfCells() > 0);
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

std::vector<vtkProp*> TetMeshActor::props() const {
    return {m_actor, m_cutOverlay.actor, m_touchedOverlay.actor, m_pickedOverlay.actor};
}

vtkPolyData* TetMeshActor::cutFaces() const {
    return m_cutOverlay.data;
}

vtkPolyData* TetMeshActor::touchedEdges() const {
    return m_touchedOverlay.data;
}

vtkPolyData* TetMeshActor::pickedOutline() const {
    return m_pickedOverlay.data;
}

vtkActor* TetMeshActor::cutFacesActor() const {
    return m_cutOverlay.actor;
}

vtkActor* TetMeshActor::touchedActor() const {
    return m_touchedOverlay.actor;
}

vtkActor* TetMeshActor::pickedActor() const {
    return m_pickedOverlay.actor;
}

vtkPolyData* TetMeshActor::boundary() const {
    return m_boundary;
}

Bounds TetMeshActor::bounds() const {
    Bounds b{1, -1, 1, -1, 1, -1};
    if (m_pos.empty())
        return b;
    Vec3 lo = displayedPosition(0), hi = lo;
    for (std::size_t n = 0; n < m_pos.size(); ++n) {
        const Vec3 p = displayedPosition(static_cast<int>(n));
        lo = lo.cwiseMin(p);
        hi = hi.cwiseMax(p);
    }
    return {lo.x(), hi.x(), lo.y(), hi.y(), lo.z(), hi.z()};
}

Vec3 TetMeshActor::offsetOfNode(int node) const {
    if (m_pieceOffsets.empty())
        return Vec3::Zero();
    const int piece = m_nodePiece.empty() ? 0 : m_nodePiece[node];
    return piece < static_cast<int>(m_pieceOffsets.size()) ? m_pieceOffsets[piece] : Vec3::Zero();
}

Vec3 TetMeshActor::displayedPosition(int node) const {
    return m_pos[node] + offsetOfNode(node);
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
    return centroid + m_shrink * (m_pos[nodes[local]] - centroid) + offsetOfNode(nodes[0]);
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

    // The triangles to draw, each with its owning tet, its nodes and whether it is a boundary
    // face of the mesh.
    std::vector<Tri> triangles;
    std::vector<int>& owners = m_cellTet;
    owners.clear();
    m_cellNodes.clear();
    m_cellOnBoundary.clear();
    m_pointsAreNodes = !(m_filterEnabled || m_mode == TetDisplayMode::ShrunkTets);
    if (!m_pointsAreNodes) {
        // Four points per shown tet, its four outward faces.
        triangles.reserve(4 * m_displayed.size());
        for (std::size_t i = 0; i < m_displayed.size(); ++i) {
            const int base = static_cast<int>(4 * i);
            const int t = m_displayed[i];
            for (int k = 0; k < 4; ++k) {
                const auto& f = kTetFaces[k];
                triangles.push_back({base + f[0], base + f[1], base + f[2]});
                owners.push_back(t);
                m_cellNodes.push_back({m_tets[t][f[0]], m_tets[t][f[1]], m_tets[t][f[2]]});
                m_cellOnBoundary.push_back((m_boundaryFaces[t] >> k) & 1u);
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
                m_cellNodes.push_back(triangles.back());
                m_cellOnBoundary.push_back(face.tets[1] < 0 ? 1 : 0);
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
    rebuildMarks();
}

void TetMeshActor::rebuildMarks() {
    const auto count = static_cast<vtkIdType>(m_cellTet.size());
    auto piece = vtkSmartPointer<vtkIntArray>::New();
    piece->SetName(kPieceArray);
    piece->SetNumberOfValues(count);
    auto colour = vtkSmartPointer<vtkUnsignedCharArray>::New();
    colour->SetName(kPieceColourArray);
    colour->SetNumberOfComponents(3);
    colour->SetNumberOfTuples(count);
    auto cutFace = vtkSmartPointer<vtkUnsignedCharArray>::New();
    cutFace->SetName(kCutFaceArray);
    cutFace->SetNumberOfValues(count);
    auto touched = vtkSmartPointer<vtkUnsignedCharArray>::New();
    touched->SetName(kTouchedArray);
    touched->SetNumberOfValues(count);

    auto cutPolys = vtkSmartPointer<vtkCellArray>::New();
    auto touchedLines = vtkSmartPointer<vtkCellArray>::New();
    std::unordered_set<std::uint64_t> lines;
    vtkCellArray* polys = m_boundary->GetPolys();
    vtkIdType npts = 0;
    const vtkIdType* pts = nullptr;
    for (vtkIdType c = 0; c < count; ++c) {
        const auto i = static_cast<std::size_t>(c);
        const int t = m_cellTet[i];
        const int p = tetPiece(t);
        piece->SetValue(c, p);
        const Rgb rgb = mixColours(piecePalette(p), m_fadeTowards, m_fade);
        for (int k = 0; k < 3; ++k)
            colour->SetTypedComponent(c, k,
                                      static_cast<unsigned char>(std::lround(255.0 * rgb[k])));
        const Tri& nodes = m_cellNodes[i];
        const bool isCut = m_cellOnBoundary[i] != 0 && !m_onCut.empty() && m_onCut[nodes[0]] != 0 &&
                           m_onCut[nodes[1]] != 0 && m_onCut[nodes[2]] != 0;
        const bool isTouched = !m_touched.empty() && m_touched[t] != 0;
        cutFace->SetValue(c, isCut ? 1 : 0);
        touched->SetValue(c, isTouched ? 1 : 0);
        if (!isCut && !isTouched)
            continue;
        polys->GetCellAtId(c, npts, pts);
        if (isCut)
            cutPolys->InsertNextCell(npts, pts);
        if (isTouched)
            for (vtkIdType k = 0; k < npts; ++k) {
                const vtkIdType a = pts[k], b = pts[(k + 1) % npts];
                if (lines.insert(lineKey(a, b)).second) {
                    const vtkIdType line[2] = {a, b};
                    touchedLines->InsertNextCell(2, line);
                }
            }
    }
    vtkCellData* cells = m_boundary->GetCellData();
    for (vtkDataArray* array :
         {static_cast<vtkDataArray*>(piece), static_cast<vtkDataArray*>(colour),
          static_cast<vtkDataArray*>(cutFace), static_cast<vtkDataArray*>(touched)}) {
        cells->RemoveArray(array->GetName());
        cells->AddArray(array);
    }
    m_boundary->Modified();

    m_cutOverlay.data->Initialize();
    m_touchedOverlay.data->Initialize();
    if (count > 0) {
        m_cutOverlay.data->SetPoints(m_points);
        m_cutOverlay.data->SetPolys(cutPolys);
        m_touchedOverlay.data->SetPoints(m_points);
        m_touchedOverlay.data->SetLines(touchedLines);
    }
    m_cutOverlay.data->Modified();
    m_touchedOverlay.data->Modified();
    rebuildPicked();
    applyVisibility();
}

void TetMeshActor::rebuildPicked() {
    m_pickedOverlay.data->Initialize();
    if (m_picked >= 0 && m_picked < static_cast<int>(m_tets.size())) {
        // Its corners as drawn: shrunk if it is drawn shrunk.
        const bool shrunk = !m_pointsAreNodes && isTetDisplayed(m_picked);
        m_pickedPoints->SetNumberOfPoints(4);
        for (int k = 0; k < 4; ++k) {
            const Vec3 p =
                shrunk ? shrunkCorner(m_picked, k) : displayedPosition(m_tets[m_picked][k]);
            m_pickedPoints->SetPoint(k, p.data());
        }
        m_pickedPoints->Modified();
        auto lines = vtkSmartPointer<vtkCellArray>::New();
        for (const auto& e : kTetEdges) {
            const vtkIdType line[2] = {e[0], e[1]};
            lines->InsertNextCell(2, line);
        }
        auto verts = vtkSmartPointer<vtkCellArray>::New();
        for (vtkIdType k = 0; k < 4; ++k)
            verts->InsertNextCell(1, &k);
        m_pickedOverlay.data->SetPoints(m_pickedPoints);
        m_pickedOverlay.data->SetLines(lines);
        m_pickedOverlay.data->SetVerts(verts);
    }
    m_pickedOverlay.data->Modified();
}

void TetMeshActor::updatePoints() {
    if (m_pointsAreNodes) {
        m_points->SetNumberOfPoints(static_cast<vtkIdType>(m_pos.size()));
        if (m_pieceOffsets.empty()) {
            for (std::size_t n = 0; n < m_pos.size(); ++n)
                m_points->SetPoint(static_cast<vtkIdType>(n), m_pos[n].data());
        } else {
            for (std::size_t n = 0; n < m_pos.size(); ++n)
                m_points->SetPoint(static_cast<vtkIdType>(n),
                                   displayedPosition(static_cast<int>(n)).data());
        }
    } else {
        m_points->SetNumberOfPoints(static_cast<vtkIdType>(4 * m_displayed.size()));
        for (std::size_t i = 0; i < m_displayed.size(); ++i)
            for (int k = 0; k < 4; ++k)
                m_points->SetPoint(static_cast<vtkIdType>(4 * i + k),
                                   shrunkCorner(m_displayed[i], k).data());
    }
    m_points->Modified();
    m_boundary->Modified();
    m_cutOverlay.data->Modified();
    m_touchedOverlay.data->Modified();
    if (m_picked >= 0)
        rebuildPicked();
}

void TetMeshActor::applyColouring() {
    m_lut->SetTableRange(m_range.first, m_range.second);
    m_mapper->SetScalarRange(m_range.first, m_range.second);
    if (m_colorMode == TetColorMode::Piece) {
        m_mapper->SetColorModeToDirectScalars();
        m_mapper->SelectColorArray(kPieceColourArray);
        m_mapper->ScalarVisibilityOn();
        m_mapper->Modified();
        return;
    }
    m_mapper->SetColorModeToMapScalars();
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
    // Cut faces are filled in every mode (in the wireframe they show where the cut is).
    m_cutOverlay.actor->GetProperty()->SetEdgeVisibility(m_mode != TetDisplayMode::Wireframe);
}

} // namespace resect
