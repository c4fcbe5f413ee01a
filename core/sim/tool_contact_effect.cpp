#include "core/sim/tool_contact_effect.h"

#include "core/mesh/topology.h"

#include <algorithm>
#include <cmath>

namespace resect {
namespace {

Vec3 closestOnSegment(const Vec3& p, const Vec3& a, const Vec3& b) {
    const Vec3 ab = b - a;
    const double l2 = ab.squaredNorm();
    const double t = l2 > 0 ? std::clamp((p - a).dot(ab) / l2, 0.0, 1.0) : 0.0;
    return a + t * ab;
}

/// A unit vector perpendicular to u (any unit vector if u is zero).
Vec3 perpendicular(const Vec3& u) {
    if (!(u.squaredNorm() > 0))
        return Vec3::UnitZ();
    Vec3 axis = Vec3::Zero();
    Eigen::Index i = 0;
    u.cwiseAbs().minCoeff(&i);
    axis[i] = 1;
    return u.cross(axis).normalized();
}

} // namespace

Status checkTool(const Tool& tool) {
    if (tool.points.empty())
        return Status::error("the tool needs at least one point");
    for (const Vec3& p : tool.points)
        if (!p.allFinite())
            return Status::error("the tool has a non-finite point");
    if (!std::isfinite(tool.radius) || !(tool.radius > 0))
        return Status::error("the tool radius must be finite and positive");
    return Status::success();
}

ToolContactEffect::ToolContactEffect(const TetMesh& mesh, Tool tool)
    : m_tool(std::move(tool)), m_previous(m_tool.points), m_position(mesh.nodeCount(), -1) {
    for (const BoundaryFace& f : boundaryFaces(mesh))
        for (int v : f.nodes)
            setSurface(v, true);
}

void ToolContactEffect::setSurface(int node, bool surface) {
    if (node >= static_cast<int>(m_position.size()))
        m_position.resize(node + 1, -1);
    const int at = m_position[node];
    if (surface && at < 0) {
        m_position[node] = static_cast<int>(m_surface.size());
        m_surface.push_back(node);
    } else if (!surface && at >= 0) {
        const int last = m_surface.back();
        m_surface[at] = last;
        m_position[last] = at;
        m_surface.pop_back();
        m_position[node] = -1;
    }
}

Status ToolContactEffect::setPose(std::span<const Vec3> points) {
    if (points.size() != m_tool.points.size())
        return Status::error("tool pose: expected " + std::to_string(m_tool.points.size()) +
                             " points, got " + std::to_string(points.size()));
    for (const Vec3& p : points)
        if (!p.allFinite())
            return Status::error("tool pose: non-finite point");
    m_tool.points.assign(points.begin(), points.end());
    return Status::success();
}

Vec3 ToolContactEffect::closestPoint(const Vec3& p) const {
    const auto& pts = m_tool.points;
    Vec3 best = pts[0];
    double bestD2 = (p - best).squaredNorm();
    for (std::size_t i = 0; i + 1 < pts.size(); ++i) {
        const Vec3 c = closestOnSegment(p, pts[i], pts[i + 1]);
        const double d2 = (p - c).squaredNorm();
        if (d2 < bestD2) {
            bestD2 = d2;
            best = c;
        }
    }
    return best;
}

bool ToolContactEffect::afterStep(const SimState& s) {
    const double r = m_tool.radius;
    const auto& pts = m_tool.points;
    Vec3 lo = pts[0], hi = pts[0];
    for (const Vec3& p : pts) {
        lo = lo.cwiseMin(p);
        hi = hi.cwiseMax(p);
    }
    lo.array() -= r;
    hi.array() += r;
    // Tool velocity at the pose's points, from the pose of the previous step (a whole step:
    // the pose moves between steps, and a step split into sub-steps moves the tool evenly
    // over all of them).
    std::vector<Vec3> velocity(pts.size(), Vec3::Zero());
    const double interval = s.stepDt > 0 ? s.stepDt : s.dt;
    if (interval > 0)
        for (std::size_t i = 0; i < pts.size(); ++i)
            velocity[i] = (pts[i] - m_previous[i]) / interval;
    const std::size_t segments = pts.size() > 1 ? pts.size() - 1 : 1;
    m_lastContacts = 0;
    for (int n : m_surface) {
        const Vec3 start = s.x[n];
        if ((start.array() < lo.array()).any() || (start.array() > hi.array()).any())
            continue;
        // Push out of every capsule; at a bend of the polyline a push out of one capsule can
        // end inside the next, so repeat a few times.
        Vec3 p = start;
        Vec3& v = s.v[n];
        for (int pass = 0; pass < 4; ++pass) {
            bool inside = false;
            for (std::size_t i = 0; i < segments; ++i) {
                const std::size_t j = pts.size() > 1 ? i + 1 : i;
                const Vec3 ab = pts[j] - pts[i];
                const double l2 = ab.squaredNorm();
                const double t = l2 > 0 ? std::clamp((p - pts[i]).dot(ab) / l2, 0.0, 1.0) : 0.0;
                const Vec3 c = pts[i] + t * ab;
                const Vec3 d = p - c;
                const double dist = d.norm();
                if (dist >= r)
                    continue;
                const Vec3 normal = dist > 0 ? Vec3(d / dist) : perpendicular(ab);
                p = c + r * normal;
                const Vec3 toolVelocity = (1 - t) * velocity[i] + t * velocity[j];
                const double approach = (v - toolVelocity).dot(normal);
                if (approach < 0)
                    v -= approach * normal;
                inside = true;
            }
            if (!inside)
                break;
        }
        if (p != start) {
            s.x[n] = p;
            ++m_lastContacts;
        }
    }
    if (s.lastSubstep)
        m_previous = pts;
    return m_lastContacts > 0;
}

void ToolContactEffect::applyCut(const TetMesh& mesh, const CutChanges& changes) {
    // A node's surface status changes only if its tets changed: it is touched, or a copy.
    if (static_cast<int>(m_position.size()) < mesh.nodeCount())
        m_position.resize(mesh.nodeCount(), -1);
    for (int n : changes.touchedNodes)
        setSurface(n, isBoundaryNode(mesh, n));
    for (const auto& [orig, copy] : changes.duplicatedNodes) {
        setSurface(orig, isBoundaryNode(mesh, orig));
        setSurface(copy, isBoundaryNode(mesh, copy));
    }
}

} // namespace resect
