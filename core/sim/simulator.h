#pragma once
// Simulator: time stepping of a TetMesh under the effects a scene declares.
//
// The mesh owns the state (positions, velocities, masses; structure of arrays, tet_mesh.h);
// effects (effect.h) own their data; this class owns only scratch buffers and runs a step:
//   1. f = sum of the effects' forces at the current state, constrained by the effects;
//   2. the integrator updates velocities and positions (explicit_integrators.h, or the
//      linearised backward Euler of backward_euler.h);
//   3. the effects' position-level corrections (contact, anchors);
//   4. divergence check. Every step reports the time spent in each effect.
//
// Divergence. A step fails, with an error Status and the state restored to what it was
// before the step (SimulatorOptions::keepLastGoodState), when any position or velocity is not
// finite, or when the monitored energy E = kinetic + the effects' potentials grows by more
// than explosionFactor * S over its reference value (taken at the first step and after every
// cut), where S = M k + |kinetic| + sum of |potentials| at the reference (M the total mass,
// k Material::stiffness: M k is the elastic energy of a 100 % strain everywhere). A stable
// run conserves (Verlet, symplectic Euler: within a bounded oscillation) or dissipates E, so
// crossing the bound means the explicit step is above the stability limit; the message says
// so and gives the stable estimate. External work (a moving tool) is far below the bound for
// any realistic tool speed.
//
// Time step. The default is the stable estimate of stable_time_step.h (the model linearised
// at rest, with a 5 % margin). It holds for small deformations. Strongly deformed tissue is
// stiffer in some directions (tension adds transverse spring stiffness, the area and volume
// terms add second-derivative stiffness) and at h omega = 1.9 that modulation slowly pumps
// energy into the highest modes: in tests/core/sim a box stretched 5 % and released diverges
// after about a thousand steps at the estimate, while 0.8 of it keeps a 10 % stretch bounded
// over 10000 steps. The divergence is detected and reported like any other; for strong
// deformations give dt with a margin, or use the implicit integrator.
//
// Threads: SimulatorOptions::threads for the node passes and the built-in effects; results
// are bit-identical for a given thread count (parallel.h).

#include "core/mesh/material.h"
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

/// The margin on the stable estimate for strongly deformed tissue (see "Time step" above):
/// replay with tool contact, the studio and the benchmarks step at this fraction of it.
inline constexpr double kLargeDeformationMargin = 0.8;

/// ProjectiveDynamics is the product's implicit integrator (projective_dynamics.h; "implicit"
/// on the command line and in scenarios); BackwardEuler, the linearised backward Euler with
/// conjugate gradients, is kept for comparison.
enum class Integrator { SymplecticEuler, VelocityVerlet, BackwardEuler, ProjectiveDynamics };

/// "symplectic-euler", "velocity-verlet", "backward-euler", "projective-dynamics".
const char* integratorName(Integrator integrator);
bool isExplicit(Integrator integrator);

struct SimulatorOptions {
    Integrator integrator = Integrator::SymplecticEuler;
    double dt = 0;    ///< s; 0: the stable explicit time step (stableTimeStep())
    int threads = 0;  ///< 0: resolveThreadCount's default
    int grain = 4096; ///< fewer threads when one would get fewer nodes or terms (parallel.h)
    double explosionFactor = 100;
    bool keepLastGoodState = true; ///< back up the state in every step (see above)
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
    /// One step of h seconds.
    Status step(double h);

    /// options.dt, or stableTimeStep() if it is 0.
    double timeStep();
    /// The smallest stable step the effects allow (the deformation effect's estimate); if no
    /// effect limits it, the estimate of the full tissue model (a natural time scale).
    /// O(mesh) the first time and after a cut, then cached.
    double stableTimeStep();

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
    std::unique_ptr<ProjectiveDynamics> m_projective;
    std::vector<char> m_held; ///< per node: held by an effect (projective dynamics)
};

} // namespace resect
