// Legacy VTK (.vtk), Medit (.mesh) and TetGen (.node/.ele) read and written (issue 21):
// exact round trips at three scales of a deformed two-piece mesh whose cut left coincident
// distinct nodes; our .vtk files as VTK's own reader sees them; files written by gmsh
// (tests/data/vtk_medit, make.sh) and by VTK's legacy writer (versions 4.2 and 5.1);
// mixed-element files; and every refusal, each naming what is wrong and leaving `out`
// untouched.

#include "scenario/mesh_io.h"

#include "grid_contract.h"
#include "scenario_test_util.h"

#include "core/mesh/predicates.h"
#include "core/mesh/topology.h"

#include <vtkCellArray.h>
#include <vtkCellData.h>
#include <vtkCellType.h>
#include <vtkDataArray.h>
#include <vtkDoubleArray.h>
#include <vtkIntArray.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkSmartPointer.h>
#include <vtkUnstructuredGrid.h>
#include <vtkUnstructuredGridReader.h>
#include <vtkUnstructuredGridWriter.h>

#include <QTemporaryDir>
#include <QtTest>

#include <cmath>

using namespace resect;
using namespace resect::test;

namespace {

const QString kData = QStringLiteral(RESECT_SOURCE_DIR "/tests/data/vtk_medit");

/// Two pieces: tets 0 and 1 share the face (0, 1, 2); tet 2 has its own nodes 5, 6, 7 at
/// the positions of nodes 1, 2, 3 (a cut separated them). Coordinates scaled by `scale`,
/// deformed by a smooth field (coincident nodes stay coincident), velocities and masses
/// that need all 17 digits.
TetMesh makeCutMesh(double scale) {
    std::vector<Vec3> ref{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}, {0.25, 0.25, -1},
                          {1, 0, 0}, {0, 1, 0}, {0, 0, 1}, {1, 1, 1}};
    for (Vec3& p : ref)
        p *= scale;
    TetMesh mesh = TetMesh::fromArrays(ref, {{0, 1, 2, 3}, {0, 2, 1, 4}, {5, 6, 7, 8}});
    for (int n = 0; n < mesh.nodeCount(); ++n) {
        const Vec3 p = ref[static_cast<std::size_t>(n)] / scale;
        mesh.positions()[n] =
            ref[static_cast<std::size_t>(n)] +
            scale * Vec3(0.01 * std::sin(3 * p.x() + 1), 0.02 * std::cos(p.y() + p.z()),
                         0.015 * std::sin(p.x() * p.y() + 0.3));
        const double s = std::sqrt(2.0 + n);
        mesh.velocities()[n] = Vec3(s, -1.0 / s, std::cbrt(s)) * scale;
        mesh.masses()[n] = 1e-4 * s * scale * scale * scale;
    }
    return mesh;
}

bool sameVectors(std::span<const Vec3> a, std::span<const Vec3> b) {
    return a.size() == b.size() && std::equal(a.begin(), a.end(), b.begin());
}

QString message(const Status& s) { return QString::fromStdString(s.message()); }

/// A legacy VTK ASCII unit tet, the base of the refusal rows.
QByteArray vtkTet(const QByteArray& header = "# vtk DataFile Version 4.2\nunit tet\nASCII\n"
                                             "DATASET UNSTRUCTURED_GRID\n",
                  const QByteArray& points = "POINTS 4 double\n0 0 0 1 0 0 0 1 0 0 0 1\n",
                  const QByteArray& cells = "CELLS 1 5\n4 0 1 2 3\n",
                  const QByteArray& types = "CELL_TYPES 1\n10\n", const QByteArray& rest = {}) {
    return header + points + cells + types + rest;
}

/// A Medit unit tet, the base of the refusal rows.
QByteArray meditTet(const QByteArray& head = "MeshVersionFormatted 2\nDimension 3\n",
                    const QByteArray& vertices = "Vertices\n4\n0 0 0 0\n1 0 0 0\n0 1 0 0\n0 0 1 0\n",
                    const QByteArray& tets = "Tetrahedra\n1\n1 2 3 4 0\n",
                    const QByteArray& end = "End\n") {
    return head + vertices + tets + end;
}

void putBigEndian(QByteArray& out, std::uint64_t v, int bytes) {
    for (int b = bytes - 1; b >= 0; --b)
        out.append(static_cast<char>((v >> (8 * b)) & 0xff));
}

/// The binary twin of vtkTet(), with `pointBytes` bytes of its POINTS data (96 = all).
QByteArray binaryVtkTet(int pointBytes = 96, double nanAt0 = 0) {
    QByteArray data;
    const double coords[12] = {nanAt0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1};
    for (double c : coords)
        putBigEndian(data, std::bit_cast<std::uint64_t>(c), 8);
    QByteArray cells;
    for (int v : {4, 0, 1, 2, 3})
        putBigEndian(cells, static_cast<std::uint32_t>(v), 4);
    QByteArray types;
    putBigEndian(types, 10, 4);
    return "# vtk DataFile Version 4.2\nunit tet\nBINARY\nDATASET UNSTRUCTURED_GRID\n"
           "POINTS 4 double\n" +
           data.left(pointBytes) +
           (pointBytes < 96 ? QByteArray()
                            : "\nCELLS 1 5\n" + cells + "\nCELL_TYPES 1\n" + types + "\n");
}

} // namespace

