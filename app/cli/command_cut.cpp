// resect cut MESH --sweep S.json [--sweep S2.json ...] --out OUT [--mesh-format KEY] [--report R.json]
//            [--method hybrid|subdivision] [--triangulation enhanced|standard] [--d 0.2]
//            [--snap | --no-snap] [--relax-steps N] [--w-spring W] [--w-particle W]
//            [--surface HI_RES --surface-out OUT.obj] [--improve on|off]
//            [--improve-quality Q] [--improve-short-edge S]
//            [--fix-box x0 y0 z0 x1 y1 z1 [--resected remove|keep] [--resected-out CHIPS.vtu]]
// With --fix-box, the pieces a cut leaves without a node in the box are resected: removed from
// the output mesh by default (--resected-out writes them, at their positions, to one file),
// or kept in it (keep). Their count, volume and mass are reported.
#include "app/cli/cli_common.h"

#include "core/mesh/masses.h"
#include "core/mesh/material.h"
#include "core/tissue/tissue.h"
#include "scenario/mesh_io.h"
#include "scenario/mesh_summary.h"
#include "scenario/surface_io.h"
#include "scenario/sweep_io.h"

#include <QJsonArray>

#include <cstdio>
#include <filesystem>

namespace resect::cli {

int runCut(Args args) {
    const std::vector<std::string> sweepFiles = args.options("--sweep");
    const std::optional<std::string> meshFormat = args.option("--mesh-format");
    const MeshOutput out = meshOutput(args.requiredOption("--out"), meshFormat);
    const auto report = args.option("--report");
    CutOptions options;
    const std::string method = args.option("--method").value_or("hybrid");
    if (method == "hybrid")
        options.method = CutMethod::Hybrid;
    else if (method == "subdivision")
        options.method = CutMethod::Subdivision;
    else
        badInput("--method: expected hybrid or subdivision, got '" + method + "'");
    const std::string triangulation =
        args.option("--triangulation").value_or(options.method == CutMethod::Hybrid ? "enhanced" : "standard");
    if (triangulation == "enhanced")
        options.triangulation = FaceTriangulation::Enhanced;
    else if (triangulation == "standard")
        options.triangulation = FaceTriangulation::Standard;
    else
        badInput("--triangulation: expected enhanced or standard, got '" + triangulation + "'");
    if (options.method == CutMethod::Subdivision && options.triangulation == FaceTriangulation::Enhanced)
        badInput("--triangulation enhanced applies to the hybrid method only");
    if (auto d = args.number("--d", 0.0, CutLimits::kMaxD))
        options.d = *d;
    const bool snap = args.flag("--snap"), noSnap = args.flag("--no-snap");
    if (snap && noSnap)
        badInput("--snap and --no-snap contradict each other");
    // The full pipeline of section 4.1 by default for the hybrid method: snapping and ten
    // relaxation steps; the subdivision baseline stays plain.
    const bool hybrid = options.method == CutMethod::Hybrid;
    options.snap = hybrid ? !noSnap : snap;
    options.relaxSteps = args.integer("--relax-steps", 0, CutLimits::kMaxRelaxSteps).value_or(hybrid ? 10 : 0);
    options.wSpring = args.number("--w-spring", 0.0, CutLimits::kMaxRelaxWeight).value_or(options.wSpring);
    options.wParticle = args.number("--w-particle", 0.0, CutLimits::kMaxRelaxWeight).value_or(options.wParticle);
    // Step 7 of the cut: local mesh improvement (on by default, for every method).
    const std::string improve = args.option("--improve").value_or("on");
    if (improve != "on" && improve != "off")
        badInput("--improve: expected on or off, got '" + improve + "'");
    options.improve = improve == "on";
    options.improveQuality =
        args.number("--improve-quality", 0.0, CutLimits::kMaxImproveQuality).value_or(options.improveQuality);
    options.improveShortEdge =
        args.number("--improve-short-edge", 0.0, CutLimits::kMaxImproveShortEdge).value_or(options.improveShortEdge);
    const auto box = args.numbers("--fix-box", 6, "x0 y0 z0 x1 y1 z1");
    const auto resectedText = args.option("--resected");
    const auto chipsOut = args.option("--resected-out");
    ResectedPieces resected = ResectedPieces::Remove;
    if (resectedText && (!parseResectedPieces(*resectedText, resected) || resected == ResectedPieces::Rigid))
        badInput("--resected: expected remove or keep, got '" + *resectedText + "'");
    if ((resectedText || chipsOut) && !box)
        badInput("--resected and --resected-out need --fix-box x0 y0 z0 x1 y1 z1 (the tissue's anchored region)");
    if (chipsOut && resected != ResectedPieces::Remove)
        badInput("--resected-out writes removed pieces: it needs --resected remove");
    FixedSelection anchors;
    if (box) {
        const Vec3 lo((*box)[0], (*box)[1], (*box)[2]), hi((*box)[3], (*box)[4], (*box)[5]);
        if ((lo.array() > hi.array()).any())
            badInput("--fix-box: expected x0 <= x1, y0 <= y1, z0 <= z1");
        anchors.box = std::array<Vec3, 2>{lo, hi};
    }
    const auto surfaceIn = args.option("--surface");
    const auto surfaceOut = args.option("--surface-out");
    if (surfaceIn.has_value() != surfaceOut.has_value())
        badInput("--surface and --surface-out go together");
    const auto files = args.positionals();
    args.finish();
    if (files.size() != 1)
        badInput("expected exactly one MESH file");
    if (sweepFiles.empty())
        badInput("--sweep is required (one or more sweep files)");
    requireDistinctMesh(files[0], out.path);
    if (report)
        requireDistinct(files[0], *report);
    if (surfaceIn)
        requireDistinct(*surfaceIn, *surfaceOut);
    std::optional<MeshOutput> chipsOutput;
    if (chipsOut) {
        // --mesh-format names the variant of --out's extension; the chips file takes it when
        // it has the same extension, else its own extension's default.
        const bool sameExtension =
            std::filesystem::path(*chipsOut).extension() == std::filesystem::path(out.path).extension();
        chipsOutput = meshOutput(*chipsOut, sameExtension ? meshFormat : std::nullopt, "--resected-out");
        requireDistinctMesh(files[0], *chipsOut);
        for (const std::string& a : meshFiles(*chipsOut))
            for (const std::string& b : meshFiles(out.path))
                if (a == b)
                    badInput("--resected-out and --out name the same file");
    }

    TetMesh mesh;
    MeshReadReport read;
    requireOk(readTetMesh(files[0], mesh, &read));
    printReadNotes(files[0], read);
    std::vector<SweepSurface> sweeps(sweepFiles.size());
    for (std::size_t i = 0; i < sweepFiles.size(); ++i)
        requireOk(readSweep(sweepFiles[i], sweeps[i]));
    // The embedded high-resolution surface (section 5), bound to the tets before any cut.
    TriangleSurface surface;
    if (surfaceIn)
        requireOk(readSurface(*surfaceIn, surface));

    const Material material;
    const QJsonObject before = meshStatsJson(mesh, material);
    // The rest state of the tissue's material (Eq. 3); cuts keep it up to date.
    computeLumpedMasses(mesh, material.density);
    Tissue tissue;
    const double massBefore = sumOfMasses(mesh);
    if (Status s = Tissue::create(std::move(mesh), std::move(surface), material, anchors, tissue); !s.ok())
        badInput((surfaceIn ? *surfaceIn : files[0]) + ": " + s.message());
    if (box && tissue.anchors().empty())
        badInput("--fix-box: no node of " + files[0] + " lies in the box");
    tissue.setResectedPieces(box ? resected : ResectedPieces::Keep);
    int collapsed = 0, smoothed = 0, removedTets = 0, flips = 0, splits = 0, improveAddedTets = 0;
    double improveMs = 0;
    CutStats total;
    int surfaceSplitEdges = 0, surfaceCapTriangles = 0;
    for (std::size_t i = 0; i < sweeps.size(); ++i) {
        TissueCut cut;
        if (Status s = tissue.cut(sweeps[i], options, &cut); !s.ok())
            throw CliError{kInternal, sweepFiles[i] + ": " + s.message()};
        surfaceSplitEdges += cut.surface.surface.splitEdges;
        surfaceCapTriangles += cut.surface.surface.capTriangles;
        total += cut.tets;
        collapsed += cut.collapsedEdges;
        smoothed += cut.smoothedNodes;
        removedTets += cut.removedTets;
        flips += cut.flips;
        splits += cut.splits;
        improveAddedTets += cut.improveAddedTets;
        improveMs += cut.improveMs;
    }
    writeMeshOutput(out, tissue.mesh());
    if (chipsOut) {
        // All chips in one file, where they are.
        std::vector<Vec3> positions;
        std::vector<Tet> tets;
        for (const Chip& chip : tissue.chips()) {
            const int base = static_cast<int>(positions.size());
            for (int n = 0; n < chip.mesh.nodeCount(); ++n)
                positions.push_back(chip.mesh.pos(n));
            for (Tet q : chip.mesh.tets()) {
                for (int& v : q)
                    v += base;
                tets.push_back(q);
            }
        }
        TetMesh chips = TetMesh::fromArrays(std::move(positions), std::move(tets));
        computeLumpedMasses(chips, material.density);
        writeMeshOutput(*chipsOutput, chips);
    }
    if (surfaceIn) {
        tissue.updateSurface();  // the surface deformed with the tets
        requireOk(writeSurface(*surfaceOut, tissue.surface().surface()));
    }
    const QJsonObject after = meshStatsJson(tissue.mesh(), material);

    if (report) {
        QJsonObject cut;
        cut["cut_edges"] = total.cutEdges;
        cut["cut_nodes"] = total.cutNodes;
        cut["snapped_nodes"] = total.snappedNodes;
        cut["refused_snaps"] = total.refusedSnaps;
        cut["decomposed_tets"] = total.decomposedTets;
        cut["added_tets"] = total.addedTets;
        cut["separated_tets"] = total.separatedTets;
        cut["max_cut_node_distance"] = total.maxCutNodeDistance;
        cut["time_ms"] = QJsonObject{{"intersect", total.timeMs.intersect},
                                     {"select", total.timeMs.select},
                                     {"decompose", total.timeMs.decompose},
                                     {"snap", total.timeMs.snap},
                                     {"relax", total.timeMs.relax},
                                     {"update", total.timeMs.update},
                                     {"total", total.timeMs.total}};
        if (surfaceIn)
            cut["surface"] = QJsonObject{{"split_edges", surfaceSplitEdges},
                                         {"cap_triangles", surfaceCapTriangles},
                                         {"vertices", tissue.surface().surface().vertexCount()},
                                         {"triangles", tissue.surface().surface().triangleCount()}};
        cut["improvement"] = QJsonObject{{"enabled", options.improve},
                                         {"collapsed_edges", collapsed},
                                         {"smoothed_nodes", smoothed},
                                         {"removed_tets", removedTets},
                                         {"flips", flips},
                                         {"splits", splits},
                                         {"added_tets", improveAddedTets},
                                         {"time_ms", improveMs}};
        QJsonObject r;
        r["resected"] = QJsonObject{{"policy", box ? resectedPiecesName(resected) : "none"},
                                    {"pieces", static_cast<int>(tissue.chips().size())},
                                    {"volume", tissue.resectedVolume()},
                                    {"mass", tissue.resectedMass()},
                                    {"mass_before", massBefore},
                                    {"mass_remaining", sumOfMasses(tissue.mesh())}};
        r["method"] = QString::fromStdString(method);
        r["triangulation"] = QString::fromStdString(triangulation);
        r["d"] = options.d;
        r["before"] = before;
        r["after"] = after;
        r["cut"] = cut;
        requireOk(writeJson(*report, r));
    }
    std::printf("%s: %d -> %d tets, %d pieces, min radius ratio %.4g", files[0].c_str(), before["tets"].toInt(),
                after["tets"].toInt(), after["pieces"].toInt(), after["min_radius_ratio"].toDouble());
    if (box && resected == ResectedPieces::Remove)
        std::printf(", %d resected (volume %.4g mm^3, mass %.4g g)", static_cast<int>(tissue.chips().size()),
                    tissue.resectedVolume(), tissue.resectedMass());
    std::printf(" -> %s\n", out.path.c_str());
    return kOk;
}

} // namespace resect::cli
