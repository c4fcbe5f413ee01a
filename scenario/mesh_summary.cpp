#include "scenario/mesh_summary.h"

#include "core/mesh/quality.h"
#include "core/mesh/stable_time_step.h"
#include "core/mesh/topology.h"
#include "core/mesh/validity.h"

#include <QJsonArray>

#include <cmath>
#include <map>

namespace resect {
namespace {
QJsonValue number(double v) { return std::isfinite(v) ? QJsonValue(v) : QJsonValue(); }
} // namespace

QJsonObject meshStatsJson(const TetMesh& mesh, const Material& material) {
    const QualitySummary q = summarizeQuality(mesh);
    double mass = 0;
    for (double m : mesh.masses())
        mass += m;
    int inverted = 0;
    for (int t = 0; t < mesh.tetCount(); ++t)
        if (!(mesh.referenceVolume(t) > 0) || !(mesh.currentVolume(t) > 0))
            ++inverted;
    QJsonObject o;
    o["nodes"] = q.nodes;
    o["edges"] = q.edges;
    o["tets"] = q.tets;
    o["volume"] = number(q.volume);
    o["mass"] = number(mass);
    o["min_radius_ratio"] = number(q.minRadiusRatio);
    o["min_aspect_ratio_paper"] = number(q.minAspectRatioPaper);
    o["mean_radius_ratio"] = number(q.meanRadiusRatio);
    o["volume_ratio"] = number(q.volumeRatio);
    o["edge_ratio"] = number(q.edgeRatio);
    o["min_edge"] = number(q.minEdge);
    o["max_edge"] = number(q.maxEdge);
    o["mean_edge"] = number(q.meanEdge);
    o["min_dihedral_deg"] = number(q.minDihedralDeg);
    o["max_dihedral_deg"] = number(q.maxDihedralDeg);
    o["stable_dt"] = number(stableTimeStep(mesh, material).dt);
    o["pieces"] = connectedComponents(mesh).count;
    o["boundary_faces"] = static_cast<int>(boundaryFaces(mesh).size());
    o["inverted"] = inverted;
    o["overlap"] = number(deepestOverlap(mesh).depth);
    return o;
}

QJsonObject meshInfoJson(const TetMesh& mesh, const Material& material) {
    QJsonObject o = meshStatsJson(mesh, material);
    const std::vector<MeshProblem> problems = checkValidity(mesh);
    std::map<std::string, int> byKind;
    QJsonArray first;
    for (const MeshProblem& p : problems) {
        ++byKind[toString(p.kind)];
        if (first.size() < 20)
            first.append(QString::fromStdString(p.message));
    }
    QJsonObject kinds;
    for (const auto& [k, n] : byKind)
        kinds[QString::fromStdString(k)] = n;
    QJsonObject validity;
    validity["valid"] = problems.empty();
    validity["problem_count"] = static_cast<int>(problems.size());
    validity["by_kind"] = kinds;
    validity["problems"] = first;
    o["validity"] = validity;
    return o;
}

} // namespace resect
