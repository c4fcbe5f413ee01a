#pragma once
// The `gravity` effect: f_i = m_i g on every node, g in mm/s^2 (default: 9.81 m/s^2 down the
// z axis). Its potential energy -sum m_i g . x_i makes the monitored total energy of a
// falling body constant.

#include "core/sim/effect.h"

namespace resect {

class GravityEffect : public Effect {
public:
    explicit GravityEffect(const Vec3& g = Vec3(0, 0, -9810), int threads = 1, int grain = 4096)
        : m_g(g), m_threads(threads), m_grain(grain) {}
    std::string name() const override { return "gravity"; }
    double addForces(const SimState& s, std::span<Vec3> f) override;
    const Vec3& acceleration() const { return m_g; }

private:
    Vec3 m_g;
    int m_threads;
    int m_grain;
};

} // namespace resect
