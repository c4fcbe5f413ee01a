// fuzz_make_seeds CORPUS_DIR: writes the seed inputs of every fuzz target into
// CORPUS_DIR/<target>/ (the checked-in fuzz/corpus/ was made with it). Seeds are small
// valid files, written by the project's own writers where it has one (.vtu, sweeps,
// surfaces, legacy VTK, Medit) and by hand otherwise (Gmsh, TetGen, ASCII .vtu through VTK's
// writer, legacy VTK 5.1 and mmg-style Medit).

#include "scenario/mesh_io.h"
#include "scenario/surface_io.h"
#include "scenario/sweep_io.h"
#include "scenario/vtk_convert.h"

#include "core/mesh/box_mesh.h"
#include "core/mesher/procedural_surfaces.h"

#include <vtkSmartPointer.h>
#include <vtkUnstructuredGrid.h>
#include <vtkXMLUnstructuredGridWriter.h>

#include <QByteArray>
#include <QDir>
#include <QFile>
#include <QFileInfo>
#include <QRegularExpression>
#include <QTemporaryDir>

#include <cstdint>
#include <cstdio>
#include <string>

using namespace resect;

namespace {

bool writeBytes(const QString& path, const QByteArray& bytes) {
    QFile f(path);
    return f.open(QIODevice::WriteOnly | QIODevice::Truncate) && f.write(bytes) == bytes.size();
}

QByteArray readBytes(const QString& path) {
    QFile f(path);
    return f.open(QIODevice::ReadOnly) ? f.readAll() : QByteArray();
}

bool check(const Status& s) {
    if (!s)
        std::fprintf(stderr, "fuzz_make_seeds: %s\n", s.message().c_str());
    return s.ok();
}

// Two tets sharing a face; node tags 10, 20, ... and element 7 negatively oriented.
const char* const kGmsh = R"($MeshFormat
4.1 0 8
$EndMeshFormat
$Nodes
1 5 10 50
3 1 0 5
10
20
30
40
50
0 0 0
1 0 0
0 1 0
0 0 1
1 1 1
$EndNodes
$Elements
2 3 1 7
2 1 2 1
1 20 30 40
3 1 4 2
5 10 20 30 40
7 20 40 30 50
$EndElements
)";

// The same two tets in TetGen's format (1-based, a boundary marker, a comment), the .node
// and .ele files joined by the separator of the tetgen target.
const char* const kTetGen = R"(# five points
5 3 0 1
1 0 0 0 1
2 1 0 0 1
3 0 1 0 1
4 0 0 1 1
5 1 1 1 0
@@ele@@
2 4 0
1 1 2 3 4
2 2 3 4 5
)";

// Legacy VTK 5.1 as VTK 9's writer makes it (OFFSETS/CONNECTIVITY, METADATA, a lookup
// table), with a triangle the reader drops and a point array it skips.
const char* const kVtk51 = R"(# vtk DataFile Version 5.1
vtk output
ASCII
DATASET UNSTRUCTURED_GRID
POINTS 5 double
0 0 0 1 0 0 0 1 0
0 0 1 1 1 1
METADATA
INFORMATION 0

CELLS 4 11
OFFSETS vtktypeint64
0 4 8 11
CONNECTIVITY vtktypeint64
0 1 2 3 1 2 3 4 0 1 2
CELL_TYPES 3
10
10
5

CELL_DATA 3
FIELD FieldData 1
CellEntityIds 1 3 int
1 2 0
POINT_DATA 5
SCALARS temperature float 1
LOOKUP_TABLE default
37 37 37 37 37
VECTORS velocity double
0 0 0 1 0 0 0 1 0 0 0 1 1 1 1
)";

// mmg-style Medit: comments, counts on the keyword's line, corners, ridges, required
// vertices, boundary triangles and references.
const char* const kMedit = R"(# mmg3d output
MeshVersionFormatted 2
Dimension 3
Vertices 5
0 0 0 1
1 0 0 1
0 1 0 1
0 0 1 1
1 1 1 2
Corners 1
1
Ridges
1
1
RequiredVertices 1 5
Edges 1
1 2 1
Triangles 2
1 3 2 4
1 2 4 4
Tetrahedra 2
1 2 3 4 1
2 3 4 5 2
End
)";

// A binary little-endian PLY tetrahedron: float coordinates, faces as uchar-counted int lists.
QByteArray binaryPly() {
    QByteArray b("ply\nformat binary_little_endian 1.0\nelement vertex 4\nproperty float x\n"
                 "property float y\nproperty float z\nelement face 4\n"
                 "property list uchar int vertex_indices\nend_header\n");
    const auto put = [&](const void* p, int n) { b.append(static_cast<const char*>(p), n); };
    const float v[4][3] = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
    for (const auto& p : v)
        for (float c : p)
            put(&c, 4); // x86_64 is little-endian
    const std::int32_t f[4][3] = {{0, 2, 1}, {0, 1, 3}, {0, 3, 2}, {1, 2, 3}};
    for (const auto& t : f) {
        const unsigned char three = 3;
        put(&three, 1);
        for (std::int32_t i : t)
            put(&i, 4);
    }
    return b;
}

