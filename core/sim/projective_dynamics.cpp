#include "core/sim/projective_dynamics.h"

#include "core/sim/deformation_model.h"
#include "core/sim/parallel.h"

#include <Eigen/SparseCholesky>
#include <Eigen/SparseCore>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <utility>

namespace resect {
namespace {

using Clock = std::chrono::steady_clock;

/// Free nodes per thread at least (right-hand side): below, the fork-join costs more than it
/// saves.
constexpr std::int64_t kNodeGrain = 8192;
/// Halvings of an iterate that raised the objective, at most.
constexpr int kMaxHalvings = 10;

/// The tet's volume and its gradient (for the weights).
inline double tetVolumeGradient(const Vec3* p, Vec3* g) {
    const Vec3 e1 = p[1] - p[0], e2 = p[2] - p[0], e3 = p[3] - p[0];
    g[1] = e2.cross(e3) / 6;
    g[2] = e3.cross(e1) / 6;
    g[3] = e1.cross(e2) / 6;
    g[0] = -(g[1] + g[2] + g[3]);
    return g[3].dot(e3);
}

/// Area of the triangle and its gradient; false where the triangle is degenerate.
inline bool triangleAreaGradient(const Vec3* p, double& area, Vec3* g) {
    const Vec3 a = p[1] - p[0], b = p[2] - p[0];
    const Vec3 n = a.cross(b);
    const double len = n.norm();
    area = len / 2;
    if (!(len > 0))
        return false;
    const Vec3 u = n / len;
    g[1] = b.cross(u) / 2;
    g[2] = u.cross(a) / 2;
    g[0] = -(g[1] + g[2]);
    return true;
}

} // namespace

struct ProjectiveDynamics::Impl {
    int nodes = 0;
    std::vector<int> freeIndex; ///< node -> row, -1 if held
    std::vector<int> freeNodes; ///< row -> node
    std::vector<char> fixed;    ///< as given at the last preparation
    std::vector<double> inertia; ///< m / h^2 per row
    /// The factor P A P^T = L D L^T, copied out of Eigen for a solve of all three coordinates
    /// at once (one pass over L per triangular solve instead of three).
    std::vector<int> lBegin, lRow, perm;
    std::vector<double> lValue, inverseD;

    std::vector<Vec3> rhs, work, previous; ///< rows
    std::vector<Vec3> y, x0, force;