class TestMeshFormatVtkMedit : public QObject {
    Q_OBJECT

private slots:
    void roundTrip_data();
    void roundTrip();
    void ourVtkThroughVtkReader_data();
    void ourVtkThroughVtkReader();
    void vtkWrittenByVtk_data();
    void vtkWrittenByVtk();
    void gmshFiles_data();
    void gmshFiles();
    void meditStyles_data();
    void meditStyles();
    void tetgenRegionsAndForeignAttributes();
    void refusals_data();
    void refusals();
    void damagedFilesNeverCrash_data();
    void damagedFilesNeverCrash();
};

void TestMeshFormatVtkMedit::roundTrip_data() {
    QTest::addColumn<QString>("key");
    QTest::addColumn<QString>("name");
    QTest::addColumn<QString>("readName"); // the file read back (TetGen: the other half)
    QTest::addColumn<double>("scale");
    struct Format {
        const char *key, *name, *readName;
    };
    const Format formats[] = {{"vtk", "m.vtk", "m.vtk"},
                              {"vtk-ascii", "m.vtk", "m.vtk"},
                              {"medit", "m.mesh", "m.mesh"},
                              {"tetgen", "m.node", "m.ele"},
                              {"tetgen", "M.ELE", "M.NODE"}};
    for (const Format& f : formats)
        for (double scale : {1e-3, 1.0, 1e3})
            QTest::addRow("%s %s scale %g", f.key, f.name, scale)
                << f.key << f.name << f.readName << scale;
}

void TestMeshFormatVtkMedit::roundTrip() {
    QFETCH(QString, key);
    QFETCH(QString, name);
    QFETCH(QString, readName);
    QFETCH(double, scale);
    QTemporaryDir dir;
    QVERIFY(dir.isValid());
    const TetMesh mesh = makeCutMesh(scale);
    const MeshFormatInfo* format = findMeshFormat(key.toStdString());
    QVERIFY(format);
    const Status w = writeTetMesh(dir.filePath(name).toStdString(), mesh, format->format);
    QVERIFY2(w.ok(), w.message().c_str());

    TetMesh back;
    MeshReadReport report;
    const Status r = readTetMesh(dir.filePath(readName).toStdString(), back, &report);
    QVERIFY2(r.ok(), r.message().c_str());
    // Coincident nodes stay distinct, and the cut stays a cut.
    QCOMPARE(back.nodeCount(), mesh.nodeCount());
    QCOMPARE(back.tetCount(), mesh.tetCount());
    QCOMPARE(connectedComponents(back).count, 2);
    for (int t = 0; t < mesh.tetCount(); ++t)
        QVERIFY(back.tet(t) == mesh.tet(t));
    QVERIFY(sameVectors(back.positions(), mesh.positions()));
    // Volume groups: piece + 1, read from the piece array, Medit references or TetGen regions.
    QCOMPARE(report.groups.size(), std::size_t(2));
    QCOMPARE(report.groups[0].tag, std::int64_t(1));
    QCOMPARE(report.groups[0].tets, std::int64_t(2));
    QCOMPARE(report.groups[1].tag, std::int64_t(2));
    QCOMPARE(report.groups[1].tets, std::int64_t(1));
    QCOMPARE(report.tetGroup, (std::vector<std::int64_t>{1, 1, 2}));
    if (key != "medit")
        QVERIFY(report.dropped.empty());

    const bool vtk = key.startsWith("vtk");
    if (key == "medit") {
        QCOMPARE(report.format, std::string("Medit"));
        // The boundary triangles (6 of piece 0, 4 of piece 1) are written, outward, with
        // reference piece + 1, and dropped on reading.
        QCOMPARE(report.dropped.size(), std::size_t(1));
        QCOMPARE(report.dropped[0].what, std::string("3-node triangle"));
        QCOMPARE(report.dropped[0].count, std::int64_t(10));
        const QByteArray text = readBytes(dir.filePath(name));
        const qsizetype at = text.indexOf("Triangles\n10\n");
        QVERIFY(at >= 0);
        const QList<QByteArray> lines = text.mid(at).split('\n');
        for (int i = 2; i < 12; ++i) {
            const QList<QByteArray> v = lines[i].split(' ');
            QCOMPARE(v.size(), 4);
            const int a = v[0].toInt() - 1, b = v[1].toInt() - 1, c = v[2].toInt() - 1;
            int tet = -1;
            for (int t = 0; t < mesh.tetCount(); ++t) {
                const Tet& q = mesh.tet(t);
                if (std::count(q.begin(), q.end(), a) + std::count(q.begin(), q.end(), b) +
                        std::count(q.begin(), q.end(), c) == 3)
                    tet = t;
            }
            QVERIFY(tet >= 0);
            QCOMPARE(v[3].toInt(), tet == 2 ? 2 : 1);
            int d = 0;
            for (int k : mesh.tet(tet))
                if (k != a && k != b && k != c)
                    d = k;
            const auto p = mesh.positions();
            QCOMPARE(orient3d(p[a], p[b], p[c], p[d]), -1); // the tet lies behind its face
        }
        // Positions only: the reference configuration is the current one.
        QVERIFY(sameVectors(back.referencePositions(), mesh.positions()));
        return;
    }
    QVERIFY(sameVectors(back.referencePositions(), mesh.referencePositions()));
    QVERIFY(std::equal(back.masses().begin(), back.masses().end(), mesh.masses().begin()));
    if (vtk) {
        QCOMPARE(report.format, std::string(key == "vtk" ? "Legacy VTK binary" : "Legacy VTK ASCII"));
        QVERIFY(sameVectors(back.velocities(), mesh.velocities()));
    } else {
        QCOMPARE(report.format, std::string("TetGen"));
        for (const Vec3& v : back.velocities())
            QCOMPARE(v, Vec3(Vec3::Zero()));
    }
}