// A VTK ASCII file with one tet: the smallest .vtu VTK reads.
QByteArray asciiVtu(const TetMesh& mesh) {
    QTemporaryDir dir;
    const QString path = dir.filePath("a.vtu");
    auto writer = vtkSmartPointer<vtkXMLUnstructuredGridWriter>::New();
    writer->SetFileName(path.toStdString().c_str());
    writer->SetInputData(toUnstructuredGrid(mesh));
    writer->SetDataModeToAscii();
    writer->SetCompressorTypeToNone();
    return writer->Write() == 1 ? readBytes(path) : QByteArray();
}

/// Text glTF with its buffer inlined as a data: URI (a fuzz input is one file).
QByteArray inlineGltf(const TriangleSurface& surface) {
    QTemporaryDir dir;
    const QString path = dir.filePath("cube.gltf");
    if (!check(writeSurface(path.toStdString(), surface)))
        return {};
    QByteArray gltf = readBytes(path);
    const QRegularExpression uri("\"uri\"\\s*:\\s*\"([^\"]+\\.bin)\"");
    const QRegularExpressionMatch m = uri.match(QString::fromUtf8(gltf));
    if (!m.hasMatch())
        return {};
    const QByteArray bin = readBytes(dir.filePath(m.captured(1)));
    gltf.replace(m.captured(1).toUtf8(), "data:application/octet-stream;base64," + bin.toBase64());
    return gltf;
}

} // namespace

int main(int argc, char** argv) {
    if (argc != 2) {
        std::fprintf(stderr, "usage: fuzz_make_seeds CORPUS_DIR\n");
        return 2;
    }
    const QDir corpus(QString::fromLocal8Bit(argv[1]));
    const auto file = [&](const char* target, const char* name) {
        corpus.mkpath(target);
        return corpus.filePath(QString(target) + "/" + name);
    };
    bool ok = true;

    // Sweeps: the paper's two-curve case and three poses.
    SweepSurface two, three;
    ok &= check(
        SweepSurface::fromCurves({{{0, 0, 0.5}, {1, 0, 0.5}}, {{0, 1, 0.5}, {1, 1, 0.5}}}, two));
    ok &= check(SweepSurface::fromCurves({{{0, 0, 0}, {0.5, 0, 0.1}, {1, 0, 0}},
                                          {{0, 1, 0}, {0.5, 1, 0.2}, {1, 1, 0}},
                                          {{0, 2, 0.5}, {0.5, 2, 0.5}, {1, 2, 0.5}}},
                                         three));
    ok &= check(writeSweep(file("sweep", "two-curves.json").toStdString(), two));
    ok &= check(writeSweep(file("sweep", "three-curves.json").toStdString(), three));

    // Tet meshes.
    const TetMesh box = makeBoxTetMesh({0, 0, 0}, {1, 1, 1}, 1, 1, 1);
    ok &= check(writeVtu(file("vtu", "box.vtu").toStdString(), box));
    const TetMesh one =
        TetMesh::fromArrays({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}}, {{0, 1, 2, 3}});
    const QByteArray ascii = asciiVtu(one);
    ok &= !ascii.isEmpty() && writeBytes(file("vtu", "one-tet-ascii.vtu"), ascii);
    ok &= writeBytes(file("msh", "two-tets.msh"), kGmsh);
    ok &= writeBytes(file("tetgen", "two-tets.node-ele"), kTetGen);
    ok &= check(writeVtkLegacy(file("vtk", "one-tet-binary.vtk").toStdString(), one, true));
    ok &= check(writeVtkLegacy(file("vtk", "one-tet-ascii.vtk").toStdString(), one, false));
    ok &= writeBytes(file("vtk", "two-tets-5.1.vtk"), kVtk51);
    ok &= check(writeMedit(file("medit", "box.mesh").toStdString(), box));
    ok &= writeBytes(file("medit", "two-tets-mmg.mesh"), kMedit);

    // Surfaces: a unit cube with texture coordinates, in every format.
    TriangleSurface cube = makeBox({0, 0, 0}, {1, 1, 1});
    cube.uvs.clear();
    for (const Vec3& p : cube.positions)
        cube.uvs.emplace_back(p.x() + 0.5 * p.z(), p.y());
    for (const char* ext : {"obj", "stl", "ply", "off", "glb"}) {
        const std::string target = std::string("surface_") + ext;
        ok &= check(writeSurface(
            file(target.c_str(), (std::string("cube.") + ext).c_str()).toStdString(), cube));
    }
    ok &= writeBytes(file("surface_ply", "tet-binary.ply"), binaryPly());
    const QByteArray gltf = inlineGltf(cube);
    ok &= !gltf.isEmpty() && writeBytes(file("surface_gltf", "cube.gltf"), gltf);
    return ok ? 0 : 1;
}
