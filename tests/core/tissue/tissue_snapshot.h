#pragma once
// Everything a Tissue holds, as plain data compared bit for bit: the mesh (node arrays, tets
// and every node's adjacency list in order), the embedded surface and its binding, the
// anchors, the schemes, and (when simulating) the simulator's time, steps and energy.
#include "core/mesh/tet_mesh.h"
#include "core/tissue/tissue.h"

#include <QString>
#include <QStringList>

#include <cstring>
#include <map>
#include <vector>

namespace resect::testing {

template <class T> bool sameBits(const std::vector<T>& a, const std::vector<T>& b) {
    return a.size() == b.size() && (a.empty() || std::memcmp(a.data(), b.data(), a.size() * sizeof(T)) == 0);
}

template <class T> std::vector<T> copyOf(std::span<const T> s) { return std::vector<T>(s.begin(), s.end()); }

struct TissueSnapshot {
    std::vector<Vec3> ref, pos, vel;
    std::vector<double> mass;
    std::vector<Tet> tets;
    std::vector<std::vector<int>> adjacency;
    std::vector<Vec3> surfacePositions;
    std::vector<Tri> surfaceTriangles;
    std::vector<Eigen::Vector2d> surfaceUvs, surfaceCutUvs;
    std::vector<std::uint8_t> surfaceCutFaces;
    std::vector<int> boundTet;
    std::vector<std::array<double, 4>> boundWeights;
    std::vector<int> anchors;
    std::vector<Scheme> schemes;
    int cuts = 0;
    double simTime = 0;
    int simSteps = 0;

    explicit TissueSnapshot(const Tissue& t) {
        const TetMesh& m = t.mesh();
        ref = copyOf(m.referencePositions());
        pos = copyOf(m.positions());
        vel = copyOf(m.velocities());
        mass = copyOf(m.masses());
        tets = m.tets();
        for (int n = 0; n < m.nodeCount(); ++n)
            adjacency.push_back(copyOf(m.nodeTets(n)));
        const TriangleSurface& s = t.surface().surface();
        surfacePositions = s.positions;
        surfaceTriangles = s.triangles;
        surfaceUvs = s.uvs;
        surfaceCutUvs = s.cutUvs;
        surfaceCutFaces = s.cutFaces;
        for (int v = 0; v < t.surface().binding().vertexCount(); ++v) {
            boundTet.push_back(t.surface().binding().tetOf(v));
            boundWeights.push_back(t.surface().binding().weightsOf(v));
        }
        anchors = t.anchors().nodes();
        schemes = t.schemes();
        cuts = t.cutCount();
        if (const Simulator* sim = t.simulator()) {
            simTime = sim->time();
            simSteps = sim->stepsTaken();
        }
    }

    /// Empty if equal, else what differs.
    QString differenceTo(const TissueSnapshot& o) const {
        QStringList d;
        if (!sameBits(ref, o.ref)) d << "reference positions";
        if (!sameBits(pos, o.pos)) d << "positions";
        if (!sameBits(vel, o.vel)) d << "velocities";
        if (!sameBits(mass, o.mass)) d << "masses";
        if (!sameBits(tets, o.tets)) d << "tets";
        if (adjacency != o.adjacency) d << "node adjacency";
        if (!sameBits(surfacePositions, o.surfacePositions)) d << "surface positions";
        if (!sameBits(surfaceTriangles, o.surfaceTriangles)) d << "surface triangles";
        if (!sameBits(surfaceUvs, o.surfaceUvs)) d << "surface uvs";
        if (!sameBits(surfaceCutUvs, o.surfaceCutUvs)) d << "surface cut uvs";
        if (!sameBits(surfaceCutFaces, o.surfaceCutFaces)) d << "surface cut faces";
        if (!sameBits(boundTet, o.boundTet) || !sameBits(boundWeights, o.boundWeights)) d << "binding";
        if (anchors != o.anchors) d << "anchors";
        if (schemes != o.schemes) d << "schemes";
        if (cuts != o.cuts) d << "cut count";
        if (simTime != o.simTime || simSteps != o.simSteps) d << "simulation clock";
        return d.join(", ");
    }
};

/// True if every edge of the surface is in exactly two triangles, once in each direction.
inline bool surfaceIsClosed(const TriangleSurface& s) {
    std::map<std::pair<int, int>, int> directed;
    for (const Tri& t : s.triangles)
        for (int e = 0; e < 3; ++e)
            ++directed[{t[e], t[(e + 1) % 3]}];
    for (const auto& [e, n] : directed)
        if (n != 1 || directed.count({e.second, e.first}) != 1)
            return false;
    return true;
}

} // namespace resect::testing