void TestMeshFormatVtkMedit::ourVtkThroughVtkReader_data() {
    QTest::addColumn<bool>("binary");
    QTest::newRow("ascii") << false;
    QTest::newRow("binary") << true;
}

void TestMeshFormatVtkMedit::ourVtkThroughVtkReader() {
    QFETCH(bool, binary);
    QTemporaryDir dir;
    QVERIFY(dir.isValid());
    const TetMesh mesh = makeCutMesh(1.0);
    const std::string path = dir.filePath("m.vtk").toStdString();
    const Status w = writeVtkLegacy(path, mesh, binary);
    QVERIFY2(w.ok(), w.message().c_str());
    QVERIFY(readBytes(dir.filePath("m.vtk")).startsWith("# vtk DataFile Version 4.2\n"));

    auto reader = vtkSmartPointer<vtkUnstructuredGridReader>::New();
    reader->SetFileName(path.c_str());
    reader->Update();
    vtkUnstructuredGrid* grid = reader->GetOutput();
    // The .vtu contract on what VTK read: every value exact, the cells the mesh's tets.
    const QString problem = gridContractProblem(grid, mesh, connectedComponents(mesh).tetComponent);
    QVERIFY2(problem.isEmpty(), qPrintable(problem));
}

void TestMeshFormatVtkMedit::vtkWrittenByVtk_data() {
    QTest::addColumn<int>("version");
    QTest::addColumn<bool>("binary");
    for (int version : {42, 51})
        for (bool binary : {false, true})
            QTest::addRow("%d %s", version, binary ? "binary" : "ascii") << version << binary;
}

