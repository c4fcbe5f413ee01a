#include "core/mesh/quality.h"

#include "core/mesh/topology.h"
#include "core/mesh/vec3_lanes.h"

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

namespace resect {

TetQuality tetQuality(const Vec3& p0, const Vec3& p1, const Vec3& p2, const Vec3& p3) {
    TetQuality q;
    const Vec3 p[4] = {p0, p1, p2, p3};
    double lmin = std::numeric_limits<double>::infinity(), lmax = 0;
    for (const auto& e : kTetEdges) {
        const double l = (p[e[1]] - p[e[0]]).norm();
        lmin = std::min(lmin, l);
        lmax = std::max(lmax, l);
    }
    q.minEdge = lmin;
    q.maxEdge = lmax;
    q.volume = signedVolume(p0, p1, p2, p3);
    if (!(lmax > 0) || !std::isfinite(lmax))
        return q;

    // Normalise: translate to p0 and scale by the longest edge (scale invariance).
    const double s = 1.0 / lmax;
    const Vec3 a = (p1 - p0) * s, b = (p2 - p0) * s, c = (p3 - p0) * s;
    const double sixV = a.dot(b.cross(c));  // 6 * signed volume of the normalised tet

    // Face area normals, outward for a positive tet (kTetFaces order).
    const Vec3 q0 = Vec3::Zero();
    const Vec3 qs[4] = {q0, a, b, c};
    Vec3 n[4];
    double areaSum = 0;
    for (int f = 0; f < 4; ++f) {
        const auto& lf = kTetFaces[f];
        n[f] = 0.5 * (qs[lf[1]] - qs[lf[0]]).cross(qs[lf[2]] - qs[lf[0]]);
        areaSum += n[f].norm();
    }
    // r_in = 3V / A_total; R_circ = |a^2 (b x c) + b^2 (c x a) + c^2 (a x b)| / (12 V).
    const Vec3 num = a.squaredNorm() * b.cross(c) + b.squaredNorm() * c.cross(a) +
                     c.squaredNorm() * a.cross(b);
    const double absSixV = std::abs(sixV);
    if (absSixV > 0 && areaSum > 0) {
        const double rIn = (absSixV / 2.0) / areaSum;  // 3V / A = (6V/2) / A
        const double rCirc = num.norm() / (2.0 * absSixV);
        q.radiusRatio = std::copysign(3.0 * rIn / rCirc, sixV);
    }
    // Dihedral angle at edge (i, j) between the two faces containing it: pi minus the angle
    // between their outward normals. Faces containing edge (i,j) are those opposite the
    // other two nodes k, l.
    double dmin = std::numbers::pi, dmax = 0;
    for (const auto& e : kTetEdges) {
        int other[2], m = 0;
        for (int v = 0; v < 4; ++v)
            if (v != e[0] && v != e[1])
                other[m++] = v;
        const double nn = n[other[0]].norm() * n[other[1]].norm();
        if (!(nn > 0)) {
            dmin = 0;
            continue;
        }
        const double cosAngle = std::clamp(-n[other[0]].dot(n[other[1]]) / nn, -1.0, 1.0);
        const double angle = std::acos(cosAngle);
        dmin = std::min(dmin, angle);
        dmax = std::max(dmax, angle);
    }
    q.minDihedral = dmin;
    q.maxDihedral = dmax;
    return q;
}

std::array<double, 2> radiusRatioPair(const std::array<Vec3, 4>& s, const std::array<Vec3, 4>& t) {
    // radiusRatio line by line, on both tets at once.
    Vec3Lanes p[4];
    for (int i = 0; i < 4; ++i)
        p[i] = Vec3Lanes(s[i], t[i]);
    Lanes lmax2 = Lanes::Zero();
    for (const auto& e : kTetEdges) {
        const Vec3Lanes d = p[e[1]] - p[e[0]];
        lmax2 = lmax2.max(dot(d, d)); // (d > lmax2 ? d : lmax2), as std::max(lmax2, d)
    }
    const Lanes scale = Lanes::Ones() / lmax2.sqrt();
    const Vec3Lanes a = (p[1] - p[0]) * scale, b = (p[2] - p[0]) * scale, c = (p[3] - p[0]) * scale;
    const Vec3Lanes bc = cross(b, c), ca = cross(c, a), ab = cross(a, b), far = cross(b - a, c - a);
    const Lanes sixV = dot(a, bc);
    const Lanes areaSum = 0.5 * (((dot(ab, ab).sqrt() + dot(bc, bc).sqrt()) + dot(ca, ca).sqrt()) +
                                 dot(far, far).sqrt());
    const Lanes a2 = dot(a, a), b2 = dot(b, b), c2 = dot(c, c);
    const Vec3Lanes num = {(a2 * bc.x + b2 * ca.x) + c2 * ab.x, (a2 * bc.y + b2 * ca.y) + c2 * ab.y,
                           (a2 * bc.z + b2 * ca.z) + c2 * ab.z};
    const Lanes absSixV = sixV.abs();
    const Lanes rIn = (absSixV / 2.0) / areaSum;
    const Lanes rCirc = dot(num, num).sqrt() / (2.0 * absSixV);
    const Lanes ratio = 3.0 * rIn / rCirc;
    std::array<double, 2> out;
    for (int l = 0; l < 2; ++l) {
        const bool degenerate =
            !(lmax2[l] > 0) || !std::isfinite(lmax2[l]) || !(absSixV[l] > 0) || !(areaSum[l] > 0);
        out[l] = degenerate ? 0.0 : std::copysign(ratio[l], sixV[l]);
    }
    return out;
}

std::vector<TetQuality> tetQualities(const TetMesh& mesh) {
    std::vector<TetQuality> result(mesh.tetCount());
    for (int t = 0; t < mesh.tetCount(); ++t) {
        const Tet& q = mesh.tet(t);
        result[t] = tetQuality(mesh.ref(q[0]), mesh.ref(q[1]), mesh.ref(q[2]), mesh.ref(q[3]));
    }
    return result;
}

double meanEdgeLength(const TetMesh& mesh) {
    const auto edges = uniqueEdges(mesh);
    if (edges.empty())
        return 0;
    double sum = 0;
    for (const auto& e : edges)
        sum += (mesh.ref(e[1]) - mesh.ref(e[0])).norm();
    return sum / static_cast<double>(edges.size());
}

QualitySummary summarizeQuality(const TetMesh& mesh) {
    QualitySummary s;
    s.nodes = mesh.nodeCount();
    s.tets = mesh.tetCount();
    const auto edges = uniqueEdges(mesh);
    s.edges = static_cast<int>(edges.size());
    if (mesh.empty())
        return s;

    double vmin = std::numeric_limits<double>::infinity(), vmax = 0, rrSum = 0;
    double rrMin = std::numeric_limits<double>::infinity();
    double dmin = std::numbers::pi, dmax = 0;
    for (int t = 0; t < mesh.tetCount(); ++t) {
        const Tet& q = mesh.tet(t);
        const TetQuality tq =
            tetQuality(mesh.ref(q[0]), mesh.ref(q[1]), mesh.ref(q[2]), mesh.ref(q[3]));
        s.volume += tq.volume;
        vmin = std::min(vmin, std::abs(tq.volume));
        vmax = std::max(vmax, std::abs(tq.volume));
        rrMin = std::min(rrMin, tq.radiusRatio);
        rrSum += tq.radiusRatio;
        dmin = std::min(dmin, tq.minDihedral);
        dmax = std::max(dmax, tq.maxDihedral);
    }
    s.minRadiusRatio = rrMin;
    s.meanRadiusRatio = rrSum / mesh.tetCount();
    s.minAspectRatioPaper = rrMin / 3.0;
    s.volumeRatio = vmin > 0 ? vmax / vmin : std::numeric_limits<double>::infinity();
    s.minDihedralDeg = dmin * 180.0 / std::numbers::pi;
    s.maxDihedralDeg = dmax * 180.0 / std::numbers::pi;

    double lmin = std::numeric_limits<double>::infinity(), lmax = 0, lsum = 0;
    for (const auto& e : edges) {
        const double l = (mesh.ref(e[1]) - mesh.ref(e[0])).norm();
        lmin = std::min(lmin, l);
        lmax = std::max(lmax, l);
        lsum += l;
    }
    s.minEdge = lmin;
    s.maxEdge = lmax;
    s.meanEdge = edges.empty() ? 0 : lsum / static_cast<double>(edges.size());
    s.edgeRatio = lmin > 0 ? lmax / lmin : std::numeric_limits<double>::infinity();
    return s;
}

} // namespace resect
