#pragma once
// SimulationPanel: play, pause, single step and reset of the simulation
// (SimulationController), the effects the scenario declares as check boxes (toggling one is
// an undoable document edit), and what the simulation costs: time step, stable time step,
// milliseconds per step of each effect and compute time per simulated second, and the
// real-time factor (simulated seconds per second of compute) with the integrator.

#include <QWidget>

#include <map>
#include <string>

class QCheckBox;
class QLabel;
class QPushButton;

namespace resect {

class ScenarioDocument;
class SimulationController;

class SimulationPanel : public QWidget {
    Q_OBJECT

public:
    SimulationPanel(ScenarioDocument& document, SimulationController& controller, QWidget* parent = nullptr);

    /// The check box of an effect (knownEffectNames()); null for an unknown name.
    QCheckBox* effectBox(const std::string& name) const;

private:
    void syncEffects();
    void updateState();
    void updateFigures();

    ScenarioDocument& m_document;
    SimulationController& m_controller;
    std::map<std::string, QCheckBox*> m_effects;
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
