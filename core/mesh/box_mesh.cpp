#include "core/mesh/box_mesh.h"

#include <algorithm>
#include <array>

namespace resect {

TetMesh makeBoxTetMesh(const Vec3& lo, const Vec3& hi, int nx, int ny, int nz) {
    const auto index = [&](int i, int j, int k) { return i + (nx + 1) * (j + (ny + 1) * k); };
    std::vector<Vec3> points;
    points.reserve(static_cast<std::size_t>(nx + 1) * (ny + 1) * (nz + 1));
    const Vec3 step = (hi - lo).cwiseQuotient(Vec3(nx, ny, nz));
    for (int k = 0; k <= nz; ++k)
        for (int j = 0; j <= ny; ++j)
            for (int i = 0; i <= nx; ++i)
                points.push_back(lo + Vec3(i * step.x(), j * step.y(), k * step.z()));

    // The six paths from corner 000 to 111, one axis at a time.
    static constexpr std::array<std::array<int, 3>, 6> kPaths{
        {{0, 1, 2}, {0, 2, 1}, {1, 0, 2}, {1, 2, 0}, {2, 0, 1}, {2, 1, 0}}};
    std::vector<Tet> tets;
    tets.reserve(static_cast<std::size_t>(nx) * ny * nz * 6);
    for (int k = 0; k < nz; ++k)
        for (int j = 0; j < ny; ++j)
            for (int i = 0; i < nx; ++i)
                for (const auto& path : kPaths) {
                    std::array<int, 3> c{i, j, k};
                    Tet t;
                    t[0] = index(c[0], c[1], c[2]);
                    for (int s = 0; s < 3; ++s) {
                        ++c[path[s]];
                        t[s + 1] = index(c[0], c[1], c[2]);
                    }
                    if (signedVolume(points[t[0]], points[t[1]], points[t[2]], points[t[3]]) < 0)
                        std::swap(t[2], t[3]);
                    tets.push_back(t);
                }
    return TetMesh::fromArrays(std::move(points), std::move(tets));
}

} // namespace resect
