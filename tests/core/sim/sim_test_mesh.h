#pragma once
// Meshes and state set-ups shared by the simulation tests.
#include "core/mesh/box_mesh.h"
#include "core/mesh/masses.h"
#include "core/mesh/material.h"
#include "core/sweep/sweep_surface.h"

#include <QtGlobal>

#include <random>

namespace resect::testing {

/// A box of cells (nx, ny, nz) unit cubes, its interior nodes jittered by up to `jitter` (a
/// fraction of the cell), with lumped masses (Eq. 3) at the default density.
inline TetMesh simBox(int nx, int ny, int nz, double jitter = 0.2, unsigned seed = 1) {
    TetMesh m = makeBoxTetMesh(Vec3::Zero(), Vec3(nx, ny, nz), nx, ny, nz);
    std::mt19937 rng(seed);
    std::uniform_real_distribution<double> u(-jitter, jitter);
    for (int n = 0; n < m.nodeCount(); ++n) {
        const Vec3 p = m.ref(n);
        const bool interior =
            p.x() > 0 && p.y() > 0 && p.z() > 0 && p.x() < nx && p.y() < ny && p.z() < nz;
        if (interior) {
            m.referencePositions()[n] += Vec3(u(rng), u(rng), u(rng));
            m.positions()[n] = m.ref(n);
        }
    }
    computeLumpedMasses(m, Material{}.density);
    return m;
}

/// Moves every node by a random displacement of up to `amplitude` (mm), reproducibly.
inline void perturb(TetMesh& m, double amplitude, unsigned seed = 7) {
    std::mt19937 rng(seed);
    std::uniform_real_distribution<double> u(-amplitude, amplitude);
    for (Vec3& p : m.positions())
        p += Vec3(u(rng), u(rng), u(rng));
}

/// The planar sweep from the segment (a0, a1) to the segment (b0, b1).
inline SweepSurface quad(const Vec3& a0, const Vec3& a1, const Vec3& b0, const Vec3& b1) {
    SweepSurface s;
    if (const Status st = SweepSurface::fromStartEnd({a0, a1}, {b0, b1}, s); !st.ok())
        qFatal("%s", st.message().c_str());
    return s;
}

/// Tets with non-positive current volume.
inline int countInvertedTets(const TetMesh& m) {
    int n = 0;
    for (int t = 0; t < m.tetCount(); ++t)
        n += !(m.currentVolume(t) > 0);
    return n;
}

} // namespace resect::testing