    /// rhs -> solution in place (rows entries).
    void solve(std::vector<Vec3>& b) {
        const int rows = static_cast<int>(perm.size());
        work.resize(rows);
        for (int i = 0; i < rows; ++i)
            work[perm[i]] = b[i];
        for (int j = 0; j < rows; ++j) {  // L z = P b (unit lower, by columns)
            const Vec3 zj = work[j];
            for (int p = lBegin[j]; p < lBegin[j + 1]; ++p)
                work[lRow[p]] -= lValue[p] * zj;
        }
        for (int j = 0; j < rows; ++j)
            work[j] *= inverseD[j];
        for (int j = rows - 1; j >= 0; --j) {  // L^T w = z
            Vec3 wj = work[j];
            for (int p = lBegin[j]; p < lBegin[j + 1]; ++p)
                wj -= lValue[p] * work[lRow[p]];
            work[j] = wj;
        }
        for (int i = 0; i < rows; ++i)
            b[i] = work[perm[i]];
    }
};

ProjectiveDynamics::ProjectiveDynamics() : m_impl(std::make_unique<Impl>()) {}
ProjectiveDynamics::~ProjectiveDynamics() = default;

Status ProjectiveDynamics::prepare(const TetMesh& mesh, const DeformationModel& model,
                                   std::span<const char> fixed, double h) {
    const auto t0 = Clock::now();
    Impl& d = *m_impl;
    const int n = mesh.nodeCount();
    d.nodes = n;
    d.fixed.assign(fixed.begin(), fixed.end());
    const auto mass = mesh.masses();
    d.freeIndex.assign(n, -1);
    d.freeNodes.clear();
    for (int i = 0; i < n; ++i)
        if (!fixed[i] && mass[i] > 0) {
            d.freeIndex[i] = static_cast<int>(d.freeNodes.size());
            d.freeNodes.push_back(i);
        }
    const int rows = static_cast<int>(d.freeNodes.size());

    // The matrix M / h^2 + sum w A^T A over the free nodes (held ones: their rows and columns
    // are dropped; the solve is for a change of the free nodes only). Weights: see the header.
    std::vector<Eigen::Triplet<double>> entries;
    d.inertia.assign(rows, 0);
    const auto add = [&](int a, int b, double value) {
        const int ra = d.freeIndex[a], rb = d.freeIndex[b];
        if (ra >= 0 && rb >= 0)
            entries.emplace_back(ra, rb, value);
    };
    for (int r = 0; r < rows; ++r) {
        d.inertia[r] = mass[d.freeNodes[r]] / (h * h);
        entries.emplace_back(r, r, d.inertia[r]);
    }
    {
        const auto e = model.edges();
        const auto k = model.edgeStiffness();
        for (std::size_t i = 0; i < e.size(); ++i)
            if (k[i] > 0) {
                const auto [a, b] = e[i];
                add(a, a, k[i]), add(b, b, k[i]), add(a, b, -k[i]), add(b, a, -k[i]);
            }
    }
    const auto addCentred = [&](const int* nodes, int count, double w) {
        // w (I - J / count): the centring operator is a projector, so A^T A = A.
        for (int i = 0; i < count; ++i)
            for (int j = 0; j < count; ++j)
                add(nodes[i], nodes[j], w * ((i == j ? 1.0 : 0.0) - 1.0 / count));
    };
    if (model.terms().volume) {
        const auto k36 = model.tetStiffness36();
        for (int t = 0; t < mesh.tetCount() && t < static_cast<int>(k36.size()); ++t) {
            if (!(k36[t] > 0))
                continue;
            const Tet& q = mesh.tet(t);
            Vec3 p[4], g[4];
            for (int c = 0; c < 4; ++c)
                p[c] = mesh.ref(q[c]);
            tetVolumeGradient(p, g);
            double gg = 0;
            for (const Vec3& v : g)
                gg += v.squaredNorm();
            addCentred(q.data(), 4, 36 * k36[t] * gg);
        }
    }
    if (model.terms().area) {
        const auto tr = model.triangles();
        const auto k = model.triangleStiffness();
        for (std::size_t i = 0; i < tr.size(); ++i) {
            if (!(k[i] > 0))
                continue;
            Vec3 p[3], g[3];
            for (int c = 0; c < 3; ++c)
                p[c] = mesh.ref(tr[i][c]);
            double area = 0;
            if (!triangleAreaGradient(p, area, g))
                continue;
            double gg = 0;
            for (const Vec3& v : g)
                gg += v.squaredNorm();
            addCentred(tr[i].data(), 3, k[i] * gg);
        }
    }
    // Factored by Eigen, then copied out (L, D, P): Eigen's copy and the matrix are freed.
    Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> solver;
    {
        Eigen::SparseMatrix<double> matrix(rows, rows);
        matrix.setFromTriplets(entries.begin(), entries.end());
        entries = {};
        solver.compute(matrix);
    }
    if (solver.info() != Eigen::Success)
        return Status::error("projective dynamics: the system matrix (" + std::to_string(rows) +
                             " free nodes) could not be factored");
    {
        // Eigen's LDL^T keeps L's strictly lower part by columns and D apart.
        const auto& l = solver.matrixL().nestedExpression();
        d.lBegin.assign(l.outerIndexPtr(), l.outerIndexPtr() + rows + 1);
        d.lRow.clear(), d.lValue.clear();
        d.lRow.reserve(l.nonZeros()), d.lValue.reserve(l.nonZeros());
        for (int j = 0; j < rows; ++j) {
            const int begin = l.outerIndexPtr()[j];
            const int end = l.isCompressed() ? l.outerIndexPtr()[j + 1] : begin + l.innerNonZeroPtr()[j];
            d.lBegin[j] = static_cast<int>(d.lRow.size());
            for (int p = begin; p < end; ++p)
                if (l.innerIndexPtr()[p] > j) {
                    d.lRow.push_back(l.innerIndexPtr()[p]);
                    d.lValue.push_back(l.valuePtr()[p]);
                }
        }
        d.lBegin[rows] = static_cast<int>(d.lRow.size());
        const auto& diag = solver.vectorD();
        d.inverseD.resize(rows);
        for (int i = 0; i < rows; ++i)
            d.inverseD[i] = 1 / diag[i];
        const auto& indices = solver.permutationP().indices();
        d.perm.assign(indices.data(), indices.data() + rows);
    }

    d.rhs.resize(rows);
    m_h = h;
    m_valid = true;
    m_lastEnergy = -1; // unknown until a step ends
    m_stats.factorMs = std::chrono::duration<double, std::milli>(Clock::now() - t0).count();
    ++m_stats.factorizations;
    m_stats.unknowns = rows;
    m_stats.nonZeros = static_cast<double>(d.lRow.size());
    return Status::success();
}

Status ProjectiveDynamics::step(TetMesh& mesh, const DeformationModel& model,
                                std::span<const char> fixed, std::span<const Vec3> fext, double h,
                                const ProjectiveDynamicsOptions& options, int threads,
                                std::span<Vec3> backupX, std::span<Vec3> backupV, const Forces& forces) {
    Impl& d = *m_impl;
    const int n = mesh.nodeCount();
    if (!m_valid || m_h != h || d.nodes != n || !std::equal(fixed.begin(), fixed.end(), d.fixed.begin(), d.fixed.end()))
        if (Status s = prepare(mesh, model, fixed, h); !s.ok())
            return s;
    const std::span<Vec3> x = mesh.positions(), v = mesh.velocities();
    const std::span<const double> mass = std::as_const(mesh).masses();
    if (!backupX.empty()) {
        std::copy(x.begin(), x.end(), backupX.begin());
        std::copy(v.begin(), v.end(), backupV.begin());
    }
    const int rows = static_cast<int>(d.freeNodes.size());
    d.y.resize(n);
    d.x0.assign(x.begin(), x.end());
    for (int r = 0; r < rows; ++r) {
        const int i = d.freeNodes[r];
        d.y[i] = x[i] + h * v[i] + (h * h / mass[i]) * fext[i];
    }

    // The model's forces and energy at x (the deformation effect's kernels), and the
    // backward-Euler objective 1/(2 h^2) |x - y|_M^2 + E(x).
    d.force.resize(n);
    const auto evaluate = [&]() {
        std::fill(d.force.begin(), d.force.end(), Vec3::Zero());
        m_energy = forces(x, d.force);
        double inertial = 0;
        for (int r = 0; r < rows; ++r) {
            const int i = d.freeNodes[r];
            inertial += d.inertia[r] * (x[i] - d.y[i]).squaredNorm();
        }
        return inertial / 2 + m_energy;
    };
    if (m_lastEnergy < 0) { // (the first step after a preparation)
        evaluate();
        m_lastEnergy = m_energy;
    }
    // The start x + h v; where it is worse than staying at x (objective 1/2 |v + h a|_M^2 +
    // E(x), E from the end of the last step), x: then no step can end with more potential
    // energy than the total before it (plus the external forces' work).
    for (int r = 0; r < rows; ++r)
        x[d.freeNodes[r]] += h * v[d.freeNodes[r]];
    double g = evaluate();
    {
        double stay = m_lastEnergy;
        for (int r = 0; r < rows; ++r) {
            const int i = d.freeNodes[r];
            stay += mass[i] / 2 * (v[i] + (h / mass[i]) * fext[i]).squaredNorm();
        }
        if (g > stay + 1e-12 * std::abs(stay)) { // (beyond rounding: with v = 0 both are the same point)
            for (int r = 0; r < rows; ++r)
                x[d.freeNodes[r]] = d.x0[d.freeNodes[r]];
            g = evaluate();
            ++m_stats.restarts;
        }
    }
    // Iterations: x += (M / h^2 + L)^-1 (M / h^2 (y - x) + f(x)), the local-global step of
    // projective dynamics written with the model's forces (see the header). Safeguard: an
    // iterate that raises the objective (far from rest, where the fixed matrix underestimates
    // the model's stiffness) is pulled back halfway towards the previous one, so the objective
    // never grows and the step cannot blow up.
    d.previous.resize(rows);
    double objective = std::numeric_limits<double>::infinity();
    const int nodeThreads = threadsFor(threads, rows, kNodeGrain);
    for (int it = 0; it <= options.iterations; ++it) {
        if (it > 0)
            g = evaluate();
        for (int halving = 0; halving < kMaxHalvings && g > objective; ++halving) {
            for (int r = 0; r < rows; ++r)
                x[d.freeNodes[r]] = (x[d.freeNodes[r]] + d.previous[r]) / 2;
            g = evaluate();
            ++m_stats.halvings;
        }
        if (it == options.iterations)
            break; // the last iterate checked
        objective = std::min(objective, g);
        parallelRun(nodeThreads, [&](int t) {
            for (auto r = chunkBegin(rows, nodeThreads, t); r < chunkBegin(rows, nodeThreads, t + 1); ++r) {
                const int i = d.freeNodes[r];
                d.previous[r] = x[i];
                d.rhs[r] = d.inertia[r] * (d.y[i] - x[i]) + d.force[i];
            }
        });
        d.solve(d.rhs);
        for (int r = 0; r < rows; ++r)
            x[d.freeNodes[r]] += d.rhs[r];
    }
    const double invH = 1 / h;
    for (int r = 0; r < rows; ++r) {
        const int i = d.freeNodes[r];
        v[i] = (x[i] - d.x0[i]) * invH;
    }
    m_lastEnergy = m_energy;
    return Status::success();
}

} // namespace resect
