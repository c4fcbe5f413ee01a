#pragma once
// Invariants of a cut embedded surface, shared by the surface tests: closed and 2-manifold
// (every edge in exactly two triangles, once in each direction; every vertex's triangles form
// one fan), and cut faces carrying their sweep (u, v); and the plane sweeps they cut with.
#include "core/mesh/triangle_surface.h"
#include "core/sweep/sweep_surface.h"

#include <QString>
#include <QStringList>

#include <algorithm>
#include <cmath>
#include <map>
#include <unordered_map>
#include <vector>

namespace resect::testing {

/// Empty if the surface is closed and 2-manifold, else the first problems found.
inline QString manifoldProblems(const TriangleSurface& s) {
    QStringList problems;
    std::map<std::pair<int, int>, int> directed;
    for (int t = 0; t < s.triangleCount(); ++t) {
        const Tri& q = s.triangles[t];
        if (q[0] == q[1] || q[1] == q[2] || q[0] == q[2])
            problems << QString("triangle %1 repeats a vertex").arg(t);
        for (int e = 0; e < 3; ++e)
            ++directed[{q[e], q[(e + 1) % 3]}];
    }
    for (const auto& [edge, count] : directed) {
        const auto it = directed.find({edge.second, edge.first});
        const int opposite = it == directed.end() ? 0 : it->second;
        if (count != 1 || opposite != 1) {
            problems << QString("edge (%1, %2): %3 times, opposite %4 times")
                            .arg(edge.first).arg(edge.second).arg(count).arg(opposite);
            if (problems.size() > 8)
                return problems.join("; ");
        }
    }
    // Fans: the triangles around each vertex, chained by shared edges, form one cycle.
    std::unordered_map<int, std::vector<std::pair<int, int>>> wedges;  // vertex -> (next, prev)
    for (const Tri& q : s.triangles)
        for (int e = 0; e < 3; ++e)
            wedges[q[e]].push_back({q[(e + 1) % 3], q[(e + 2) % 3]});
    for (const auto& [v, list] : wedges) {
        std::unordered_map<int, int> next;  // a -> b for wedge (a, b)
        for (const auto& [a, b] : list)
            next[a] = b;
        int steps = 0;
        int x = list.front().first;
        do {
            auto it = next.find(x);
            if (it == next.end())
                break;
            x = it->second;
            ++steps;
        } while (x != list.front().first && steps <= static_cast<int>(list.size()));
        if (steps != static_cast<int>(list.size())) {
            problems << QString("vertex %1: its %2 triangles form more than one fan").arg(v).arg(list.size());
            if (problems.size() > 8)
                break;
        }
    }
    return problems.join("; ");
}

/// Empty if every vertex of a cut face has a finite (u, v) in [0, 1]^2.
inline QString capUvProblems(const TriangleSurface& s) {
    for (int t = 0; t < s.triangleCount(); ++t) {
        if (!s.isCutFace(t))
            continue;
        for (int v : s.triangles[t]) {
            const auto& uv = s.cutUvs[v];
            if (!uv.allFinite() || (uv.array() < -1e-12).any() || (uv.array() > 1 + 1e-12).any())
                return QString("cut face %1: vertex %2 has (u, v) (%3, %4)").arg(t).arg(v).arg(uv.x()).arg(uv.y());
        }
    }
    return {};
}

/// A plane sweep through point p (exactly: p is a vertex of the sweep) with normal roughly n.
inline bool planeThrough(const Vec3& p, const Vec3& n, double size, SweepSurface& out) {
    const Vec3 a = n.unitOrthogonal(), b = n.normalized().cross(a);
    const std::vector<Vec3> start{p - size * a - size * b, p - size * b, p + size * a - size * b};
    const std::vector<Vec3> middle{p - size * a, p, p + size * a};
    const std::vector<Vec3> end{p - size * a + size * b, p + size * b, p + size * a + size * b};
    return SweepSurface::fromCurves({start, middle, end}, out).ok();
}

} // namespace resect::testing
