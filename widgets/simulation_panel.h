#pragma once
// SimulationPanel: play, pause, single step and reset of the simulation
// (SimulationController), the effects the scenario declares as check boxes with their
// parameters under them (EffectParameterEditor; under "Fixed regions", the tissue's boxes:
// FixedRegionEditor), and what the simulation costs: time step, stable time step,
// milliseconds per step of each effect and compute time per simulated second, and the
// real-time factor (simulated seconds per second of compute) with the integrator.
//
// Every toggle and parameter is an undoable document edit. An effect starts with parameters
// that let it run (scenario/scene_defaults.h); switching the fixed effect on without a fixed
// region adds the tissue's base region in the same undo step (ScenarioDocument::fixRegion).
// Nothing here opens a dialog: an edit the document refuses (TissueSession::editRefused: the
// state would not derive or simulate, e.g. a box that holds no node while the fixed effect is
// on) is undone and the reason shown in the notice line ("simNotice") until the next edit; an
// effect that cannot run yet (no tissue loaded) says so there too.

#include <QWidget>

#include <map>
#include <string>

class QCheckBox;
class QLabel;
class QPushButton;

namespace resect {

class EffectParameterEditor;
class FixedRegionEditor;
class ScenarioDocument;
class SimulationController;
class TissueSession;

class SimulationPanel : public QWidget {
    Q_OBJECT

public:
    SimulationPanel(ScenarioDocument& document, TissueSession& session, SimulationController& controller,
                    QWidget* parent = nullptr);

    /// The check box of an effect (knownEffectNames()); null for an unknown name.
    QCheckBox* effectBox(const std::string& name) const;
    /// The parameters of an effect; null for an unknown name and for "fixed".
    EffectParameterEditor* parameterEditor(const std::string& name) const;
    FixedRegionEditor* fixedRegionEditor() const { return m_fixedRegions; }
    /// The notice line's text (empty when there is nothing to report).
    QString notice() const;

private:
    void onEffectToggled(const std::string& name, bool on);
    void setNotice(const QString& text);
    void syncEffects();
    void updateState();
    void updateFigures();

    ScenarioDocument& m_document;
    TissueSession& m_session;
    SimulationController& m_controller;
    std::map<std::string, QCheckBox*> m_effects;
    std::map<std::string, EffectParameterEditor*> m_parameters;
    FixedRegionEditor* m_fixedRegions = nullptr;
    QLabel* m_notice = nullptr;
    QPushButton* m_play = nullptr;
    QPushButton* m_step = nullptr;
    QPushButton* m_reset = nullptr;
    QLabel* m_time = nullptr;
    QLabel* m_dt = nullptr;
    QLabel* m_cost = nullptr;
    QLabel* m_realTime = nullptr;
    QLabel* m_status = nullptr;
    bool m_syncing = false;
};

} // namespace resect
