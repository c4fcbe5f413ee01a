#include "core/mesh/stable_time_step.h"

#include "core/mesh/topology.h"

#include <Eigen/Eigenvalues>
#include <Eigen/Geometry>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

namespace resect {
namespace {

/// The linearised model of stable_time_step.h, precomputed once per estimate.
struct RestStiffness {
    std::vector<std::array<int, 2>> edges;
    std::vector<Vec3> edgeDir;        ///< unit direction per edge
    std::vector<double> edgeK;        ///< k_s per edge (Eq. 4)
    std::vector<std::array<Vec3, 4>> tetGrad;  ///< dV/dp_i per tet
    std::vector<double> tetK;         ///< k_v per tet (Eq. 4)
    std::vector<Tri> tris;            ///< boundary triangles (area term only)
    std::vector<std::array<Vec3, 3>> triGrad;  ///< dA/dp_i per triangle
    std::vector<double> triK;         ///< k_a per triangle
};

RestStiffness buildRestStiffness(const TetMesh& mesh, const Material& material, bool areaTerm) {
    RestStiffness s;
    const auto m = mesh.masses();
    s.edges = uniqueEdges(mesh);
    s.edgeDir.resize(s.edges.size());
    s.edgeK.resize(s.edges.size());
    for (std::size_t e = 0; e < s.edges.size(); ++e) {
        const auto [a, b] = s.edges[e];
        const Vec3 d = mesh.ref(b) - mesh.ref(a);
        const double l2 = d.squaredNorm();
        s.edgeDir[e] = l2 > 0 ? Vec3(d / std::sqrt(l2)) : Vec3::Zero();
        s.edgeK[e] = l2 > 0 ? material.stiffness * (m[a] + m[b]) / l2 : 0.0;
    }
    s.tetGrad.resize(mesh.tetCount());
    s.tetK.resize(mesh.tetCount());
    for (int t = 0; t < mesh.tetCount(); ++t) {
        const Tet& q = mesh.tet(t);
        const Vec3 &p0 = mesh.ref(q[0]), &p1 = mesh.ref(q[1]), &p2 = mesh.ref(q[2]),
                   &p3 = mesh.ref(q[3]);
        // V = (p1-p0) . ((p2-p0) x (p3-p0)) / 6; gradients by cyclic permutation.
        std::array<Vec3, 4> g;
        g[1] = (p2 - p0).cross(p3 - p0) / 6.0;
        g[2] = (p3 - p0).cross(p1 - p0) / 6.0;
        g[3] = (p1 - p0).cross(p2 - p0) / 6.0;
        g[0] = -(g[1] + g[2] + g[3]);
        s.tetGrad[t] = g;
        const double v0 = mesh.referenceVolume(t);
        const double msum = m[q[0]] + m[q[1]] + m[q[2]] + m[q[3]];
        s.tetK[t] = v0 != 0 ? material.stiffness * msum / (v0 * v0) : 0.0;
    }
    if (areaTerm) {
        for (const BoundaryFace& f : boundaryFaces(mesh)) {
            const Vec3 &p0 = mesh.ref(f.nodes[0]), &p1 = mesh.ref(f.nodes[1]),
                       &p2 = mesh.ref(f.nodes[2]);
            const Vec3 n = (p1 - p0).cross(p2 - p0);
            const double a0 = 0.5 * n.norm();
            if (!(a0 > 0))
                continue;
            const Vec3 h = n / (4 * a0);  // unit normal / 2
            s.tris.push_back(f.nodes);
            s.triGrad.push_back({h.cross(p2 - p1), h.cross(p0 - p2), h.cross(p1 - p0)});
            s.triK.push_back(material.stiffness *
                             (m[f.nodes[0]] + m[f.nodes[1]] + m[f.nodes[2]]) / (a0 * a0));
        }
    }
    return s;
}

void apply(const TetMesh& mesh, const RestStiffness& s, std::span<const Vec3> x,
           std::span<Vec3> y) {
    std::fill(y.begin(), y.end(), Vec3::Zero());
    for (std::size_t e = 0; e < s.edges.size(); ++e) {
        const auto [a, b] = s.edges[e];
        const Vec3& n = s.edgeDir[e];
        const Vec3 f = s.edgeK[e] * n.dot(x[b] - x[a]) * n;
        y[a] -= f;
        y[b] += f;
    }
    for (int t = 0; t < mesh.tetCount(); ++t) {
        const Tet& q = mesh.tet(t);
        const auto& g = s.tetGrad[t];
        double dv = 0;
        for (int i = 0; i < 4; ++i)
            dv += g[i].dot(x[q[i]]);
        const double c = s.tetK[t] * dv;
        for (int i = 0; i < 4; ++i)
            y[q[i]] += c * g[i];
    }
    for (std::size_t f = 0; f < s.tris.size(); ++f) {
        const Tri& q = s.tris[f];
        const auto& a = s.triGrad[f];
        const double c = s.triK[f] * (a[0].dot(x[q[0]]) + a[1].dot(x[q[1]]) + a[2].dot(x[q[2]]));
        for (int i = 0; i < 3; ++i)
            y[q[i]] += c * a[i];
    }
}

/// A fixed pseudo-random field in [-1/2, 1/2)^3 on the nodes of positive weight, zero on the
/// others: the reproducible start vector of the eigenvalue estimates.
std::vector<Vec3> pseudoRandomField(const std::vector<double>& weight) {
    std::vector<Vec3> x(weight.size());
    std::uint64_t state = 0x853c49e6748fea9bull;
    auto next = [&state] {
        state = state * 6364136223846793005ull + 1442695040888963407ull;
        return static_cast<double>(state >> 11) / static_cast<double>(1ull << 53) - 0.5;
    };
    for (std::size_t i = 0; i < weight.size(); ++i)
        x[i] = weight[i] > 0 ? Vec3(next(), next(), next()) : Vec3::Zero();
    return x;
}

double dot(std::span<const Vec3> a, std::span<const Vec3> b) {
    double s = 0;
    for (std::size_t i = 0; i < a.size(); ++i)
        s += a[i].dot(b[i]);
    return s;
}

double squaredNorm(std::span<const Vec3> a) { return dot(a, a); }

/// y -= c x
void subtract(std::span<Vec3> y, double c, std::span<const Vec3> x) {
    for (std::size_t i = 0; i < y.size(); ++i)
        y[i] -= c * x[i];
}

/// One Lanczos round of at most `steps` products from the unit vector q (mass-weighted
/// coordinates); returns the largest Ritz value and leaves its unit Ritz vector in q.
double lanczosRound(const StiffnessProduct& stiffness, const std::vector<double>& invSqrtMass,
                    std::vector<Vec3>& q, int steps, int& products) {
    const std::size_t n = q.size();
    std::vector<std::vector<Vec3>> basis;
    std::vector<double> alpha, beta;
    std::vector<Vec3> z(n), w(n);
    for (int j = 0; j < steps; ++j) {
        basis.push_back(q);
        for (std::size_t i = 0; i < n; ++i)
            z[i] = q[i] * invSqrtMass[i];
        std::fill(w.begin(), w.end(), Vec3::Zero());
        stiffness(z, w);
        ++products;
        for (std::size_t i = 0; i < n; ++i)
            w[i] *= invSqrtMass[i];
        const double a = dot(w, q);
        alpha.push_back(a);
        // Full re-orthogonalisation against the basis (which also removes a q and b q_prev).
        for (const auto& b : basis)
            subtract(w, dot(w, b), b);
        const double b = std::sqrt(squaredNorm(w));
        double scale = 0;
        for (double v : alpha)
            scale = std::max(scale, std::abs(v));
        if (j + 1 == steps || !(b > 1e-10 * scale))
            break; // the Krylov space is invariant (or complete)
        beta.push_back(b);
        for (std::size_t i = 0; i < n; ++i)
            q[i] = w[i] / b;
    }
    const int m = static_cast<int>(alpha.size());
    Eigen::MatrixXd t = Eigen::MatrixXd::Zero(m, m);
    for (int i = 0; i < m; ++i) {
        t(i, i) = alpha[i];
        if (i + 1 < m)
            t(i, i + 1) = t(i + 1, i) = beta[i];
    }
    const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> eigen(t);
    const Eigen::VectorXd y = eigen.eigenvectors().col(m - 1);
    std::fill(q.begin(), q.end(), Vec3::Zero());
    for (int j = 0; j < m; ++j)
        subtract(q, -y[j], basis[j]);
    const double norm = std::sqrt(squaredNorm(q));
    if (norm > 0)
        for (Vec3& v : q)
            v /= norm;
    return eigen.eigenvalues()[m - 1];
}

} // namespace

EigenEstimate largestEigenvalue(const StiffnessProduct& stiffness, std::span<const double> mass,
                                std::vector<Vec3>& start, const LanczosOptions& options) {
    EigenEstimate result;
    const std::size_t n = mass.size();
    std::vector<double> invSqrtMass(n, 0.0);
    for (std::size_t i = 0; i < n; ++i)
        invSqrtMass[i] = mass[i] > 0 ? 1.0 / std::sqrt(mass[i]) : 0.0;
    start.resize(n, Vec3::Zero());
    for (std::size_t i = 0; i < n; ++i)
        if (!(invSqrtMass[i] > 0) || !start[i].allFinite())
            start[i] = Vec3::Zero();
    // The start: the given vector mixed with the fixed field (both normalised), or the field.
    std::vector<Vec3> field = pseudoRandomField(invSqrtMass);
    const double fieldNorm = std::sqrt(squaredNorm(field));
    if (!(fieldNorm > 0))
        return result; // no node with mass
    const double startNorm = std::sqrt(squaredNorm(start));
    const double fresh = startNorm > 0 ? std::clamp(options.freshFraction, 0.0, 1.0) : 1.0;
    std::vector<Vec3> q(n);
    for (std::size_t i = 0; i < n; ++i)
        q[i] = (1 - fresh) * (startNorm > 0 ? Vec3(start[i] / startNorm) : Vec3::Zero()) +
               fresh * field[i] / fieldNorm;
    const double qNorm = std::sqrt(squaredNorm(q));
    for (Vec3& v : q)
        v /= qNorm;

    const int steps = std::max(2, options.steps);
    double previous = 0;
    for (int round = 0; round < std::max(1, options.maxRounds); ++round) {
        const double lambda = lanczosRound(stiffness, invSqrtMass, q, steps, result.products);
        result.lambdaMax = std::max(result.lambdaMax, lambda);
        if (round > 0 &&
            std::abs(lambda - previous) <= options.relativeTolerance * std::abs(lambda))
            break;
        previous = lambda;
    }
    start = std::move(q);
    return result;
}

void applyRestStiffness(const TetMesh& mesh, const Material& material, std::span<const Vec3> x,
                        std::span<Vec3> y, bool areaTerm) {
    apply(mesh, buildRestStiffness(mesh, material, areaTerm), x, y);
}

std::vector<double> tetStableTimeSteps(const TetMesh& mesh, const Material& material,
                                       const StableTimeStepOptions& options) {
    using Mat12 = Eigen::Matrix<double, 12, 12>;
    std::vector<double> result(mesh.tetCount(), std::numeric_limits<double>::infinity());
    const auto m = mesh.masses();
    // Boundary faces by tet (area term only).
    std::vector<std::vector<Tri>> faces;
    if (options.areaTerm) {
        faces.resize(mesh.tetCount());
        for (const BoundaryFace& f : boundaryFaces(mesh))
            faces[f.tet].push_back(f.nodes);
    }
    // K += k a a^T for a gradient a over the tet's corners (local indices).
    const auto addRankOne = [](Mat12& K, double k, const std::array<int, 4>& corner,
                               const std::array<Vec3, 4>& a, int count) {
        for (int i = 0; i < count; ++i)
            for (int j = 0; j < count; ++j)
                K.block<3, 3>(3 * corner[i], 3 * corner[j]) += k * a[i] * a[j].transpose();
    };
    for (int t = 0; t < mesh.tetCount(); ++t) {
        const Tet& q = mesh.tet(t);
        bool massless = false;
        for (int i = 0; i < 4; ++i)
            massless = massless || !(m[q[i]] > 0);
        if (massless)
            continue;
        Mat12 K = Mat12::Zero();
        // Springs (Eq. 4): k_s (n n^T) (x) [[1,-1],[-1,1]].
        for (const auto& e : kTetEdges) {
            const Vec3 d = mesh.ref(q[e[1]]) - mesh.ref(q[e[0]]);
            const double l2 = d.squaredNorm();
            if (!(l2 > 0))
                continue;
            const Vec3 n = d / std::sqrt(l2);
            addRankOne(K, material.stiffness * (m[q[e[0]]] + m[q[e[1]]]) / l2, {e[0], e[1], 0, 0},
                       {Vec3(-n), n, Vec3::Zero(), Vec3::Zero()}, 2);
        }
        // Volume term: k_v g g^T.
        const Vec3 &p0 = mesh.ref(q[0]), &p1 = mesh.ref(q[1]), &p2 = mesh.ref(q[2]), &p3 = mesh.ref(q[3]);
        std::array<Vec3, 4> g;
        g[1] = (p2 - p0).cross(p3 - p0) / 6.0;
        g[2] = (p3 - p0).cross(p1 - p0) / 6.0;
        g[3] = (p1 - p0).cross(p2 - p0) / 6.0;
        g[0] = -(g[1] + g[2] + g[3]);
        const double v0 = mesh.referenceVolume(t);
        const double msum = m[q[0]] + m[q[1]] + m[q[2]] + m[q[3]];
        if (v0 != 0)
            addRankOne(K, material.stiffness * msum / (v0 * v0), {0, 1, 2, 3}, g, 4);
        // Area terms of its boundary faces: k_a a a^T.
        if (options.areaTerm)
            for (const Tri& f : faces[t]) {
                std::array<int, 4> corner{};
                for (int i = 0; i < 3; ++i)
                    corner[i] = static_cast<int>(std::find(q.begin(), q.end(), f[i]) - q.begin());
                const Vec3 &a0 = mesh.ref(f[0]), &a1 = mesh.ref(f[1]), &a2 = mesh.ref(f[2]);
                const Vec3 n = (a1 - a0).cross(a2 - a0);
                const double area = 0.5 * n.norm();
                if (!(area > 0))
                    continue;
                const Vec3 h = n / (4 * area);
                addRankOne(K, material.stiffness * (m[f[0]] + m[f[1]] + m[f[2]]) / (area * area), corner,
                           {h.cross(a2 - a1), h.cross(a0 - a2), h.cross(a1 - a0), Vec3::Zero()}, 3);
            }
        // M^-1/2 K M^-1/2, symmetric.
        for (int i = 0; i < 12; ++i)
            for (int j = 0; j < 12; ++j)
                K(i, j) /= std::sqrt(m[q[i / 3]] * m[q[j / 3]]);
        const double lambda =
            Eigen::SelfAdjointEigenSolver<Mat12>(K, Eigen::EigenvaluesOnly).eigenvalues().maxCoeff();
        if (lambda > 0 && std::isfinite(lambda))
            result[t] = options.safety * 2 / std::sqrt(lambda);
    }
    return result;
}

StableTimeStep stableTimeStep(const TetMesh& mesh, const Material& material,
                              const StableTimeStepOptions& options) {
    StableTimeStep result;
    const int n = mesh.nodeCount();
    if (mesh.empty() || n == 0)
        return result;
    const RestStiffness s = buildRestStiffness(mesh, material, options.areaTerm);
    const auto m = mesh.masses();

    // Block Gershgorin bound on M^-1 K: |lambda| <= max_i (||K_ii|| + sum_j ||K_ij||) / m_i.
    std::vector<double> rowSum(n, 0.0);
    for (std::size_t e = 0; e < s.edges.size(); ++e) {
        rowSum[s.edges[e][0]] += 2 * s.edgeK[e];
        rowSum[s.edges[e][1]] += 2 * s.edgeK[e];
    }
    for (int t = 0; t < mesh.tetCount(); ++t) {
        const auto& g = s.tetGrad[t];
        const double total = g[0].norm() + g[1].norm() + g[2].norm() + g[3].norm();
        for (int i = 0; i < 4; ++i)
            rowSum[mesh.tet(t)[i]] += s.tetK[t] * g[i].norm() * total;
    }
    for (std::size_t f = 0; f < s.tris.size(); ++f) {
        const auto& a = s.triGrad[f];
        const double total = a[0].norm() + a[1].norm() + a[2].norm();
        for (int i = 0; i < 3; ++i)
            rowSum[s.tris[f][i]] += s.triK[f] * a[i].norm() * total;
    }
    std::vector<double> invSqrtMass(n, 0.0);
    for (int i = 0; i < n; ++i) {
        if (m[i] > 0) {
            invSqrtMass[i] = 1.0 / std::sqrt(m[i]);
            result.gershgorinBound = std::max(result.gershgorinBound, rowSum[i] / m[i]);
        }
    }
    if (!(result.gershgorinBound > 0))
        return result;

    // Power iteration on A = M^-1/2 K M^-1/2 (symmetric positive semi-definite). The start
    // vector is a fixed pseudo-random field so that the estimate is reproducible.
    std::vector<Vec3> x = pseudoRandomField(invSqrtMass), z(n), y(n);
    double norm2 = squaredNorm(x);
    double rayleigh = 0;
    for (int it = 0; it < options.maxIterations; ++it) {
        const double inv = 1.0 / std::sqrt(norm2);
        for (int i = 0; i < n; ++i) {
            x[i] *= inv;
            z[i] = x[i] * invSqrtMass[i];
        }
        apply(mesh, s, z, y);
        double rq = 0;
        norm2 = 0;
        for (int i = 0; i < n; ++i) {
            y[i] *= invSqrtMass[i];
            rq += x[i].dot(y[i]);
            norm2 += y[i].squaredNorm();
        }
        result.iterations = it + 1;
        const bool converged = std::abs(rq - rayleigh) <= options.relativeTolerance * std::abs(rq);
        rayleigh = rq;
        if (converged || !(norm2 > 0))
            break;
        std::swap(x, y);
    }
    result.lambdaMax = std::min(std::max(rayleigh, 0.0), result.gershgorinBound);
    if (!(result.lambdaMax > 0))
        result.lambdaMax = result.gershgorinBound;
    result.dt = options.safety * 2.0 / std::sqrt(result.lambdaMax);
    return result;
}

} // namespace resect
