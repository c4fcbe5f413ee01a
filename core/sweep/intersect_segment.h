#pragma once
// Exact crossing test of a segment with the sweep surface (section 4.3, step 2 of 4.1).
// Whether a segment crosses a sweep triangle is decided with exact orientation predicates;
// only the crossing parameter t and the crossing point are computed in floating point.

#include "core/sweep/sweep_surface.h"

#include <cstdint>
#include <vector>

namespace resect {

struct SegmentHit {
    double t = 0;          ///< parameter along p -> q, strictly inside (0, 1) in exact terms
    int triangle = -1;     ///< sweep triangle crossed
    Vec3 point = Vec3::Zero();
    Vec2 uv = Vec2::Zero();
    int sideP = 0;         ///< side of p relative to the triangle (+1 / -1); q is on the other
    std::int64_t feature = 0;  ///< what was crossed: the triangle's interior, a sweep edge or
                               ///< a sweep vertex; hits with the same feature are one crossing
};

struct SegmentQuery {
    std::vector<SegmentHit> hits;  ///< distinct crossings, sorted by t
    bool pOnSweep = false;         ///< p lies exactly on the sweep surface
    bool qOnSweep = false;         ///< q lies exactly on the sweep surface
};

/// Crossings of segment p -> q with the sweep surface. An endpoint lying exactly on the
/// surface is reported as on-sweep, not as a crossing. `candidates` is scratch space.
void intersectSegment(const SweepSurface& sweep, const Vec3& p, const Vec3& q, SegmentQuery& out,
                      std::vector<int>& candidates);

} // namespace resect
