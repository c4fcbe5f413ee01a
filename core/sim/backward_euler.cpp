#include "core/sim/backward_euler.h"

#include <Eigen/IterativeLinearSolvers>
#include <Eigen/SparseCore>

namespace resect {
namespace {
class OperatorMatrix;
} // namespace
} // namespace resect

template <>
struct Eigen::internal::traits<resect::OperatorMatrix>
    : public Eigen::internal::traits<Eigen::SparseMatrix<double>> {};

namespace resect {
namespace {

/// A SystemOperator seen by Eigen as a (3n x 3n) self-adjoint matrix (Eigen's documented
/// matrix-free pattern: an EigenBase with a custom product).
class OperatorMatrix : public Eigen::EigenBase<OperatorMatrix> {
public:
    using Scalar = double;
    using RealScalar = double;
    using StorageIndex = int;
    enum {
        ColsAtCompileTime = Eigen::Dynamic,
        MaxColsAtCompileTime = Eigen::Dynamic,
        IsRowMajor = false
    };

    OperatorMatrix(const SystemOperator& apply, std::span<const Vec3> diagonal)
        : m_apply(apply), m_diagonal(diagonal) {}
    Eigen::Index rows() const { return 3 * static_cast<Eigen::Index>(m_diagonal.size()); }
    Eigen::Index cols() const { return rows(); }

    template <typename Rhs>
    Eigen::Product<OperatorMatrix, Rhs, Eigen::AliasFreeProduct>
    operator*(const Eigen::MatrixBase<Rhs>& x) const {
        return Eigen::Product<OperatorMatrix, Rhs, Eigen::AliasFreeProduct>(*this, x.derived());
    }

    /// y += alpha A x
    void multiplyAdd(const Eigen::VectorXd& x, double alpha, Eigen::Ref<Eigen::VectorXd> y) const {
        const auto n = m_diagonal.size();
        m_out.resize(x.size());
        m_apply(std::span<const Vec3>(reinterpret_cast<const Vec3*>(x.data()), n),
                std::span<Vec3>(reinterpret_cast<Vec3*>(m_out.data()), n));
        y += alpha * m_out;
    }
    std::span<const Vec3> diagonal() const { return m_diagonal; }

private:
    const SystemOperator& m_apply;
    std::span<const Vec3> m_diagonal;
    mutable Eigen::VectorXd m_out;
};

/// Jacobi preconditioner with the interface Eigen's iterative solvers expect.
class JacobiPreconditioner {
public:
    JacobiPreconditioner() = default;
    template <typename M> JacobiPreconditioner& analyzePattern(const M&) { return *this; }
    template <typename M> JacobiPreconditioner& factorize(const M& m) {
        const auto d = m.diagonal();
        m_inverse.resize(3 * static_cast<Eigen::Index>(d.size()));
        for (std::size_t i = 0; i < d.size(); ++i)
            for (int c = 0; c < 3; ++c)
                m_inverse[3 * static_cast<Eigen::Index>(i) + c] = d[i][c] > 0 ? 1.0 / d[i][c] : 1.0;
        return *this;
    }
    template <typename M> JacobiPreconditioner& compute(const M& m) { return factorize(m); }
    template <typename Rhs> Eigen::VectorXd solve(const Rhs& b) const {
        return m_inverse.cwiseProduct(b);
    }
    Eigen::ComputationInfo info() const { return Eigen::Success; }

private:
    Eigen::VectorXd m_inverse;
};

} // namespace
} // namespace resect

namespace Eigen::internal {

template <typename Rhs>
struct generic_product_impl<resect::OperatorMatrix, Rhs, SparseShape, DenseShape, GemvProduct>
    : generic_product_impl_base<resect::OperatorMatrix, Rhs,
                                generic_product_impl<resect::OperatorMatrix, Rhs>> {
    using Scalar = typename Product<resect::OperatorMatrix, Rhs>::Scalar;
    template <typename Dest>
    static void scaleAndAddTo(Dest& dst, const resect::OperatorMatrix& lhs, const Rhs& rhs,
                              const Scalar& alpha) {
        lhs.multiplyAdd(Eigen::VectorXd(rhs), alpha, dst);
    }
};

} // namespace Eigen::internal

namespace resect {

LinearSolve solveConjugateGradient(const SystemOperator& apply, std::span<const Vec3> diagonal,
                                   std::span<const Vec3> b, std::span<Vec3> x,
                                   const BackwardEulerOptions& options) {
    const auto n = static_cast<Eigen::Index>(b.size());
    const OperatorMatrix a(apply, diagonal);
    Eigen::ConjugateGradient<OperatorMatrix, Eigen::Lower | Eigen::Upper, JacobiPreconditioner> cg;
    cg.setTolerance(options.tolerance);
    cg.setMaxIterations(options.maxIterations);
    cg.compute(a);
    const Eigen::Map<const Eigen::VectorXd> rhs(reinterpret_cast<const double*>(b.data()), 3 * n);
    const Eigen::VectorXd solution = cg.solve(rhs);
    Eigen::Map<Eigen::VectorXd>(reinterpret_cast<double*>(x.data()), 3 * n) = solution;
    LinearSolve r;
    r.iterations = static_cast<int>(cg.iterations());
    r.relativeResidual = cg.error();
    r.converged = cg.info() == Eigen::Success;
    return r;
}

} // namespace resect
