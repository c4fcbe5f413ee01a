#pragma once
// Projective dynamics (Bouaziz, Martin, Liu, Kavan and Pauly, SIGGRAPH 2014) for the paper's
// tissue model: the implicit integrator the product uses (Integrator::ProjectiveDynamics,
// "implicit" on the command line and in scenarios).
//
// Every term of the model (forces.h) is a quadratic penalty 1/2 k (C(x) - C0)^2 on a scalar
// constraint. Projective dynamics writes a term as the distance of its nodes from the set
// where the constraint holds,
//   E_i = w_i / 2 | A_i x - p_i |^2,   p_i = the projection of A_i x onto { C = C0 },
// where A_i takes the term's nodes relative to their centroid (an edge: the edge vector):
//   edge (a, b):   p = l0 d / |d| for d = x_b - x_a: E_i = k/2 (|d| - l0)^2 exactly, w = k;
//   tet, triangle: p = the nodes moved along grad C by (C - C0) / |grad C0|^2 (a Newton step
//                  towards the set), w = k |grad C0|^2;
// with these, w_i A_i^T (A_i x - p_i) is exactly the term's force of forces.h. Backward Euler,
//   x' = argmin 1/(2h^2) |x - y|_M^2 + E(x),   y = x + h v + h^2 M^-1 f_ext,
// is solved by local-global iterations, the global step solving
//   (M / h^2 + sum w_i A_i^T A_i) x = M / h^2 y + sum w_i A_i^T p_i.
// Written with the forces this is x += S^-1 (M / h^2 (y - x) + f(x)), S the matrix on the left
// (the quasi-Newton view of Liu, Bouaziz and Kavan 2017): the local step is the model's force
// evaluation (the deformation effect's vectorised, threaded kernels), and a converged step is
// the model's own backward-Euler step. S is the same for x, y and z and constant while the
// mesh, the masses and h do not change: it is factored once (sparse LDL^T with a
// fill-reducing ordering) and every iteration costs a force evaluation and two triangular
// solves of three columns at once. v' = (x' - x) / h.
//
// External forces (gravity, damping, the other effects) enter y, evaluated at the start of
// the step. Constrained nodes (an effect's constrain() zeroes them: anchors) and nodes without
// mass are eliminated from the system: they keep their position (the iterations change only
// the free nodes). Each step starts from x + h v (not from y: the settled state is
// then exactly the model's equilibrium whatever the number of iterations), or from x where
// that is better for the objective below (violent motion at large steps), and no iterate may
// raise the backward-Euler objective 1/(2h^2) |x - y|_M^2 + E(x) (one that does is pulled back
// halfway, up to ten times), so the step stays bounded at any h. Few iterations lag the
// converged motion and add damping (measured in the README, "Real time").
//
// After a cut (or a change of h) the matrix is re-assembled and re-factored: O(mesh) and
// measured by `resect bench realtime` (refactor ms).

#include "core/mesh/tet_mesh.h"
#include "core/status.h"

#include <functional>
#include <memory>
#include <span>
#include <vector>

namespace resect {

class DeformationModel;

/// The step of an implicit integrator where a scene asks for "stable" (it has no stability
/// limit): 1 ms, a haptic trainer's rate.
inline constexpr double kImplicitDefaultStep = 0.001;

struct ProjectiveDynamicsOptions {
    /// Local-global iterations per step. Fewer are faster and lag: on the sample polyp under
    /// gravity at 1 ms (README, "Simulation"), 5 follow the explicit reference within about
    /// 50 ms, 1 lags it by about 0.3 s; all settle to the same sag within 2 %.
    int iterations = 5;
};

struct ProjectiveDynamicsStats {
    double factorMs = 0;   ///< the last assembly and factorisation
    int factorizations = 0;
    int unknowns = 0;      ///< free nodes in the system
    double nonZeros = 0;   ///< of the factor L
    long long halvings = 0; ///< iterates pulled back because they raised the objective
    long long restarts = 0; ///< steps started from x instead of x + h v
};

class ProjectiveDynamics {
public:
    ProjectiveDynamics();
    ~ProjectiveDynamics();
    ProjectiveDynamics(const ProjectiveDynamics&) = delete;
    ProjectiveDynamics& operator=(const ProjectiveDynamics&) = delete;

    /// Marks the system stale (after a cut: the terms, masses or nodes changed).
    void invalidate() { m_valid = false; }

    /// One step of h. `fixed`: per node, non-zero if the node is held (it does not move).
    /// fext: the external forces at the start of the step (#nodes). The mesh's positions and
    /// velocities are updated.
    /// backupX, backupV: #nodes or empty; receive the state before the step.
    /// Fails (state untouched) only if the system cannot be factored.
    /// forces(x, f): f += the model's forces at x (all nodes), returns its energy.
    using Forces = std::function<double(std::span<Vec3> x, std::span<Vec3> f)>;
    Status step(TetMesh& mesh, const DeformationModel& model, std::span<const char> fixed,
                std::span<const Vec3> fext, double h, const ProjectiveDynamicsOptions& options,
                int threads, std::span<Vec3> backupX, std::span<Vec3> backupV, const Forces& forces);

    const ProjectiveDynamicsStats& stats() const { return m_stats; }
    /// The model's energy (forces.h) at the end of the last step.
    double energy() const { return m_energy; }

private:
    struct Impl;
    Status prepare(const TetMesh& mesh, const DeformationModel& model, std::span<const char> fixed,
                   double h);

    std::unique_ptr<Impl> m_impl;
    bool m_valid = false;
    double m_h = 0;
    double m_energy = 0;
    double m_lastEnergy = -1; ///< E at the end of the last step (< 0: unknown)
    ProjectiveDynamicsStats m_stats;
};

} // namespace resect
