#include "core/sim/gravity_effect.h"

#include "core/sim/parallel.h"

namespace resect {

double GravityEffect::addForces(const SimState& s, std::span<Vec3> f) {
    return parallelSum(threadsFor(m_threads, static_cast<std::int64_t>(f.size()), m_grain),
                       static_cast<std::int64_t>(f.size()),
                       [&](std::int64_t begin, std::int64_t end) {
                           double potential = 0;
                           for (std::int64_t i = begin; i < end; ++i) {
                               f[i] += s.mass[i] * m_g;
                               potential -= s.mass[i] * m_g.dot(s.x[i]);
                           }
                           return potential;
                       });
}

} // namespace resect
