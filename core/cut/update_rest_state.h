#pragma once
// Step 8 of the cut (section 4.7): the rest state after a cut. Rest edge lengths and rest
// volumes are the reference geometry; node masses follow Eq. 3 and stiffnesses Eq. 4. Only
// nodes whose incident tets changed are updated.

#include "core/cut/cut_types.h"
#include "core/mesh/material.h"

#include <vector>

namespace resect {

/// Eq. 3 for the given nodes: m_i = k * sum over incident tets of V0 / 4 (density k).
void updateMasses(TetMesh& mesh, const std::vector<int>& nodes, double density);

/// Eq. 4, spring on edge (a, b): k_s = k (m_a + m_b) / l0^2 (stiffness constant k); 0 for
/// an edge of zero rest length.
double springStiffness(const TetMesh& mesh, int a, int b, const Material& material);
/// Eq. 4, volume term of tet t: k_v = k (m_1 + m_2 + m_3 + m_4) / V0^2; 0 for a tet of zero
/// rest volume.
double volumeStiffness(const TetMesh& mesh, int t, const Material& material);

} // namespace resect
