#pragma once
// Picking on a triangle surface with a camera ray (camera_ray.h): where a click lands on
// the tissue, for placing sweep points and choosing a stroke's depth. Pure geometry on the
// CPU (no renderer), so it works under the `offscreen` platform.

#include "core/mesh/tet_mesh.h"
#include "core/mesh/triangle_surface.h"
#include "widgets/camera_ray.h"

#include <optional>

namespace resect {

/// The nearest point (smallest s >= 0) where the ray meets a triangle of the surface; both
/// sides of a triangle count. Triangles of zero area and non-finite positions are skipped.
/// Brute force, O(#triangles): meant for one pick per click.
std::optional<Vec3> raySurfaceHit(const Ray& ray, const TriangleSurface& surface);

/// The boundary of a tet mesh at its current positions, as a surface to pick on
/// (outward-oriented boundary faces; every node is kept so indices match the mesh).
TriangleSurface pickSurfaceOf(const TetMesh& mesh);

} // namespace resect
