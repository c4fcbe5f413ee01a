#pragma once
// Effect: one composable part of a simulated scene (deformation, gravity, fixed nodes, tool
// contact, damping, ...). The Simulator (simulator.h) runs only the effects it was given, in
// order of phase() and then of addition; an effect that is not added allocates nothing and
// costs nothing. New effects implement this interface and are registered by name in the
// EffectRegistry (effect_registry.h).
//
// Every hook has a do-nothing default, so an effect implements only what it does:
//   forces          addForces (+ the differentials, for the implicit integrator)
//   constraints     constrain: zero the entries of nodes it holds (forces, velocities, and
//                   the implicit solver's vectors), and afterStep to re-impose positions
//   contact         afterStep: position-level projection after the integrator moved nodes
//   topology        applyCut: follow a cut in time proportional to the change

#include "core/cut/cut_types.h"
#include "core/mesh/tet_mesh.h"

#include <limits>
#include <span>
#include <string>

namespace resect {

/// The state effects see. Spans are #nodes; positions in mm, velocities in mm/s, masses in g.
struct SimState {
    std::span<Vec3> x;
    std::span<Vec3> v;
    std::span<const double> mass;
    double time = 0; ///< s, at the start of the step
    double dt = 0;   ///< s, the step being taken
    /// The simulator may split a step into sub-steps (explicit integrators, simulator.h): the
    /// whole step (0: dt) and whether this sub-step ends it. The caller changes the scene (a
    /// tool's pose) between whole steps only.
    double stepDt = 0;
    bool lastSubstep = true;
};

class Effect {
public:
    /// Effects run by increasing phase, then in the order they were added.
    enum Phase { kForces = 0, kContact = 1, kConstraints = 2 };

    virtual ~Effect() = default;
    virtual std::string name() const = 0;
    virtual int phase() const { return kForces; }

    /// f += this effect's forces (g mm/s^2) at the state; returns the potential energy of the
    /// conservative part (g mm^2/s^2; 0 if none) for energy monitoring.
    virtual double addForces(const SimState& s, std::span<Vec3> f) { return 0; }
    /// df += (df/dx) dx, a symmetric negative semi-definite approximation (implicit Euler).
    virtual void addForceDifferential(const SimState& s, std::span<const Vec3> dx,
                                      std::span<Vec3> df) {}
    /// df += (df/dv) dv, symmetric negative semi-definite (implicit Euler).
    virtual void addVelocityDifferential(const SimState& s, std::span<const Vec3> dv,
                                         std::span<Vec3> df) {}
    /// diag += the diagonal of -(h df/dv + h^2 df/dx), for the implicit solver's
    /// preconditioner.
    virtual void addSystemDiagonal(const SimState& s, double h, std::span<Vec3> diag) {}

    /// Zeroes the entries of the nodes this effect holds in a per-node vector.
    virtual void constrain(std::span<Vec3> perNode) const {}
    /// After the integrator moved the nodes (positions and velocities already updated):
    /// position-level corrections. Returns true if it changed any position.
    virtual bool afterStep(const SimState& s) { return false; }

    /// The largest stable explicit step this effect allows (+inf if it does not limit it).
    virtual double stableTimeStep(const TetMesh& mesh) {
        return std::numeric_limits<double>::infinity();
    }
    /// After a cut: the mesh has new nodes and tets (CutChanges), masses already updated.
    virtual void applyCut(const TetMesh& mesh, const CutChanges& changes) {}
};

} // namespace resect
