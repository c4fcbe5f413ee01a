// The tet mesh formats (meshFormats), the choice of reader and writer by extension, and
// the read report. The readers and writers live in vtu_io.cpp, gmsh_reader.cpp,
// gmsh_writer.cpp, vtk_legacy_io.cpp, medit_io.cpp and tetgen_io.cpp; their shared checks
// in mesh_io_detail.cpp.

#include "scenario/mesh_io.h"
#include "scenario/mesh_io_detail.h"

#include <algorithm>
#include <array>

namespace resect {
namespace {

constexpr std::string_view kCarriesAll =
    "current and reference positions, mass, velocity; per tet quality and piece";

constexpr std::array<MeshFormatInfo, 9> kFormats{{
    {MeshFormat::Vtu, "vtu", "VTK XML unstructured grid", ".vtu", true, kCarriesAll},
    {MeshFormat::Msh41, "msh41", "Gmsh 4.1 ASCII", ".msh", true,
     "current positions; node data reference_position, mass, velocity; element data "
     "quality, piece; each piece a physical volume"},
    {MeshFormat::Msh41Binary, "msh41-binary", "Gmsh 4.1 binary", ".msh", false,
     "as Gmsh 4.1 ASCII"},
    {MeshFormat::Msh22, "msh22", "Gmsh 2.2 ASCII", ".msh", false, "as Gmsh 4.1 ASCII"},
    {MeshFormat::Msh22Binary, "msh22-binary", "Gmsh 2.2 binary", ".msh", false,
     "as Gmsh 4.1 ASCII"},
    {MeshFormat::Vtk, "vtk", "Legacy VTK binary", ".vtk", true, kCarriesAll},
    {MeshFormat::VtkAscii, "vtk-ascii", "Legacy VTK ASCII", ".vtk", false, kCarriesAll},
    {MeshFormat::Medit, "medit", "Medit", ".mesh", true,
     "current positions; boundary triangles; piece as element reference"},
    {MeshFormat::TetGen, "tetgen", "TetGen", ".node .ele", true,
     "current positions; node attributes reference position and mass; piece as region "
     "attribute"},
}};

bool hasExtension(const MeshFormatInfo& f, const std::string& ext) {
    if (ext.empty())
        return false;
    std::string_view list = f.extensions;
    while (!list.empty()) {
        const std::size_t space = list.find(' ');
        if (list.substr(0, space) == ext)
            return true;
        if (space == std::string_view::npos)
            break;
        list.remove_prefix(space + 1);
    }
    return false;
}

} // namespace

std::span<const MeshFormatInfo> meshFormats() { return kFormats; }

const MeshFormatInfo& meshFormatInfo(MeshFormat format) {
    for (const MeshFormatInfo& f : kFormats)
        if (f.format == format)
            return f;
    return kFormats[0]; // unreachable: every enumerator has a row
}

const MeshFormatInfo* findMeshFormat(std::string_view key) {
    for (const MeshFormatInfo& f : kFormats)
        if (f.key == key)
            return &f;
    return nullptr;
}

std::string tetMeshExtensionList() { return ".vtu, .msh, .vtk, .mesh, .node or .ele"; }

std::span<const MeshFileFamily> meshFileFamilies() {
    static constexpr std::array<MeshFileFamily, 5> kFamilies{{
        {"VTK XML unstructured grid", ".vtu"},
        {"Gmsh 2.2 and 4.1, ASCII and binary", ".msh"},
        {"Legacy VTK, ASCII and binary", ".vtk"},
        {"Medit", ".mesh"},
        {"TetGen", ".node .ele"},
    }};
    return kFamilies;
}

bool isTetMeshPath(const std::string& path) {
    const std::string ext = detail::lowerExtension(path);
    if (ext == ".meshb")
        return true; // Medit binary: read as a tet mesh, which says it is not supported
    return std::any_of(kFormats.begin(), kFormats.end(),
                       [&](const MeshFormatInfo& f) { return hasExtension(f, ext); });
}

Status chooseMeshWriteFormat(const std::string& path, std::string_view key, MeshFormat& out) {
    const std::string ext = detail::lowerExtension(path);
    if (ext.empty())
        return Status::error(path + ": no file extension; a tet mesh is written as " +
                             tetMeshExtensionList());
    if (std::none_of(kFormats.begin(), kFormats.end(),
                     [&](const MeshFormatInfo& f) { return hasExtension(f, ext); }))
        return Status::error(path + ": cannot write a tet mesh as '" + ext + "'; use " +
                             tetMeshExtensionList());
    if (!key.empty()) {
        const MeshFormatInfo* f = findMeshFormat(key);
        if (!f) {
            std::string keys;
            for (const MeshFormatInfo& g : kFormats)
                keys += (keys.empty() ? "" : ", ") + std::string(g.key);
            return Status::error("unknown mesh format '" + std::string(key) + "'; expected one of " +
                                 keys);
        }
        if (!hasExtension(*f, ext))
            return Status::error(path + ": format " + std::string(f->key) + " (" +
                                 std::string(f->name) + ") is written as " +
                                 std::string(f->extensions) + ", not '" + ext + "'");
        out = f->format;
        return Status::success();
    }
    for (const MeshFormatInfo& f : kFormats)
        if (f.extensionDefault && hasExtension(f, ext)) {
            out = f.format;
            return Status::success();
        }
    return Status::error(path + ": no default format for '" + ext + "'"); // unreachable
}

Status readTetMesh(const std::string& path, TetMesh& out, MeshReadReport* report) {
    const std::string ext = detail::lowerExtension(path);
    MeshReadReport local;
    MeshReadReport* r = report ? &local : nullptr;
    Status status;
    if (ext == ".vtu")
        status = readVtu(path, out, r);
    else if (ext == ".msh")
        status = readGmsh(path, out, r);
    else if (ext == ".vtk")
        status = readVtkLegacy(path, out, r);
    else if (ext == ".mesh" || ext == ".meshb")  // (.meshb: refused by the Medit reader, naming it)
        status = readMedit(path, out, r);
    else if (ext == ".node" || ext == ".ele")
        status = readTetGen(path, out, r);
    else if (ext.empty())
        return Status::error(path + ": no file extension; expected " + tetMeshExtensionList());
    else
        return Status::error(path + ": unknown tet mesh extension '" + ext + "'; expected " +
                             tetMeshExtensionList());
    if (status && report)
        *report = std::move(local);
    return status;
}

Status writeTetMesh(const std::string& path, const TetMesh& mesh, MeshFormat format) {
    const MeshFormatInfo& info = meshFormatInfo(format);
    if (!hasExtension(info, detail::lowerExtension(path)))
        return Status::error(path + ": format " + std::string(info.key) + " (" +
                             std::string(info.name) + ") is written as " +
                             std::string(info.extensions));
    switch (format) {
    case MeshFormat::Vtu: return writeVtu(path, mesh);
    case MeshFormat::Msh41: return writeGmsh(path, mesh, 41, false);
    case MeshFormat::Msh41Binary: return writeGmsh(path, mesh, 41, true);
    case MeshFormat::Msh22: return writeGmsh(path, mesh, 22, false);
    case MeshFormat::Msh22Binary: return writeGmsh(path, mesh, 22, true);
    case MeshFormat::Vtk: return writeVtkLegacy(path, mesh, true);
    case MeshFormat::VtkAscii: return writeVtkLegacy(path, mesh, false);
    case MeshFormat::Medit: return writeMedit(path, mesh);
    case MeshFormat::TetGen: return writeTetGen(path, mesh);
    }
    return Status::error(path + ": unknown mesh format"); // unreachable
}

Status writeTetMesh(const std::string& path, const TetMesh& mesh) {
    MeshFormat format{};
    if (Status s = chooseMeshWriteFormat(path, {}, format); !s)
        return s;
    return writeTetMesh(path, mesh, format);
}

void MeshReadReport::drop(const std::string& what, std::int64_t count) {
    for (Dropped& d : dropped)
        if (d.what == what) {
            d.count += count;
            return;
        }
    dropped.push_back({what, count});
}

std::string MeshReadReport::summary() const {
    std::string s = format;
    const auto part = [&](const std::string& text) {
        if (text.empty())
            return;
        s += (s.empty() ? "" : "; ") + text;
    };
    std::int64_t droppedTotal = 0;
    std::string drops;
    for (const Dropped& d : dropped) {
        droppedTotal += d.count;
        drops += (drops.empty() ? "" : ", ") + d.what + " " + std::to_string(d.count);
    }
    if (droppedTotal > 0)
        part("dropped " + std::to_string(droppedTotal) +
             (droppedTotal == 1 ? " element that is not a 4-node tetrahedron ("
                                : " elements that are not 4-node tetrahedra (") +
             drops + ")");
    std::string list;
    for (const Group& g : groups) {
        if (g.dimension != 3)
            continue;
        list += (list.empty() ? "" : ", ") + std::to_string(g.tag) +
                (g.name.empty() ? "" : " '" + g.name + "'") + " (" + std::to_string(g.tets) +
                " tets)";
    }
    if (!list.empty())
        part("volume groups: " + list);
    for (const std::string& n : notes)
        part(n);
    return s;
}

} // namespace resect
