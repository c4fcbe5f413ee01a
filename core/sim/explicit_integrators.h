#pragma once
// Explicit time integration kernels: one pass over the nodes each, stateless, over spans.
//
//   symplectic Euler:  v += h f(x) / m;  x += h v                     (one force evaluation)
//   velocity Verlet:   v += h/2 f(x) / m;  x += h v;  [f at new x];  v += h/2 f(x) / m
//                      (kick-drift-kick; the closing kick's forces start the next step)
// Both are symplectic and stable for h omega_max < 2, the limit stable_time_step.h estimates.
// Nodes of zero mass (not in any tet) do not move.
//
// Each pass returns the kinetic energy 1/2 sum m v^2 of the velocities it wrote, their largest
// speed, and whether every value it wrote is finite, so that divergence is detected without
// another pass. A pass given backup spans first copies the nodes' positions and velocities
// there, so the caller can restore the state of before the step.

#include "core/mesh/tet_mesh.h"

#include <span>

namespace resect {

struct NodePass {
    double kineticEnergy = 0; ///< g mm^2 / s^2
    double maxSpeed = 0;      ///< mm / s
    bool finite = true;
};

/// x, v, f, mass: #nodes. backupX, backupV: #nodes or empty. f is consumed: it is left zero,
/// ready for the next step's forces (saving the caller a pass over it).
NodePass symplecticEulerUpdate(std::span<Vec3> x, std::span<Vec3> v, std::span<Vec3> f,
                               std::span<const double> mass, double h, std::span<Vec3> backupX,
                               std::span<Vec3> backupV, int threads);

/// Verlet's opening kick and drift: v += h/2 f / m; x += h v.
NodePass verletKickDrift(std::span<Vec3> x, std::span<Vec3> v, std::span<const Vec3> f,
                         std::span<const double> mass, double h, std::span<Vec3> backupX,
                         std::span<Vec3> backupV, int threads);

/// Verlet's closing kick: v += h/2 f / m.
NodePass verletKick(std::span<Vec3> v, std::span<const Vec3> f, std::span<const double> mass,
                    double h, int threads);

/// After an implicit solve for the velocity change dv: v += dv; x += h v.
NodePass velocityChangeUpdate(std::span<Vec3> x, std::span<Vec3> v, std::span<const Vec3> dv,
                              std::span<const double> mass, double h, std::span<Vec3> backupX,
                              std::span<Vec3> backupV, int threads);

/// Kinetic energy, largest speed and finiteness of the velocities, without changing them.
NodePass measureVelocities(std::span<const Vec3> v, std::span<const double> mass, int threads);

} // namespace resect
