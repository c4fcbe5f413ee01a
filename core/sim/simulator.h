#pragma once
// Simulator: time stepping of a TetMesh under the effects a scene declares.
//
// The mesh owns the state (positions, velocities, masses; structure of arrays, tet_mesh.h);
// effects (effect.h) own their data; this class owns only scratch buffers and runs a step
// (split into sub-steps where the configuration needs it, see "Time step"):
//   1. f = sum of the effects' forces at the current state, constrained by the effects;
//   2. the integrator updates velocities and positions (explicit_integrators.h, or the
//      linearised backward Euler of backward_euler.h);
//   3. the effects' position-level corrections (contact, anchors);
//   4. divergence check. Every step reports the time spent in each effect.
//
// Divergence. A step fails, with an error Status and the state restored to what it was
// before the step, sub-steps and all (SimulatorOptions::keepLastGoodState), when any position
// or velocity is not finite, or when the monitored energy E = kinetic + the effects'
// potentials grows by more than explosionFactor * S over its reference value (taken at the
// first step and after every cut), where S = M k + |kinetic| + sum of |potentials| at the
// reference (M the total mass, k Material::stiffness: M k is the elastic energy of a 100 %
// strain everywhere). A stable run conserves (Verlet, symplectic Euler: within a bounded
// oscillation) or dissipates E, so crossing the bound means the explicit step is above the
// stability limit; the message says so and gives the stable estimate. External work (a
// moving tool) is far below the bound for any realistic tool speed.
//
// Time step. timeStep() is options.dt, or by default (dt = 0) the stable estimate of
// stable_time_step.h: the model linearised at rest, with a 5 % margin (h omega_max = 1.9).
// Deformed tissue is stiffer in some directions (tension adds transverse spring stiffness,
// the area and volume terms' gradients turn), and near the limit its oscillation pumps energy
// into the highest modes: the sample polyp hanging under gravity stiffens by up to a third as
// it swings, and a fixed step at the rest estimate diverges at t = 0.25 s. So at the default
// the simulator keeps explicit steps stable at the CURRENT configuration (stable stepping,
// StableSteppingOptions; tests/core/sim/test_sim_stable_stepping.cpp):
//   - Estimate. omega_max^2 = lambda_max(M^-1 K(x)) at the current positions, K from the
//     effects' force differentials (the deformation's Gauss-Newton terms plus the transverse
//     stiffness of stretched springs: within 0.5 % of the exact Hessian's on the swinging
//     polyp) with the effects' constraints applied, by Lanczos (largestEigenvalue,
//     stable_time_step.h): converged at the first step, after a cut and after an effect is
//     added; then 5 products warm-started from the last Ritz vector, every 50 to 400
//     integrator steps (the interval doubles while lambda_max moves little compared with the
//     headroom left, and halves when it does not), and at once when the monitored energy
//     (see "Divergence") has grown by energyTrigger * S since its mark.
//   - Safe step: 2 safety / omega_max, the rest estimate's margin. It shortens at once; it
//     lengthens only after holdEstimates estimates that all allow it (then to their largest
//     lambda's, less relaxMargin), because sub-step counts that follow an oscillating
//     tissue's stiffness back and forth pump energy themselves. When the energy grew but the
//     estimate did not shorten the step (a resonance below the linear limit), the safe step
//     is multiplied by energyStepFactor (down to half the estimate's at most).
//   - Sub-steps: every step(h), whatever h, is split into n = ceil(h / (safe (1 + tolerance)))
//     equal sub-steps. At rest n = 1 (the two estimates agree); the swinging polyp needs
//     n = 2 for most of its first second (74 450 integrator steps for 40 000 steps of the
//     default 2.8e-5 s) and conserves its energy within 1e-3 of its kinetic energy.
//   Cost: one estimate is about 8 force evaluations; the estimates add 2 to 4 % to a run at
//   rest (on 1e5 and 1e6 tets) and to the polyp's, the first converged one about as much as
//   stableTimeStep() (a third of it on 1e6 tets).
// With options.dt > 0 the caller chose the step: it is taken as given, without estimates,
// and a step above the limit diverges (and is reported as below). The implicit integrators
// take every step whole.
//
// Threads: SimulatorOptions::threads for the node passes and the built-in effects; results
// are bit-identical for a given thread count (parallel.h).

