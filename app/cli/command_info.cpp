// resect info MESH: JSON summary on stdout.
#include "app/cli/cli_common.h"

#include "core/mesh/material.h"
#include "scenario/mesh_io.h"
#include "scenario/mesh_summary.h"

namespace resect::cli {

int runInfo(Args args) {
    const auto files = args.positionals();
    args.finish();
    if (files.size() != 1)
        badInput("expected exactly one MESH file");
    TetMesh mesh;
    requireOk(readTetMesh(files[0], mesh));
    QJsonObject o;
    o["file"] = QString::fromStdString(files[0]);
    const QJsonObject info = meshInfoJson(mesh, Material{});
    for (auto it = info.begin(); it != info.end(); ++it)
        o[it.key()] = it.value();
    printJson(o);
    return kOk;
}

} // namespace resect::cli
