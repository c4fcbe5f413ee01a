#pragma once
// The `damping` effect: mass-proportional velocity damping f_i = -c m_i v_i (c in 1/s,
// Material::damping). It removes energy at the rate c * 2 * kinetic energy. In the explicit
// integrators it is evaluated with the velocity at force time (stable for c dt < 2, far above
// any useful c); backward Euler treats it implicitly (df/dv = -c M).

#include "core/sim/effect.h"

namespace resect {

class DampingEffect : public Effect {
public:
    explicit DampingEffect(double coefficient, int threads = 1, int grain = 4096)
        : m_c(coefficient), m_threads(threads), m_grain(grain) {}
    std::string name() const override { return "damping"; }
    double addForces(const SimState& s, std::span<Vec3> f) override;
    void addVelocityDifferential(const SimState& s, std::span<const Vec3> dv,
                                 std::span<Vec3> df) override;
    void addSystemDiagonal(const SimState& s, double h, std::span<Vec3> diag) override;
    double coefficient() const { return m_c; }

private:
    double m_c;
    int m_threads;
    int m_grain;
};

} // namespace resect