#include "core/mesh/material.h"
#include "core/mesh/stable_time_step.h"
#include "core/sim/backward_euler.h"
#include "core/sim/effect.h"
#include "core/sim/effect_registry.h"
#include "core/sim/explicit_integrators.h"
#include "core/sim/projective_dynamics.h"
#include "core/status.h"

#include <memory>
#include <string>
#include <vector>

namespace resect {

/// ProjectiveDynamics is the product's implicit integrator (projective_dynamics.h; "implicit"
/// on the command line and in scenarios); BackwardEuler, the linearised backward Euler with
/// conjugate gradients, is kept for comparison.
enum class Integrator { SymplecticEuler, VelocityVerlet, BackwardEuler, ProjectiveDynamics };

/// "symplectic-euler", "velocity-verlet", "backward-euler", "projective-dynamics".
const char* integratorName(Integrator integrator);
/// The names above and the product's aliases: "implicit" (projective dynamics), "explicit"
/// (symplectic Euler), "verlet". False for anything else.
bool parseIntegrator(const std::string& name, Integrator& out);
bool isExplicit(Integrator integrator);

/// Stable stepping of the explicit integrators at the default step (see "Time step" above).
struct StableSteppingOptions {
    /// The safe step at the current configuration is 2 safety / omega_max, (0, 1]: the rest
    /// estimate's margin (StableTimeStepOptions::safety), so that at rest n = 1.
    double safety = 0.95;
    /// A step up to this fraction longer than the safe step is taken whole, >= 0. A mesh
    /// vibrating about rest moves omega_max by about 1 %, and sub-steps for that would double
    /// the cost; 2 % (h omega_max <= 1.94) keeps a box stretched 5 % bounded, 5 % does not.
    double tolerance = 0.02;
    /// Integrator steps between estimates: `interval` after a converged estimate; then
    /// doubled while the growth of lambda_max the sub-step still allows is above four times
    /// its last change, halved when below twice it, within [minInterval, maxInterval].
    int interval = 50;
    int minInterval = 50;
    int maxInterval = 400;
    /// When the monitored energy (kinetic plus potentials; conserved by a stable run without
    /// external work) has grown by this fraction of its scale S (see "Divergence") since its
    /// mark (after the first step and a cut, and the last time it grew), estimate again at
    /// once, and if the estimate does not shorten the safe step, multiply it by
    /// energyStepFactor (in (0, 1]).
    double energyTrigger = 1e-3;
    double energyStepFactor = 0.8;
    int holdEstimates = 8;    ///< a longer safe step needs this many estimates allowing it
    double relaxMargin = 0.1; ///< and is then their largest lambda's, shortened by this
    int maxSubsteps = 1000; ///< more sub-steps than this: the step fails (diverged tissue)
    /// One warm-started estimate: 5 products (on the polyp swinging under gravity, within
    /// 1e-4 of the converged value at its worst, 4 products; 1e-9, 6). Converged estimates
    /// use rounds of 10 and restart.
    LanczosOptions lanczos{.steps = 5};
};

struct SimulatorOptions {
    Integrator integrator = Integrator::SymplecticEuler;
    /// s; 0: the stable explicit time step (stableTimeStep()), kept stable at the current
    /// configuration by sub-steps (see "Time step"); > 0: this step, taken as given
    double dt = 0;
    int threads = 0;  ///< 0: resolveThreadCount's default
    int grain = 4096; ///< fewer threads when one would get fewer nodes or terms (parallel.h)
    double explosionFactor = 100;
    bool keepLastGoodState = true; ///< back up the state in every step (see above)
    StableSteppingOptions stable;
    BackwardEulerOptions implicit;
    ProjectiveDynamicsOptions projective;
};

struct EffectTime {
    std::string name;
    double ms = 0;
};

struct StepReport {
    std::vector<EffectTime> effects; ///< per effect, in run order: this step
    double integrateMs = 0;          ///< node passes and solver, outside the effects
    double kineticEnergy = 0;        ///< after the step
    double potentialEnergy = 0;      ///< at the last force evaluation
    double maxSpeed = 0;             ///< mm/s, after the step
    int solverIterations = 0;        ///< conjugate-gradient (backward Euler) or local-global (projective dynamics) iterations
    int substeps = 1;                ///< sub-steps the step was split into (stable stepping)
    double estimateMs = 0;           ///< estimating the stable step (stable stepping), if it ran
};

class Simulator {
public:
    /// Keeps a reference to the mesh. If every mass is zero, sets the lumped masses of Eq. 3
    /// with material.density.
    Simulator(TetMesh& mesh, const Material& material, const SimulatorOptions& options = {});
    ~Simulator();
    Simulator(const Simulator&) = delete;
    Simulator& operator=(const Simulator&) = delete;

