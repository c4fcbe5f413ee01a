// resect info MESH: JSON summary on stdout, with what the file held besides tets (the
// format read, dropped elements, groups).
#include "app/cli/cli_common.h"

#include "core/mesh/material.h"
#include "scenario/mesh_io.h"
#include "scenario/mesh_summary.h"

#include <QJsonArray>

namespace resect::cli {

int runInfo(Args args) {
    const auto files = args.positionals();
    args.finish();
    if (files.size() != 1)
        badInput("expected exactly one MESH file");
    TetMesh mesh;
    MeshReadReport read;
    requireOk(readTetMesh(files[0], mesh, &read));
    QJsonObject o;
    o["file"] = QString::fromStdString(files[0]);
    o["format"] = QString::fromStdString(read.format);
    const QJsonObject info = meshInfoJson(mesh, Material{});
    for (auto it = info.begin(); it != info.end(); ++it)
        o[it.key()] = it.value();
    QJsonObject dropped;
    for (const MeshReadReport::Dropped& d : read.dropped)
        dropped[QString::fromStdString(d.what)] = static_cast<double>(d.count);
    o["dropped"] = dropped;
    QJsonArray groups;
    for (const MeshReadReport::Group& g : read.groups)
        groups.append(QJsonObject{{"dimension", g.dimension},
                                  {"tag", static_cast<double>(g.tag)},
                                  {"name", QString::fromStdString(g.name)},
                                  {"tets", static_cast<double>(g.tets)}});
    o["groups"] = groups;
    QJsonArray notes;
    for (const std::string& n : read.notes)
        notes.append(QString::fromStdString(n));
    o["notes"] = notes;
    printJson(o);
    return kOk;
}

} // namespace resect::cli