void TestMeshFormatVtkMedit::vtkWrittenByVtk() {
    QFETCH(int, version);
    QFETCH(bool, binary);
    // A tet, a 10-node tet on the same corners moved by 2 along x, a triangle and a vertex;
    // point data mass (SCALARS), a temperature the reader skips, cell data CellEntityIds.
    auto grid = vtkSmartPointer<vtkUnstructuredGrid>::New();
    auto points = vtkSmartPointer<vtkPoints>::New();
    points->SetDataTypeToDouble();
    const double corners[4][3] = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
    for (const auto& c : corners)
        points->InsertNextPoint(c);
    for (const auto& c : corners)
        points->InsertNextPoint(c[0] + 2, c[1], c[2]);
    for (int k = 0; k < 6; ++k) // the 10-node tet's edge midpoints
        points->InsertNextPoint(2.1 + 0.1 * k, 0.1, 0.1);
    grid->SetPoints(points);
    const vtkIdType tet[4] = {0, 1, 2, 3};
    const vtkIdType quadratic[10] = {4, 5, 6, 7, 8, 9, 10, 11, 12, 13};
    const vtkIdType tri[3] = {0, 1, 2};
    const vtkIdType vertex[1] = {3};
    grid->InsertNextCell(VTK_TETRA, 4, tet);
    grid->InsertNextCell(VTK_QUADRATIC_TETRA, 10, quadratic);
    grid->InsertNextCell(VTK_TRIANGLE, 3, tri);
    grid->InsertNextCell(VTK_VERTEX, 1, vertex);
    auto mass = vtkSmartPointer<vtkDoubleArray>::New();
    mass->SetName("mass");
    auto temperature = vtkSmartPointer<vtkDoubleArray>::New();
    temperature->SetName("temperature");
    for (vtkIdType i = 0; i < 14; ++i) {
        mass->InsertNextValue(0.1 + std::sqrt(2.0 + static_cast<double>(i)));
        temperature->InsertNextValue(37);
    }
    grid->GetPointData()->SetScalars(temperature);
    grid->GetPointData()->AddArray(mass);
    auto ids = vtkSmartPointer<vtkIntArray>::New();
    ids->SetName("CellEntityIds");
    for (int v : {7, 9, 1, 1})
        ids->InsertNextValue(v);
    grid->GetCellData()->AddArray(ids);

    QTemporaryDir dir;
    QVERIFY(dir.isValid());
    const QString path = dir.filePath("vtk.vtk");
    auto writer = vtkSmartPointer<vtkUnstructuredGridWriter>::New();
    writer->SetFileName(path.toLocal8Bit().constData());
    writer->SetInputData(grid);
    writer->SetFileVersion(version);
    if (binary)
        writer->SetFileTypeToBinary();
    QVERIFY(writer->Write());
    const QByteArray bytes = readBytes(path);
    QVERIFY(bytes.startsWith(version == 42 ? "# vtk DataFile Version 4.2"
                                           : "# vtk DataFile Version 5.1"));
    QCOMPARE(bytes.contains("OFFSETS"), version == 51);

    TetMesh mesh;
    MeshReadReport report;
    const Status r = readTetMesh(path.toStdString(), mesh, &report);
    QVERIFY2(r.ok(), r.message().c_str());
    QCOMPARE(report.format, std::string(binary ? "Legacy VTK binary" : "Legacy VTK ASCII"));
    QCOMPARE(mesh.tetCount(), 2);
    QCOMPARE(mesh.nodeCount(), 8); // the midpoints and nothing else are dropped
    QCOMPARE(mesh.totalReferenceVolume(), 2.0 / 6.0);
    QCOMPARE(report.dropped.size(), std::size_t(2));
    QCOMPARE(report.dropped[0].what, std::string("VTK_TRIANGLE"));
    QCOMPARE(report.dropped[0].count, std::int64_t(1));
    QCOMPARE(report.dropped[1].what, std::string("VTK_VERTEX"));
    QCOMPARE(report.notes.size(), std::size_t(1));
    QVERIFY(QString::fromStdString(report.notes[0]).contains("1 10-node tetrahedra"));
    QCOMPARE(report.tetGroup, (std::vector<std::int64_t>{7, 9}));
    QVERIFY(QString::fromStdString(report.summary()).contains("VTK_TRIANGLE 1"));
    // The masses of the file: exact in binary; VTK's ASCII writer prints 11 digits.
    for (int n = 0; n < 8; ++n) {
        const double expected = 0.1 + std::sqrt(2.0 + n);
        if (binary)
            QCOMPARE(mesh.masses()[n], expected);
        else
            QVERIFY(std::abs(mesh.masses()[n] - expected) < 1e-9);
    }
}

void TestMeshFormatVtkMedit::gmshFiles_data() {
    QTest::addColumn<QString>("file");
    QTest::addColumn<QString>("format");
    QTest::addColumn<QStringList>("dropped"); // "what count", in the order met
    QTest::newRow("ascii vtk") << "box.vtk"
                               << "Legacy VTK ASCII"
                               << QStringList{"VTK_VERTEX 8", "VTK_LINE 36", "VTK_TRIANGLE 156"};
    QTest::newRow("binary vtk") << "box-bin.vtk"
                                << "Legacy VTK binary"
                                << QStringList{"VTK_VERTEX 8", "VTK_LINE 36", "VTK_TRIANGLE 156"};
    QTest::newRow("medit") << "box.mesh"
                           << "Medit" << QStringList{"2-node edge 36", "3-node triangle 156"};
}

void TestMeshFormatVtkMedit::gmshFiles() {
    QFETCH(QString, file);
    QFETCH(QString, format);
    QFETCH(QStringList, dropped);
    TetMesh mesh;
    MeshReadReport report;
    const Status r = readTetMesh((kData + "/" + file).toStdString(), mesh, &report);
    QVERIFY2(r.ok(), r.message().c_str());
    QCOMPARE(QString::fromStdString(report.format), format);
    QCOMPARE(mesh.nodeCount(), 81);
    QCOMPARE(mesh.tetCount(), 184);
    QVERIFY(std::abs(mesh.totalReferenceVolume() - 1.0) < 1e-12);
    QStringList got;
    for (const MeshReadReport::Dropped& d : report.dropped)
        got << QString::fromStdString(d.what) + " " + QString::number(d.count);
    QCOMPARE(got, dropped);
    // gmsh's physical volume 1 ("tissue"): CellEntityIds in .vtk, the reference in .mesh.
    QCOMPARE(report.groups.size(), std::size_t(1));
    QCOMPARE(report.groups[0].tag, std::int64_t(1));
    QCOMPARE(report.groups[0].tets, std::int64_t(184));
}

