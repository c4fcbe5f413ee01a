#include "widgets/shown_tissue.h"

#include "widgets/cut_preview.h"
#include "widgets/quality_panel.h"
#include "widgets/simulation_controller.h"
#include "widgets/tissue_display.h"
#include "widgets/tissue_session.h"
#include "widgets/vtk_viewport.h"

#include <QPointer>

#include <limits>

#include <vtkActor.h>

namespace resect {

ShownTissue::ShownTissue(TissueSession& session, CutPreview& preview,
                         SimulationController& simulation, VtkViewport& viewport,
                         QualityPanel& quality, QObject* parent)
    : QObject(parent), m_session(session), m_preview(preview), m_simulation(simulation),
      m_viewport(viewport), m_quality(quality), m_display(new TissueDisplay(viewport, this)) {
    // The picked tet is outlined; the legend is only for the quality colouring.
    connect(&m_quality, &QualityPanel::tetPicked, m_display, &TissueDisplay::setPickedTet);
    connect(m_display, &TissueDisplay::settingsChanged, &m_quality, &QualityPanel::updateLegend);
    // A picked tet is inspected in the mesh on show.
    m_quality.setMeshProvider([self = QPointer<ShownTissue>(this)]() -> const TetMesh* {
        return self ? self->mesh() : nullptr;
    });
    connect(&m_session, &TissueSession::baseChanged, this, &ShownTissue::onBaseChanged);
    connect(&m_session, &TissueSession::currentChanged, this, [this] {
        refresh(true);
        updateComparison();
    });
    connect(&m_preview, &CutPreview::changed, this, [this] {
        refresh(true);
        updateComparison();
    });
    connect(&m_simulation, &SimulationController::stepped, this, [this] { refresh(false); });
    connect(&m_simulation, &SimulationController::resetDone, this, [this] { refresh(true); });
    connect(&m_simulation, &SimulationController::cutsFollowed, this, [this] { refresh(true); });
    applyVisibility();
}

const Tissue* ShownTissue::tissueOf(Source source) const {
    switch (source) {
    case Source::None:
        return nullptr;
    case Source::Current:
    case Source::Preview:
        return m_state ? &m_state->tissue : nullptr;
    case Source::Simulation:
        return &m_simulation.tissue();
    }
    return nullptr;
}

const TetMesh* ShownTissue::mesh() const {
    const Tissue* tissue = tissueOf(m_source);
    return tissue ? &tissue->mesh() : nullptr;
}

void ShownTissue::setTetsVisible(bool visible) {
    m_tetsVisible = visible;
    applyVisibility();
}

void ShownTissue::setSurfaceVisible(bool visible) {
    m_surfaceVisible = visible;
    // Simulation steps move the surface only while it is visible: bring it up to date.
    const Tissue* tissue = tissueOf(m_source);
    if (visible && tissue &&
        !m_viewport.surfaceActor().updatePositions(tissue->surface().surface()))
        m_viewport.setSurface(tissue->surface().surface(), false);
    applyVisibility();
    if (visible && tissue)
        m_display->follow(*tissue);
}

void ShownTissue::applyVisibility() {
    m_display->setMeshesVisible(m_tetsVisible, m_surfaceVisible);
    m_viewport.requestRender();
}

void ShownTissue::onBaseChanged() {
    if (!m_session.base()) {
        m_source = Source::None;
        m_state.reset();
        m_viewport.clear();
        m_display->clear();
        m_quality.meshChanged();
        updateComparison();
        return;
    }
    // Frame the tissue when it is first shown (its cuts may still be being applied); a tet
    // picked in another tissue is not outlined in this one.
    m_frameNext = true;
    m_display->setPickedTet(-1);
    refresh(true);
}

void ShownTissue::refresh(bool topology) {
    const auto preview = m_preview.preview();
    const auto state = preview ? preview : m_session.current();
    if (!state) {
        m_source = Source::None;
        m_state.reset();
        return;
    }
    const bool simulated = !preview && m_simulation.isReady() && m_simulation.steps() > 0;
    const Source source = preview     ? Source::Preview
                          : simulated ? Source::Simulation
                                      : Source::Current;
    const bool frame = m_frameNext;
    const Tissue& tissue = source == Source::Simulation ? m_simulation.tissue() : state->tissue;
    // A simulation step only moves points (STYLE.md item 8).
    if (!topology && !frame && source == Source::Simulation && m_source == Source::Simulation &&
        m_viewport.tetMeshActor().updatePositions(tissue.mesh())) {
        if (m_surfaceVisible &&
            !m_viewport.surfaceActor().updatePositions(tissue.surface().surface()))
            m_viewport.setSurface(tissue.surface().surface(), false);
        m_display->follow(tissue);
        m_viewport.requestRender();
        return;
    }
    m_frameNext = false;
    m_source = source;
    m_state = state;
    // The surface is replaced before framing: the view frames the union of the tet mesh's
    // and the surface's bounds, and the old surface (another tissue's, perhaps 100 times
    // larger) would leave the new one a dot.
    m_viewport.setTetMesh(tissue.mesh(), false);
    m_viewport.tetMeshActor().setTetSchemes(tissue.schemes());
    m_viewport.setSurface(tissue.surface().surface(), false);
    m_display->show(tissue);
    if (frame)
        m_viewport.resetCamera();
    applyVisibility();
    m_quality.meshChanged();
    if (frame)
        emit framed();
}

void ShownTissue::updateComparison() {
    // Before and after: the current tissue and its preview while a cut is pending, else the
    // uncut tissue and the current one once the document has cuts.
    const auto preview = m_preview.preview();
    const auto current = m_session.current();
    const auto base = m_session.base();
    const auto before = preview ? current : base;
    const auto after = preview ? preview : (current && current->cuts() > 0 ? current : nullptr);
    if (before)
        m_quality.setBeforeMesh(before->mesh(), before->stableDt, before->overlap);
    else
        m_quality.clearBefore();
    if (after)
        m_quality.setAfterMesh(after->mesh(), after->stableDt, after->overlap);
    else
        m_quality.clearAfter();
    // The worst tet after each of current's cuts, and after the pending one (a preview on
    // current adds exactly one cut to current's; one of an older current is not shown).
    if (current && !current->tissue.empty()) {
        const bool pending = preview && preview->worstRatios.size() == current->worstRatios.size() + 1;
        m_quality.setCutCurve(current->tissue.inputWorstRatio(), current->worstRatios,
                              pending ? preview->worstRatios.back()
                                      : std::numeric_limits<double>::quiet_NaN());
    } else {
        m_quality.clearCutCurve();
    }
}

} // namespace resect
