#pragma once
// Force kernels of the tissue model: the distance, volume and surface-area preserving
// energies of Teschner, Heidelberger, Mueller and Gross, "A Versatile and Robust Model for
// Geometrically Complex Deformable Solids" (CGI 2004; the paper's ref. [19]), with the
// stiffnesses of Eq. 4 and the masses of Eq. 3 (section 4.7). Stateless functions over spans;
// the data they read is owned by DeformationModel (deformation_model.h).
//
// Every term is a quadratic penalty on a scalar constraint C(x) with rest value C0:
//   E = 1/2 k (C(x) - C0)^2,   f_i = -dE/dx_i = -k (C - C0) dC/dx_i
//   edge (a, b):        C = |x_b - x_a|                        (distance preservation)
//   tet (p0..p3):       C = det[p1-p0, p2-p0, p3-p0] / 6       (volume preservation, signed)
//   triangle (p0..p2):  C = |(p1-p0) x (p2-p0)| / 2            (surface-area preservation)
// The rest values come from the reference positions through the same arithmetic as the
// kernels (restEdgeLength, restTetVolume6, restTriangleArea), so a mesh at rest has exactly
// zero force (this relies on identical rounding, i.e. no FMA contraction differing between
// the two; the default x86-64 build has no FMA).
//
// Volume terms are stored scaled, to spare two divisions per tet: the rest value is
// 6 V0 = det[p1-p0, p2-p0, p3-p0] and the stiffness k_v / 36, so that
// E = 1/2 (k_v / 36) (6V - 6V0)^2 = 1/2 k_v (V - V0)^2.
//
// Performance: the edge and volume kernels run two terms per SSE2 instruction (Eigen's
// Array2d or intrinsics; the arithmetic of each lane is the scalar arithmetic), then scatter
// each term's forces. About 5 ns per edge and 9 ns per tet on one core of the 2-core
// benchmark machine (resect bench sim), compute-bound.
//
// The differentials are the Gauss-Newton part of the Hessian, k dC/dx dC/dx^T, plus for the
// edges the transverse term k max(0, 1 - l0/l) (I - n n^T): symmetric negative semi-definite
// force differentials, exact at rest (where C = C0), as the implicit integrator needs.
//
// Units: positions in mm, stiffnesses such that forces are in g mm / s^2 (see material.h).
// Each kernel accumulates into a ForceWindow and returns the energy of the terms it ran.

#include "core/mesh/tet_mesh.h"

#include <array>
#include <cmath>
#include <span>

namespace resect {

using Edge = std::array<int, 2>;

/// A per-node accumulator covering nodes [first, first + values.size()): a thread's private
/// window of the force array (see DeformationEffect), or the whole array with first = 0.
struct ForceWindow {
    std::span<Vec3> values;
    int first = 0;
    Vec3& operator[](int node) const { return values[static_cast<std::size_t>(node - first)]; }
};

// --- rest values: the constraint functions, shared by the kernels -------------------------
double restEdgeLength(const Vec3& a, const Vec3& b);
/// 6 V0 = det[p1-p0, p2-p0, p3-p0] (signed).
double restTetVolume6(const Vec3& p0, const Vec3& p1, const Vec3& p2, const Vec3& p3);
double restTriangleArea(const Vec3& p0, const Vec3& p1, const Vec3& p2);

// --- forces and energies ------------------------------------------------------------------
/// Distance preservation. edges, restLength, stiffness: #edges. x: #nodes positions.
/// A term with restLength 0 and stiffness 0 (a free slot) contributes nothing.
double addEdgeForces(std::span<const Edge> edges, std::span<const double> restLength,
                     std::span<const double> stiffness, std::span<const Vec3> x, ForceWindow f);

/// Volume preservation. tets, restVolume6 (6 V0, signed), stiffness36 (k_v / 36): #tets.
double addVolumeForces(std::span<const Tet> tets, std::span<const double> restVolume6,
                       std::span<const double> stiffness36, std::span<const Vec3> x, ForceWindow f);

/// Surface-area preservation. triangles, restArea, stiffness: #triangles. A triangle of zero
/// current area has no defined gradient and contributes its energy but no force.
double addAreaForces(std::span<const Tri> triangles, std::span<const double> restArea,
                     std::span<const double> stiffness, std::span<const Vec3> x, ForceWindow f);

// --- force differentials df = (df/dx) dx (Gauss-Newton, see above) -----------------------
void addEdgeForceDifferential(std::span<const Edge> edges, std::span<const double> restLength,
                              std::span<const double> stiffness, std::span<const Vec3> x,
                              std::span<const Vec3> dx, ForceWindow df);
void addVolumeForceDifferential(std::span<const Tet> tets, std::span<const double> stiffness36,
                                std::span<const Vec3> x, std::span<const Vec3> dx, ForceWindow df);
void addAreaForceDifferential(std::span<const Tri> triangles, std::span<const double> stiffness,
                              std::span<const Vec3> x, std::span<const Vec3> dx, ForceWindow df);

/// diag += the diagonal of -(df/dx) (per node, per coordinate; for Jacobi preconditioning).
void addEdgeStiffnessDiagonal(std::span<const Edge> edges, std::span<const double> restLength,
                              std::span<const double> stiffness, std::span<const Vec3> x,
                              ForceWindow diag);
void addVolumeStiffnessDiagonal(std::span<const Tet> tets, std::span<const double> stiffness36,
                                std::span<const Vec3> x, ForceWindow diag);
void addAreaStiffnessDiagonal(std::span<const Tri> triangles, std::span<const double> stiffness,
                              std::span<const Vec3> x, ForceWindow diag);

} // namespace resect
