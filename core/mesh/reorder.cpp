#include "core/mesh/reorder.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <numeric>

namespace resect {
namespace {

/// Spreads the low 21 bits of x so that they occupy every third bit.
std::uint64_t spreadBits(std::uint64_t x) {
    x &= 0x1fffff;
    x = (x | x << 32) & 0x1f00000000ffffull;
    x = (x | x << 16) & 0x1f0000ff0000ffull;
    x = (x | x << 8) & 0x100f00f00f00f00full;
    x = (x | x << 4) & 0x10c30c30c30c30c3ull;
    x = (x | x << 2) & 0x1249249249249249ull;
    return x;
}

/// Z-order codes of points in the box [lo, lo + size], 21 bits per axis.
struct MortonGrid {
    Vec3 lo;
    double scale;  // cells per unit length, the same on every axis (the curve keeps its shape)
    std::uint64_t code(const Vec3& p) const {
        const Vec3 c = ((p - lo) * scale).cwiseMax(0.0).cwiseMin(2097151.0);
        return spreadBits(static_cast<std::uint64_t>(c.x())) | spreadBits(static_cast<std::uint64_t>(c.y())) << 1 |
               spreadBits(static_cast<std::uint64_t>(c.z())) << 2;
    }
};

/// Indices 0..n-1 sorted by code (ties by index: the order is deterministic).
std::vector<int> sortedBy(const std::vector<std::uint64_t>& code) {
    std::vector<int> order(code.size());
    std::iota(order.begin(), order.end(), 0);
    std::sort(order.begin(), order.end(), [&](int a, int b) { return code[a] != code[b] ? code[a] < code[b] : a < b; });
    return order;
}

} // namespace

Reordering reorderForLocality(TetMesh& mesh) {
    Reordering r;
    const int nodes = mesh.nodeCount(), tets = mesh.tetCount();
    if (nodes == 0)
        return r;
    Vec3 lo = mesh.ref(0), hi = mesh.ref(0);
    for (const Vec3& p : mesh.referencePositions()) {
        lo = lo.cwiseMin(p);
        hi = hi.cwiseMax(p);
    }
    const double extent = (hi - lo).maxCoeff();
    const MortonGrid grid{lo, extent > 0 && std::isfinite(extent) ? 2097151.0 / extent : 0.0};

    std::vector<std::uint64_t> code(nodes);
    for (int n = 0; n < nodes; ++n)
        code[n] = grid.code(mesh.ref(n));
    const std::vector<int> nodeOrder = sortedBy(code);  // new -> old
    r.newNode.resize(nodes);
    for (int i = 0; i < nodes; ++i)
        r.newNode[nodeOrder[i]] = i;

    code.assign(tets, 0);
    for (int t = 0; t < tets; ++t) {
        const Tet& q = mesh.tet(t);
        code[t] = grid.code(0.25 * (mesh.ref(q[0]) + mesh.ref(q[1]) + mesh.ref(q[2]) + mesh.ref(q[3])));
    }
    const std::vector<int> tetOrder = sortedBy(code);
    r.newTet.resize(tets);
    for (int i = 0; i < tets; ++i)
        r.newTet[tetOrder[i]] = i;

    std::vector<Vec3> ref(nodes), pos(nodes), vel(nodes);
    std::vector<double> mass(nodes);
    for (int i = 0; i < nodes; ++i) {
        const int old = nodeOrder[i];
        ref[i] = mesh.ref(old);
        pos[i] = mesh.pos(old);
        vel[i] = mesh.velocities()[old];
        mass[i] = mesh.masses()[old];
    }
    std::vector<Tet> newTets(tets);
    for (int i = 0; i < tets; ++i) {
        Tet q = mesh.tet(tetOrder[i]);
        for (int& v : q)
            v = r.newNode[v];  // the corners keep their order: the orientation is unchanged
        newTets[i] = q;
    }
    TetMesh out = TetMesh::fromArrays(std::move(ref), std::move(newTets));
    std::copy(pos.begin(), pos.end(), out.positions().begin());
    std::copy(vel.begin(), vel.end(), out.velocities().begin());
    std::copy(mass.begin(), mass.end(), out.masses().begin());
    mesh = std::move(out);
    return r;
}

double nodeIndexSpread(const TetMesh& mesh) {
    if (mesh.tetCount() == 0 || mesh.nodeCount() == 0)
        return 0;
    double sum = 0;
    for (const Tet& q : mesh.tets()) {
        const auto [lo, hi] = std::minmax_element(q.begin(), q.end());
        sum += *hi - *lo;
    }
    return sum / mesh.tetCount() / mesh.nodeCount();
}

} // namespace resect
