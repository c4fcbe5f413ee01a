#include "core/mesher/samples.h"

#include "core/mesher/procedural_surfaces.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>
#include <utility>
#include <vector>

namespace resect {

namespace {

constexpr double kPi = std::numbers::pi;

double smoothstep(double e0, double e1, double x) {
    const double t = std::clamp((x - e0) / (e1 - e0), 0.0, 1.0);
    return t * t * (3.0 - 2.0 * t);
}

/// Grid resolution for a sample at the given detail: rings x segments quads, so the
/// triangle count 2 * segments * (rings - 1) scales linearly with `detail`. The minimum
/// keeps very low details closed and recognisable.
struct Resolution {
    int rings;
    int segments;
};
Resolution resolution(double detail, int rings1, int segments1) {
    if (!std::isfinite(detail) || detail <= 0.0)
        detail = 1.0;
    const double f = std::sqrt(detail);
    return {std::max(8, static_cast<int>(std::lround(rings1 * f))),
            std::max(12, static_cast<int>(std::lround(segments1 * f)))};
}

// ---------------------------------------------------------------------------------------
// Polyp (the paper's Figure 9: a pedunculated polyp). Units: mm, base at z = 0, apex at
// z = 20. Built slice by slice: every horizontal slice z = const is a star-shaped curve
// about a centre c(z), so with z strictly increasing from the bottom pole to the top pole
// the triangulated surface cannot intersect itself (each band of triangles lies in its
// own slab between two ring heights, and each slice of a band is a simple star-shaped
// polygon because every ring radius is positive).
// ---------------------------------------------------------------------------------------

constexpr double kPolypHeight = 20.0;

/// Axisymmetric radius of the polyp at height z in [0, kPolypHeight]; zero exactly at the
/// two ends.
///  - Base (z <= 1.5): a quarter superellipse |r / 4.6|^4 + |(z - 1.5) / 1.5|^4 = 1, a
///    flat bottom with a rounded rim, reaching r = 4.6 with a vertical tangent.
///  - Flare and stalk (z >= 1.5): the stalk radius 2.0 (with a slight waist) plus a
///    Gaussian flare that starts at 4.6 with zero slope and decays over about 2 mm.
///  - Head: two half ellipses of revolution joined at z = 14 (radius 5.2), half-height
///    6 above (apex at z = 20) and 5 below. Stalk and head are blended by a p-norm,
///    (a^p + b^p)^(1/p), smooth for p = 4 (head^4 is smooth where the head starts) and
///    keeping the apex closed.
double polypProfile(double z) {
    z = std::clamp(z, 0.0, kPolypHeight);
    constexpr double baseRadius = 4.6, baseHeight = 1.5;
    if (z <= baseHeight) {
        const double t = (baseHeight - z) / baseHeight;
        return baseRadius * std::pow(std::max(0.0, 1.0 - std::pow(t, 4)), 0.25);
    }
    constexpr double headCentre = 14.0, headRadius = 5.2;
    constexpr double headUpper = 6.0, headLower = 5.0; // half-heights above and below
    const double h = (z - headCentre) / (z > headCentre ? headUpper : headLower);
    const double head = headRadius * std::sqrt(std::max(0.0, 1.0 - h * h));
    constexpr double stalkRadius = 2.0;
    const double waist = 1.0 - 0.08 * std::exp(-std::pow((z - 6.0) / 2.0, 2));
    const double flare =
        (baseRadius - stalkRadius * waist) * std::exp(-std::pow((z - baseHeight) / 1.8, 2));
    // The stalk fades out inside the head so that it never reaches the apex.
    const double stalk = (stalkRadius * waist + flare) * (1.0 - smoothstep(12.0, 16.0, z));
    constexpr double p = 4.0;
    return std::pow(std::pow(head, p) + std::pow(stalk, p), 1.0 / p);
}

/// Sideways offset of the slice centre: the stalk leans gently, the head sits off-axis.
Vec3 polypCentre(double z) {
    const double lean = smoothstep(1.5, 12.0, z);
    return Vec3(1.2 * lean, 0.5 * lean * lean, z);
}

/// Radial factor of the head's soft lobes: four Gaussian bumps of different size, angle
/// and height (irregular, like a real polyp head) on a head that is pulled in by 18 %
/// between them (the clefts). Always in [0.82, 1.2], so the radius stays positive and
/// each slice star-shaped.
double polypLobes(double z, double phi) {
    struct Lobe {
        double amplitude, angle, height;
    };
    static constexpr std::array<Lobe, 4> lobes{
        {{0.36, 0.3, 15.8}, {0.28, 1.85, 14.2}, {0.34, 3.5, 15.2}, {0.25, 5.0, 13.8}}};
    const double angularWidth = 0.5;  // rad
    const double verticalWidth = 3.0; // mm
    const double cleft = 0.18 * smoothstep(9.5, 12.5, z);
    double f = 1.0 - cleft;
    for (const Lobe& l : lobes) {
        const double d = std::remainder(phi - l.angle, 2.0 * kPi); // periodic difference
        f += l.amplitude * std::exp(-std::pow(d / angularWidth, 2)) *
             std::exp(-std::pow((z - l.height) / verticalWidth, 2));
    }
    return f;
}

/// The polyp's meridian (profile(z), z) resampled uniformly in arc length, so rings are
/// evenly spaced along the surface (the flat base and the rounded apex get their share).
class PolypMeridian {
public:
    PolypMeridian() {
        // Dense sampling with z = H (1 - cos(pi t)) / 2, which crowds samples at the two
        // poles where the radius changes fastest; r and z are interpolated linearly
        // between samples, so the meridian is a fine polyline with z strictly increasing.
        constexpr int n = 20000;
        m_r.resize(n + 1);
        m_z.resize(n + 1);
        m_length.resize(n + 1);
        double length = 0.0;
        for (int i = 0; i <= n; ++i) {
            const double t = static_cast<double>(i) / n;
            m_z[i] = 0.5 * kPolypHeight * (1.0 - std::cos(kPi * t));
            m_r[i] = (i == 0 || i == n) ? 0.0 : polypProfile(m_z[i]);
            if (i > 0)
                length += std::hypot(m_r[i] - m_r[i - 1], m_z[i] - m_z[i - 1]);
            m_length[i] = length;
        }
    }
    /// (radius, height) at arc-length fraction s in [0, 1]; the height increases strictly
    /// with s and the radius is positive for 0 < s < 1.
    std::pair<double, double> at(double s) const {
        const double target = std::clamp(s, 0.0, 1.0) * m_length.back();
        const auto it = std::lower_bound(m_length.begin(), m_length.end(), target);
        if (it == m_length.begin())
            return {m_r.front(), m_z.front()};
        if (it == m_length.end())
            return {m_r.back(), m_z.back()};
        const std::size_t i = static_cast<std::size_t>(it - m_length.begin());
        const double l0 = m_length[i - 1], l1 = m_length[i];
        const double w = l1 > l0 ? (target - l0) / (l1 - l0) : 0.0;
        return {m_r[i - 1] + w * (m_r[i] - m_r[i - 1]), m_z[i - 1] + w * (m_z[i] - m_z[i - 1])};
    }

private:
    std::vector<double> m_r;
    std::vector<double> m_z;
    std::vector<double> m_length;
};

TriangleSurface makePolyp(double detail) {
    const PolypMeridian meridian;
    // 126 x 160 gives 40 000 triangles at detail 1.
    const Resolution res = resolution(detail, 126, 160);
    return makePolarGridSurface(
        [&meridian](double s, double phi) {
            const auto [radius, z] = meridian.at(s);
            const double r = radius * polypLobes(z, phi);
            const Vec3 c = polypCentre(z);
            return Vec3(c.x() + r * std::cos(phi), c.y() + r * std::sin(phi), z);
        },
        res.rings, res.segments);
}

// ---------------------------------------------------------------------------------------
// Myoma (the paper's Figure 10): a roughly spherical mass about 20 mm across. Radial
// graph over the unit sphere, r(d) = R (1 + f(d)), with f a smooth low-frequency
// perturbation of at most about 10 %, followed by a mild anisotropic scaling. A radial
// graph over a triangulated convex polyhedron containing the centre never intersects
// itself (each triangle stays inside the cone of its spherical triangle), so the surface
// is free of self-intersections for any positive r.
// ---------------------------------------------------------------------------------------

double myomaPerturbation(const Vec3& d) {
    // A few smooth functions of the direction (low frequency: at most three bumps around
    // any great circle); fixed phases, so the shape is deterministic.
    return 0.045 * std::sin(2.0 * d.x() + 1.1 * d.y() + 0.4) +
           0.035 * std::cos(2.6 * d.z() - 1.3 * d.x() + 0.2) +
           0.025 * std::sin(3.1 * d.y() * d.z() + 1.7 * d.x()) +
           0.020 * (d.x() * d.x() - d.y() * d.y());
}

TriangleSurface makeMyoma(double detail) {
    // 126 x 160 gives 40 000 triangles at detail 1.
    const Resolution res = resolution(detail, 126, 160);
    const double radius = 10.0;         // mm
    const Vec3 scale(1.04, 0.97, 0.93); // slightly oblate, irregular
    return makePolarGridSurface(
        [radius, scale](double s, double phi) {
            const double theta = kPi * s; // from the bottom pole (-z)
            const Vec3 d(std::sin(theta) * std::cos(phi), std::sin(theta) * std::sin(phi),
                         -std::cos(theta));
            const double r = radius * (1.0 + myomaPerturbation(d));
            return Vec3(scale.cwiseProduct(r * d));
        },
        res.rings, res.segments);
}

} // namespace

std::optional<Sample> sampleFromName(std::string_view name) {
    if (name == "polyp")
        return Sample::Polyp;
    if (name == "myoma")
        return Sample::Myoma;
    return std::nullopt;
}

std::string sampleName(Sample sample) {
    switch (sample) {
    case Sample::Polyp:
        return "polyp";
    case Sample::Myoma:
        return "myoma";
    }
    return "unknown";
}

std::vector<std::string> sampleNames() {
    return {"polyp", "myoma"};
}

TriangleSurface sampleSurface(Sample sample, double detail) {
    switch (sample) {
    case Sample::Polyp:
        return makePolyp(detail);
    case Sample::Myoma:
        return makeMyoma(detail);
    }
    return {};
}

} // namespace resect
