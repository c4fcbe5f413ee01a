#include "core/embed/surface_index.h"

#include <algorithm>

namespace resect {

namespace {

/// Corner code of cutSurface's candidate test: one bit per face of the box that p lies
/// strictly beyond.
int outside(const Vec3& p, const Vec3& lo, const Vec3& hi) {
    return (p.x() < lo.x() ? 1 : 0) | (p.x() > hi.x() ? 2 : 0) | (p.y() < lo.y() ? 4 : 0) | (p.y() > hi.y() ? 8 : 0) |
           (p.z() < lo.z() ? 16 : 0) | (p.z() > hi.z() ? 32 : 0);
}

} // namespace

void SurfaceIndex::build(const TriangleSurface& surface) {
    m_vertexBoxes.clear();
    m_refs.assign((surface.triangleCount() + kTriangleBlock - 1) / kTriangleBlock, {});
    m_vertices = 0;
    m_stale = true;
    for (int t = 0; t < surface.triangleCount(); ++t)
        addTriangle(surface, t);
}

void SurfaceIndex::addTriangle(const TriangleSurface& surface, int t) {
    const int block = t / kTriangleBlock;
    if (static_cast<int>(m_refs.size()) <= block)
        m_refs.resize(block + 1);
    std::vector<int>& refs = m_refs[block];
    for (int v : surface.triangles[t]) {
        const int vb = v / kVertexBlock;
        if (std::find(refs.begin(), refs.end(), vb) == refs.end())
            refs.push_back(vb);
    }
}

void SurfaceIndex::growVertexBox(const Vec3& p, int block) {
    if (static_cast<int>(m_vertexBoxes.size()) <= block)
        m_vertexBoxes.resize(block + 1, Box3());  // (an empty box)
    m_vertexBoxes[block].extend(p);
}

void SurfaceIndex::refit(const TriangleSurface& surface) {
    const int n = surface.vertexCount();
    m_vertexBoxes.assign((n + kVertexBlock - 1) / kVertexBlock, Box3());
    for (int b = 0; b < static_cast<int>(m_vertexBoxes.size()); ++b) {
        const int end = std::min(n, (b + 1) * kVertexBlock);
        Vec3 lo = surface.positions[b * kVertexBlock], hi = lo;
        for (int v = b * kVertexBlock + 1; v < end; ++v) {
            lo = lo.cwiseMin(surface.positions[v]);
            hi = hi.cwiseMax(surface.positions[v]);
        }
        m_vertexBoxes[b] = Box3(lo, hi);
    }
    m_vertices = n;
    m_stale = false;
}

Box3 SurfaceIndex::triangleBlockBox(int block) const {
    Box3 box;
    for (int vb : m_refs[block])
        box.extend(m_vertexBoxes[vb]);
    return box;
}

void SurfaceIndex::candidates(const TriangleSurface& surface, const Box3& box, std::vector<int>& out) {
    out.clear();
    if (m_stale || m_vertices != surface.vertexCount())
        refit(surface);
    const Vec3 lo = box.min(), hi = box.max();
    const int blocks = std::min(static_cast<int>(m_refs.size()),
                                (surface.triangleCount() + kTriangleBlock - 1) / kTriangleBlock);
    for (int b = 0; b < blocks; ++b) {
        // A block whose box lies strictly beyond a face of the query holds no candidate.
        const Box3 bb = triangleBlockBox(b);
        if ((bb.max().array() < lo.array()).any() || (bb.min().array() > hi.array()).any())
            continue;
        const int end = std::min(surface.triangleCount(), (b + 1) * kTriangleBlock);
        for (int t = b * kTriangleBlock; t < end; ++t) {
            const Tri& q = surface.triangles[t];
            if ((outside(surface.positions[q[0]], lo, hi) & outside(surface.positions[q[1]], lo, hi) &
                 outside(surface.positions[q[2]], lo, hi)) == 0)
                out.push_back(t);
        }
    }
}

void SurfaceIndex::followCut(const TriangleSurface& surface, int firstNewVertex, int firstNewTriangle,
                             std::span<const int> replaced) {
    if (!m_stale && m_vertices == firstNewVertex) {
        for (int v = firstNewVertex; v < surface.vertexCount(); ++v)
            growVertexBox(surface.positions[v], v / kVertexBlock);
        m_vertices = surface.vertexCount();
    } else {
        m_stale = true;  // refit at the next query anyway
    }
    for (int t : replaced)
        addTriangle(surface, t);
    for (int t = firstNewTriangle; t < surface.triangleCount(); ++t)
        addTriangle(surface, t);
}

} // namespace resect
