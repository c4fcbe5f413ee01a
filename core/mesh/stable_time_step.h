#pragma once
// Largest stable explicit time step of the mass-spring model.
//
// Model (Teschner et al. 2004 with the stiffnesses of Eq. 4, section 4.7):
//   springs on every edge e = (a, b):  E_e = 1/2 k_s (l - l0)^2,   k_s = k (m_a + m_b) / l0^2
//   volume term on every tet t:         E_t = 1/2 k_v (V - V0)^2,   k_v = k (sum m_i) / V0^2
// and, when the simulation has it (StableTimeStepOptions::areaTerm, see core/sim),
//   area term on every boundary triangle: E_f = 1/2 k_a (A - A0)^2,  k_a = k (sum m_i) / A0^2
// with lumped masses m (Eq. 3). Linearised at rest, the stiffness matrix is
//   K = sum_e k_s (n n^T) (x) [[1,-1],[-1,1]]  +  sum_t k_v g g^T  (+ sum_f k_a a a^T)
// where n is the unit edge direction, g the gradient of V with respect to the tet's twelve
// coordinates (g_i = (opposite face area normal) / 3) and a the gradient of A with respect to
// the triangle's nine (a_i = 1/2 n^ x (opposite edge)).
//
// Symplectic Euler / velocity Verlet on M x'' = -K x is stable iff dt * omega_max <= 2,
// omega_max^2 = lambda_max(M^-1 K). lambda_max is found by power iteration on the
// symmetric M^-1/2 K M^-1/2 (its Rayleigh quotient approaches lambda_max from below), and
// the Gershgorin bound max_i sum_j |K_ij| / m_i (always >= lambda_max) caps it. The result
//   dt = safety * 2 / sqrt(lambda_max),  safety = 0.95
// keeps a 5 % margin for the unconverged part of the power iteration. Verified in
// tests/core/mesh: an explicit run of the linearised model at dt stays bounded, one at
// 1.2 * 2 / sqrt(lambda_max) blows up.

#include "core/mesh/material.h"
#include "core/mesh/tet_mesh.h"

#include <functional>
#include <span>
#include <vector>

namespace resect {

struct StableTimeStep {
    double dt = 0;               ///< safety * 2 / sqrt(lambdaMax)
    double lambdaMax = 0;        ///< largest eigenvalue of M^-1 K (1/s^2)
    double gershgorinBound = 0;  ///< upper bound on lambdaMax
    int iterations = 0;          ///< power iterations used
};

struct StableTimeStepOptions {
    double safety = 0.95;
    /// Power iterations at most; 0: none, dt is then that of the Gershgorin bound (O(mesh),
    /// never above the limit, about 0.57 of the estimate on a Kuhn box lattice, and the same
    /// for any box of the same cells: the bound is a maximum over nodes).
    int maxIterations = 400;
    double relativeTolerance = 1e-7;
    bool areaTerm = false;  ///< include the surface-area term (core/sim's default model has it)
};

/// Needs masses (computeLumpedMasses). Nodes with zero mass are ignored.
StableTimeStep stableTimeStep(const TetMesh& mesh, const Material& material,
                              const StableTimeStepOptions& options = {});

/// Per tet, the stable step of its own terms alone: dt_t = safety * 2 / sqrt(lambda_t), where
/// lambda_t is the largest eigenvalue of M_t^-1 K_t, K_t the 12x12 linearised stiffness of the
/// tet's six edge springs (each at its full k_s), its volume term and, with options.areaTerm,
/// the area terms of its boundary faces, and M_t the lumped masses of its four nodes. Not a
/// bound on the mesh's step (terms shared by several tets are counted in each), but where the
/// mesh's highest frequency lives: the tets with the smallest dt_t are the ones that limit
/// stableTimeStep (a sliver's volume term, a short edge between light nodes). For a mesh of one
/// tet it is stableTimeStep's dt. +inf for a tet with no stiffness or a massless node. #tets,
/// O(tets) (options.maxIterations and relativeTolerance are not used: each is solved exactly).
std::vector<double> tetStableTimeSteps(const TetMesh& mesh, const Material& material,
                                       const StableTimeStepOptions& options = {});

/// The linearised stiffness operator y = K x at the reference configuration (x, y: #nodes
/// displacements). Exposed so that tests can run the linear model the estimate is about.
void applyRestStiffness(const TetMesh& mesh, const Material& material,
                        std::span<const Vec3> x, std::span<Vec3> y, bool areaTerm = false);

/// y = K x for displacements x (#nodes; y is zero on entry): a symmetric stiffness, positive
/// semi-definite in the directions that limit the time step.
using StiffnessProduct = std::function<void(std::span<const Vec3> x, std::span<Vec3> y)>;

struct LanczosOptions {
    int steps = 8;     ///< products per round (the Krylov dimension), >= 2
    int maxRounds = 1; ///< rounds, each restarted from the last round's Ritz vector, >= 1
    double relativeTolerance = 1e-3; ///< fewer rounds when the estimate changes less
    /// Weight in [0, 1] of the fixed pseudo-random field mixed into a non-zero start vector,
    /// so that a mode that was not the highest at the last estimate is seen (a zero start
    /// vector is replaced by that field).
    double freshFraction = 0.1;
};

struct EigenEstimate {
    double lambdaMax = 0; ///< 1/s^2; a lower bound on the true value that converges to it
    int products = 0;     ///< stiffness products used
};

/// Largest eigenvalue of M^-1 K by Lanczos on the symmetric M^-1/2 K M^-1/2 (full
/// re-orthogonalisation; the largest Ritz value of the tridiagonal matrix), restarted from its
/// Ritz vector until two rounds agree within the tolerance. mass: #nodes (zero-mass nodes are
/// left out). start (#nodes, in mass-weighted coordinates M^1/2 x): in, the start vector (all
/// zero: the fixed pseudo-random field, so the result is reproducible); out, the Ritz vector,
/// the warm start of the next estimate. Serial apart from K, so deterministic whenever K is.
EigenEstimate largestEigenvalue(const StiffnessProduct& stiffness, std::span<const double> mass,
                                std::vector<Vec3>& start, const LanczosOptions& options = {});

} // namespace resect
