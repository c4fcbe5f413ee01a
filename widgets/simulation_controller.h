#pragma once
// SimulationController: runs the mass-spring simulation of the current tissue
// (TissueSession::current()) with exactly the effects the scenario declares
// (scenario_run.h planLoadedTissue, replay.h simulationSetup: fixed nodes, gravity, tool
// contact, damping, the integrator and time step of the scenario's simulation settings).
//
// It owns a Tissue, a copy of the current state's made when the simulation is (re)built, and
// runs it through Tissue::startSimulation and Tissue::step. When the session publishes a new
// current state that is the one followed so far plus appended cuts with the same cut
// settings (appendedCuts, tissue_state.h), the new sweeps are applied to the running,
// deformed tissue by Tissue::cut (the simulator follows the change list locally): no reset,
// the time continues (cutsFollowed()). Anything else (undo, other cut settings, another
// document, other effects), or a local cut that fails, rebuilds from the current state at
// time 0 (resetDone()).
//
// play() advances the simulation from a GUI timer in slices: each tick simulates until the
// simulated time has caught up with the wall time (times `speed`), but computes for at most
// kTickBudgetMs, so the GUI stays responsive whatever the mesh; step() takes one step;
// reset() rebuilds from the current tissue. A diverging step stops the play, keeps the last
// good state (the simulator restores it) and reports why.
//
// The tool of `tool-contact` rests withdrawn above the tissue (as in replay between
// strokes) so that toggling the effect does not push the tissue.

#include "core/tissue/tissue.h"

#include <QElapsedTimer>
#include <QObject>
#include <QString>
#include <QTimer>

#include <memory>
#include <string>
#include <vector>

namespace resect {

class ScenarioDocument;
class TissueSession;
struct TissueState;

class SimulationController : public QObject {
    Q_OBJECT

public:
    static constexpr int kTickMs = 16;
    static constexpr double kTickBudgetMs = 10.0;

    SimulationController(ScenarioDocument& document, TissueSession& session, QObject* parent = nullptr);
    ~SimulationController() override;

    /// True when a simulator could be built for the current tissue.
    bool isReady() const { return m_tissue.isSimulating(); }
    bool isPlaying() const { return m_timer.isActive(); }
    /// Why the simulator could not be built or the last step failed (empty otherwise).
    const QString& error() const { return m_error; }

    /// The simulated tissue: its mesh (current positions), its surface (moved with the tets
    /// after every step and cut) and its schemes. Empty when there is no current tissue.
    const Tissue& tissue() const { return m_tissue; }
    const TetMesh& mesh() const { return m_tissue.mesh(); }
    const EmbeddedSurface& surface() const { return m_tissue.surface(); }

    double time() const;
    long long steps() const;
    double timeStep() const { return m_dt; }
    double stableTimeStep() const { return m_stableDt; }
    /// The effects in the order they run.
    std::vector<std::string> effectNames() const;
    /// Milliseconds per step of each effect, averaged over the steps so far.
    std::vector<std::pair<std::string, double>> effectMsPerStep() const;
    /// Compute time per simulated second (ms), from the steps so far; 0 before any step.
    double msPerSimulatedSecond() const;

    /// Simulated seconds per wall-clock second while playing (default 1).
    void setSpeed(double speed);
    double speed() const { return m_speed; }

public slots:
    void play();
    void pause();
    /// One step; false (and failed()) if it diverged.
    bool step();
    /// Rebuilds from the current tissue at time 0.
    void reset();

signals:
    /// Positions changed (after a tick or a step): views move their points.
    void stepped();
    /// A new simulation was built (after reset): views rebuild.
    void resetDone();
    /// The running simulation followed new cuts of the document (tets and surface changed,
    /// the time continues): views rebuild their cells.
    void cutsFollowed();
    void playingChanged(bool playing);
    void failed(const QString& message);

private:
    /// The session published a new current state: follow its new cuts, or rebuild.
    void followCurrent();
    /// Applies the cuts `current` adds to the followed state; false if one fails.
    bool followCuts(const TissueState& current, int appended);
    /// The step: the simulator's (stable unless set), with replay's margin under tool contact.
    void updateTimeStep();
    void tick();
    bool stepOnce();

    ScenarioDocument& m_document;
    TissueSession& m_session;
    Tissue m_tissue;
    /// The current state the simulated tissue was built from or has followed to.
    std::shared_ptr<const TissueState> m_followed;
    bool m_newDocument = false;   ///< a new document's tissue is on its way: rebuild when it comes
    double m_dt = 0, m_stableDt = 0;
    double m_speed = 1.0;
    double m_computeMs = 0;
    QString m_error;
    QTimer m_timer;
    QElapsedTimer m_wall;
    double m_wallStartSim = 0;
};

} // namespace resect