void TestMeshFormatVtkMedit::meditStyles_data() {
    QTest::addColumn<QByteArray>("text");
    QTest::addColumn<int>("nodes");
    QTest::addColumn<QStringList>("dropped");
    QTest::addColumn<QList<qint64>>("groups");
    // TetWild: counts on their own lines, references 0 (no groups).
    QTest::newRow("tetwild") << QByteArray("MeshVersionFormatted 1\nDimension 3\nVertices\n5\n"
                                           "0 0 0 0\n1 0 0 0\n0 1 0 0\n0 0 1 0\n1 1 1 0\n"
                                           "Tetrahedra\n2\n1 2 3 4 0\n2 3 4 5 0\nEnd\n")
                             << 5 << QStringList{} << QList<qint64>{};
    // mmg: comments, counts on the keyword's line, Corners, Ridges, RequiredVertices,
    // Edges, Triangles with references, keywords in other cases, CRLF line ends; an
    // inverted tet (2 4 3 5) that the reader reorders; vertex 6 is used by no tet.
    QTest::newRow("mmg") << QByteArray("# written by mmg3d\r\nMeshVersionFormatted 2\r\n\r\n"
                                       "Dimension 3\r\nVertices 6\r\n"
                                       "0 0 0 1\r\n1 0 0 1\r\n0 1 0 1\r\n0 0 1 1\r\n1 1 1 2\r\n"
                                       "9 9 9 0\r\n"
                                       "Corners 2\r\n1 2\r\nRidges\r\n1\r\n1\r\n"
                                       "RequiredVertices 1\r\n5\r\n"
                                       "Edges 1\r\n1 2 3\r\n"
                                       "TRIANGLES 2\r\n1 2 3 4 # bottom\r\n1 2 4 4\r\n"
                                       "Normals 1\r\n0 0 1\r\nNormalAtVertices 1\r\n1 1\r\n"
                                       "tetrahedra 2\r\n1 2 3 4 3\r\n2 4 3 5 8\r\nEnd\r\n")
                         << 5 << QStringList{"2-node edge 1", "3-node triangle 2"}
                         << QList<qint64>{3, 8};
}

void TestMeshFormatVtkMedit::meditStyles() {
    QFETCH(QByteArray, text);
    QFETCH(int, nodes);
    QFETCH(QStringList, dropped);
    QFETCH(QList<qint64>, groups);
    QTemporaryDir dir;
    QVERIFY(dir.isValid());
    QVERIFY(writeBytes(dir.filePath("m.mesh"), text));
    TetMesh mesh;
    MeshReadReport report;
    const Status r = readTetMesh(dir.filePath("m.mesh").toStdString(), mesh, &report);
    QVERIFY2(r.ok(), r.message().c_str());
    QCOMPARE(mesh.nodeCount(), nodes);
    QCOMPARE(mesh.tetCount(), 2);
    QCOMPARE(mesh.totalReferenceVolume(), 0.5); // 1/6 + 2/6
    QStringList got;
    for (const MeshReadReport::Dropped& d : report.dropped)
        got << QString::fromStdString(d.what) + " " + QString::number(d.count);
    QCOMPARE(got, dropped);
    QList<qint64> tags;
    for (const MeshReadReport::Group& g : report.groups) {
        tags << g.tag;
        QCOMPARE(g.dimension, 3);
        QCOMPARE(g.tets, std::int64_t(1));
    }
    QCOMPARE(tags, groups);
    QCOMPARE(report.tetGroup.size(), groups.isEmpty() ? std::size_t(0) : std::size_t(2));
}

void TestMeshFormatVtkMedit::tetgenRegionsAndForeignAttributes() {
    QTemporaryDir dir;
    QVERIFY(dir.isValid());
    // TetGen -A output: region attributes 1 and -1 (TetGen's own numbers); 4 point
    // attributes of someone else's (no resect comment): positions only.
    QVERIFY(writeBytes(dir.filePath("r.node"),
                       "# Created by tetgen\n5 3 4 0\n1 0 0 0 7 7 7 7\n2 1 0 0 7 7 7 7\n"
                       "3 0 1 0 7 7 7 7\n4 0 0 1 7 7 7 7\n5 1 1 1 7 7 7 7\n"));
    QVERIFY(writeBytes(dir.filePath("r.ele"), "2 4 1\n1 1 2 3 4 1\n2 2 3 4 5 -1\n"));
    TetMesh mesh;
    MeshReadReport report;
    Status r = readTetMesh(dir.filePath("r.node").toStdString(), mesh, &report);
    QVERIFY2(r.ok(), r.message().c_str());
    QCOMPARE(mesh.referencePositions()[1], Vec3(1, 0, 0));
    QVERIFY(mesh.masses()[0] != 7.0);
    QCOMPARE(report.tetGroup, (std::vector<std::int64_t>{1, -1}));
    QCOMPARE(report.groups.size(), std::size_t(2));
    // Non-integer attributes are no regions.
    QVERIFY(writeBytes(dir.filePath("r.ele"), "2 4 1\n1 1 2 3 4 1\n2 2 3 4 5 0.5\n"));
    r = readTetMesh(dir.filePath("r.ele").toStdString(), mesh, &report);
    QVERIFY2(r.ok(), r.message().c_str());
    QVERIFY(report.tetGroup.empty());
    QVERIFY(report.groups.empty());
}

