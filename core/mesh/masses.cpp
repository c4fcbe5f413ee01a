#include "core/mesh/masses.h"

#include <algorithm>
#include <cmath>

namespace resect {

void computeLumpedMasses(TetMesh& mesh, double density) {
    // Eq. 3: m_i = k * sum_j V0_j / 4. Inverted tets contribute |V0| so that a bad mesh
    // still gets positive masses; the validity check reports the inversion.
    auto mass = mesh.masses();
    std::fill(mass.begin(), mass.end(), 0.0);
    for (int t = 0; t < mesh.tetCount(); ++t) {
        const double quarter = density * std::abs(mesh.referenceVolume(t)) / 4.0;
        for (int v : mesh.tet(t))
            mass[v] += quarter;
    }
}

double sumOfMasses(const TetMesh& mesh) {
    double sum = 0;
    for (double m : mesh.masses())
        sum += m;
    return sum;
}

} // namespace resect
