#include "core/sim/forces.h"

namespace resect {
namespace {

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
    r.volume6 = d1.dot(r.g1);  // the expression of restTetVolume, times 6
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
    r.area = 0.5 * n2;  // the expression of restTriangleArea
    r.defined = n2 > 0;
    const Vec3 h = r.defined ? Vec3(n / (2 * n2)) : Vec3::Zero();
    r.a0 = h.cross(p2 - p1);
    r.a1 = h.cross(p0 - p2);
    r.a2 = h.cross(p1 - p0);
    return r;
}

} // namespace

double addEdgeForces(std::span<const Edge> edges, std::span<const double> restLength,
                     std::span<const double> stiffness, std::span<const Vec3> x, ForceWindow f) {
    double energy = 0;
    for (std::size_t e = 0; e < edges.size(); ++e) {
        const int a = edges[e][0], b = edges[e][1];
        const Vec3 d = x[b] - x[a];
        const double l = d.norm();
        const double stretch = l - restLength[e];
        const double k = stiffness[e];
        energy += 0.5 * k * stretch * stretch;
        // f_a = k (l - l0) d / l; a zero-length edge has no direction and gets no force.
        const double s = l > 0 ? k * stretch / l : 0.0;
        const Vec3 fa = s * d;
        f[a] += fa;
        f[b] -= fa;
    }
    return energy;
}

double addVolumeForces(std::span<const Tet> tets, std::span<const double> restVolume,
                       std::span<const double> stiffness, std::span<const Vec3> x,
                       ForceWindow f) {
    double energy = 0;
    for (std::size_t t = 0; t < tets.size(); ++t) {
        const Tet& q = tets[t];
        const VolumeGradient g = volumeGradient(x[q[0]], x[q[1]], x[q[2]], x[q[3]]);
        const double dv = g.volume6 / 6.0 - restVolume[t];
        const double k = stiffness[t];
        energy += 0.5 * k * dv * dv;
        const double c = -k * dv / 6.0;  // f_i = -k (V - V0) dV/dp_i, dV/dp_i = g_i / 6
        f[q[0]] += c * g.g0;
        f[q[1]] += c * g.g1;
        f[q[2]] += c * g.g2;
        f[q[3]] += c * g.g3;
    }
    return energy;
}

double addAreaForces(std::span<const Tri> triangles, std::span<const double> restArea,
                     std::span<const double> stiffness, std::span<const Vec3> x,
                     ForceWindow f) {
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

void addVolumeForceDifferential(std::span<const Tet> tets, std::span<const double> stiffness,
                                std::span<const Vec3> x, std::span<const Vec3> dx,
                                ForceWindow df) {
    for (std::size_t t = 0; t < tets.size(); ++t) {
        const Tet& q = tets[t];
        const VolumeGradient g = volumeGradient(x[q[0]], x[q[1]], x[q[2]], x[q[3]]);
        const double dvdx = (g.g0.dot(dx[q[0]]) + g.g1.dot(dx[q[1]]) + g.g2.dot(dx[q[2]]) +
                             g.g3.dot(dx[q[3]])) /
                            6.0;
        const double c = -stiffness[t] * dvdx / 6.0;
        df[q[0]] += c * g.g0;
        df[q[1]] += c * g.g1;
        df[q[2]] += c * g.g2;
        df[q[3]] += c * g.g3;
    }
}

void addAreaForceDifferential(std::span<const Tri> triangles, std::span<const double> stiffness,
                              std::span<const Vec3> x, std::span<const Vec3> dx,
                              ForceWindow df) {
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

void addVolumeStiffnessDiagonal(std::span<const Tet> tets, std::span<const double> stiffness,
                                std::span<const Vec3> x, ForceWindow diag) {
    for (std::size_t t = 0; t < tets.size(); ++t) {
        const Tet& q = tets[t];
        const VolumeGradient g = volumeGradient(x[q[0]], x[q[1]], x[q[2]], x[q[3]]);
        const double c = stiffness[t] / 36.0;
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