void TestMeshFormatVtkMedit::refusals_data() {
    QTest::addColumn<QString>("name");
    QTest::addColumn<QByteArray>("content");
    QTest::addColumn<QString>("expected");
    const QByteArray head = "# vtk DataFile Version 4.2\nunit tet\nASCII\nDATASET UNSTRUCTURED_GRID\n";
    const QByteArray pts = "POINTS 4 double\n0 0 0 1 0 0 0 1 0 0 0 1\n";
    const QByteArray cells = "CELLS 1 5\n4 0 1 2 3\n";
    const QByteArray types = "CELL_TYPES 1\n10\n";
    // Legacy VTK.
    QTest::newRow("vtk not vtk") << "a.vtk" << QByteArray("solid cube\n") << "not a legacy VTK file";
    QTest::newRow("vtk version 6.0")
        << "a.vtk" << vtkTet("# vtk DataFile Version 6.0\nt\nASCII\nDATASET UNSTRUCTURED_GRID\n")
        << "version '6.0'";
    QTest::newRow("vtk no ascii/binary")
        << "a.vtk" << vtkTet("# vtk DataFile Version 4.2\nt\nTEXT\nDATASET UNSTRUCTURED_GRID\n")
        << "expected ASCII or BINARY";
    QTest::newRow("vtk polydata")
        << "a.vtk" << vtkTet("# vtk DataFile Version 4.2\nt\nASCII\nDATASET POLYDATA\n")
        << "dataset type POLYDATA";
    QTest::newRow("vtk header only")
        << "a.vtk" << QByteArray("# vtk DataFile Version 3.0") << "ends after its first line";
    QTest::newRow("vtk huge point count")
        << "a.vtk" << vtkTet(head, "POINTS 2000000000 double\n0 0 0 1 0 0 0 1 0 0 0 1\n")
        << "POINTS declares 6000000000 values";
    QTest::newRow("vtk point count beyond int")
        << "a.vtk" << vtkTet(head, "POINTS 9000000000 double\n0 0 0\n") << "larger than";
    QTest::newRow("vtk huge cell size")
        << "a.vtk" << vtkTet(head, pts, "CELLS 1 999999999\n4 0 1 2 3\n")
        << "CELLS declares 999999999 values";
    QTest::newRow("vtk cell size past the end")
        << "a.vtk" << vtkTet(head, pts, "CELLS 1 5\n7 0 1 2 3\n") << "declares 7 nodes";
    QTest::newRow("vtk negative cell size")
        << "a.vtk" << vtkTet(head, pts, "CELLS 1 5\n-1 0 1 2 3\n") << "declares -1 nodes";
    QTest::newRow("vtk cell count")
        << "a.vtk" << vtkTet(head, pts, "CELLS 2 5\n4 0 1 2 3\n") << "declares 2 cells";
    QTest::newRow("vtk cell type count")
        << "a.vtk" << vtkTet(head, pts, cells, "CELL_TYPES 2\n10 10\n") << "lists 2 types for 1";
    QTest::newRow("vtk polyhedron")
        << "a.vtk" << vtkTet(head, pts, cells, "CELL_TYPES 1\n42\n") << "VTK_POLYHEDRON";
    QTest::newRow("vtk unknown cell type")
        << "a.vtk" << vtkTet(head, pts, cells, "CELL_TYPES 1\n200\n") << "VTK does not know";
    QTest::newRow("vtk no cell types") << "a.vtk" << vtkTet(head, pts, cells, "") << "no CELL_TYPES";
    QTest::newRow("vtk tetra of 3 nodes")
        << "a.vtk" << vtkTet(head, pts, "CELLS 1 4\n3 0 1 2\n") << "VTK_TETRA with 3 nodes";
    QTest::newRow("vtk no tets")
        << "a.vtk" << vtkTet(head, pts, "CELLS 1 4\n3 0 1 2\n", "CELL_TYPES 1\n5\n")
        << "no tetrahedra";
    QTest::newRow("vtk node index")
        << "a.vtk" << vtkTet(head, pts, "CELLS 1 5\n4 0 1 2 9\n") << "refers to node 9";
    QTest::newRow("vtk nan ascii")
        << "a.vtk" << vtkTet(head, "POINTS 4 double\nnan 0 0 1 0 0 0 1 0 0 0 1\n")
        << "POINTS: 'nan' is not a finite number";
    QTest::newRow("vtk bad number")
        << "a.vtk" << vtkTet(head, "POINTS 4 double\n0 0 0 1 0 0 0 1x 0 0 0 1\n")
        << "'1x' is not a finite number";
    QTest::newRow("vtk nan binary") << "a.vtk" << binaryVtkTet(96, std::nan(""))
                                    << "the position of point 0 is not finite";
    QTest::newRow("vtk truncated binary")
        << "a.vtk" << binaryVtkTet(50) << "bytes follow (truncated file?)";
    QTest::newRow("vtk truncated ascii")
        << "a.vtk" << vtkTet(head, pts, "CELLS 1 5\n4 0 1\n\n\n\n\n\n\n", "")
        << "unexpected end of file after 3 of 5 values";
    QTest::newRow("vtk point data count")
        << "a.vtk" << vtkTet(head, pts, cells, types, "POINT_DATA 3\n") << "POINT_DATA 3 does not match";
    QTest::newRow("vtk unknown section")
        << "a.vtk" << vtkTet(head, pts, cells, types, "BLAH 3\n") << "unknown section 'BLAH'";
    QTest::newRow("vtk string array")
        << "a.vtk"
        << vtkTet(head, pts, cells, types, "POINT_DATA 4\nFIELD f 1\nmass 1 4 string\na b c d\n")
        << "data type 'string'";
    QTest::newRow("vtk huge field array")
        << "a.vtk"
        << vtkTet(head, pts, cells, types, "POINT_DATA 4\nFIELD f 1\nx 60000 2000000000 double\n0\n")
        << "FIELD array 'x' declares";
    QTest::newRow("vtk mass components")
        << "a.vtk"
        << vtkTet(head, pts, cells, types,
                  "POINT_DATA 4\nSCALARS mass double 2\nLOOKUP_TABLE default\n1 1 1 1 1 1 1 1\n")
        << "point array 'mass' has 2 components";
    QTest::newRow("vtk negative mass")
        << "a.vtk"
        << vtkTet(head, pts, cells, types,
                  "POINT_DATA 4\nSCALARS mass double\nLOOKUP_TABLE default\n1 -1 1 1\n")
        << "mass of node 1 is -1";
    QTest::newRow("vtk scalars without lookup table")
        << "a.vtk"
        << vtkTet(head, pts, cells, types, "POINT_DATA 4\nSCALARS mass double 1\n1 1 1 1\n")
        << "needs a LOOKUP_TABLE";
    QTest::newRow("vtk offsets")
        << "a.vtk"
        << vtkTet("# vtk DataFile Version 5.1\nt\nASCII\nDATASET UNSTRUCTURED_GRID\n", pts,
                  "CELLS 2 4\nOFFSETS vtktypeint64\n0 9\nCONNECTIVITY vtktypeint64\n0 1 2 3\n")
        << "OFFSETS must run from 0";
    QTest::newRow("vtk zero volume")
        << "a.vtk" << vtkTet(head, "POINTS 4 double\n0 0 0 1 0 0 0 1 0 1 1 0\n") << "zero volume";
    // Medit.
    QTest::newRow("medit meshb content")
        << "a.mesh" << QByteArray("\x01\x00\x00\x00\x02\x00\x00\x00", 8) << ".meshb";
    QTest::newRow("medit meshb name") << "a.meshb" << meditTet() << ".meshb";
    QTest::newRow("medit dimension 2")
        << "a.mesh" << meditTet("MeshVersionFormatted 2\nDimension 2\n") << "Dimension 2";
    QTest::newRow("medit version 3")
        << "a.mesh" << meditTet("MeshVersionFormatted 3\nDimension 3\n") << "versions 1 and 2";
    QTest::newRow("medit no header")
        << "a.mesh" << meditTet("") << "expected MeshVersionFormatted, found 'Vertices'";
    QTest::newRow("medit huge count")
        << "a.mesh" << meditTet(QByteArray("MeshVersionFormatted 2\nDimension 3\n"),
                                "Vertices\n99999999999\n0 0 0 0\n")
        << "Vertices declares 99999999999 records";
    QTest::newRow("medit index past the end")
        << "a.mesh" << meditTet(QByteArray("MeshVersionFormatted 2\nDimension 3\n"),
                                "Vertices\n4\n0 0 0 0\n1 0 0 0\n0 1 0 0\n0 0 1 0\n",
                                "Tetrahedra\n1\n1 2 3 9 0\n")
        << "refers to vertex 9";
    QTest::newRow("medit index 0")
        << "a.mesh" << meditTet(QByteArray("MeshVersionFormatted 2\nDimension 3\n"),
                                "Vertices\n4\n0 0 0 0\n1 0 0 0\n0 1 0 0\n0 0 1 0\n",
                                "Tetrahedra\n1\n0 1 2 3 0\n")
        << "refers to vertex 0";
    QTest::newRow("medit nan")
        << "a.mesh" << meditTet(QByteArray("MeshVersionFormatted 2\nDimension 3\n"),
                                "Vertices\n4\n0 0 0 0\n1 0 nan 0\n0 1 0 0\n0 0 1 0\n")
        << "vertex 2 has a non-finite coordinate";
    QTest::newRow("medit bad number")
        << "a.mesh" << meditTet(QByteArray("MeshVersionFormatted 2\nDimension 3\n"),
                                "Vertices\n4\n0 0 0 0\n1 0 z 0\n0 1 0 0\n0 0 1 0\n")
        << "expected the z of vertex 2, found 'z'";
    QTest::newRow("medit unknown keyword")
        << "a.mesh" << meditTet(QByteArray("MeshVersionFormatted 2\nDimension 3\nFoo 3\n"))
        << "unknown keyword 'Foo'";
    QTest::newRow("medit truncated")
        << "a.mesh" << QByteArray("MeshVersionFormatted 2\nDimension 3\nVertices\n4\n0 0 0 0\n"
                                  "1 0 0 0\n0 1 0 0\n0 0 1\n")
        << "unexpected end of file, expected the reference of vertex 4";
    QTest::newRow("medit no tetrahedra")
        << "a.mesh" << meditTet(QByteArray("MeshVersionFormatted 2\nDimension 3\n"),
                                "Vertices\n4\n0 0 0 0\n1 0 0 0\n0 1 0 0\n0 0 1 0\n", "")
        << "no Tetrahedra section";
    QTest::newRow("medit zero volume")
        << "a.mesh" << meditTet(QByteArray("MeshVersionFormatted 2\nDimension 3\n"),
                                "Vertices\n4\n0 0 0 0\n1 0 0 0\n0 1 0 0\n1 1 0 0\n")
        << "tetrahedron 1 has zero volume";
}

