#pragma once
// Invariants every cut must keep, shared by the cut tests.
#include "core/cut/hybrid_cutter.h"
#include "core/mesh/topology.h"
#include "core/mesh/validity.h"
#include "core/sweep/intersect_segment.h"

#include <QString>
#include <QStringList>

#include "core/mesh/box_mesh.h"

#include <random>
#include <unordered_set>

namespace resect::testing {

/// A cube of side `scale` split into cells^3 Kuhn cubes, its interior nodes moved at random
/// by up to `jitter` times the cube size (reproducible from `seed`).
inline TetMesh jitteredBox(double scale, unsigned seed, double jitter, int cells = 6) {
    TetMesh m = makeBoxTetMesh(Vec3::Zero(), Vec3(1, 1, 1) * scale, cells, cells, cells);
    std::mt19937 rng(seed);
    std::uniform_real_distribution<double> u(-jitter * scale, jitter * scale);
    for (int n = 0; n < m.nodeCount(); ++n) {
        const Vec3 p = m.ref(n);
        if ((p.array() > 1e-9 * scale).all() && (p.array() < scale * (1 - 1e-9)).all()) {
            m.referencePositions()[n] += Vec3(u(rng), u(rng), u(rng));
            m.positions()[n] = m.ref(n);
        }
    }
    return m;
}

/// Empty if the mesh after a cut is valid: volume conserved to `volumeTolerance` relative,
/// no validity problem (inverted or flat tets, over-shared faces, T-junctions, unused or
/// non-finite nodes), and no edge crossing the sweep unless it ends on the cut surface
/// (an edge crossed twice joins nodes on the same side: such crossings are discarded by
/// design, section 4.3, and only an odd number of crossings counts).
inline QString cutViolations(const TetMesh& mesh, const SweepSurface& sweep, double volumeBefore,
                             const CutResult& result, double volumeTolerance = 1e-9) {
    QStringList problems;
    const double volume = mesh.totalReferenceVolume();
    if (std::abs(volume - volumeBefore) > volumeTolerance * std::abs(volumeBefore))
        problems << QString("volume %1 -> %2").arg(volumeBefore, 0, 'g', 17).arg(volume, 0, 'g', 17);
    for (const MeshProblem& p : checkValidity(mesh)) {
        problems << QString::fromStdString(p.message);
        if (problems.size() > 10)
            break;
    }
    const std::unordered_set<int> onCut(result.changes.cutSurfaceNodes.begin(),
                                        result.changes.cutSurfaceNodes.end());
    SegmentQuery query;
    std::vector<int> scratch;
    int crossing = 0;
    for (const auto& e : uniqueEdges(mesh)) {
        if (onCut.count(e[0]) || onCut.count(e[1]))
            continue;
        intersectSegment(sweep, mesh.pos(e[0]), mesh.pos(e[1]), query, scratch);
        if (query.hits.size() % 2 == 1 && crossing++ < 5)
            problems << QString("edge (%1, %2) crosses the sweep").arg(e[0]).arg(e[1]);
    }
    return problems.join("; ");
}

} // namespace resect::testing
