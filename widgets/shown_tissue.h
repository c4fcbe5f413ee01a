#pragma once
// ShownTissue: which tissue the views show, and keeping them in step with it.
//
// What is shown: the preview of a pending cut (CutPreview), else the simulated tissue once it
// has moved (SimulationController, after its first step), else the current tissue
// (TissueSession). This object observes the three, keeps the shown state alive while it is on
// show (a shared TissueState; the simulated tissue is the controller's, asked for when
// needed, never held by pointer), and drives the views:
//  - the viewport (STYLE.md 8): setTetMesh with the tissue's schemes when the topology or the
//    source changes, TetMeshActor::updatePositions for simulation steps; the surface follows;
//  - the quality panel: its mesh provider (the tet inspector looks up picked tets in the
//    mesh on show), meshChanged() after a rebuild, the before/after comparison (current
//    and its preview while a cut is pending, else the uncut and the current tissue) and the
//    curve of the worst tet over the current tissue's cuts (and the pending one's);
//  - its TissueDisplay (display()): the pieces, cut faces, chips, explode and highlights of
//    the tissue on show (issue 19), with the tet picked in the quality panel outlined.
// A new document or tissue is framed once it is shown (frameNext(), framed()).

#include <QObject>

#include <memory>

namespace resect {

class CutPreview;
class QualityPanel;
class SimulationController;
class TetMesh;
class Tissue;
class TissueDisplay;
class TissueSession;
struct TissueState;
class VtkViewport;

class ShownTissue : public QObject {
    Q_OBJECT

public:
    enum class Source { None, Current, Preview, Simulation };

    ShownTissue(TissueSession& session, CutPreview& preview, SimulationController& simulation,
                VtkViewport& viewport, QualityPanel& quality, QObject* parent = nullptr);

    Source source() const { return m_source; }
    /// The tet mesh on show, or null.
    const TetMesh* mesh() const;

    /// Which meshes the viewport draws (the View menu).
    void setTetsVisible(bool visible);
    void setSurfaceVisible(bool visible);
    bool tetsVisible() const { return m_tetsVisible; }
    bool surfaceVisible() const { return m_surfaceVisible; }

    /// Frames the next tissue shown (a new document).
    void frameNext() { m_frameNext = true; }

    /// How the pieces, cut faces and chips of the tissue on show are drawn.
    TissueDisplay& display() { return *m_display; }

signals:
    /// A tissue was shown and framed (after frameNext() or a new base).
    void framed();

private:
    /// The tissue on show for `source` (null for None).
    const Tissue* tissueOf(Source source) const;
    void onBaseChanged();
    /// Shows what should be shown; `topology`: the shown tissue's cells may have changed.
    void refresh(bool topology);
    void updateComparison();
    void applyVisibility();

    TissueSession& m_session;
    CutPreview& m_preview;
    SimulationController& m_simulation;
    VtkViewport& m_viewport;
    QualityPanel& m_quality;
    TissueDisplay* m_display = nullptr;

    Source m_source = Source::None;
    /// The state on show (current or preview), kept alive while shown.
    std::shared_ptr<const TissueState> m_state;
    bool m_tetsVisible = true;
    bool m_surfaceVisible = false;
    bool m_frameNext = false;
};

} // namespace resect
