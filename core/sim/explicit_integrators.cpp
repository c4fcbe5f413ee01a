#include "core/sim/explicit_integrators.h"

#include "core/sim/parallel.h"

#include <algorithm>
#include <cmath>
#include <vector>

namespace resect {
namespace {

/// Runs body(begin, end, pass) on `threads` chunks of [0, count) and combines the passes in
/// chunk order. body accumulates kinetic energy, squared max speed and a NaN-on-non-finite sum.
struct Partial {
    double kinetic = 0;
    double maxSpeed2 = 0;
    double poison = 0; ///< stays 0 unless a non-finite value was seen (then NaN)
};

template <class Body> NodePass runPass(std::int64_t count, int threads, Body&& body) {
    std::vector<Partial> parts(static_cast<std::size_t>(std::max(threads, 1)));
    parallelRun(threads, [&](int t) {
        body(chunkBegin(count, threads, t), chunkBegin(count, threads, t + 1), parts[t]);
    });
    NodePass r;
    double poison = 0;
    double maxSpeed2 = 0;
    for (const Partial& p : parts) {
        r.kineticEnergy += p.kinetic;
        maxSpeed2 = std::max(maxSpeed2, p.maxSpeed2);
        poison += p.poison;
    }
    r.maxSpeed = std::sqrt(maxSpeed2);
    r.finite = poison == 0 && std::isfinite(r.kineticEnergy);
    return r;
}

inline void account(Partial& p, double m, const Vec3& x, const Vec3& v) {
    const double v2 = v.squaredNorm();
    p.kinetic += 0.5 * m * v2;
    p.maxSpeed2 = std::max(p.maxSpeed2, v2);
    p.poison += (x.sum() + v.sum()) * 0.0; // NaN if any component is inf or NaN
}

inline double stepOverMass(double h, double m) {
    return m > 0 ? h / m : 0.0;
}

} // namespace

NodePass symplecticEulerUpdate(std::span<Vec3> x, std::span<Vec3> v, std::span<Vec3> f,
                               std::span<const double> mass, double h, std::span<Vec3> backupX,
                               std::span<Vec3> backupV, int threads) {
    const bool backup = !backupX.empty();
    return runPass(static_cast<std::int64_t>(x.size()), threads,
                   [&](std::int64_t begin, std::int64_t end, Partial& p) {
                       for (std::int64_t i = begin; i < end; ++i) {
                           if (backup) {
                               backupX[i] = x[i];
                               backupV[i] = v[i];
                           }
                           const double m = mass[i];
                           const Vec3 vi =
                               m > 0 ? Vec3(v[i] + stepOverMass(h, m) * f[i]) : Vec3::Zero();
                           const Vec3 xi = x[i] + h * vi;
                           v[i] = vi;
                           x[i] = xi;
                           f[i].setZero();
                           account(p, m, xi, vi);
                       }
                   });
}

NodePass verletKickDrift(std::span<Vec3> x, std::span<Vec3> v, std::span<const Vec3> f,
                         std::span<const double> mass, double h, std::span<Vec3> backupX,
                         std::span<Vec3> backupV, int threads) {
    const bool backup = !backupX.empty();
    return runPass(static_cast<std::int64_t>(x.size()), threads,
                   [&](std::int64_t begin, std::int64_t end, Partial& p) {
                       for (std::int64_t i = begin; i < end; ++i) {
                           if (backup) {
                               backupX[i] = x[i];
                               backupV[i] = v[i];
                           }
                           const double m = mass[i];
                           const Vec3 vi =
                               m > 0 ? Vec3(v[i] + stepOverMass(0.5 * h, m) * f[i]) : Vec3::Zero();
                           const Vec3 xi = x[i] + h * vi;
                           v[i] = vi;
                           x[i] = xi;
                           account(p, m, xi, vi);
                       }
                   });
}

NodePass verletKick(std::span<Vec3> v, std::span<const Vec3> f, std::span<const double> mass,
                    double h, int threads) {
    return runPass(static_cast<std::int64_t>(v.size()), threads,
                   [&](std::int64_t begin, std::int64_t end, Partial& p) {
                       for (std::int64_t i = begin; i < end; ++i) {
                           const double m = mass[i];
                           const Vec3 vi =
                               m > 0 ? Vec3(v[i] + stepOverMass(0.5 * h, m) * f[i]) : Vec3::Zero();
                           v[i] = vi;
                           account(p, m, Vec3::Zero(), vi);
                       }
                   });
}

NodePass velocityChangeUpdate(std::span<Vec3> x, std::span<Vec3> v, std::span<const Vec3> dv,
                              std::span<const double> mass, double h, std::span<Vec3> backupX,
                              std::span<Vec3> backupV, int threads) {
    const bool backup = !backupX.empty();
    return runPass(static_cast<std::int64_t>(x.size()), threads,
                   [&](std::int64_t begin, std::int64_t end, Partial& p) {
                       for (std::int64_t i = begin; i < end; ++i) {
                           if (backup) {
                               backupX[i] = x[i];
                               backupV[i] = v[i];
                           }
                           const double m = mass[i];
                           const Vec3 vi = m > 0 ? Vec3(v[i] + dv[i]) : Vec3::Zero();
                           const Vec3 xi = x[i] + h * vi;
                           v[i] = vi;
                           x[i] = xi;
                           account(p, m, xi, vi);
                       }
                   });
}

NodePass measureVelocities(std::span<const Vec3> v, std::span<const double> mass, int threads) {
    return runPass(static_cast<std::int64_t>(v.size()), threads,
                   [&](std::int64_t begin, std::int64_t end, Partial& p) {
                       for (std::int64_t i = begin; i < end; ++i)
                           account(p, mass[i], Vec3::Zero(), v[i]);
                   });
}

} // namespace resect
