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
    Effect* deformation = nullptr;
    std::fill(m_force.begin(), m_force.end(), Vec3::Zero());
    potential = 0;
    for (std::size_t i = 0; i < m_effects.size(); ++i) {
        if (m_effects[i]->name() == "deformation") {
            deformation = m_effects[i].get();
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
    const auto* model = deformation ? &static_cast<DeformationEffect*>(deformation)->model() : &kNoTerms;
    if (Status st = m_projective->step(m_mesh, *model, m_held, m_force, h, m_options.projective,
                                       m_threads, m_backupX, m_backupV);
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

Status Simulator::step(double h) {
    if (!std::isfinite(h) || !(h > 0))
        return Status::error("time step must be finite and positive, got " + format(h));
    ensureBuffers();
    std::fill(m_effectMs.begin(), m_effectMs.end(), 0.0);
    m_last.solverIterations = 0;
    const SimState s = state(h);
    const auto stepStart = Clock::now();

    if (m_needReference) {
        // Energy reference for divergence detection (see simulator.h).
        const double kinetic = kineticEnergy();
        m_forcePotential = evaluateForces(s, m_force, m_forceZero);
        m_forcesValid = true;
        m_forceZero = false;
        m_referenceEnergy = kinetic + m_forcePotential;
        double totalMass = 0;
        for (double m : m_mesh.masses())
            totalMass += m;
        m_energyScale = totalMass * m_material.stiffness + std::abs(kinetic);
        for (double p : m_effectPotential)
            m_energyScale += std::abs(p);
        m_needReference = false;
    }

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
        std::string message = "the simulation diverged at step " + std::to_string(m_steps + 1) +
                              " (t = " + format(m_time) + " s): ";
        if (isExplicit(m_options.integrator)) {
            const double stable = stableTimeStep();
            message += "the time step " + format(h) + " s is too large for the explicit " +
                       std::string(integratorName(m_options.integrator)) +
                       " integrator (stable estimate " + format(stable) + " s)";
            if (h <= stable)
                message += ", which holds for small deformations: strongly deformed tissue "
                           "needs a margin (" + format(kLargeDeformationMargin) +
                           " x the estimate) or the implicit integrator";
        } else
            message += "the implicit step " + format(h) + " s did not stay bounded (" +
                       std::to_string(m_last.solverIterations) + " solver iterations)";
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
    m_time += h;
    ++m_steps;
    return Status::success();
}

void Simulator::applyCut(const CutChanges& changes) {
    for (auto& e : m_effects)
        e->applyCut(m_mesh, changes);
    ensureBuffers();
    m_forcesValid = false;
    m_needReference = true;
    m_fallbackStableDt = 0;
    if (m_projective)
        m_projective->invalidate();
}

} // namespace resect