    /// Builds the named effect (EffectRegistry) and adds it, with the simulator's threads and
    /// grain (settings.threads and settings.grain are overridden).
    Status addEffect(const std::string& name, EffectSettings settings = {},
                     const EffectRegistry& registry = EffectRegistry::withBuiltins());
    /// Adds an effect; it runs by its phase, then in the order added.
    void addEffect(std::unique_ptr<Effect> effect);
    /// The effect with this name, or nullptr.
    Effect* findEffect(const std::string& name) const;
    std::vector<std::string> effectNames() const;

    /// One step of timeStep().
    Status step();
    /// One step of h seconds; with stable stepping, split into as many sub-steps as the
    /// current configuration needs (lastStep().substeps). On failure the state is that of
    /// before the step (keepLastGoodState) and the clock has not moved.
    Status step(double h);

    /// options.dt, or stableTimeStep() if it is 0.
    double timeStep();
    /// The smallest stable step the effects allow (the deformation effect's estimate); if no
    /// effect limits it, the estimate of the full tissue model (a natural time scale).
    /// O(mesh) the first time and after a cut, then cached.
    double stableTimeStep();
    /// True when the simulator keeps explicit steps stable itself: options.dt = 0 and an
    /// explicit integrator.
    bool stableStepping() const;
    /// The stable step at the current configuration, 2 safety / omega_max (s; +inf without
    /// stiffness), as of the last estimate (estimated now if there is none yet). Any
    /// integrator: a diagnostic for the implicit ones.
    double currentStableTimeStep();

    /// After HybridCutter::cut (which has already updated masses): every effect follows the
    /// change, in time proportional to it.
    void applyCut(const CutChanges& changes);

    /// All effects' forces at the current state (constraints applied); returns their
    /// potential energy. f: #nodes.
    double computeForces(std::span<Vec3> f);
    double kineticEnergy() const;
    /// Kinetic plus the effects' potential energy at the current state.
    double totalEnergy();

