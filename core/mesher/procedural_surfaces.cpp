#include "core/mesher/procedural_surfaces.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace resect {

namespace {

constexpr double kTwoPi = 2.0 * std::numbers::pi;

/// Reverses every triangle if the signed enclosed volume is negative, so the generators
/// give outward orientation whatever the handedness of the caller's parameterisation.
void orientByVolume(TriangleSurface& surface) {
    if (enclosedVolume(surface) < 0.0) {
        for (Tri& t : surface.triangles)
            std::swap(t[1], t[2]);
    }
}

/// Appends the two triangles of the quad (a, b, c, d), listed counter-clockwise.
void addQuad(std::vector<Tri>& triangles, int a, int b, int c, int d) {
    triangles.push_back({a, b, c});
    triangles.push_back({a, c, d});
}

} // namespace

TriangleSurface makeTorus(double R, double r, int nu, int nv) {
    nu = std::max(nu, 3);
    nv = std::max(nv, 3);
    TriangleSurface s;
    s.positions.reserve(static_cast<std::size_t>(nu) * nv);
    s.uvs.reserve(static_cast<std::size_t>(nu) * nv);
    // Vertex (i, j): u = 2 pi i / nu around the z axis, v = 2 pi j / nv around the tube.
    // Both directions are periodic: the last row and column reuse the first vertices, so
    // the surface is closed; texture coordinates jump from (n-1)/n back to 0 at the seams.
    for (int i = 0; i < nu; ++i) {
        const double u = kTwoPi * i / nu;
        for (int j = 0; j < nv; ++j) {
            const double v = kTwoPi * j / nv;
            const double rho = R + r * std::cos(v);
            s.positions.emplace_back(rho * std::cos(u), rho * std::sin(u), r * std::sin(v));
            s.uvs.emplace_back(static_cast<double>(i) / nu, static_cast<double>(j) / nv);
        }
    }
    auto index = [nu, nv](int i, int j) { return (i % nu) * nv + (j % nv); };
    s.triangles.reserve(2 * static_cast<std::size_t>(nu) * nv);
    // d/du x d/dv points out of the tube, so (i,j), (i+1,j), (i+1,j+1), (i,j+1) is
    // counter-clockwise seen from outside.
    for (int i = 0; i < nu; ++i)
        for (int j = 0; j < nv; ++j)
            addQuad(s.triangles, index(i, j), index(i + 1, j), index(i + 1, j + 1),
                    index(i, j + 1));
    orientByVolume(s);
    return s;
}

TriangleSurface makeEllipsoid(const Vec3& radii, int rings, int segments) {
    const Vec3 a = radii;
    return makePolarGridSurface(
        [a](double s, double phi) {
            // Polar angle theta = pi s, measured from the bottom pole (-z).
            const double theta = std::numbers::pi * s;
            const double st = std::sin(theta);
            return Vec3(a.x() * st * std::cos(phi), a.y() * st * std::sin(phi),
                        -a.z() * std::cos(theta));
        },
        rings, segments);
}

TriangleSurface makeBox(const Vec3& lo, const Vec3& hi) {
    TriangleSurface s;
    // Corner k has x from bit 0, y from bit 1, z from bit 2.
    for (int k = 0; k < 8; ++k) {
        s.positions.emplace_back((k & 1) ? hi.x() : lo.x(), (k & 2) ? hi.y() : lo.y(),
                                 (k & 4) ? hi.z() : lo.z());
        // A simple planar projection (x, z) onto the unit square, slanted by y so that
        // no two corners share coordinates; boxes carry no meaningful texture.
        s.uvs.emplace_back(((k & 1) ? 0.75 : 0.0) + ((k & 2) ? 0.25 : 0.0), (k & 4) ? 1.0 : 0.0);
    }
    // Faces as counter-clockwise quads seen from outside.
    addQuad(s.triangles, 0, 2, 3, 1); // z = lo
    addQuad(s.triangles, 4, 5, 7, 6); // z = hi
    addQuad(s.triangles, 0, 1, 5, 4); // y = lo
    addQuad(s.triangles, 2, 6, 7, 3); // y = hi
    addQuad(s.triangles, 0, 4, 6, 2); // x = lo
    addQuad(s.triangles, 1, 3, 7, 5); // x = hi
    orientByVolume(s);                // a box given with lo > hi on an odd number of axes
    return s;
}

TriangleSurface makePolarGridSurface(const std::function<Vec3(double s, double phi)>& point,
                                     int rings, int segments) {
    rings = std::max(rings, 2);
    segments = std::max(segments, 3);
    TriangleSurface surf;
    const int ringVertices = rings - 1; // rings of `segments` vertices between the poles
    surf.positions.reserve(static_cast<std::size_t>(ringVertices) * segments + 2);
    surf.uvs.reserve(surf.positions.capacity());

    // Vertex 0: bottom pole (s = 0); then ring k = 1 .. rings-1 at s = k / rings with
    // vertices j = 0 .. segments-1 at phi = 2 pi j / segments; last: top pole (s = 1).
    // phi = 2 pi is the same vertex as phi = 0 (shared, so the surface is closed); the
    // texture coordinate u therefore jumps from (segments-1)/segments back to 0 there.
    surf.positions.push_back(point(0.0, 0.0));
    surf.uvs.emplace_back(0.0, 0.0);
    for (int k = 1; k <= ringVertices; ++k) {
        const double s = static_cast<double>(k) / rings;
        for (int j = 0; j < segments; ++j) {
            const double phi = kTwoPi * j / segments;
            surf.positions.push_back(point(s, phi));
            surf.uvs.emplace_back(static_cast<double>(j) / segments, s);
        }
    }
    surf.positions.push_back(point(1.0, 0.0));
    surf.uvs.emplace_back(0.0, 1.0);

    const int bottom = 0;
    const int top = surf.vertexCount() - 1;
    auto index = [segments](int k, int j) { return 1 + (k - 1) * segments + (j % segments); };

    surf.triangles.reserve(2 * static_cast<std::size_t>(segments) * ringVertices);
    // With phi counter-clockwise about +z and s increasing upwards, the cross product
    // d/dphi x d/ds points outwards, so these are counter-clockwise seen from outside.
    for (int j = 0; j < segments; ++j)
        surf.triangles.push_back({bottom, index(1, j + 1), index(1, j)});
    for (int k = 1; k < ringVertices; ++k)
        for (int j = 0; j < segments; ++j)
            addQuad(surf.triangles, index(k, j), index(k, j + 1), index(k + 1, j + 1),
                    index(k + 1, j));
    for (int j = 0; j < segments; ++j)
        surf.triangles.push_back({top, index(ringVertices, j), index(ringVertices, j + 1)});

    // A caller's mapping with the opposite handedness (phi clockwise, or s running
    // downwards) would give an inside-out surface; fix it here.
    orientByVolume(surf);
    return surf;
}

} // namespace resect
