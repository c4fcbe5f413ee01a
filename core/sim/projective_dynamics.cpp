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

/// Terms (local step) and free nodes (right-hand side) per thread at least: below, the
/// fork-join costs more than it saves.
constexpr std::int64_t kLocalGrain = 32768, kNodeGrain = 8192;
constexpr int kMaxThreads = 256;
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
    /// Coupling of free rows to held nodes: rhs[row] -= value * x[node].
    struct Coupling {
        int row, node;
        double value;
    };
    std::vector<Coupling> coupling;
    Eigen::SparseMatrix<double> matrix;
    Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> solver;

    // The terms (live ones only).
    std::vector<Edge> edges;
    std::vector<double> edgeRest, edgeW;
    std::vector<Tet> tets;
    std::vector<double> tetRest6, tetW, tetInvGG0; ///< 6 V0, w, 1 / sum |G|^2 at rest
    std::vector<Tri> tris;
    std::vector<double> triRest, triW, triInvGG0;

    /// Projections, w A^T p, per term and node, stored by node (node i sums the contiguous
    /// slots [slotBegin[i], slotBegin[i + 1])): the local step scatters its writes, the
    /// right-hand side reads in order. slot[]: per term and node (edges 2, tets 4, triangles
    /// 3 consecutive entries, from tetBase and triBase), the slot it writes.
    std::vector<Vec3> contribution;
    std::size_t tetBase = 0, triBase = 0;
    std::vector<int> slotBegin, slot;

    /// The factor P A P^T = L D L^T, copied out of Eigen for a solve of all three coordinates
    /// at once (one pass over L per triangular solve instead of three).
    std::vector<int> lBegin, lRow, perm;
    std::vector<double> lValue, inverseD;

    std::vector<Vec3> rhs, work, previous; ///< rows
    std::vector<Vec3> y, x0;

    /// The volume term i's projection (see the header), in plain arithmetic: with
    /// G_k = 6 grad_k V and D = 6 V, p_k = y_k - (D - 6 V0) / sum |G0|^2 G_k. Writes w p_k to
    /// the nodes' slots; returns twice the term's energy, w (D - 6 V0)^2 / sum |G0|^2.
    double projectTet(std::int64_t i, std::span<const Vec3> x) {
        const Tet& q = tets[i];
        const Vec3 &x0 = x[q[0]], &x1 = x[q[1]], &x2 = x[q[2]], &x3 = x[q[3]];
        const double e1x = x1.x() - x0.x(), e1y = x1.y() - x0.y(), e1z = x1.z() - x0.z();
        const double e2x = x2.x() - x0.x(), e2y = x2.y() - x0.y(), e2z = x2.z() - x0.z();
        const double e3x = x3.x() - x0.x(), e3y = x3.y() - x0.y(), e3z = x3.z() - x0.z();
        const double g1x = e2y * e3z - e2z * e3y, g1y = e2z * e3x - e2x * e3z, g1z = e2x * e3y - e2y * e3x;
        const double g2x = e3y * e1z - e3z * e1y, g2y = e3z * e1x - e3x * e1z, g2z = e3x * e1y - e3y * e1x;
        const double g3x = e1y * e2z - e1z * e2y, g3y = e1z * e2x - e1x * e2z, g3z = e1x * e2y - e1y * e2x;
        const double g0x = -(g1x + g2x + g3x), g0y = -(g1y + g2y + g3y), g0z = -(g1z + g2z + g3z);
        const double det = g3x * e3x + g3y * e3y + g3z * e3z;
        const double residual = det - tetRest6[i];
        const double mu = residual * tetInvGG0[i];
        const double w = tetW[i];
        const double cx = 0.25 * (x0.x() + x1.x() + x2.x() + x3.x());
        const double cy = 0.25 * (x0.y() + x1.y() + x2.y() + x3.y());
        const double cz = 0.25 * (x0.z() + x1.z() + x2.z() + x3.z());
        const std::int64_t base = tetBase + 4 * i;
        contribution[slot[base]] = w * Vec3(x0.x() - cx - mu * g0x, x0.y() - cy - mu * g0y, x0.z() - cz - mu * g0z);
        contribution[slot[base + 1]] = w * Vec3(x1.x() - cx - mu * g1x, x1.y() - cy - mu * g1y, x1.z() - cz - mu * g1z);
        contribution[slot[base + 2]] = w * Vec3(x2.x() - cx - mu * g2x, x2.y() - cy - mu * g2y, x2.z() - cz - mu * g2z);
        contribution[slot[base + 3]] = w * Vec3(x3.x() - cx - mu * g3x, x3.y() - cy - mu * g3y, x3.z() - cz - mu * g3z);
        return w * mu * residual;  // w |mu G|^2 = w mu^2 gg = w mu residual
    }

    /// The area term i's projection, likewise (with G_k = 2 grad_k A and the doubled area |n|:
    /// p_k = y_k - (|n| - 2 A0) / sum |G0|^2 G_k). A degenerate triangle projects to itself.
    double projectTriangle(std::int64_t i, std::span<const Vec3> x) {
        const Tri& q = tris[i];
        const Vec3 &x0 = x[q[0]], &x1 = x[q[1]], &x2 = x[q[2]];
        const double ax = x1.x() - x0.x(), ay = x1.y() - x0.y(), az = x1.z() - x0.z();
        const double bx = x2.x() - x0.x(), by = x2.y() - x0.y(), bz = x2.z() - x0.z();
        const double nx = ay * bz - az * by, ny = az * bx - ax * bz, nz = ax * by - ay * bx;
        const double len = std::sqrt(nx * nx + ny * ny + nz * nz);
        const double inv = len > 0 ? 1 / len : 0.0;
        const double ux = nx * inv, uy = ny * inv, uz = nz * inv;
        const double g1x = by * uz - bz * uy, g1y = bz * ux - bx * uz, g1z = bx * uy - by * ux;
        const double g2x = uy * az - uz * ay, g2y = uz * ax - ux * az, g2z = ux * ay - uy * ax;
        const double g0x = -(g1x + g2x), g0y = -(g1y + g2y), g0z = -(g1z + g2z);
        const double residual = len - 2 * triRest[i];
        const double mu = len > 0 ? residual * triInvGG0[i] : 0.0;
        const double w = triW[i];
        const double cx = (x0.x() + x1.x() + x2.x()) / 3, cy = (x0.y() + x1.y() + x2.y()) / 3,
                     cz = (x0.z() + x1.z() + x2.z()) / 3;
        const std::int64_t base = triBase + 3 * i;
        contribution[slot[base]] = w * Vec3(x0.x() - cx - mu * g0x, x0.y() - cy - mu * g0y, x0.z() - cz - mu * g0z);
        contribution[slot[base + 1]] = w * Vec3(x1.x() - cx - mu * g1x, x1.y() - cy - mu * g1y, x1.z() - cz - mu * g1z);
        contribution[slot[base + 2]] = w * Vec3(x2.x() - cx - mu * g2x, x2.y() - cy - mu * g2y, x2.z() - cz - mu * g2z);
        return w * mu * residual;
    }

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

    // Live terms and their weights (see the header).
    d.edges.clear(), d.edgeRest.clear(), d.edgeW.clear();
    d.tets.clear(), d.tetRest6.clear(), d.tetW.clear(), d.tetInvGG0.clear();
    d.tris.clear(), d.triRest.clear(), d.triW.clear(), d.triInvGG0.clear();
    {
        const auto e = model.edges();
        const auto rest = model.edgeRestLength();
        const auto k = model.edgeStiffness();
        for (std::size_t i = 0; i < e.size(); ++i)
            if (k[i] > 0) {
                d.edges.push_back(e[i]);
                d.edgeRest.push_back(rest[i]);
                d.edgeW.push_back(k[i]);
            }
    }
    if (model.terms().volume) {
        const auto rest6 = model.tetRestVolume6();
        const auto k36 = model.tetStiffness36();
        for (int t = 0; t < mesh.tetCount() && t < static_cast<int>(k36.size()); ++t) {
            if (!(k36[t] > 0))
                continue;
            const Tet& q = mesh.tet(t);
            Vec3 p[4], g[4];
            for (int k = 0; k < 4; ++k)
                p[k] = mesh.ref(q[k]);
            tetVolumeGradient(p, g);
            double gg = 0;
            for (const Vec3& v : g)
                gg += v.squaredNorm();
            d.tets.push_back(q);
            d.tetRest6.push_back(rest6[t]);
            d.tetW.push_back(36 * k36[t] * gg);
            d.tetInvGG0.push_back(1 / (36 * gg)); // G = 6 grad V
        }
    }
    if (model.terms().area) {
        const auto tr = model.triangles();
        const auto rest = model.triangleRestArea();
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
            d.tris.push_back(tr[i]);
            d.triRest.push_back(rest[i]);
            d.triW.push_back(k[i] * gg);
            d.triInvGG0.push_back(1 / (4 * gg)); // G = 2 grad A
        }
    }

    // The matrix M / h^2 + sum w A^T A over all nodes, split into free x free and free x held.
    std::vector<Eigen::Triplet<double>> entries;
    d.coupling.clear();
    d.inertia.assign(rows, 0);
    const auto add = [&](int a, int b, double value) {
        const int ra = d.freeIndex[a];
        if (ra < 0)
            return;
        const int rb = d.freeIndex[b];
        if (rb >= 0)
            entries.emplace_back(ra, rb, value);
        else
            d.coupling.push_back({ra, b, value});
    };
    for (int r = 0; r < rows; ++r) {
        d.inertia[r] = mass[d.freeNodes[r]] / (h * h);
        entries.emplace_back(r, r, d.inertia[r]);
    }
    for (std::size_t i = 0; i < d.edges.size(); ++i) {
        const auto [a, b] = d.edges[i];
        const double w = d.edgeW[i];
        add(a, a, w), add(b, b, w), add(a, b, -w), add(b, a, -w);
    }
    const auto addCentred = [&](const int* nodes, int count, double w) {
        // w (I - J / count): the centring operator is a projector, so A^T A = A.
        for (int i = 0; i < count; ++i)
            for (int j = 0; j < count; ++j)
                add(nodes[i], nodes[j], w * ((i == j ? 1.0 : 0.0) - 1.0 / count));
    };
    for (std::size_t i = 0; i < d.tets.size(); ++i)
        addCentred(d.tets[i].data(), 4, d.tetW[i]);
    for (std::size_t i = 0; i < d.tris.size(); ++i)
        addCentred(d.tris[i].data(), 3, d.triW[i]);
    d.matrix.resize(rows, rows);
    d.matrix.setFromTriplets(entries.begin(), entries.end());
    d.solver.compute(d.matrix);
    if (d.solver.info() != Eigen::Success)
        return Status::error("projective dynamics: the system matrix (" + std::to_string(rows) +
                             " free nodes) could not be factored");
    {
        // Eigen's LDL^T keeps L's strictly lower part by columns and D apart.
        const auto& l = d.solver.matrixL().nestedExpression();
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
        const auto& diag = d.solver.vectorD();
        d.inverseD.resize(rows);
        for (int i = 0; i < rows; ++i)
            d.inverseD[i] = 1 / diag[i];
        const auto& indices = d.solver.permutationP().indices();
        d.perm.assign(indices.data(), indices.data() + rows);
    }

    // Contribution slots and, per node, the slots it sums.
    d.tetBase = 2 * d.edges.size();
    d.triBase = d.tetBase + 4 * d.tets.size();
    d.contribution.assign(d.triBase + 3 * d.tris.size(), Vec3::Zero());
    std::vector<int> count(n + 1, 0);
    for (const Edge& e : d.edges)
        ++count[e[0] + 1], ++count[e[1] + 1];
    for (const Tet& q : d.tets)
        for (int v : q)
            ++count[v + 1];
    for (const Tri& t : d.tris)
        for (int v : t)
            ++count[v + 1];
    for (int i = 0; i < n; ++i)
        count[i + 1] += count[i];
    d.slotBegin = count;
    d.slot.assign(count[n], 0);
    std::vector<int> fill(count.begin(), count.end() - 1);
    for (std::size_t i = 0; i < d.edges.size(); ++i)
        for (int k = 0; k < 2; ++k)
            d.slot[2 * i + k] = fill[d.edges[i][k]]++;
    for (std::size_t i = 0; i < d.tets.size(); ++i)
        for (int k = 0; k < 4; ++k)
            d.slot[d.tetBase + 4 * i + k] = fill[d.tets[i][k]]++;
    for (std::size_t i = 0; i < d.tris.size(); ++i)
        for (int k = 0; k < 3; ++k)
            d.slot[d.triBase + 3 * i + k] = fill[d.tris[i][k]]++;

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
                                std::span<Vec3> backupX, std::span<Vec3> backupV) {
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

    const auto edgeCount = static_cast<std::int64_t>(d.edges.size());
    const auto tetCount = static_cast<std::int64_t>(d.tets.size());
    const auto triCount = static_cast<std::int64_t>(d.tris.size());
    const int localThreads = std::min(kMaxThreads, threadsFor(threads, edgeCount + tetCount + triCount, kLocalGrain));
    const int nodeThreads = threadsFor(threads, rows, kNodeGrain);
    double partial[kMaxThreads] = {};
    // Local: every term's projection at x, w A^T p into its slots; returns the backward-Euler
    // objective 1/(2 h^2) |x - y|_M^2 + E(x) (E the model's energy, exact: see the header).
    const auto local = [&]() {
        parallelRun(localThreads, [&](int t) {
            double energy = 0;
            for (auto i = chunkBegin(edgeCount, localThreads, t); i < chunkBegin(edgeCount, localThreads, t + 1); ++i) {
                const auto [a, b] = d.edges[i];
                const Vec3 e = x[b] - x[a];
                const double len = e.norm();
                const Vec3 p = len > 0 ? Vec3(e * (d.edgeRest[i] / len)) : e;
                energy += d.edgeW[i] * (len - d.edgeRest[i]) * (len - d.edgeRest[i]);
                d.contribution[d.slot[2 * i]] = -d.edgeW[i] * p;
                d.contribution[d.slot[2 * i + 1]] = d.edgeW[i] * p;
            }
            for (auto i = chunkBegin(tetCount, localThreads, t); i < chunkBegin(tetCount, localThreads, t + 1); ++i)
                energy += d.projectTet(i, x);
            for (auto i = chunkBegin(triCount, localThreads, t); i < chunkBegin(triCount, localThreads, t + 1); ++i)
                energy += d.projectTriangle(i, x);
            partial[t] = energy / 2;
        });
        m_energy = 0;
        for (int t = 0; t < localThreads; ++t)
            m_energy += partial[t];
        double inertial = 0;
        for (int r = 0; r < rows; ++r) {
            const int i = d.freeNodes[r];
            inertial += d.inertia[r] * (x[i] - d.y[i]).squaredNorm();
        }
        return inertial / 2 + m_energy;
    };
    // Safeguard: an iterate that raises the objective (far from rest, where the fixed matrix
    // underestimates the model's stiffness) is pulled back halfway towards the previous one,
    // so the objective never grows and the step cannot blow up.
    d.previous.resize(rows);
    double objective = std::numeric_limits<double>::infinity();
    // The start x + h v; where it is worse than staying at x (objective 1/2 |v + h a|_M^2 +
    // E(x), E from the end of the last step), x: then no step can end with more potential
    // energy than the total before it (plus the external forces' work).
    if (m_lastEnergy < 0) { // (the first step after a preparation)
        local();
        m_lastEnergy = m_energy;
    }
    for (int r = 0; r < rows; ++r)
        x[d.freeNodes[r]] += h * v[d.freeNodes[r]];
    double g = local();
    {
        double stay = m_lastEnergy;
        for (int r = 0; r < rows; ++r) {
            const int i = d.freeNodes[r];
            stay += mass[i] / 2 * (v[i] + (h / mass[i]) * fext[i]).squaredNorm();
        }
        if (g > stay) {
            for (int r = 0; r < rows; ++r)
                x[d.freeNodes[r]] = d.x0[d.freeNodes[r]];
            g = local();
            ++m_stats.restarts;
        }
    }
    for (int it = 0; it <= options.iterations; ++it) {
        if (it > 0)
            g = local();
        for (int halving = 0; halving < kMaxHalvings && g > objective; ++halving) {
            for (int r = 0; r < rows; ++r)
                x[d.freeNodes[r]] = (x[d.freeNodes[r]] + d.previous[r]) / 2;
            g = local();
            ++m_stats.halvings;
        }
        if (it == options.iterations)
            break; // the last iterate checked
        objective = std::min(objective, g);
        for (int r = 0; r < rows; ++r)
            d.previous[r] = x[d.freeNodes[r]];
        // Global: right-hand side per free node (gathered, no races), then the solve.
        parallelRun(nodeThreads, [&](int t) {
            for (auto r = chunkBegin(rows, nodeThreads, t); r < chunkBegin(rows, nodeThreads, t + 1); ++r) {
                const int i = d.freeNodes[r];
                Vec3 b = d.inertia[r] * d.y[i];
                for (int s = d.slotBegin[i]; s < d.slotBegin[i + 1]; ++s)
                    b += d.contribution[s];
                d.rhs[r] = b;
            }
        });
        for (const Impl::Coupling& c : d.coupling)
            d.rhs[c.row] -= c.value * x[c.node];
        d.solve(d.rhs);
        for (int r = 0; r < rows; ++r)
            x[d.freeNodes[r]] = d.rhs[r];
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
