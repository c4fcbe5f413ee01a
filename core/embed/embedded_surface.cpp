#include "core/embed/embedded_surface.h"

#include <chrono>
#include <limits>

namespace resect {

Status EmbeddedSurface::bind(const TetMesh& mesh, TriangleSurface surface) {
    m_surface = {};
    m_binding = {};
    if (Status s = m_binding.bind(mesh, surface); !s.ok())
        return s;
    m_surface = std::move(surface);
    // Cut-face data from the start, and headroom, so that cuts append without moving the
    // whole surface (a cut then costs in proportion to what it touches, plus one bounding-box
    // pass over the triangles; see cutSurface).
    m_surface.cutUvs.resize(m_surface.positions.size(), Vec2::Constant(std::numeric_limits<double>::quiet_NaN()));
    m_surface.cutFaces.resize(m_surface.triangles.size(), 0);
    const auto headroom = [](auto& v) { v.reserve(v.size() + v.size() / 4 + 1024); };
    headroom(m_surface.positions);
    headroom(m_surface.uvs);
    headroom(m_surface.cutUvs);
    headroom(m_surface.triangles);
    headroom(m_surface.cutFaces);
    return Status::success();
}

void EmbeddedSurface::update(const TetMesh& mesh) {
    if (!empty())
        m_binding.apply(mesh, m_surface.positions);
}

Status EmbeddedSurface::cut(const TetMesh& mesh, const CutChanges& changes, const SweepSurface& sweep,
                            EmbeddedCut* stats) {
    if (empty())
        return Status::success();
    using Clock = std::chrono::steady_clock;
    const auto ms = [](Clock::time_point t0) {
        return std::chrono::duration<double, std::milli>(Clock::now() - t0).count();
    };
    EmbeddedCut c;
    // The surface cut first: it is the one step that may fail, and it changes nothing then.
    // Re-binding only reads the positions of the vertices it re-binds (never moved by the
    // surface cut) and the new vertices are bound after it.
    auto t0 = Clock::now();
    if (Status s = cutSurface(m_surface, nullptr, sweep, c.surface); !s.ok())
        return s;
    c.cutMs = ms(t0);
    t0 = Clock::now();
    c.reboundVertices = m_binding.rebind(mesh, changes, m_surface.positions, sweep);
    c.rebindMs = ms(t0);
    t0 = Clock::now();
    const SurfaceCut& sc = c.surface;
    m_binding.bindNewVertices(mesh, m_surface.positions, sc.firstNewVertex, sc.sourceEdge, sc.side, changes, sweep);
    c.bindNewMs = ms(t0);
    if (stats)
        *stats = std::move(c);
    return Status::success();
}

} // namespace resect
