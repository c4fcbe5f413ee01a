#include "core/sim/damping_effect.h"

#include "core/sim/parallel.h"

namespace resect {

double DampingEffect::addForces(const SimState& s, std::span<Vec3> f) {
    parallelSum(threadsFor(m_threads, static_cast<std::int64_t>(f.size()), m_grain),
                static_cast<std::int64_t>(f.size()), [&](std::int64_t begin, std::int64_t end) {
                    for (std::int64_t i = begin; i < end; ++i)
                        f[i] -= m_c * s.mass[i] * s.v[i];
                    return 0.0;
                });
    return 0; // not conservative
}

void DampingEffect::addVelocityDifferential(const SimState& s, std::span<const Vec3> dv,
                                            std::span<Vec3> df) {
    for (std::size_t i = 0; i < df.size(); ++i)
        df[i] -= m_c * s.mass[i] * dv[i];
}

void DampingEffect::addSystemDiagonal(const SimState& s, double h, std::span<Vec3> diag) {
    for (std::size_t i = 0; i < diag.size(); ++i)
        diag[i] += Vec3::Constant(h * m_c * s.mass[i]);
}

} // namespace resect