void TestMeshFormatVtkMedit::refusals() {
    QFETCH(QString, name);
    QFETCH(QByteArray, content);
    QFETCH(QString, expected);
    QTemporaryDir dir;
    QVERIFY(dir.isValid());
    const QString path = dir.filePath(name);
    QVERIFY(writeBytes(path, content));
    TetMesh out = makeCutMesh(1.0);
    const TetMesh original = out;
    MeshReadReport report;
    report.format = "untouched";
    StderrCapture capture;
    const Status s = name.endsWith(".meshb") ? readMedit(path.toStdString(), out, &report)
                                             : readTetMesh(path.toStdString(), out, &report);
    const QByteArray printed = capture.text();
    QVERIFY(!s.ok());
    QVERIFY2(message(s).startsWith(path + ":"), s.message().c_str());
    QVERIFY2(message(s).contains(expected), s.message().c_str());
    QVERIFY2(printed.isEmpty(), printed.constData());
    QCOMPARE(report.format, std::string("untouched"));
    QCOMPARE(out.nodeCount(), original.nodeCount());
    QVERIFY(sameVectors(out.positions(), original.positions()));
    QVERIFY(sameVectors(out.referencePositions(), original.referencePositions()));
}

void TestMeshFormatVtkMedit::damagedFilesNeverCrash_data() {
    QTest::addColumn<QString>("name");
    QTest::addColumn<QByteArray>("valid");
    QTemporaryDir dir;
    QVERIFY(dir.isValid());
    const TetMesh mesh = makeCutMesh(1.0);
    const auto written = [&](const QString& name, MeshFormat format) {
        const Status w = writeTetMesh(dir.filePath(name).toStdString(), mesh, format);
        return w.ok() ? readBytes(dir.filePath(name)) : QByteArray();
    };
    QTest::newRow("vtk binary") << "d.vtk" << written("b.vtk", MeshFormat::Vtk);
    QTest::newRow("vtk ascii") << "d.vtk" << written("a.vtk", MeshFormat::VtkAscii);
    QTest::newRow("gmsh vtk binary") << "d.vtk" << readBytes(kData + "/box-bin.vtk");
    QTest::newRow("medit") << "d.mesh" << written("m.mesh", MeshFormat::Medit);
}

