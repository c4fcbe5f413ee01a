#pragma once
// A tiny scenario on disk for export tests (tests/scenario/test_trainer_export,
// tests/widgets/test_export_runner): a 3x3x3-cell box tet mesh [0, 4]^3 mm anchored at the
// bottom, a box surface inside it, a sweep file cutting the top off at z = 2.3 and 10 ms of
// simulation; its expectation (2 pieces) passes. Exports in well under a second.

#include "core/mesh/box_mesh.h"
#include "core/mesh/masses.h"
#include "core/mesher/procedural_surfaces.h"
#include "scenario/mesh_io.h"
#include "scenario/surface_io.h"

#include <QByteArray>
#include <QFile>
#include <QString>

namespace resect::test {

/// Writes box.vtu, box.obj, cut.json and box.json (the scenario) into `dir`; returns the
/// scenario's path. `duration`: the simulated seconds (a long one keeps an export or a run
/// busy for seconds, for tests that must act while it runs).
inline QString writeTinyScenario(const QString& dir, double duration = 0.01) {
    TetMesh mesh = makeBoxTetMesh(Vec3::Zero(), Vec3::Constant(4), 3, 3, 3);
    computeLumpedMasses(mesh, Material{}.density);
    if (!writeVtu((dir + "/box.vtu").toStdString(), mesh).ok())
        qFatal("cannot write box.vtu");
    if (!writeSurface((dir + "/box.obj").toStdString(),
                      makeBox(Vec3::Constant(0.2), Vec3::Constant(3.8)))
             .ok())
        qFatal("cannot write box.obj");
    const auto write = [&dir](const char* name, const QByteArray& text) {
        QFile f(dir + "/" + name);
        if (!f.open(QIODevice::WriteOnly) || f.write(text) != text.size())
            qFatal("cannot write %s", name);
    };
    write("cut.json",
          R"({"curves": [[[-1, -1, 2.3], [-1, 5, 2.3]], [[5, -1, 2.31], [5, 5, 2.31]]]})");
    write("box.json", QString(R"({"format": "resect-scenario", "version": 1,
        "tissues": [{"name": "box", "surface": "box.obj", "mesh": "box.vtu",
                     "fixed_regions": [{"min": [-1, -1, -1], "max": [5, 5, 0.001]}]}],
        "sweeps": [{"name": "cut", "file": "cut.json"}],
        "effects": [{"name": "deformation"}, {"name": "gravity"}, {"name": "fixed"}],
        "simulation": {"duration": %1},
        "expectations": [{"kind": "pieces_at_least", "value": 2}]})")
                          .arg(duration, 0, 'g', 17)
                          .toUtf8());
    return dir + "/box.json";
}

} // namespace resect::test
