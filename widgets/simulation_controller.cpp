#include "widgets/simulation_controller.h"

#include "core/sim/tool_contact_effect.h"
#include "scenario/replay.h"
#include "scenario/scenario_run.h"
#include "widgets/scenario_document.h"
#include "widgets/tissue_session.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <utility>

namespace resect {

SimulationController::SimulationController(ScenarioDocument& document, TissueSession& session, QObject* parent)
    : QObject(parent), m_document(document), m_session(session) {
    m_timer.setInterval(kTickMs);
    connect(&m_timer, &QTimer::timeout, this, &SimulationController::tick);
    connect(&m_session, &TissueSession::currentChanged, this, &SimulationController::followCurrent);
    // A new document announces its effects too: its simulation is built once the session
    // publishes its tissue (at once if it has none: the session has already said so).
    connect(&m_document, &ScenarioDocument::documentReset, this, [this] { m_newDocument = m_session.isBusy(); });
    connect(&m_document, &ScenarioDocument::effectsChanged, this, [this] {
        if (!m_newDocument)
            reset();
    });
    reset();
}

SimulationController::~SimulationController() = default;

double SimulationController::time() const { return m_tissue.simulator() ? m_tissue.simulator()->time() : 0.0; }
long long SimulationController::steps() const {
    return m_tissue.simulator() ? m_tissue.simulator()->stepsTaken() : 0;
}

std::vector<std::string> SimulationController::effectNames() const {
    return m_tissue.simulator() ? m_tissue.simulator()->effectNames() : std::vector<std::string>{};
}

std::vector<std::pair<std::string, double>> SimulationController::effectMsPerStep() const {
    std::vector<std::pair<std::string, double>> out;
    const Simulator* sim = m_tissue.simulator();
    if (!sim)
        return out;
    const double n = std::max(1, sim->stepsTaken());
    for (const EffectTime& e : sim->totalTimes())
        out.emplace_back(e.name, e.ms / n);
    return out;
}

double SimulationController::msPerSimulatedSecond() const {
    const Simulator* sim = m_tissue.simulator();
    if (!sim || sim->time() <= 0)
        return 0;
    return m_computeMs / sim->time();
}

void SimulationController::setSpeed(double speed) {
    if (std::isfinite(speed) && speed > 0)
        m_speed = speed;
}

void SimulationController::followCurrent() {
    const bool newDocument = std::exchange(m_newDocument, false);
    const auto current = m_session.current();
    const int appended = current && m_followed && !newDocument && isReady()
                             ? appendedCuts(m_followed->applied, current->applied)
                             : -1;
    if (appended < 0) {
        reset();
        return;
    }
    if (appended == 0) {
        m_followed = current;
        return;
    }
    if (!followCuts(*current, appended)) {
        reset(); // the deformed tissue could not take the cut: start again from the current state
        return;
    }
    m_followed = current;
    emit cutsFollowed();
}

bool SimulationController::followCuts(const TissueState& current, int appended) {
    const std::vector<SweepSurface>& sweeps = current.applied.sweeps;
    for (std::size_t i = sweeps.size() - static_cast<std::size_t>(appended); i < sweeps.size(); ++i)
        if (!m_tissue.cut(sweeps[i], current.applied.options).ok())
            return false;
    m_tissue.updateSurface();
    updateTimeStep();
    return true;
}

void SimulationController::updateTimeStep() {
    Simulator* sim = m_tissue.simulator();
    m_stableDt = sim->stableTimeStep();
    m_dt = sim->timeStep(); // the simulator sub-steps where the tissue needs it (simulator.h)
}

void SimulationController::reset() {
    const bool wasPlaying = isPlaying();
    m_timer.stop();
    m_tissue = Tissue();
    m_followed.reset();
    m_error.clear();
    m_computeMs = 0;
    m_dt = m_stableDt = 0;
    const auto current = m_session.current();
    const Scenario& scenario = m_document.scenario();
    const auto done = [&] {
        emit resetDone();
        if (wasPlaying)
            emit playingChanged(false);
    };
    if (!current || scenario.tissues.empty() || current->tissue.empty()) {
        done();
        return;
    }
    m_tissue = Tissue(current->tissue);
    m_followed = current;
    // The simulation's settings as replay takes them (the plan's anchors are not used: the
    // tissue holds its own, which followed its cuts).
    ReplayPlan plan;
    Status status = planLoadedTissue(scenario, scenario.tissues.front(), current->mesh(), {}, plan);
    if (status.ok()) {
        if (std::find(plan.effects.begin(), plan.effects.end(), "tool-contact") != plan.effects.end())
            plan.effectSettings.tool.points = withdrawnTool(plan.effectSettings.tool.points, m_tissue.mesh());
        // The studio may use both cores; replay stays on one for reproducibility.
        plan.simulation.threads = 0;
        plan.effectSettings.threads = 0;
        status = m_tissue.startSimulation(simulationSetup(plan));
    }
    if (!status.ok()) {
        m_error = QString::fromStdString(status.message());
        emit resetDone();
        emit failed(m_error);
        if (wasPlaying)
            emit playingChanged(false);
        return;
    }
    updateTimeStep();
    done();
}

void SimulationController::play() {
    if (!isReady() || isPlaying())
        return;
    m_wall.start();
    m_wallStartSim = time();
    m_timer.start();
    emit playingChanged(true);
}

void SimulationController::pause() {
    if (!isPlaying())
        return;
    m_timer.stop();
    emit playingChanged(false);
}

bool SimulationController::stepOnce() {
    if (!isReady() || !(m_dt > 0) || !std::isfinite(m_dt)) {
        m_error = tr("The simulation has no usable time step.");
        return false;
    }
    const auto t0 = std::chrono::steady_clock::now();
    const Status s = m_tissue.step(m_dt);
    m_computeMs += std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
    if (!s.ok()) {
        m_error = tr("The simulation diverged at t = %1 s: %2")
                      .arg(time())
                      .arg(QString::fromStdString(s.message()));
        return false;
    }
    return true;
}

bool SimulationController::step() {
    if (!stepOnce()) {
        pause();
        emit failed(m_error);
        return false;
    }
    m_tissue.updateSurface();
    emit stepped();
    return true;
}

void SimulationController::tick() {
    if (!isReady()) {
        pause();
        return;
    }
    const double target = m_wallStartSim + m_speed * (m_wall.elapsed() / 1000.0);
    const auto start = std::chrono::steady_clock::now();
    bool ok = true;
    int taken = 0;
    while (time() + 0.5 * m_dt < target) {
        if (!stepOnce()) {
            ok = false;
            break;
        }
        ++taken;
        if (std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count() >
            kTickBudgetMs) {
            // Behind real time: let the clock slip instead of blocking the GUI.
            m_wall.start();
            m_wallStartSim = time();
            break;
        }
    }
    if (taken > 0 || !ok) {
        m_tissue.updateSurface();
        emit stepped();
    }
    if (!ok) {
        pause();
        emit failed(m_error);
    }
}

} // namespace resect
