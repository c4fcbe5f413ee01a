#pragma once
// TissueDisplay: how the views show what the cuts did (issue 19, "see the cut"). For the
// tissue on show (ShownTissue) it fills the viewport's actors with the tissue's pieces and cut
// marks and its resected chips, and applies the display settings:
//  - colour by quality (the quality panel's overlay) or by piece: the tissue's connected
//    components (Tissue::pieces(), in their order) and then its resected chips
//    (Tissue::chips(), in the order they came off), each in its piecePalette() colour;
//  - cut faces: on the tet mesh the boundary faces whose nodes lie on a cut surface
//    (Tissue::onCutSurface), on the high-resolution surface its cut faces with the sweep's
//    (u, v) texture (SurfaceActor);
//  - resected chips shown, dimmed (drawn translucent) or hidden; in the quality colouring
//    they are grey (kResectedColour), never tissue-coloured;
//  - explode: piece p is drawn moved by factor * (c_p - c), c_p its centroid and c the
//    centroid of all pieces (volume-weighted, reference configuration, so that a simulation
//    step only moves points). Display only: the tissue is never changed;
//  - the last cut's touched tets (Tissue::tetCuts() == cutCount()) and a picked tet outlined.
//
// ShownTissue calls show() when the shown tissue or its topology changed and follow() after a
// simulation step (positions only); setMeshesVisible() carries the View menu's choice of tet
// mesh and surface to the chips too.

#include "widgets/tet_mesh_actor.h"

#include <QObject>

#include <vector>

namespace resect {

class Tissue;
class VtkViewport;

class TissueDisplay : public QObject {
    Q_OBJECT

public:
    /// How resected chips are drawn.
    enum class Resected { Shown, Dimmed, Hidden };
    /// How far dimmed chips fade towards the view's background (TetMeshActor::setFade).
    static constexpr double kDimmedFade = 0.6;
    /// Largest explode factor (setExplode clamps to [0, kMaxExplode]).
    static constexpr double kMaxExplode = 1.5;

    explicit TissueDisplay(VtkViewport& viewport, QObject* parent = nullptr);

    // --- settings (each applied at once and announced by settingsChanged) ---
    void setColorMode(TetColorMode mode);
    TetColorMode colorMode() const { return m_colorMode; }
    void setCutFacesVisible(bool visible);
    bool cutFacesVisible() const { return m_cutFacesVisible; }
    void setLastCutHighlighted(bool highlighted);
    bool lastCutHighlighted() const { return m_lastCutHighlighted; }
    void setResected(Resected resected);
    Resected resected() const { return m_resected; }
    void setExplode(double factor);
    double explode() const { return m_explode; }
    /// The tet outlined in the tissue's mesh (-1: none); kept across cuts while the mesh has it.
    void setPickedTet(int tet);
    int pickedTet() const;
    /// Whether the tet meshes and the surfaces are drawn at all (the View menu), for the
    /// tissue and its chips alike.
    void setMeshesVisible(bool tets, bool surface);

    // --- the tissue on show ---
    /// Shows `tissue`'s pieces, marks and chips; call after the viewport's tet mesh and surface
    /// were set to the tissue's.
    void show(const Tissue& tissue);
    /// After a simulation step: the chips follow their bodies (positions only).
    void follow(const Tissue& tissue);
    /// Nothing on show.
    void clear();

    /// Pieces on show: the tissue's components, then its chips.
    int pieceCount() const { return static_cast<int>(m_directions.size()); }
    int tissuePieceCount() const { return m_tissuePieces; }
    /// The explode direction of every piece, c_p - c (reference configuration, mm).
    const std::vector<Vec3>& explodeDirections() const { return m_directions; }

signals:
    /// A setting changed (the actors are up to date).
    void settingsChanged();

private:
    void showChips(const Tissue& tissue);
    void applyOffsets();
    void applyResected();
    void applyVisibility();

    VtkViewport& m_viewport;
    TetColorMode m_colorMode = TetColorMode::Quality;
    bool m_cutFacesVisible = true;
    bool m_lastCutHighlighted = true;
    Resected m_resected = Resected::Dimmed;
    double m_explode = 0;
    bool m_tetsVisible = true;
    bool m_surfaceVisible = false;

    int m_tissuePieces = 0;
    std::vector<Vec3> m_directions;     ///< per piece
    std::vector<int> m_surfacePiece;    ///< per vertex of the tissue's surface: its piece
    std::vector<int> m_chipVertexPiece; ///< per vertex of the chips' surfaces: its piece
    std::vector<int> m_chipNodes;       ///< node count of every chip (to tell a new set of chips)
};

} // namespace resect
