#pragma once
// Exact comparisons of tissues for widget tests: the studio must cut bit-identically to a
// Tissue cut directly (core/tissue/tissue.h).

#include "core/tissue/tissue.h"

#include <QString>

#include <span>

namespace resect::test {

/// The first index where two spans differ (exact ==), or -1; the sizes must match first.
template <class T> long long firstDifference(std::span<const T> a, std::span<const T> b) {
    if (a.size() != b.size())
        return 0;
    for (std::size_t i = 0; i < a.size(); ++i)
        if (!(a[i] == b[i]))
            return static_cast<long long>(i);
    return -1;
}

/// Empty if the two meshes are bit-identical (positions, reference positions, masses, tets);
/// else what differs first.
inline QString meshDifference(const TetMesh& a, const TetMesh& b) {
    if (a.nodeCount() != b.nodeCount() || a.tetCount() != b.tetCount())
        return QStringLiteral("%1 nodes, %2 tets vs %3 nodes, %4 tets")
            .arg(a.nodeCount())
            .arg(a.tetCount())
            .arg(b.nodeCount())
            .arg(b.tetCount());
    if (const auto i = firstDifference(a.positions(), b.positions()); i >= 0)
        return QStringLiteral("position of node %1").arg(i);
    if (const auto i = firstDifference(a.referencePositions(), b.referencePositions()); i >= 0)
        return QStringLiteral("reference position of node %1").arg(i);
    if (const auto i = firstDifference(a.masses(), b.masses()); i >= 0)
        return QStringLiteral("mass of node %1").arg(i);
    if (const auto i =
            firstDifference(std::span<const Tet>(a.tets()), std::span<const Tet>(b.tets()));
        i >= 0)
        return QStringLiteral("tet %1").arg(i);
    return {};
}

/// Empty if the two tissues' meshes, surfaces (positions and triangles), schemes and anchors
/// are bit-identical; else what differs first.
inline QString tissueDifference(const Tissue& a, const Tissue& b) {
    if (QString d = meshDifference(a.mesh(), b.mesh()); !d.isEmpty())
        return QStringLiteral("mesh: ") + d;
    const TriangleSurface& sa = a.surface().surface();
    const TriangleSurface& sb = b.surface().surface();
    if (sa.vertexCount() != sb.vertexCount() || sa.triangleCount() != sb.triangleCount())
        return QStringLiteral("surface: %1 vertices, %2 triangles vs %3, %4")
            .arg(sa.vertexCount())
            .arg(sa.triangleCount())
            .arg(sb.vertexCount())
            .arg(sb.triangleCount());
    if (const auto i = firstDifference(std::span<const Vec3>(sa.positions),
                                       std::span<const Vec3>(sb.positions));
        i >= 0)
        return QStringLiteral("surface vertex %1").arg(i);
    if (sa.triangles != sb.triangles)
        return QStringLiteral("surface triangles");
    if (a.schemes() != b.schemes())
        return QStringLiteral("schemes");
    if (a.anchors().nodes() != b.anchors().nodes())
        return QStringLiteral("anchors");
    return {};
}

} // namespace resect::test
