#include "core/sim/simulator.h"

#include "core/mesh/masses.h"
#include "core/mesh/stable_time_step.h"
#include "core/sim/deformation_effect.h"
#include "core/sim/parallel.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>

namespace resect {
namespace {

using Clock = std::chrono::steady_clock;

/// A converged estimate (first step, after a cut) runs Lanczos rounds of this many products,
/// restarted up to this many rounds until two agree within the tolerance.
constexpr int kConvergedSteps = 10;
constexpr int kConvergedRounds = 30;
constexpr double kConvergedTolerance = 1e-4;
/// The energy trigger shortens the safe step down to this fraction of the estimate's at most.
constexpr double kEnergyStepFloor = 0.5;

double msSince(Clock::time_point t0) {
    return std::chrono::duration<double, std::milli>(Clock::now() - t0).count();
}

std::string format(double value) {
    char text[32];
    std::snprintf(text, sizeof text, "%.6g", value);
    return text;
}

/// Sets v to zero on `threads` threads.
void zero(std::span<Vec3> v, int threads) {
    const auto n = static_cast<std::int64_t>(v.size());
    parallelRun(threads, [&](int t) {
        const auto b = chunkBegin(n, threads, t), e = chunkBegin(n, threads, t + 1);
        std::fill(v.begin() + b, v.begin() + e, Vec3::Zero());
    });
}

} // namespace

const char* integratorName(Integrator integrator) {
    switch (integrator) {
    case Integrator::SymplecticEuler:
        return "symplectic-euler";
    case Integrator::VelocityVerlet:
        return "velocity-verlet";
    case Integrator::BackwardEuler:
        return "backward-euler";
    case Integrator::ProjectiveDynamics:
        return "projective-dynamics";
    }
    return "?";
}

bool parseIntegrator(const std::string& name, Integrator& out) {
    if (name == "symplectic-euler" || name == "explicit")
        out = Integrator::SymplecticEuler;
    else if (name == "velocity-verlet" || name == "verlet")
        out = Integrator::VelocityVerlet;
    else if (name == "projective-dynamics" || name == "implicit")
        out = Integrator::ProjectiveDynamics;
    else if (name == "backward-euler")
        out = Integrator::BackwardEuler;
    else
        return false;
    return true;
}

bool isExplicit(Integrator integrator) {
    return integrator != Integrator::BackwardEuler && integrator != Integrator::ProjectiveDynamics;
}

Simulator::Simulator(TetMesh& mesh, const Material& material, const SimulatorOptions& options)
    : m_mesh(mesh), m_material(material), m_options(options),
      m_threads(resolveThreadCount(options.threads)) {
    const auto m = mesh.masses();
    if (std::all_of(m.begin(), m.end(), [](double v) { return v == 0; }))
        computeLumpedMasses(mesh, material.density);
}

Simulator::~Simulator() = default;

Status Simulator::addEffect(const std::string& name, EffectSettings settings,
                            const EffectRegistry& registry) {
    if (findEffect(name))
        return Status::error("effect '" + name + "' added twice");
    settings.threads = m_threads;
    settings.grain = m_options.grain;
    std::unique_ptr<Effect> effect;
    if (Status s = registry.create(name, m_mesh, m_material, settings, effect); !s.ok())
        return s;
    addEffect(std::move(effect));
    return Status::success();
}

void Simulator::addEffect(std::unique_ptr<Effect> effect) {
    const int phase = effect->phase();
    auto at = std::find_if(m_effects.begin(), m_effects.end(),
                           [&](const auto& e) { return e->phase() > phase; });
    const auto i = at - m_effects.begin();
    m_effects.insert(at, std::move(effect));
    m_total.insert(m_total.begin() + i, EffectTime{m_effects[i]->name(), 0});
    m_last.effects.insert(m_last.effects.begin() + i, EffectTime{m_effects[i]->name(), 0});
    m_effectMs.assign(m_effects.size(), 0);
    m_effectPotential.assign(m_effects.size(), 0);
    m_forcesValid = false;
    m_needReference = true;
    m_needConvergedEstimate = true;
}

int Simulator::nodeThreads() const {
    return threadsFor(m_threads, m_mesh.nodeCount(), m_options.grain);
}

Effect* Simulator::findEffect(const std::string& name) const {
    for (const auto& e : m_effects)
        if (e->name() == name)
            return e.get();
    return nullptr;
}

std::vector<std::string> Simulator::effectNames() const {
    std::vector<std::string> names;
    for (const auto& e : m_effects)
        names.push_back(e->name());
    return names;
}

double Simulator::stableTimeStep() {
    double dt = std::numeric_limits<double>::infinity();
    for (auto& e : m_effects)
        dt = std::min(dt, e->stableTimeStep(m_mesh));
    if (std::isfinite(dt))
        return dt;
    if (!(m_fallbackStableDt > 0)) {
        StableTimeStepOptions options;
        options.areaTerm = true;
        m_fallbackStableDt = resect::stableTimeStep(m_mesh, m_material, options).dt;
    }
    return m_fallbackStableDt;
}

double Simulator::timeStep() {
    return m_options.dt > 0 ? m_options.dt : stableTimeStep();
}

SimState Simulator::state(double h) {
    SimState s;
    s.x = m_mesh.positions();
    s.v = m_mesh.velocities();
    s.mass = m_mesh.masses();
    s.time = m_time;
    s.dt = h;
    return s;
}

void Simulator::ensureBuffers() {
    const auto n = static_cast<std::size_t>(m_mesh.nodeCount());
    if (m_force.size() != n) {
        m_force.resize(n, Vec3::Zero()); // new entries zero: m_forceZero stays true
        m_forcesValid = false;
    }
    if (m_options.keepLastGoodState) {
        m_backupX.resize(n);
        m_backupV.resize(n);
    }
}

void Simulator::constrainAll(std::span<Vec3> v, bool timed) {
    for (std::size_t i = 0; i < m_effects.size(); ++i) {
        const auto t0 = Clock::now();
        m_effects[i]->constrain(v);
        if (timed)
            m_effectMs[i] += msSince(t0);
    }
}

double Simulator::evaluateForces(const SimState& s, std::span<Vec3> f, bool zeroed) {
    if (!zeroed)
        zero(f, nodeThreads());
    double potential = 0;
    for (std::size_t i = 0; i < m_effects.size(); ++i) {
        const auto t0 = Clock::now();
        m_effectPotential[i] = m_effects[i]->addForces(s, f);
        potential += m_effectPotential[i];
        m_effectMs[i] += msSince(t0);
    }
    constrainAll(f, true);
    return potential;
}

double Simulator::computeForces(std::span<Vec3> f) {
    return evaluateForces(state(0), f);
}

double Simulator::kineticEnergy() const {
    return measureVelocities(m_mesh.velocities(), m_mesh.masses(), nodeThreads()).kineticEnergy;
}

double Simulator::totalEnergy() {
    std::vector<Vec3> f(m_mesh.nodeCount());
    return kineticEnergy() + evaluateForces(state(0), f);
}

Status Simulator::implicitStep(const SimState& s, double h, NodePass& pass, double& potential) {
    const auto n = static_cast<std::size_t>(m_mesh.nodeCount());
    for (auto* b : {&m_rhs, &m_dv, &m_diag, &m_tmp, &m_kd, &m_dd})
        b->resize(n);
    potential = evaluateForces(s, m_force, m_forceZero);
    m_forceZero = false;

    // b = h (f + h K v), constrained.
    std::fill(m_kd.begin(), m_kd.end(), Vec3::Zero());
    for (std::size_t i = 0; i < m_effects.size(); ++i) {
        const auto t0 = Clock::now();
        m_effects[i]->addForceDifferential(s, s.v, m_kd);
        m_effectMs[i] += msSince(t0);
    }
    for (std::size_t i = 0; i < n; ++i)
        m_rhs[i] = h * (m_force[i] + h * m_kd[i]);
    constrainAll(m_rhs, true);

    // Diagonal of A = M - h D - h^2 K; constrained and massless nodes get 1 (A = I there).
    for (std::size_t i = 0; i < n; ++i)
        m_diag[i] = Vec3::Constant(s.mass[i]);
    for (std::size_t i = 0; i < m_effects.size(); ++i) {
        const auto t0 = Clock::now();
        m_effects[i]->addSystemDiagonal(s, h, m_diag);
        m_effectMs[i] += msSince(t0);
    }
    std::fill(m_tmp.begin(), m_tmp.end(), Vec3::Ones());
    constrainAll(m_tmp, true);
    for (std::size_t i = 0; i < n; ++i)
        for (int c = 0; c < 3; ++c)
            if (m_tmp[i][c] == 0 || s.mass[i] == 0)
                m_diag[i][c] = 1;

    const SystemOperator apply = [&](std::span<const Vec3> in, std::span<Vec3> out) {
        std::copy(in.begin(), in.end(), m_tmp.begin());
        constrainAll(m_tmp, true);
        std::fill(m_kd.begin(), m_kd.end(), Vec3::Zero());
        std::fill(m_dd.begin(), m_dd.end(), Vec3::Zero());
        for (std::size_t i = 0; i < m_effects.size(); ++i) {
            const auto t0 = Clock::now();
            m_effects[i]->addForceDifferential(s, m_tmp, m_kd);
            m_effects[i]->addVelocityDifferential(s, m_tmp, m_dd);
            m_effectMs[i] += msSince(t0);
        }
        for (std::size_t i = 0; i < n; ++i)
            out[i] = s.mass[i] * m_tmp[i] - h * m_dd[i] - h * h * m_kd[i];
        constrainAll(out, true);
        for (std::size_t i = 0; i < n; ++i)
            out[i] += s.mass[i] > 0 ? Vec3(in[i] - m_tmp[i]) : Vec3(in[i] - out[i]);
    };
    const LinearSolve solve =
        solveConjugateGradient(apply, m_diag, m_rhs, m_dv, m_options.implicit);
    m_last.solverIterations = solve.iterations;
    constrainAll(m_dv, true);
    pass = velocityChangeUpdate(s.x, s.v, m_dv, s.mass, h, m_backupX, m_backupV, nodeThreads());
    return Status::success();
}

Status Simulator::projectiveStep(const SimState& s, double h, NodePass& pass, double& potential) {
    const auto n = static_cast<std::size_t>(m_mesh.nodeCount());
    if (!m_projective)
        m_projective = std::make_unique<ProjectiveDynamics>();
    // External forces: every effect but the deformation, at the start of the step.
    DeformationEffect* deformation = nullptr;
    std::size_t deformationIndex = 0;
    std::fill(m_force.begin(), m_force.end(), Vec3::Zero());
    potential = 0;
    for (std::size_t i = 0; i < m_effects.size(); ++i) {
        if (auto* d = dynamic_cast<DeformationEffect*>(m_effects[i].get()); d && !deformation) {
            deformation = d;
            deformationIndex = i;
            continue;
        }
        const auto t0 = Clock::now();
        m_effectPotential[i] = m_effects[i]->addForces(s, m_force);
        potential += m_effectPotential[i];
        m_effectMs[i] += msSince(t0);
    }
    constrainAll(m_force, true);
    m_forceZero = false;
    // Held nodes: those an effect's constraint zeroes.
    m_tmp.assign(n, Vec3::Ones());
    constrainAll(m_tmp, true);
    m_held.resize(n);
    for (std::size_t i = 0; i < n; ++i)
        m_held[i] = m_tmp[i] != Vec3::Ones();
    static const DeformationModel kNoTerms;
    const DeformationModel* model = deformation ? &deformation->model() : &kNoTerms;
    // The iterations evaluate the deformation's forces (timed as the deformation effect's).
    const ProjectiveDynamics::Forces forces = [&](std::span<Vec3> x, std::span<Vec3> f) {
        if (!deformation)
            return 0.0;
        const auto t0 = Clock::now();
        SimState at = s;
        at.x = x;
        const double energy = deformation->addForces(at, f);
        m_effectMs[deformationIndex] += msSince(t0);
        return energy;
    };
    if (Status st = m_projective->step(m_mesh, *model, m_held, m_force, h, m_options.projective,
                                       m_threads, m_backupX, m_backupV, forces);
        !st.ok())
        return st;
    m_last.solverIterations = m_options.projective.iterations;
    potential += m_projective->energy();
    pass = measureVelocities(s.v, s.mass, nodeThreads());
    return Status::success();
}

Status Simulator::step() {
    return step(timeStep());
}

bool Simulator::stableStepping() const {
    return !(m_options.dt > 0) && isExplicit(m_options.integrator);
}

double Simulator::currentStableTimeStep() {
    if (m_needConvergedEstimate || m_lambda < 0)
        estimateStableStep(true);
    return m_lambda > 0 ? 2 * m_options.stable.safety / std::sqrt(m_lambda)
                        : std::numeric_limits<double>::infinity();
}

void Simulator::estimateStableStep(bool converged) {
    const auto t0 = Clock::now();
    const SimState s = state(0);
    m_probe.resize(static_cast<std::size_t>(m_mesh.nodeCount()));
    // y = K x = -(df/dx) x over the unconstrained nodes: P K P, symmetric.
    const StiffnessProduct stiffness = [&](std::span<const Vec3> x, std::span<Vec3> y) {
        std::copy(x.begin(), x.end(), m_probe.begin());
        constrainAll(m_probe, false);
        for (auto& e : m_effects)
            e->addForceDifferential(s, m_probe, y);
        constrainAll(y, false);
        for (Vec3& v : y)
            v = -v;
    };
    const StableSteppingOptions& o = m_options.stable;
    LanczosOptions lanczos = o.lanczos;
    if (converged) {
        lanczos.steps = std::max(lanczos.steps, kConvergedSteps);
        lanczos.maxRounds = std::max(lanczos.maxRounds, kConvergedRounds);
        lanczos.relativeTolerance = std::min(lanczos.relativeTolerance, kConvergedTolerance);
    }
    const double previous = m_lambda;
    m_lambda = largestEigenvalue(stiffness, m_mesh.masses(), m_mode, lanczos).lambdaMax;
    // The held stable step: shorter at once, longer only after `holdEstimates` estimates
    // that all allow it with a margin (switching sub-step counts back and forth pumps energy
    // into an oscillating tissue, as the counts follow its stiffness).
    const double now =
        m_lambda > 0 ? 2 * o.safety / std::sqrt(m_lambda) : std::numeric_limits<double>::infinity();
    if (converged || !(m_heldDt > 0) || now <= m_heldDt) {
        holdStep(now);
    } else {
        m_calmLambda = std::max(m_calmLambda, m_lambda);
        if (++m_calmEstimates >= o.holdEstimates) {
            m_heldDt =
                std::max(m_heldDt, 2 * o.safety / std::sqrt(m_calmLambda) / (1 + o.relaxMargin));
            m_calmLambda = m_lambda;
            m_calmEstimates = 0;
        }
    }
    // How much lambda moved since the last estimate (relative), for the interval.
    m_lambdaChange = !converged && previous > 0 ? std::abs(m_lambda - previous) / previous : -1;
    m_stepsSinceEstimate = 0;
    m_needConvergedEstimate = false;
    ++m_estimates;
    const double ms = msSince(t0);
    m_last.estimateMs += ms;
    m_estimateMsTotal += ms;
}

Status Simulator::substepsFor(double h, int& substeps) {
    substeps = 1;
    if (!stableStepping())
        return Status::success();
    const bool estimated =
        m_needConvergedEstimate || m_lambda < 0 || m_stepsSinceEstimate >= m_interval;
    if (estimated) {
        const double held = m_heldDt;
        estimateStableStep(m_needConvergedEstimate || m_lambda < 0);
        if (m_energyGrew) {
            // The energy grew although the step was within the estimate (a resonance of the
            // deformed tissue at h omega near the limit): shorten the step unless the estimate
            // just did, and mark the energy anew.
            if (!(m_heldDt < held)) {
                // At most down to half the estimate's step (resonances near the limit are gone
                // far above it), so that external work a tool does costs at most twice.
                const double now = 2 * m_options.stable.safety / std::sqrt(m_lambda);
                holdStep(std::min(m_heldDt, std::max(m_options.stable.energyStepFactor * m_heldDt,
                                                     kEnergyStepFloor * now)));
            }
            m_energyMark = m_energy;
            m_energyGrew = false;
        }
    }
    if (!(m_heldDt > 0) || !std::isfinite(m_heldDt))
        return Status::success(); // nothing stiff (or non-finite: the step reports it)
    const double ratio = h / m_heldDt;
    if (!(ratio <= m_options.stable.maxSubsteps))
        return Status::error("the step " + format(h) + " s needs more than " +
                             std::to_string(m_options.stable.maxSubsteps) +
                             " sub-steps at the current configuration (its stable step is " +
                             format(m_heldDt) +
                             " s): the tissue has collapsed or diverged; the state is unchanged");
    substeps = std::max(1, static_cast<int>(std::ceil(ratio / (1 + m_options.stable.tolerance))));
    if (estimated)
        scheduleEstimate(h / substeps);
    return Status::success();
}

void Simulator::holdStep(double dt) {
    m_heldDt = dt;
    m_calmLambda = m_lambda;
    m_calmEstimates = 0;
}

void Simulator::scheduleEstimate(double substep) {
    // Headroom: how much lambda may grow before the sub-step is no longer taken whole. The
    // interval doubles while the headroom is well above the last change of the estimate and
    // halves when it is not (lambda oscillates with the tissue: its changes are compared with
    // the headroom, not extrapolated in time).
    const StableSteppingOptions& o = m_options.stable;
    const double use = substep * std::sqrt(std::max(m_lambda, 0.0)) /
                       (2 * o.safety * (1 + std::max(o.tolerance, 0.0)));
    const double headroom = use > 0 ? 1 / (use * use) - 1 : std::numeric_limits<double>::infinity();
    const int lo = std::max(1, o.minInterval), hi = std::max(lo, o.maxInterval);
    if (m_lambdaChange < 0)
        m_interval = std::clamp(o.interval, lo, hi);
    else if (!(headroom > 0) || headroom < 2 * m_lambdaChange)
        m_interval = std::max(lo, m_interval / 2);
    else if (headroom > 4 * m_lambdaChange)
        m_interval = std::min(hi, 2 * m_interval);
}

void Simulator::ensureReference() {
    if (!m_needReference)
        return;
    // Energy reference for divergence detection (see simulator.h).
    const double kinetic = kineticEnergy();
    m_forcePotential = evaluateForces(state(0), m_force, m_forceZero);
    m_forcesValid = true;
    m_forceZero = false;
    m_referenceEnergy = kinetic + m_forcePotential;
    double totalMass = 0;
    for (double m : m_mesh.masses())
        totalMass += m;
    m_energyScale = totalMass * m_material.stiffness + std::abs(kinetic);
    for (double p : m_effectPotential)
        m_energyScale += std::abs(p);
    m_energy = m_referenceEnergy;
    // Marked after the first step: the explicit steps monitor the kinetic energy after the
    // step with the potential before it, which differs from the reference's.
    m_energyMark = std::numeric_limits<double>::quiet_NaN();
    m_energyGrew = false;
    m_needReference = false;
}

Status Simulator::step(double h) {
    if (!std::isfinite(h) || !(h > 0))
        return Status::error("time step must be finite and positive, got " + format(h));
    ensureBuffers();
    std::fill(m_effectMs.begin(), m_effectMs.end(), 0.0);
    m_last.estimateMs = 0;
    ensureReference();
    int substeps = 1;
    if (Status s = substepsFor(h, substeps); !s.ok())
        return s;

    const double start = m_time;
    Status failure;
    if (substeps == 1) {
        failure = integrate(h, 0, 1);
    } else {
        const auto n = static_cast<std::size_t>(m_mesh.nodeCount());
        if (m_options.keepLastGoodState) {
            m_stepBackupX.assign(m_mesh.positions().begin(), m_mesh.positions().end());
            m_stepBackupV.assign(m_mesh.velocities().begin(), m_mesh.velocities().end());
        }
        const double sub = h / substeps;
        std::vector<double> effectMs(m_effects.size(), 0.0);
        double integrateMs = 0, maxSpeed = 0;
        int iterations = 0;
        for (int k = 0; k < substeps && failure.ok(); ++k) {
            if (k > 0)
                std::fill(m_effectMs.begin(), m_effectMs.end(), 0.0);
            failure = integrate(sub, k, substeps);
            if (!failure.ok())
                break;
            m_time = start + (k + 1) * sub;
            for (std::size_t i = 0; i < m_effects.size(); ++i)
                effectMs[i] += m_last.effects[i].ms;
            integrateMs += m_last.integrateMs;
            maxSpeed = std::max(maxSpeed, m_last.maxSpeed);
            iterations += m_last.solverIterations;
        }
        if (!failure.ok()) {
            if (m_options.keepLastGoodState && m_stepBackupX.size() == n) {
                std::copy(m_stepBackupX.begin(), m_stepBackupX.end(), m_mesh.positions().begin());
                std::copy(m_stepBackupV.begin(), m_stepBackupV.end(), m_mesh.velocities().begin());
            }
        } else {
            for (std::size_t i = 0; i < m_effects.size(); ++i)
                m_last.effects[i].ms = effectMs[i];
            m_last.integrateMs = integrateMs;
            m_last.maxSpeed = maxSpeed;
            m_last.solverIterations = iterations;
        }
    }
    if (!failure.ok()) {
        m_time = start;
        m_forcesValid = false;
        return failure;
    }
    m_time = start + h;
    ++m_steps;
    m_substeps += substeps;
    m_stepsSinceEstimate += substeps;
    m_last.substeps = substeps;
    // Energy growth since the mark: estimate again at the next step (substepsFor).
    if (std::isnan(m_energyMark))
        m_energyMark = m_energy;
    if (stableStepping() && !m_energyGrew &&
        m_energy - m_energyMark > m_options.stable.energyTrigger * m_energyScale) {
        m_energyGrew = true;
        m_stepsSinceEstimate = std::max(m_stepsSinceEstimate, m_interval);
    }
    return Status::success();
}

Status Simulator::integrate(double h, int substep, int substeps) {
    m_last.solverIterations = 0;
    SimState s = state(h);
    s.stepDt = h * substeps;
    s.lastSubstep = substep + 1 == substeps;
    const auto stepStart = Clock::now();

    NodePass pass;
    double potential = 0;
    switch (m_options.integrator) {
    case Integrator::SymplecticEuler:
        potential = evaluateForces(s, m_force, m_forceZero);
        pass = symplecticEulerUpdate(s.x, s.v, m_force, s.mass, h, m_backupX, m_backupV,
                                     nodeThreads());
        m_forcesValid = false;
        m_forceZero = true;
        break;
    case Integrator::VelocityVerlet: {
        m_forceZero = false;
        if (!m_forcesValid)
            m_forcePotential = evaluateForces(s, m_force);
        const NodePass drift =
            verletKickDrift(s.x, s.v, m_force, s.mass, h, m_backupX, m_backupV, nodeThreads());
        potential = evaluateForces(s, m_force);
        pass = verletKick(s.v, m_force, s.mass, h, nodeThreads());
        pass.finite = pass.finite && drift.finite;
        m_forcePotential = potential;
        m_forcesValid = true;
        break;
    }
    case Integrator::BackwardEuler:
        if (Status st = implicitStep(s, h, pass, potential); !st.ok())
            return st;
        m_forcesValid = false;
        break;
    case Integrator::ProjectiveDynamics:
        if (Status st = projectiveStep(s, h, pass, potential); !st.ok())
            return st;
        m_forcesValid = false;
        break;
    }

    const double energy = pass.kineticEnergy + potential;
    const bool diverged = !pass.finite || !std::isfinite(energy) ||
                          energy - m_referenceEnergy > m_options.explosionFactor * m_energyScale;
    if (diverged) {
        std::string message = "the simulation diverged at step " + std::to_string(m_steps + 1);
        if (substeps > 1)
            message += " (sub-step " + std::to_string(substep + 1) + " of " +
                       std::to_string(substeps) + ")";
        message += " (t = " + format(m_time) + " s): ";
        if (isExplicit(m_options.integrator)) {
            const double stable = stableTimeStep();
            if (stableStepping())
                message += "the explicit " + std::string(integratorName(m_options.integrator)) +
                           " step " + format(h) +
                           " s, within the stable step of the configuration estimated " +
                           std::to_string(m_stepsSinceEstimate) +
                           " steps earlier, did not stay bounded (stable estimate at rest " +
                           format(stable) + " s): the tissue stiffened faster than the " +
                           "estimates followed; use the implicit integrator";
            else
                message += "the time step " + format(h) + " s is too large for the explicit " +
                           std::string(integratorName(m_options.integrator)) +
                           " integrator (stable estimate " + format(stable) +
                           " s at rest; deformed tissue can need less: leave the time step " +
                           "at its default and the simulator keeps it stable, or use the " +
                           "implicit integrator)";
        } else {
            message += "the implicit step " + format(h) + " s did not stay bounded (" +
                       std::to_string(m_last.solverIterations) + " solver iterations)";
        }
        if (m_options.keepLastGoodState) {
            std::copy(m_backupX.begin(), m_backupX.end(), m_mesh.positions().begin());
            std::copy(m_backupV.begin(), m_backupV.end(), m_mesh.velocities().begin());
            message += "; the state of the last good step is kept";
        } else {
            message += "; the state is not usable";
        }
        m_forcesValid = false;
        return Status::error(message);
    }

    bool corrected = false;
    for (std::size_t i = 0; i < m_effects.size(); ++i) {
        const auto t0 = Clock::now();
        corrected = m_effects[i]->afterStep(s) || corrected;
        m_effectMs[i] += msSince(t0);
    }
    if (corrected) {
        pass = measureVelocities(s.v, s.mass, nodeThreads());
        m_forcesValid = false;
    }

    double effectsMs = 0;
    for (std::size_t i = 0; i < m_effects.size(); ++i) {
        m_last.effects[i].ms = m_effectMs[i];
        m_total[i].ms += m_effectMs[i];
        effectsMs += m_effectMs[i];
    }
    m_last.integrateMs = std::max(0.0, msSince(stepStart) - effectsMs);
    m_integrateMsTotal += m_last.integrateMs;
    m_last.kineticEnergy = pass.kineticEnergy;
    m_last.potentialEnergy = potential;
    m_last.maxSpeed = pass.maxSpeed;
    m_energy = pass.kineticEnergy + potential;
    return Status::success();
}

void Simulator::applyCut(const CutChanges& changes) {
    for (auto& e : m_effects)
        e->applyCut(m_mesh, changes);
    ensureBuffers();
    m_forcesValid = false;
    m_needReference = true;
    m_needConvergedEstimate = true;
    m_fallbackStableDt = 0;
    if (m_projective)
        m_projective->invalidate();
}

} // namespace resect
