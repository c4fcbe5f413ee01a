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
    int maxIterations = 400;
    double relativeTolerance = 1e-7;
    bool areaTerm = false;  ///< include the surface-area term (core/sim's default model has it)
};

/// Needs masses (computeLumpedMasses). Nodes with zero mass are ignored.
StableTimeStep stableTimeStep(const TetMesh& mesh, const Material& material,
                              const StableTimeStepOptions& options = {});

/// The linearised stiffness operator y = K x at the reference configuration (x, y: #nodes
/// displacements). Exposed so that tests can run the linear model the estimate is about.
void applyRestStiffness(const TetMesh& mesh, const Material& material,
                        std::span<const Vec3> x, std::span<Vec3> y, bool areaTerm = false);

} // namespace resect
