// resect mesh (SURFACE | --sample NAME) --out OUT [--mesh-format KEY] [--edge-length L] [--repair] [--seed N]
//     [--min-dihedral DEG] [--protect-features [--feature-angle DEG]] [--no-volume-match]
//     [--report R.json]
#include "app/cli/cli_common.h"

#include "core/mesh/quality.h"
#include "scenario/anatomy.h"
#include "scenario/mesh_io.h"

#include <QJsonObject>

#include <cstdio>
#include <filesystem>
#include <string>

namespace resect::cli {

namespace {

QJsonObject meshingReportJson(const MeshingReport& r, const QualitySummary& q, std::size_t triangles) {
    QJsonObject o;
    o["surface_triangles"] = static_cast<double>(triangles);
    o["nodes"] = q.nodes;
    o["tets"] = q.tets;
    o["edge_length"] = r.edgeLength;
    o["seed"] = static_cast<double>(r.seed);
    o["attempts"] = r.attempts;
    o["min_dihedral_deg"] = q.minDihedralDeg;
    o["max_dihedral_deg"] = q.maxDihedralDeg;
    o["min_radius_ratio"] = q.minRadiusRatio;
    o["min_edge"] = q.minEdge;
    o["mean_edge"] = q.meanEdge;
    o["surface_volume"] = r.surfaceVolume;
    o["inscribed_volume"] = r.inscribedVolume;
    o["volume"] = r.volume;
    o["volume_error"] = r.volumeError();
    o["max_boundary_offset"] = r.maxBoundaryOffset;
    o["restrained_nodes"] = r.restrainedNodes;
    o["feature_edges"] = r.featureEdges;
    o["collapsed_edges"] = r.collapsedEdges;
    o["seconds"] = r.seconds;
    return o;
}

} // namespace

int runMesh(Args args) {
    const auto sample = args.option("--sample");
    const MeshOutput output = meshOutput(args.requiredOption("--out"), args.option("--mesh-format"));
    const std::string& out = output.path;
    AnatomyMeshing options;
    if (auto l = args.number("--edge-length", 0.0, 1e300)) {
        if (!(*l > 0))
            badInput("--edge-length must be positive, got " + std::to_string(*l));
        options.meshing.edgeLength = *l;  // absurdly small values are rejected by the mesher
    }
    if (auto seed = args.integer("--seed", 0, 1 << 30))
        options.meshing.seed = static_cast<unsigned>(*seed);
    if (auto angle = args.number("--min-dihedral", 0.0, 180.0))
        options.meshing.minDihedralDeg = *angle; // the mesher names its own upper limit
    options.meshing.protectFeatures = args.flag("--protect-features");
    if (auto angle = args.number("--feature-angle", 0.0, 180.0)) {
        if (!options.meshing.protectFeatures)
            badInput("--feature-angle needs --protect-features");
        options.meshing.featureAngleDeg = *angle;
    }
    if (args.flag("--no-volume-match"))
        options.meshing.matchVolume = false;
    const auto reportPath = args.option("--report");
    options.repair = args.flag("--repair");
    const auto files = args.positionals();
    args.finish();
    if (sample && !files.empty())
        badInput("give either a SURFACE file or --sample, not both");
    if (!sample && files.size() != 1)
        badInput("expected one SURFACE file or --sample polyp|myoma");

    const std::string source = sample ? "sample:" + *sample : files[0];
    if (!sample)
        requireDistinctMesh(files[0], out);
    if (reportPath) {
        std::error_code ec;
        if (std::filesystem::weakly_canonical(out, ec) == std::filesystem::weakly_canonical(*reportPath, ec))
            badInput("--report " + *reportPath + " is the --out file; give them different names");
        if (!sample)
            requireDistinct(files[0], *reportPath);
    }
    TriangleSurface surface;
    requireOk(loadAnatomy(source, surface));
    TetMesh mesh;
    std::string log;
    MeshingReport report;
    requireOk(meshAnatomy(surface, options, mesh, &log, &report));
    if (!log.empty())
        std::fputs(log.c_str(), stderr);
    writeMeshOutput(output, mesh);
    const QualitySummary q = summarizeQuality(mesh);
    std::printf("%s: %d nodes, %d tets (edge length %.4g), worst dihedral %.2f deg, min radius "
                "ratio %.4f, volume %.6g (surface %.6g, %+.2f %%), %.2f s -> %s\n",
                source.c_str(), q.nodes, q.tets, report.edgeLength, q.minDihedralDeg, q.minRadiusRatio,
                q.volume, report.surfaceVolume, 100.0 * report.volumeError(), report.seconds, out.c_str());
    if (report.attempts > 1)
        std::printf("  re-meshed: attempt %d (seed %u) was the first to reach %.4g degrees\n",
                    report.attempts, report.seed, options.meshing.minDihedralDeg);
    if (options.meshing.matchVolume && report.inscribedVolume > 0)
        std::printf("  volume matched: the inscribed boundary had %+.2f %%; boundary nodes moved up to "
                    "%.3g (%.1f %% of the edge length)%s\n",
                    100.0 * (report.inscribedVolume - report.surfaceVolume) / report.surfaceVolume,
                    report.maxBoundaryOffset, 100.0 * report.maxBoundaryOffset / report.edgeLength,
                    report.restrainedNodes > 0
                        ? (", " + std::to_string(report.restrainedNodes) + " held back to keep the angles").c_str()
                        : "");
    if (options.meshing.protectFeatures)
        std::printf("  %d sharp surface edges protected\n", report.featureEdges);
    if (reportPath)
        requireOk(writeJson(*reportPath, meshingReportJson(report, q, surface.triangles.size())));
    return kOk;
}

} // namespace resect::cli
