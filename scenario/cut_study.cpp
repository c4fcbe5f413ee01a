#include "scenario/cut_study.h"

#include "core/mesh/masses.h"
#include "core/mesh/stable_time_step.h"
#include "core/mesh/topology.h"
#include "core/mesh/triangle_surface.h"
#include "core/tissue/tissue.h"

#include <cmath>
#include <cstdio>
#include <numbers>

namespace resect {

SweepSurface loopScoopSweep(const TetMesh& mesh, double heightFraction) {
    const auto [lo, hi] = boundingBox(mesh.positions());
    const Vec3 size = hi - lo;
    const double halfWidth = 0.75 * size.x();
    const double depth = 0.25 * size.z();
    const double bottom = lo.z() + heightFraction * size.z();
    const double margin = 0.1 * size.y();
    const int n = 16;
    std::vector<Vec3> start, end;
    for (int j = 0; j <= n; ++j) {
        const double x = -1.0 + 2.0 * j / n;  // -1 .. 1 across the loop
        const Vec3 p(0.5 * (lo.x() + hi.x()) + halfWidth * x, 0, bottom + depth * x * x);
        start.push_back(p + Vec3(0, lo.y() - margin, 0));
        end.push_back(p + Vec3(0, hi.y() + margin, 0));
    }
    SweepSurface sweep;
    (void)SweepSurface::fromStartEnd(start, end, sweep);  // valid by construction
    return sweep;
}

namespace {

/// Measures of a mesh whose masses follow Eq. 3 with the material.
StudyColumn measure(const std::string& name, const TetMesh& mesh, const Material& material) {
    StudyColumn c;
    c.name = name;
    c.quality = summarizeQuality(mesh);
    c.stableDt = stableTimeStep(mesh, material).dt;
    c.pieces = connectedComponents(mesh).count;
    return c;
}

} // namespace

Status runCutStudy(const TetMesh& mesh, const SweepSurface& sweep, double d, const Material& material,
                   CutStudy& out) {
    out.d = d;
    out.columns.clear();
    TetMesh original = mesh;
    computeLumpedMasses(original, material.density);
    out.columns.push_back(measure("original mesh", original, material));
    struct Method {
        const char* name;
        CutMethod method;
        FaceTriangulation triangulation;
        bool snap;
        int relaxSteps;
        bool improve = false;  // the paper's methods alone; the last column adds step 7
    };
    const Method methods[] = {
        {"traditional subdivision", CutMethod::Subdivision, FaceTriangulation::Standard, false, 0},
        {"hybrid (standard triangul.)", CutMethod::Hybrid, FaceTriangulation::Standard, false, 0},
        {"hybrid (enhanced triangul.)", CutMethod::Hybrid, FaceTriangulation::Enhanced, false, 0},
        {"enhanced + snapping", CutMethod::Hybrid, FaceTriangulation::Enhanced, true, 0},
        {"enhanced + snapping + relaxation", CutMethod::Hybrid, FaceTriangulation::Enhanced, true, 10},
        {"+ mesh improvement (defaults)", CutMethod::Hybrid, FaceTriangulation::Enhanced, true, 10, true}};
    Tissue base;  // the tissue keeps the masses of Eq. 3 through each cut
    if (Status s = Tissue::create(std::move(original), {}, material, {}, base); !s.ok())
        return s;
    for (const Method& m : methods) {
        Tissue tissue(base);
        CutOptions options;
        options.method = m.method;
        options.triangulation = m.triangulation;
        options.snap = m.snap;
        options.relaxSteps = m.relaxSteps;
        options.improve = m.improve;
        options.d = d;
        TissueCut result;
        if (Status s = tissue.cut(sweep, options, &result); !s.ok())
            return Status::error(std::string(m.name) + ": " + s.message());
        StudyColumn c = measure(m.name, tissue.mesh(), material);
        c.stats = result.tets;
        out.columns.push_back(c);
    }
    return Status::success();
}

std::string formatCutStudy(const CutStudy& study) {
    std::string s;
    char buf[256];
    const auto row = [&](const char* label, auto value) {
        s += "| ";
        s += label;
        for (const StudyColumn& c : study.columns) {
            s += " | ";
            s += value(c);
        }
        s += " |\n";
    };
    const auto fmt = [&](const char* f, double v) {
        std::snprintf(buf, sizeof buf, f, v);
        return std::string(buf);
    };
    s += "|";
    for (const StudyColumn& c : study.columns)
        s += " | " + c.name;
    s += " |\n|---";
    for (std::size_t i = 0; i < study.columns.size(); ++i)
        s += "|---:";
    s += "|\n";
    row("tets", [&](const StudyColumn& c) { return std::to_string(c.quality.tets); });
    row("edges", [&](const StudyColumn& c) { return std::to_string(c.quality.edges); });
    row("nodes", [&](const StudyColumn& c) { return std::to_string(c.quality.nodes); });
    row("tet_minAR (r/R)", [&](const StudyColumn& c) { return fmt("%.3g", c.quality.minAspectRatioPaper); });
    row("min radius ratio (3r/R)", [&](const StudyColumn& c) { return fmt("%.3g", c.quality.minRadiusRatio); });
    row("Vmax/Vmin", [&](const StudyColumn& c) { return fmt("%.4g", c.quality.volumeRatio); });
    row("lmax/lmin", [&](const StudyColumn& c) { return fmt("%.4g", c.quality.edgeRatio); });
    row("h_max (stable dt, s)", [&](const StudyColumn& c) { return fmt("%.3g", c.stableDt); });
    row("added tets", [&](const StudyColumn& c) {
        return std::to_string(c.quality.tets - study.columns.front().quality.tets);
    });
    row("pieces", [&](const StudyColumn& c) { return std::to_string(c.pieces); });
    row("cut nodes / cut edges", [&](const StudyColumn& c) {
        return std::to_string(c.stats.cutNodes) + " / " + std::to_string(c.stats.cutEdges);
    });
    row("max cut-node distance", [&](const StudyColumn& c) { return fmt("%.3g", c.stats.maxCutNodeDistance); });
    row("snapped / refused", [&](const StudyColumn& c) {
        return std::to_string(c.stats.snappedNodes) + " / " + std::to_string(c.stats.refusedSnaps);
    });
    row("cut time (ms)", [&](const StudyColumn& c) { return fmt("%.3f", c.stats.timeMs.total); });
    row("  of which snap + relax (ms)", [&](const StudyColumn& c) { return fmt("%.3f", c.stats.timeMs.snap + c.stats.timeMs.relax); });
    return s;
}

} // namespace resect
