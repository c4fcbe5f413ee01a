#include "core/sweep/intersect_segment.h"

#include "core/mesh/predicates.h"

#include <algorithm>
#include <cmath>

namespace resect {
namespace {

// Feature keys: interior of triangle t, edge (a, b) with a < b, vertex v. Tagged in the
// low two bits so that the three kinds never collide.
std::int64_t interiorKey(int t) { return (static_cast<std::int64_t>(t) << 2) | 0; }
std::int64_t edgeKey(int a, int b) {
    if (a > b)
        std::swap(a, b);
    return (((static_cast<std::int64_t>(a) << 31) | b) << 2) | 1;
}
std::int64_t vertexKey(int v) { return (static_cast<std::int64_t>(v) << 2) | 2; }

} // namespace

void intersectSegment(const SweepSurface& sweep, const Vec3& p, const Vec3& q, SegmentQuery& out,
                      std::vector<int>& candidates) {
    out.hits.clear();
    out.pOnSweep = out.qOnSweep = false;
    Box3 box;
    box.setEmpty();
    box.extend(p);
    box.extend(q);
    sweep.trianglesOverlapping(box, candidates);
    const auto& V = sweep.vertices();
    for (int t : candidates) {
        if (sweep.isDegenerate(t))
            continue;
        const Tri& tri = sweep.triangles()[t];
        const Vec3 &a = V[tri[0]], &b = V[tri[1]], &c = V[tri[2]];
        const int sp = orient3d(a, b, c, p);
        const int sq = orient3d(a, b, c, q);
        if (sp == 0 || sq == 0) {
            // Touching, not crossing: an endpoint in the plane may lie on the surface.
            if (sp == 0 && !out.pOnSweep && inClosedTriangle(p, a, b, c))
                out.pOnSweep = true;
            if (sq == 0 && !out.qOnSweep && inClosedTriangle(q, a, b, c))
                out.qOnSweep = true;
            continue;
        }
        if (sp == sq)
            continue;
        // The line p-q pierces the closed triangle iff the three edge orientations agree.
        const int e[3] = {orient3d(p, q, a, b), orient3d(p, q, b, c), orient3d(p, q, c, a)};
        int pos = 0, neg = 0, zero = 0;
        for (int s : e)
            (s > 0 ? pos : s < 0 ? neg : zero) += 1;
        if (pos > 0 && neg > 0)
            continue;
        SegmentHit hit;
        hit.triangle = t;
        hit.sideP = sp;
        if (zero == 0)
            hit.feature = interiorKey(t);
        else if (zero == 1)
            hit.feature = e[0] == 0   ? edgeKey(tri[0], tri[1])
                          : e[1] == 0 ? edgeKey(tri[1], tri[2])
                                      : edgeKey(tri[2], tri[0]);
        else
            hit.feature = (e[0] == 0 && e[1] == 0)   ? vertexKey(tri[1])
                          : (e[1] == 0 && e[2] == 0) ? vertexKey(tri[2])
                                                     : vertexKey(tri[0]);
        if (std::any_of(out.hits.begin(), out.hits.end(),
                        [&](const SegmentHit& h) { return h.feature == hit.feature; }))
            continue;
        // Floating-point crossing parameter from the signed distances to the plane, and
        // barycentric coordinates from the volumes spanned with the triangle's edges.
        const double vp = signedVolume(a, b, c, p);
        const double vq = signedVolume(a, b, c, q);
        hit.t = std::clamp(vp / (vp - vq), 0.0, 1.0);
        hit.point = p + hit.t * (q - p);
        Vec3 w(std::abs(signedVolume(p, q, b, c)), std::abs(signedVolume(p, q, c, a)),
               std::abs(signedVolume(p, q, a, b)));
        const double sum = w.sum();
        w = sum > 0 ? Vec3(w / sum) : Vec3(1.0 / 3, 1.0 / 3, 1.0 / 3);
        hit.uv = sweep.uvAt(t, w);
        out.hits.push_back(hit);
    }
    std::sort(out.hits.begin(), out.hits.end(),
              [](const SegmentHit& x, const SegmentHit& y) { return x.t < y.t; });
}

} // namespace resect