    const StepReport& lastStep() const { return m_last; }
    /// Per effect: milliseconds summed over all steps so far.
    const std::vector<EffectTime>& totalTimes() const { return m_total; }
    double integrateMsTotal() const { return m_integrateMsTotal; }
    int stepsTaken() const { return m_steps; }
    /// Integrator steps over all steps: stepsTaken() plus the extra sub-steps.
    long long substepsTaken() const { return m_substeps; }
    /// Estimates of the current stable step so far, and the milliseconds they took.
    int stableEstimates() const { return m_estimates; }
    double estimateMsTotal() const { return m_estimateMsTotal; }
    double time() const { return m_time; }
    /// Continues the clock of an earlier simulator of the same tissue (rebuilt after its tets
    /// were renumbered, e.g. when a resected piece left it).
    void resumeClock(double time, int steps) {
        m_time = time;
        m_steps = steps;
    }
    int threads() const { return m_threads; }
    /// The projective-dynamics solver's figures (factorisations, their cost), or nullptr.
    const ProjectiveDynamicsStats* projectiveStats() const {
        return m_projective ? &m_projective->stats() : nullptr;
    }
    /// Threads of the node passes for the current node count.
    int nodeThreads() const;
    const SimulatorOptions& options() const { return m_options; }
    TetMesh& mesh() { return m_mesh; }

private:
    SimState state(double h);
    /// One integrator step of h (a whole step or a sub-step): forces, update, divergence
    /// check, corrections; fills m_last (but not the clock, counters or substeps).
    Status integrate(double h, int substep, int substeps);
    /// The number of sub-steps for a step of h, estimating the stable step when due.
    Status substepsFor(double h, int& substeps);
    /// Estimates lambda_max(M^-1 K) at the current configuration into m_lambda; `converged`:
    /// restarted until it settles (first step, after a cut), else one warm round.
    void estimateStableStep(bool converged);
    /// Holds this safe step (shorter or longer than the last) and restarts the calm count.
    void holdStep(double dt);
    /// Sets m_interval after an estimate, for sub-steps of this length.
    void scheduleEstimate(double substep);
    /// The energy reference of the divergence check, at the first step and after a cut.
    void ensureReference();
    /// f = the effects' forces; f must be zero already if `zeroed`.
    double evaluateForces(const SimState& s, std::span<Vec3> f, bool zeroed = false);
    void constrainAll(std::span<Vec3> v, bool timed);
    Status implicitStep(const SimState& s, double h, NodePass& pass, double& potential);
    Status projectiveStep(const SimState& s, double h, NodePass& pass, double& potential);
    void ensureBuffers();

    TetMesh& m_mesh;
    Material m_material;
    SimulatorOptions m_options;
    int m_threads = 1;
    std::vector<std::unique_ptr<Effect>> m_effects;
    std::vector<double> m_effectMs;        ///< this step, per effect
    std::vector<double> m_effectPotential; ///< at the last force evaluation, per effect
    StepReport m_last;
    std::vector<EffectTime> m_total;
    double m_integrateMsTotal = 0;
    int m_steps = 0;
    double m_time = 0;

    std::vector<Vec3> m_force, m_backupX, m_backupV;
    std::vector<Vec3> m_rhs, m_dv, m_diag, m_tmp, m_kd, m_dd;
    bool m_forcesValid = false;  ///< m_force holds the forces at the current state (Verlet)
    bool m_forceZero = false;    ///< m_force is all zero (left so by symplectic Euler)
    double m_forcePotential = 0; ///< potential energy of m_force's evaluation
    bool m_needReference = true;
    double m_referenceEnergy = 0, m_energyScale = 0;
    double m_fallbackStableDt = 0;
    // Stable stepping (see "Time step").
    std::vector<Vec3> m_mode;               ///< Ritz vector of the last estimate (warm start)
    std::vector<Vec3> m_probe;              ///< scratch of the stiffness product
    std::vector<Vec3> m_stepBackupX, m_stepBackupV; ///< the state before a sub-stepped step
    double m_lambda = -1;                   ///< lambda_max at the last estimate; < 0: none
    double m_heldDt = 0;                    ///< the safe step in force (0: none)
    double m_calmLambda = 0;                ///< largest lambda since the held step last changed
    int m_calmEstimates = 0;                ///< estimates since then that allowed a longer step
    double m_lambdaChange = -1;             ///< relative change at the last estimate (< 0: none)
    bool m_needConvergedEstimate = true;    ///< first step, after a cut or a new effect
    int m_interval = 0;                     ///< steps between estimates (0: not started)
    int m_stepsSinceEstimate = 0;
    double m_energy = 0;                    ///< monitored energy after the last (sub-)step
    double m_energyMark = 0;                ///< energy at the mark (energyTrigger)
    bool m_energyGrew = false;              ///< grown past the trigger: estimate, shorten
    long long m_substeps = 0;
    int m_estimates = 0;
    double m_estimateMsTotal = 0;
    std::unique_ptr<ProjectiveDynamics> m_projective;
    std::vector<char> m_held; ///< per node: held by an effect (projective dynamics)
};

} // namespace resect
