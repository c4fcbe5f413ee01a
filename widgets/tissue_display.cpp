#include "widgets/tissue_display.h"

#include "core/tissue/tissue.h"
#include "widgets/piece_colors.h"
#include "widgets/vtk_viewport.h"

#include <algorithm>
#include <cmath>

namespace resect {

namespace {

/// Adds every tet's reference volume and volume-weighted centroid to its piece's sums.
void addPieceMoments(const TetMesh& mesh, const std::vector<int>& tetPiece,
                     std::vector<double>& volume, std::vector<Vec3>& moment) {
    for (int t = 0; t < mesh.tetCount(); ++t) {
        const Tet& q = mesh.tet(t);
        const double v = std::abs(mesh.referenceVolume(t));
        const Vec3 c = 0.25 * (mesh.ref(q[0]) + mesh.ref(q[1]) + mesh.ref(q[2]) + mesh.ref(q[3]));
        volume[tetPiece[t]] += v;
        moment[tetPiece[t]] += v * c;
    }
}

/// The pieces of the tissue's tets whose last cut is `cut` (none for cut 0).
std::vector<std::uint8_t> touchedBy(const std::vector<int>& tetCuts, int cut) {
    std::vector<std::uint8_t> touched(tetCuts.size(), 0);
    if (cut > 0)
        for (std::size_t t = 0; t < tetCuts.size(); ++t)
            touched[t] = tetCuts[t] == cut ? 1 : 0;
    return touched;
}

} // namespace

TissueDisplay::TissueDisplay(VtkViewport& viewport, QObject* parent)
    : QObject(parent), m_viewport(viewport) {
    TetMeshActor& chips = m_viewport.chipsActor();
    // Chips never show a quality overlay: grey in the quality colouring, their piece colour
    // in the piece colouring.
    chips.setOverlayMeasure(QualityMeasure::None);
    chips.setUniformColor(kResectedColour);
    applyResected();
    applyVisibility();
}

void TissueDisplay::setColorMode(TetColorMode mode) {
    m_colorMode = mode;
    m_viewport.tetMeshActor().setColorMode(mode);
    m_viewport.chipsActor().setColorMode(mode);
    m_viewport.requestRender();
    emit settingsChanged();
}

void TissueDisplay::setCutFacesVisible(bool visible) {
    m_cutFacesVisible = visible;
    m_viewport.tetMeshActor().setCutFacesVisible(visible);
    m_viewport.chipsActor().setCutFacesVisible(visible);
    m_viewport.surfaceActor().setCutFacesVisible(visible);
    m_viewport.chipSurfacesActor().setCutFacesVisible(visible);
    m_viewport.requestRender();
    emit settingsChanged();
}

void TissueDisplay::setLastCutHighlighted(bool highlighted) {
    m_lastCutHighlighted = highlighted;
    m_viewport.tetMeshActor().setTouchedVisible(highlighted);
    m_viewport.chipsActor().setTouchedVisible(highlighted);
    m_viewport.requestRender();
    emit settingsChanged();
}

void TissueDisplay::setResected(Resected resected) {
    m_resected = resected;
    applyResected();
    applyVisibility();
    m_viewport.requestRender();
    emit settingsChanged();
}

void TissueDisplay::setExplode(double factor) {
    m_explode = std::clamp(factor, 0.0, kMaxExplode);
    applyOffsets();
    m_viewport.sceneExtentChanged();
    emit settingsChanged();
}

void TissueDisplay::setPickedTet(int tet) {
    m_viewport.tetMeshActor().setPickedTet(tet);
    m_viewport.requestRender();
}

int TissueDisplay::pickedTet() const {
    return m_viewport.tetMeshActor().pickedTet();
}

void TissueDisplay::setMeshesVisible(bool tets, bool surface) {
    m_tetsVisible = tets;
    m_surfaceVisible = surface;
    applyVisibility();
    m_viewport.requestRender();
}

void TissueDisplay::applyResected() {
    const double fade = m_resected == Resected::Dimmed ? kDimmedFade : 0.0;
    m_viewport.chipsActor().setFade(fade, VtkViewport::kBackground);
    m_viewport.chipSurfacesActor().setFade(fade, VtkViewport::kBackground);
}

void TissueDisplay::applyVisibility() {
    const bool chips = m_resected != Resected::Hidden;
    m_viewport.tetMeshActor().setVisible(m_tetsVisible);
    m_viewport.surfaceActor().setVisible(m_surfaceVisible);
    m_viewport.chipsActor().setVisible(m_tetsVisible && chips);
    m_viewport.chipSurfacesActor().setVisible(m_surfaceVisible && chips);
}

void TissueDisplay::show(const Tissue& tissue) {
    if (tissue.empty()) {
        clear();
        return;
    }
    const Components& pieces = tissue.pieces();
    m_tissuePieces = pieces.count;
    const auto& chips = tissue.chips();
    const int count = pieces.count + static_cast<int>(chips.size());

    TetMeshActor& actor = m_viewport.tetMeshActor();
    actor.setColorMode(m_colorMode);
    actor.setCutFacesVisible(m_cutFacesVisible);
    actor.setTouchedVisible(m_lastCutHighlighted);
    actor.setPieces(pieces.tetComponent);
    actor.setCutMarks(tissue.onCutSurface(), touchedBy(tissue.tetCuts(), tissue.cutCount()));

    // Explode directions from the pieces' centroids.
    std::vector<double> volume(count, 0.0);
    std::vector<Vec3> moment(count, Vec3::Zero());
    addPieceMoments(tissue.mesh(), pieces.tetComponent, volume, moment);
    for (std::size_t c = 0; c < chips.size(); ++c) {
        const std::vector<int> piece(chips[c].mesh.tetCount(), pieces.count + static_cast<int>(c));
        addPieceMoments(chips[c].mesh, piece, volume, moment);
    }
    double total = 0;
    Vec3 centre = Vec3::Zero();
    for (int p = 0; p < count; ++p) {
        total += volume[p];
        centre += moment[p];
    }
    centre = total > 0 ? Vec3(centre / total) : Vec3::Zero();
    m_directions.assign(count, Vec3::Zero());
    for (int p = 0; p < count; ++p)
        if (volume[p] > 0)
            m_directions[p] = moment[p] / volume[p] - centre;

    // The surface's vertices go with the piece of their tet.
    const EmbeddedSurface& surface = tissue.surface();
    m_surfacePiece.assign(surface.binding().vertexCount(), 0);
    for (int v = 0; v < surface.binding().vertexCount(); ++v) {
        const int t = surface.binding().tetOf(v);
        m_surfacePiece[v] = t >= 0 && t < tissue.mesh().tetCount() ? pieces.tetComponent[t] : 0;
    }
    m_viewport.surfaceActor().setCutFacesVisible(m_cutFacesVisible);

    showChips(tissue);
    applyOffsets();
    applyResected();
    applyVisibility();
    m_viewport.requestRender();
}

void TissueDisplay::showChips(const Tissue& tissue) {
    const auto& chips = tissue.chips();
    TetMeshActor& actor = m_viewport.chipsActor();
    SurfaceActor& surfaces = m_viewport.chipSurfacesActor();
    m_chipNodes.clear();
    m_chipVertexPiece.clear();
    if (chips.empty()) {
        actor.clear();
        surfaces.clear();
        return;
    }
    // All chips as one mesh and one surface.
    std::vector<Vec3> ref, pos;
    std::vector<Tet> tets;
    std::vector<int> tetPiece;
    std::vector<std::uint8_t> onCut, touched;
    TriangleSurface surface;
    bool uvs = true;
    for (const Chip& chip : chips)
        uvs = uvs && chip.surface.uvs.size() == chip.surface.positions.size();
    for (std::size_t c = 0; c < chips.size(); ++c) {
        const Chip& chip = chips[c];
        const int piece = m_tissuePieces + static_cast<int>(c);
        const int first = static_cast<int>(ref.size());
        m_chipNodes.push_back(chip.mesh.nodeCount());
        ref.insert(ref.end(), chip.mesh.referencePositions().begin(),
                   chip.mesh.referencePositions().end());
        pos.insert(pos.end(), chip.mesh.positions().begin(), chip.mesh.positions().end());
        for (Tet q : chip.mesh.tets()) {
            for (int& n : q)
                n += first;
            tets.push_back(q);
            tetPiece.push_back(piece);
        }
        const bool marked = static_cast<int>(chip.onCutSurface.size()) == chip.mesh.nodeCount();
        for (int n = 0; n < chip.mesh.nodeCount(); ++n)
            onCut.push_back(marked ? chip.onCutSurface[n] : 0);
        const bool cuts = static_cast<int>(chip.tetCuts.size()) == chip.mesh.tetCount();
        for (int t = 0; t < chip.mesh.tetCount(); ++t)
            touched.push_back(
                cuts && tissue.cutCount() > 0 && chip.tetCuts[t] == tissue.cutCount() ? 1 : 0);

        const TriangleSurface& s = chip.surface;
        const int firstVertex = surface.vertexCount();
        surface.positions.insert(surface.positions.end(), s.positions.begin(), s.positions.end());
        if (uvs)
            surface.uvs.insert(surface.uvs.end(), s.uvs.begin(), s.uvs.end());
        const bool chipCutUvs = s.cutUvs.size() == s.positions.size();
        for (int v = 0; v < s.vertexCount(); ++v) {
            surface.cutUvs.push_back(chipCutUvs ? s.cutUvs[v]
                                                : Eigen::Vector2d::Constant(std::nan("")));
            m_chipVertexPiece.push_back(piece);
        }
        for (int f = 0; f < s.triangleCount(); ++f) {
            Tri t = s.triangles[f];
            for (int& v : t)
                v += firstVertex;
            surface.triangles.push_back(t);
            surface.cutFaces.push_back(s.isCutFace(f) ? 1 : 0);
        }
    }
    TetMesh mesh = TetMesh::fromArrays(std::move(ref), std::move(tets));
    std::copy(pos.begin(), pos.end(), mesh.positions().begin());
    actor.setMesh(mesh);
    actor.setColorMode(m_colorMode);
    actor.setCutFacesVisible(m_cutFacesVisible);
    actor.setTouchedVisible(m_lastCutHighlighted);
    actor.setPieces(std::move(tetPiece));
    actor.setCutMarks(std::move(onCut), std::move(touched));
    surfaces.setCutFacesVisible(m_cutFacesVisible);
    surfaces.setSurface(surface);
}

void TissueDisplay::follow(const Tissue& tissue) {
    const auto& chips = tissue.chips();
    bool same = chips.size() == m_chipNodes.size();
    for (std::size_t c = 0; same && c < chips.size(); ++c)
        same = chips[c].mesh.nodeCount() == m_chipNodes[c];
    if (!same) {
        showChips(tissue);
        applyOffsets();
        applyResected();
        applyVisibility();
        return;
    }
    if (chips.empty())
        return;
    std::vector<Vec3> pos, surface;
    for (const Chip& chip : chips) {
        pos.insert(pos.end(), chip.mesh.positions().begin(), chip.mesh.positions().end());
        if (m_surfaceVisible)
            surface.insert(surface.end(), chip.surface.positions.begin(),
                           chip.surface.positions.end());
    }
    m_viewport.chipsActor().updatePositions(pos);
    if (m_surfaceVisible)
        m_viewport.chipSurfacesActor().updatePositions(surface);
}

void TissueDisplay::clear() {
    m_tissuePieces = 0;
    m_directions.clear();
    m_surfacePiece.clear();
    m_chipVertexPiece.clear();
    m_chipNodes.clear();
    m_viewport.chipsActor().clear();
    m_viewport.chipSurfacesActor().clear();
    m_viewport.tetMeshActor().setPickedTet(-1);
    m_viewport.requestRender();
}

void TissueDisplay::applyOffsets() {
    std::vector<Vec3> offsets;
    if (m_explode > 0)
        for (const Vec3& d : m_directions)
            offsets.push_back(m_explode * d);
    m_viewport.tetMeshActor().setPieceOffsets(offsets);
    m_viewport.chipsActor().setPieceOffsets(offsets);
    const auto perVertex = [&](const std::vector<int>& piece) {
        std::vector<Vec3> out;
        if (offsets.empty())
            return out;
        out.reserve(piece.size());
        for (int p : piece)
            out.push_back(p < static_cast<int>(offsets.size()) ? offsets[p] : Vec3::Zero());
        return out;
    };
    m_viewport.surfaceActor().setVertexOffsets(perVertex(m_surfacePiece));
    m_viewport.chipSurfacesActor().setVertexOffsets(perVertex(m_chipVertexPiece));
}

} // namespace resect
