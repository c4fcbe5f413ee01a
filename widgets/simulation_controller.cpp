#include "widgets/simulation_controller.h"

#include "core/sim/tool_contact_effect.h"
#include "scenario/replay.h"
#include "scenario/scenario_run.h"
#include "widgets/scenario_document.h"
#include "widgets/tissue_session.h"

#include <algorithm>
#include <chrono>
#include <cmath>

namespace resect {

SimulationController::SimulationController(ScenarioDocument& document, TissueSession& session, QObject* parent)
    : QObject(parent), m_document(document), m_session(session) {
    m_timer.setInterval(kTickMs);
    connect(&m_timer, &QTimer::timeout, this, &SimulationController::tick);
    connect(&m_session, &TissueSession::currentChanged, this, &SimulationController::reset);
    connect(&m_document, &ScenarioDocument::effectsChanged, this, &SimulationController::reset);
    reset();
}

SimulationController::~SimulationController() = default;

double SimulationController::time() const { return m_sim ? m_sim->time() : 0.0; }
long long SimulationController::steps() const { return m_sim ? m_sim->stepsTaken() : 0; }

std::vector<std::string> SimulationController::effectNames() const {
    return m_sim ? m_sim->effectNames() : std::vector<std::string>{};
}

std::vector<std::pair<std::string, double>> SimulationController::effectMsPerStep() const {
    std::vector<std::pair<std::string, double>> out;
    if (!m_sim)
        return out;
    const double n = std::max(1, m_sim->stepsTaken());
    for (const EffectTime& e : m_sim->totalTimes())
        out.emplace_back(e.name, e.ms / n);
    return out;
}

double SimulationController::msPerSimulatedSecond() const {
    if (!m_sim || m_sim->time() <= 0)
        return 0;
    return m_computeMs / m_sim->time();
}

void SimulationController::setSpeed(double speed) {
    if (std::isfinite(speed) && speed > 0)
        m_speed = speed;
}

void SimulationController::reset() {
    const bool wasPlaying = isPlaying();
    m_timer.stop();
    m_sim.reset();
    m_error.clear();
    m_computeMs = 0;
    m_dt = m_stableDt = 0;
    const auto current = m_session.current();
    const Scenario& scenario = m_document.scenario();
    if (!current || scenario.tissues.empty() || current->mesh().empty()) {
        m_mesh = {};
        m_surface = {};
        emit resetDone();
        if (wasPlaying)
            emit playingChanged(false);
        return;
    }
    m_mesh = current->mesh();
    m_surface = current->surface();
    ReplayPlan plan;
    Status status = planLoadedTissue(scenario, scenario.tissues.front(), m_mesh, {}, plan);
    if (status.ok()) {
        if (std::find(plan.effects.begin(), plan.effects.end(), "tool-contact") != plan.effects.end())
            plan.effectSettings.tool.points = withdrawnTool(plan.effectSettings.tool.points, m_mesh);
        // The studio may use both cores; replay stays on one for reproducibility.
        plan.simulation.threads = 0;
        plan.effectSettings.threads = 0;
        m_sim = std::make_unique<Simulator>(m_mesh, plan.material, plan.simulation);
        for (const std::string& name : plan.effects)
            if (Status s = m_sim->addEffect(name, plan.effectSettings); !s.ok()) {
                status = Status::error("effect '" + name + "': " + s.message());
                break;
            }
    }
    if (!status.ok()) {
        m_sim.reset();
        m_error = QString::fromStdString(status.message());
        emit resetDone();
        emit failed(m_error);
        if (wasPlaying)
            emit playingChanged(false);
        return;
    }
    m_stableDt = m_sim->stableTimeStep();
    m_dt = m_sim->timeStep();
    const bool tool = m_sim->findEffect("tool-contact") != nullptr;
    if (plan.simulation.dt <= 0 && tool && isExplicit(plan.simulation.integrator))
        m_dt *= kLargeDeformationMargin; // as replay does with tool contact (replay.h)
    emit resetDone();
    if (wasPlaying)
        emit playingChanged(false);
}

void SimulationController::play() {
    if (!m_sim || isPlaying())
        return;
    m_wall.start();
    m_wallStartSim = m_sim->time();
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
    if (!m_sim || !(m_dt > 0) || !std::isfinite(m_dt)) {
        m_error = tr("The simulation has no usable time step.");
        return false;
    }
    const auto t0 = std::chrono::steady_clock::now();
    const Status s = m_sim->step(m_dt);
    m_computeMs += std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
    if (!s.ok()) {
        m_error = tr("The simulation diverged at t = %1 s: %2")
                      .arg(m_sim->time())
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
    if (!m_surface.empty())
        m_surface.update(m_mesh);
    emit stepped();
    return true;
}

void SimulationController::tick() {
    if (!m_sim) {
        pause();
        return;
    }
    const double target = m_wallStartSim + m_speed * (m_wall.elapsed() / 1000.0);
    const auto start = std::chrono::steady_clock::now();
    bool ok = true;
    int taken = 0;
    while (m_sim->time() + 0.5 * m_dt < target) {
        if (!stepOnce()) {
            ok = false;
            break;
        }
        ++taken;
        if (std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count() >
            kTickBudgetMs) {
            // Behind real time: let the clock slip instead of blocking the GUI.
            m_wall.start();
            m_wallStartSim = m_sim->time();
            break;
        }
    }
    if (taken > 0 || !ok) {
        if (!m_surface.empty())
            m_surface.update(m_mesh);
        emit stepped();
    }
    if (!ok) {
        pause();
        emit failed(m_error);
    }
}

} // namespace resect
