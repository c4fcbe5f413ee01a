#pragma once
// JSON summaries of a tet mesh, shared by `resect info`, cut reports and the studio.

#include "core/mesh/material.h"
#include "core/mesh/tet_mesh.h"

#include <QJsonObject>

namespace resect {

/// The keys of DESIGN.md's cut report "before"/"after" objects: nodes, edges, tets, volume,
/// mass, min_radius_ratio, volume_ratio, edge_ratio, stable_dt, pieces, inverted; plus
/// min_aspect_ratio_paper (the paper's tet_minAR = min_radius_ratio / 3), mean_radius_ratio,
/// min_edge, max_edge, mean_edge, min_dihedral_deg, max_dihedral_deg, boundary_faces, and
/// overlap: how deep the mesh overlaps itself (deepestOverlap, core/mesh/validity.h; 0 for a
/// conforming mesh; issue 16's known defect where both walls of a crack stay).
/// Non-finite ratios (a zero-volume tet) are written as null.
QJsonObject meshStatsJson(const TetMesh& mesh, const Material& material);

/// meshStatsJson plus "validity": {"valid", "problem_count", "by_kind": {kind: count},
/// "problems": [first 20 messages]}.
QJsonObject meshInfoJson(const TetMesh& mesh, const Material& material);

} // namespace resect
