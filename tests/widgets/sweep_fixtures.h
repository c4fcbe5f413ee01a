#pragma once
// Sweeps for widget and studio tests.

#include "core/mesh/tet_mesh.h"
#include "scenario/scenario_document.h"

namespace resect::test {

/// A horizontal plane through the mesh at `heightFraction` of its height (reference
/// positions), as a sweep from a start curve before the mesh to an end curve behind it, each
/// reaching 10 % beyond the mesh. `tilt` raises each later corner by that much (mm), so that
/// the plane is not aligned with anything.
inline SweepSpec planeSweep(const TetMesh& mesh, double heightFraction, double tilt = 0) {
    Vec3 lo = mesh.ref(0), hi = mesh.ref(0);
    for (const Vec3& p : mesh.referencePositions()) {
        lo = lo.cwiseMin(p);
        hi = hi.cwiseMax(p);
    }
    const Vec3 pad = 0.1 * (hi - lo);
    const double z = lo.z() + heightFraction * (hi.z() - lo.z());
    SweepSpec s;
    s.name = "plane";
    s.curves = {{Vec3(lo.x() - pad.x(), lo.y() - pad.y(), z), Vec3(hi.x() + pad.x(), lo.y() - pad.y(), z + tilt)},
                {Vec3(lo.x() - pad.x(), hi.y() + pad.y(), z + 2 * tilt),
                 Vec3(hi.x() + pad.x(), hi.y() + pad.y(), z + 3 * tilt)}};
    return s;
}

} // namespace resect::test
