#pragma once
// Lumped node masses, Eq. 3 (section 4.7): m_i = k * sum_j V0_j / 4 over incident tets j.

#include "core/mesh/material.h"
#include "core/mesh/tet_mesh.h"

namespace resect {

/// Sets every node's mass from the reference volumes of its tets and the density.
void computeLumpedMasses(TetMesh& mesh, double density);

/// The sum of the node masses (g).
double sumOfMasses(const TetMesh& mesh);

} // namespace resect
