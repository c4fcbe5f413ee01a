#pragma once
// BodySurface: the surface of the body as it was before any cut (the boundary faces of the
// input tet mesh, reference positions), for the rule of issue 16 that no node may leave the
// body's surface: the mesh improvement asks it whether a trial position is outside the body.
//
// Signed distance by the nearest triangle and the angle-weighted pseudo-normal of the feature
// (face, edge or vertex) the nearest point lies on (Baerentzen & Aanaes 2005): the sign is
// right for any point of a closed, consistently oriented surface. Triangles are bucketed in a
// uniform grid of about one mean edge, so a query near the surface costs a few cells.

#include "core/mesh/tet_mesh.h"

#include <memory>
#include <vector>

namespace resect {

/// The point of triangle (a, b, c) nearest to p, by the Voronoi regions of its corners, edges
/// and face; `feature` (if given) says which: 0-2 corner i, 3 + i edge (i, i + 1), 6 the face.
/// A degenerate triangle gives its corner nearest to p.
Vec3 closestPointOnTriangle(const Vec3& p, const Vec3& a, const Vec3& b, const Vec3& c, int* feature = nullptr);

class BodySurface {
public:
    /// The boundary faces of `mesh` (outward), at reference positions. Empty for an empty mesh.
    static std::shared_ptr<const BodySurface> fromBoundary(const TetMesh& mesh);

    bool empty() const { return m_tris.empty(); }
    int triangleCount() const { return static_cast<int>(m_tris.size()); }

    /// The signed distance of p from the surface (positive outside) where a triangle is within
    /// `range` of p, otherwise -range ("inside": a caller that moves a point by at most `range`
    /// from a position inside or on the body passes the surface's triangles on the way out, so
    /// a point with none within range is still inside); and how far off the surface the
    /// nearest triangle allows: the chordal error of a smooth patch (kSharpBend below), zero on
    /// a flat patch or at a sharp edge or corner, where the surface is what it is.
    struct Side {
        double distance = 0;
        double slack = 0;
    };
    Side side(const Vec3& p, double range) const;

    /// Edges whose faces' normals turn by more than this (radians) are sharp features.
    static constexpr double kSharpBend = 0.5;

private:
    struct Nearest {
        double distance;
        int tri = -1;
        int feature = -1;  ///< 0-2: vertex i; 3-5: edge (i, i+1); 6: face
        Vec3 point;
    };
    Nearest nearest(const Vec3& p, double range) const;
    Vec3 featureNormal(const Nearest& n) const;

    std::vector<Vec3> m_points;
    std::vector<Tri> m_tris;
    std::vector<Vec3> m_faceNormals;    ///< unit
    std::vector<Vec3> m_vertexNormals;  ///< angle-weighted sums of face normals
    std::vector<std::array<Vec3, 3>> m_edgeNormals;  ///< per triangle edge (i, i+1): sum of its faces' normals
    std::vector<double> m_slack;  ///< per triangle: largest sagitta of its smooth edges and theirs at its corners
    // Grid: origin, cell size, dims; cell -> triangles (CSR).
    Vec3 m_origin = Vec3::Zero();
    double m_cell = 1;
    std::array<int, 3> m_dims{0, 0, 0};
    std::vector<int> m_cellStart, m_cellTris;
};

} // namespace resect
