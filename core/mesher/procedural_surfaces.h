#pragma once
// Closed, outward-oriented, manifold triangle surfaces generated procedurally: used by the
// built-in samples and by tests that need surfaces of known shape and volume.
// Every generator returns texture coordinates (one per vertex).

#include "core/mesh/triangle_surface.h"

#include <functional>

namespace resect {

/// Torus around the z axis: major radius R, minor radius r (0 < r < R), nu segments around
/// the axis and nv around the tube (both >= 3). Exact enclosed volume of the smooth torus:
/// 2 pi^2 R r^2.
TriangleSurface makeTorus(double R, double r, int nu, int nv);

/// Ellipsoid with semi-axes (a, b, c) along x, y, z, centred at the origin; `rings`
/// latitude bands (>= 2) and `segments` longitude segments (>= 3); poles are single
/// vertices. Smooth volume: 4/3 pi a b c.
TriangleSurface makeEllipsoid(const Vec3& radii, int rings, int segments);

/// Axis-aligned box [lo, hi] as 12 triangles.
TriangleSurface makeBox(const Vec3& lo, const Vec3& hi);

/// General closed surface of revolution-like shape about the z axis, star-shaped in each
/// horizontal slice: s in [0, 1] runs from the bottom pole (s = 0) to the top pole
/// (s = 1), phi in [0, 2 pi) around the axis. `point(s, phi)` gives the surface point; it
/// must map s = 0 and s = 1 to single points (the poles). rings >= 2, segments >= 3.
/// Texture coordinates are (phi / 2 pi, s).
TriangleSurface makePolarGridSurface(const std::function<Vec3(double s, double phi)>& point,
                                     int rings, int segments);

} // namespace resect
