#include "core/sim/forces.h"

#include <algorithm>

#include <emmintrin.h> // SSE2, part of every x86-64 target

namespace resect {
namespace {

using Lanes = Eigen::Array2d; ///< two terms at once (SSE2)

/// Gradients of the tet volume (times 6): g_i = d(6V)/dp_i, and 6V itself.
struct VolumeGradient {
    Vec3 g0, g1, g2, g3;
    double volume6;
};

inline VolumeGradient volumeGradient(const Vec3& p0, const Vec3& p1, const Vec3& p2,
                                     const Vec3& p3) {
    const Vec3 d1 = p1 - p0, d2 = p2 - p0, d3 = p3 - p0;
    VolumeGradient r;
    r.g1 = d2.cross(d3);
    r.g2 = d3.cross(d1);
    r.g3 = d1.cross(d2);
    r.g0 = -(r.g1 + r.g2 + r.g3);
    r.volume6 = d1.x() * r.g1.x() + d1.y() * r.g1.y() + d1.z() * r.g1.z();
    return r;
}

/// Area gradients dA/dp_i = 1/2 n^ x (opposite edge, in cyclic order), and the area.
struct AreaGradient {
    Vec3 a0, a1, a2;
    double area;
    bool defined;
};

inline AreaGradient areaGradient(const Vec3& p0, const Vec3& p1, const Vec3& p2) {
    const Vec3 n = (p1 - p0).cross(p2 - p0);
    const double n2 = n.norm();
    AreaGradient r;
    r.area = 0.5 * n2; // restTriangleArea
    r.defined = n2 > 0;
    const Vec3 h = r.defined ? Vec3(n * (0.5 / n2)) : Vec3::Zero(); // one division, not three
    r.a0 = h.cross(p2 - p1);
    r.a1 = h.cross(p0 - p2);
    r.a2 = h.cross(p1 - p0);
    return r;
}

} // namespace

double restEdgeLength(const Vec3& a, const Vec3& b) {
    const double dx = b.x() - a.x(), dy = b.y() - a.y(), dz = b.z() - a.z();
    return std::sqrt(dx * dx + dy * dy + dz * dz); // the arithmetic of addEdgeForces
}

double restTetVolume6(const Vec3& p0, const Vec3& p1, const Vec3& p2, const Vec3& p3) {
    return volumeGradient(p0, p1, p2, p3).volume6; // the arithmetic of addVolumeForces
}

double restTriangleArea(const Vec3& p0, const Vec3& p1, const Vec3& p2) {
    return areaGradient(p0, p1, p2).area;
}

double addEdgeForces(std::span<const Edge> edges, std::span<const double> restLength,
                     std::span<const double> stiffness, std::span<const Vec3> x, ForceWindow f) {
    // Edges e and u = e + 1 in the two lanes (u = e for an odd last edge, with stiffness 0
    // in its lane so that it adds no energy, and its forces scattered once).
    __m128d energy = _mm_setzero_pd();
    const std::size_t n = edges.size();
    for (std::size_t e = 0; e < n; e += 2) {
        const bool pair = e + 1 < n;
        const std::size_t u = pair ? e + 1 : e;
        const Vec3 &a0 = x[edges[e][0]], &b0 = x[edges[e][1]];
        const Vec3 &a1 = x[edges[u][0]], &b1 = x[edges[u][1]];
        const __m128d dx = _mm_sub_pd(_mm_set_pd(b1.x(), b0.x()), _mm_set_pd(a1.x(), a0.x()));
        const __m128d dy = _mm_sub_pd(_mm_set_pd(b1.y(), b0.y()), _mm_set_pd(a1.y(), a0.y()));
        const __m128d dz = _mm_sub_pd(_mm_set_pd(b1.z(), b0.z()), _mm_set_pd(a1.z(), a0.z()));
        const __m128d l = _mm_sqrt_pd(
            _mm_add_pd(_mm_add_pd(_mm_mul_pd(dx, dx), _mm_mul_pd(dy, dy)), _mm_mul_pd(dz, dz)));
        const __m128d stretch = _mm_sub_pd(l, _mm_set_pd(restLength[u], restLength[e]));
        const __m128d kStretch =
            _mm_mul_pd(_mm_set_pd(pair ? stiffness[u] : 0.0, stiffness[e]), stretch);
        energy = _mm_add_pd(energy, _mm_mul_pd(kStretch, stretch));
        // f_a = k (l - l0) d / l; a zero-length edge (or a free slot) has no direction and
        // gets no force: the mask zeroes its lane.
        const __m128d s = _mm_and_pd(_mm_cmpgt_pd(l, _mm_setzero_pd()), _mm_div_pd(kStretch, l));
        alignas(16) double fx[2], fy[2], fz[2];
        _mm_store_pd(fx, _mm_mul_pd(s, dx));
        _mm_store_pd(fy, _mm_mul_pd(s, dy));
        _mm_store_pd(fz, _mm_mul_pd(s, dz));
        for (int j = 0; j < (pair ? 2 : 1); ++j) {
            const Edge& q = edges[j ? u : e];
            const Vec3 fa(fx[j], fy[j], fz[j]);
            f[q[0]] += fa;
            f[q[1]] -= fa;
        }
    }
    alignas(16) double sum[2];
    _mm_store_pd(sum, energy);
    return 0.5 * (sum[0] + sum[1]);
}

double addVolumeForces(std::span<const Tet> tets, std::span<const double> restVolume6,
                       std::span<const double> stiffness36, std::span<const Vec3> x,
                       ForceWindow f) {
    // Tets t and u = t + 1 in the two lanes, as in addEdgeForces. The arithmetic per lane is
    // volumeGradient's: g1 = d2 x d3, g2 = d3 x d1, g3 = d1 x d2, 6V = d1 . g1, and
    // f_i = -k36 (6V - 6V0) g_i (dV/dp_i = g_i / 6).
    Lanes energy = Lanes::Zero();
    const std::size_t n = tets.size();
    for (std::size_t t = 0; t < n; t += 2) {
        const bool pair = t + 1 < n;
        const std::size_t u = pair ? t + 1 : t;
        const Tet &q = tets[t], &r = tets[u];
        const auto lane = [&](int node, int c) { return Lanes(x[q[node]][c], x[r[node]][c]); };
        const Lanes ox = lane(0, 0), oy = lane(0, 1), oz = lane(0, 2);
        const Lanes ax = lane(1, 0) - ox, ay = lane(1, 1) - oy, az = lane(1, 2) - oz;
        const Lanes bx = lane(2, 0) - ox, by = lane(2, 1) - oy, bz = lane(2, 2) - oz;
        const Lanes cx = lane(3, 0) - ox, cy = lane(3, 1) - oy, cz = lane(3, 2) - oz;
        const Lanes g1x = by * cz - bz * cy, g1y = bz * cx - bx * cz, g1z = bx * cy - by * cx;
        const Lanes g2x = cy * az - cz * ay, g2y = cz * ax - cx * az, g2z = cx * ay - cy * ax;
        const Lanes g3x = ay * bz - az * by, g3y = az * bx - ax * bz, g3z = ax * by - ay * bx;
        const Lanes volume6 = ax * g1x + ay * g1y + az * g1z;
        const Lanes dv = volume6 - Lanes(restVolume6[t], restVolume6[u]);
        const Lanes kdv = Lanes(stiffness36[t], pair ? stiffness36[u] : 0.0) * dv;
        energy += kdv * dv;
        const Lanes c = -kdv;
        const Lanes f1x = c * g1x, f1y = c * g1y, f1z = c * g1z;
        const Lanes f2x = c * g2x, f2y = c * g2y, f2z = c * g2z;
        const Lanes f3x = c * g3x, f3y = c * g3y, f3z = c * g3z;
        const Lanes f0x = -(f1x + f2x + f3x), f0y = -(f1y + f2y + f3y), f0z = -(f1z + f2z + f3z);
        for (int j = 0; j < (pair ? 2 : 1); ++j) {
            const Tet& w = j ? r : q;
            f[w[0]] += Vec3(f0x[j], f0y[j], f0z[j]);
            f[w[1]] += Vec3(f1x[j], f1y[j], f1z[j]);
            f[w[2]] += Vec3(f2x[j], f2y[j], f2z[j]);
            f[w[3]] += Vec3(f3x[j], f3y[j], f3z[j]);
        }
    }
    return 0.5 * energy.sum();
}

double addAreaForces(std::span<const Tri> triangles, std::span<const double> restArea,
                     std::span<const double> stiffness, std::span<const Vec3> x, ForceWindow f) {
    double energy = 0;
    for (std::size_t i = 0; i < triangles.size(); ++i) {
        const Tri& q = triangles[i];
        const AreaGradient g = areaGradient(x[q[0]], x[q[1]], x[q[2]]);
        const double da = g.area - restArea[i];
        const double k = stiffness[i];
        energy += 0.5 * k * da * da;
        const double c = -k * da;
        f[q[0]] += c * g.a0;
        f[q[1]] += c * g.a1;
        f[q[2]] += c * g.a2;
    }
    return energy;
}

void addEdgeForceDifferential(std::span<const Edge> edges, std::span<const double> restLength,
                              std::span<const double> stiffness, std::span<const Vec3> x,
                              std::span<const Vec3> dx, ForceWindow df) {
    for (std::size_t e = 0; e < edges.size(); ++e) {
        const int a = edges[e][0], b = edges[e][1];
        const Vec3 d = x[b] - x[a];
        const double l = d.norm();
        if (!(l > 0))
            continue;
        const Vec3 n = d / l;
        const double k = stiffness[e];
        const double transverse = std::max(0.0, 1.0 - restLength[e] / l);
        const Vec3 u = dx[b] - dx[a];
        const double un = n.dot(u);
        // H u with H = k (n n^T + transverse (I - n n^T)); df_a = H u, df_b = -H u.
        const Vec3 hu = k * (un * n + transverse * (u - un * n));
        df[a] += hu;
        df[b] -= hu;
    }
}

void addVolumeForceDifferential(std::span<const Tet> tets, std::span<const double> stiffness36,
                                std::span<const Vec3> x, std::span<const Vec3> dx, ForceWindow df) {
    for (std::size_t t = 0; t < tets.size(); ++t) {
        const Tet& q = tets[t];
        const VolumeGradient g = volumeGradient(x[q[0]], x[q[1]], x[q[2]], x[q[3]]);
        // df_i = -k_v (dV/dp_i) (dV/dx . dx) = -k36 g_i (g . dx)
        const double gdx =
            g.g0.dot(dx[q[0]]) + g.g1.dot(dx[q[1]]) + g.g2.dot(dx[q[2]]) + g.g3.dot(dx[q[3]]);
        const double c = -stiffness36[t] * gdx;
        df[q[0]] += c * g.g0;
        df[q[1]] += c * g.g1;
        df[q[2]] += c * g.g2;
        df[q[3]] += c * g.g3;
    }
}

void addAreaForceDifferential(std::span<const Tri> triangles, std::span<const double> stiffness,
                              std::span<const Vec3> x, std::span<const Vec3> dx, ForceWindow df) {
    for (std::size_t i = 0; i < triangles.size(); ++i) {
        const Tri& q = triangles[i];
        const AreaGradient g = areaGradient(x[q[0]], x[q[1]], x[q[2]]);
        const double dadx = g.a0.dot(dx[q[0]]) + g.a1.dot(dx[q[1]]) + g.a2.dot(dx[q[2]]);
        const double c = -stiffness[i] * dadx;
        df[q[0]] += c * g.a0;
        df[q[1]] += c * g.a1;
        df[q[2]] += c * g.a2;
    }
}

void addEdgeStiffnessDiagonal(std::span<const Edge> edges, std::span<const double> restLength,
                              std::span<const double> stiffness, std::span<const Vec3> x,
                              ForceWindow diag) {
    for (std::size_t e = 0; e < edges.size(); ++e) {
        const int a = edges[e][0], b = edges[e][1];
        const Vec3 d = x[b] - x[a];
        const double l = d.norm();
        if (!(l > 0))
            continue;
        const Vec3 n2 = (d / l).cwiseAbs2();
        const double transverse = std::max(0.0, 1.0 - restLength[e] / l);
        const Vec3 h = stiffness[e] * (n2 + transverse * (Vec3::Ones() - n2));
        diag[a] += h;
        diag[b] += h;
    }
}

void addVolumeStiffnessDiagonal(std::span<const Tet> tets, std::span<const double> stiffness36,
                                std::span<const Vec3> x, ForceWindow diag) {
    for (std::size_t t = 0; t < tets.size(); ++t) {
        const Tet& q = tets[t];
        const VolumeGradient g = volumeGradient(x[q[0]], x[q[1]], x[q[2]], x[q[3]]);
        const double c = stiffness36[t];
        diag[q[0]] += c * g.g0.cwiseAbs2();
        diag[q[1]] += c * g.g1.cwiseAbs2();
        diag[q[2]] += c * g.g2.cwiseAbs2();
        diag[q[3]] += c * g.g3.cwiseAbs2();
    }
}

void addAreaStiffnessDiagonal(std::span<const Tri> triangles, std::span<const double> stiffness,
                              std::span<const Vec3> x, ForceWindow diag) {
    for (std::size_t i = 0; i < triangles.size(); ++i) {
        const Tri& q = triangles[i];
        const AreaGradient g = areaGradient(x[q[0]], x[q[1]], x[q[2]]);
        diag[q[0]] += stiffness[i] * g.a0.cwiseAbs2();
        diag[q[1]] += stiffness[i] * g.a1.cwiseAbs2();
        diag[q[2]] += stiffness[i] * g.a2.cwiseAbs2();
    }
}

} // namespace resect