/// Every prefix (in steps) and many single-byte changes of valid files: each read gives a
/// mesh or an error naming the file, prints nothing and never crashes.
void TestMeshFormatVtkMedit::damagedFilesNeverCrash() {
    QFETCH(QString, name);
    QFETCH(QByteArray, valid);
    QVERIFY(!valid.isEmpty());
    QTemporaryDir dir;
    QVERIFY(dir.isValid());
    const QString path = dir.filePath(name);
    std::vector<QByteArray> damaged;
    const qsizetype step = std::max<qsizetype>(1, valid.size() / 300);
    for (qsizetype n = 0; n < valid.size(); n += step)
        damaged.push_back(valid.left(n));
    for (qsizetype at = 0; at < valid.size(); at += step)
        for (char c : {'\xff', '\x00', '9', '-', ' '}) {
            QByteArray b = valid;
            b[at] = c;
            damaged.push_back(b);
        }
    int accepted = 0;
    StderrCapture capture;
    for (const QByteArray& bytes : damaged) {
        QVERIFY(writeBytes(path, bytes));
        TetMesh out;
        const Status s = readTetMesh(path.toStdString(), out);
        if (s.ok())
            ++accepted;
        else
            QVERIFY2(message(s).startsWith(path + ":"), s.message().c_str());
    }
    const QByteArray printed = capture.text();
    QVERIFY2(printed.isEmpty(), printed.constData());
    QVERIFY(accepted > 0); // some changes (in digits, in skipped data) leave a valid file
}

QTEST_GUILESS_MAIN(TestMeshFormatVtkMedit)
#include "test_mesh_format_vtk_medit.moc"
