#include "core/cut/update_rest_state.h"

#include <cmath>

namespace resect {

void updateMasses(TetMesh& mesh, const std::vector<int>& nodes, double density) {
    for (int n : nodes) {
        double m = 0;
        for (int t : mesh.nodeTets(n))
            m += std::abs(mesh.referenceVolume(t)) / 4.0;
        mesh.setMass(n, density * m);
    }
}

double springStiffness(const TetMesh& mesh, int a, int b, const Material& material) {
    const double l2 = (mesh.ref(b) - mesh.ref(a)).squaredNorm();
    return l2 > 0 ? material.stiffness * (mesh.masses()[a] + mesh.masses()[b]) / l2 : 0.0;
}

double volumeStiffness(const TetMesh& mesh, int t, const Material& material) {
    const double v0 = mesh.referenceVolume(t);
    double m = 0;
    for (int v : mesh.tet(t))
        m += mesh.masses()[v];
    return v0 != 0 ? material.stiffness * m / (v0 * v0) : 0.0;
}

} // namespace resect
