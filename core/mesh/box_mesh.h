#pragma once
// Structured tet mesh of an axis-aligned box: nx * ny * nz cubes, each split into six tets
// along its main diagonal (Kuhn / Freudenthal subdivision, conforming across cubes).
// Used by tests (known volume and topology) and by the scaling benchmarks.

#include "core/mesh/tet_mesh.h"

namespace resect {

/// Node (i, j, k) has index i + (nx + 1) * (j + (ny + 1) * k). Tets are positively
/// oriented. Requires nx, ny, nz >= 1 and lo < hi componentwise.
TetMesh makeBoxTetMesh(const Vec3& lo, const Vec3& hi, int nx, int ny, int nz);

} // namespace resect
