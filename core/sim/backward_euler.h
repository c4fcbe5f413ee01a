#pragma once
// Linearised backward Euler (Baraff and Witkin, "Large Steps in Cloth Simulation", 1998):
// one Newton step of
//   v' = v + M^-1 h f(x + h v', v'),   x' = x + h v'
// linearised at (x, v), gives for the velocity change dv = v' - v
//   (M - h D - h^2 K) dv = h (f + h K v),    K = df/dx, D = df/dv,
// then v' = v + dv and x' = x + h v'. K and D are the effects' differentials (effect.h):
// symmetric negative semi-definite (the Gauss-Newton part of the Hessian for the tissue
// model, forces.h), so the system matrix is symmetric positive definite and conjugate
// gradients apply. The step is stable for any h and dissipates energy (more for larger h);
// it is the integrator for steps far beyond the explicit limit.
//
// The solve is matrix-free: Eigen's ConjugateGradient drives a SystemOperator through
// Eigen's matrix-free interface, with a Jacobi (diagonal) preconditioner.

#include "core/mesh/tet_mesh.h"

#include <functional>
#include <span>

namespace resect {

struct BackwardEulerOptions {
    double tolerance = 1e-6; ///< relative residual |A dv - b| / |b| at which CG stops
    int maxIterations = 1000;
};

struct LinearSolve {
    int iterations = 0;
    double relativeResidual = 0;
    bool converged = false;
};

/// y = A x for per-node vectors x, y (#nodes each). Must be symmetric positive definite.
using SystemOperator = std::function<void(std::span<const Vec3> x, std::span<Vec3> y)>;

/// Solves A x = b by preconditioned conjugate gradients, starting from x = 0. diagonal: the
/// diagonal of A (#nodes, all entries > 0). x receives the solution (#nodes).
LinearSolve solveConjugateGradient(const SystemOperator& apply, std::span<const Vec3> diagonal,
                                   std::span<const Vec3> b, std::span<Vec3> x,
                                   const BackwardEulerOptions& options);

} // namespace resect
