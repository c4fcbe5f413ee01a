// Tet mesh files: .vtu round trip (checked also with VTK's own reader), Gmsh and TetGen
// import (each format in detail: test_mesh_format_*), and every kind of bad input: each
// must give an error naming the file, leave the input file byte-for-byte unchanged, leave
// the output mesh untouched, never crash and print nothing on stderr.

#include "scenario/mesh_io.h"
#include "scenario/vtk_convert.h"

#include "grid_contract.h"
#include "scenario_test_util.h"

#include "core/mesh/masses.h"
#include "core/mesh/material.h"
#include "core/mesh/predicates.h"
#include "core/mesh/quality.h"

#include <vtkCellData.h>
#include <vtkCellType.h>
#include <vtkDataArray.h>
#include <vtkDoubleArray.h>
#include <vtkIdList.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkSmartPointer.h>
#include <vtkUnstructuredGrid.h>
#include <vtkXMLUnstructuredGridReader.h>
#include <vtkXMLUnstructuredGridWriter.h>

#include <QTemporaryDir>
#include <QtTest>

#include <algorithm>
#include <cmath>
#include <limits>
#include <random>

using namespace resect;
using namespace resect::test;

namespace {

// Gmsh 4.1: non-contiguous node tags in three entity blocks (tag 99 is used by no tet and
// is dropped), a point and a triangle element that are skipped, and element 105, which is
// negatively oriented: it is tet (3, 10, 20, 7) with two nodes swapped.
const char* const kGmsh = R"($MeshFormat
4.1 0 8
$EndMeshFormat
$PhysicalNames
1
3 1 "tissue"
$EndPhysicalNames
$Entities
1 0 0 1
1 0 0 0 0
1 0 0 0 1 1 1 0 0
$EndEntities
$Nodes
3 6 3 99
0 1 0 1
40
0 0 0
3 1 0 4
3
10
20
7
1 0 0
0 1 0
0 0 1
1 1 1
0 2 0 1
99
5 5 5
$EndNodes
$Elements
3 4 1 105
0 1 15 1
1 40
2 1 2 1
2 40 3 10
3 1 4 2
100 40 3 10 20
105 3 20 10 7
$EndElements
)";

/// The positions the Gmsh and TetGen samples must give, in file order of the used nodes.
const std::vector<Vec3> kUnitPositions{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}, {1, 1, 1}};

/// TetGen .node with 5 points from `base`, comments, a boundary marker and an attribute.
QByteArray tetgenNode(int base) {
    QByteArray s = "# points: count, dimension, attributes, boundary markers\n"
                   "5 3 1 1\n";
    const char* rows[] = {"0 0 0 0.5 1", "1 0 0 0.5 1  # a corner", "0 1 0 0.5 0", "0 0 1 0.5 1",
                          "1 1 1 0.5 1"};
    for (int i = 0; i < 5; ++i)
        s += QByteArray::number(base + i) + "  " + rows[i] + "\n";
    return s;
}

/// TetGen .ele: tet 2 is negatively oriented (two nodes of (1, 2, 3, 4) swapped).
/// `perTet` 10 adds six (ignored) mid-edge nodes to each tet.
QByteArray tetgenEle(int base, int perTet = 4) {
    auto n = [base](int i) { return QByteArray::number(base + i); };
    QByteArray extra;
    if (perTet == 10)
        extra = " " + n(0) + " " + n(1) + " " + n(2) + " " + n(3) + " " + n(4) + " " + n(0);
    QByteArray s = "2 " + QByteArray::number(perTet) + " 1\n";
    s += n(0) + " " + n(0) + " " + n(1) + " " + n(2) + " " + n(3) + extra + " 7\n";
    s += "\n# the second one is inverted\n";
    s += n(1) + " " + n(1) + " " + n(3) + " " + n(2) + " " + n(4) + extra + " 7\n";
    return s;
}

/// Writes a grid with VTK's own writer (so that tests can make files our writer refuses
/// to make): points, cells given as (VTK type, node ids), and optional point data.
QByteArray vtkGridBytes(const QString& scratchPath, const std::vector<Vec3>& points,
                        const std::vector<std::pair<int, std::vector<vtkIdType>>>& cells,
                        vtkDataArray* pointArray = nullptr) {
    auto grid = vtkSmartPointer<vtkUnstructuredGrid>::New();
    auto pts = vtkSmartPointer<vtkPoints>::New();
    pts->SetDataTypeToDouble();
    for (const Vec3& p : points)
        pts->InsertNextPoint(p.x(), p.y(), p.z());
    grid->SetPoints(pts);
    for (const auto& [type, ids] : cells)
        grid->InsertNextCell(type, static_cast<vtkIdType>(ids.size()), ids.data());
    if (pointArray)
        grid->GetPointData()->AddArray(pointArray);
    auto writer = vtkSmartPointer<vtkXMLUnstructuredGridWriter>::New();
    writer->SetFileName(scratchPath.toStdString().c_str());
    writer->SetInputData(grid);
    writer->Write();
    return readBytes(scratchPath);
}

const std::vector<Vec3> kCorner{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}, {1, 1, 1}};

/// A hand-written ASCII .vtu with one unit tet, whose Piece declares `pointsAttribute`.
QByteArray asciiVtu(const QByteArray& pointsAttribute) {
    return R"(<?xml version="1.0"?>
<VTKFile type="UnstructuredGrid" version="0.1" byte_order="LittleEndian">
<UnstructuredGrid><Piece NumberOfPoints=")" +
           pointsAttribute + R"(" NumberOfCells="1">
<Points><DataArray type="Float64" NumberOfComponents="3" format="ascii">
0 0 0 1 0 0 0 1 0 0 0 1</DataArray></Points>
<Cells>
<DataArray type="Int64" Name="connectivity" format="ascii">0 1 2 3</DataArray>
<DataArray type="Int64" Name="offsets" format="ascii">4</DataArray>
<DataArray type="UInt8" Name="types" format="ascii">10</DataArray>
</Cells></Piece></UnstructuredGrid></VTKFile>
)";
}

/// True if every tet is positively oriented in the reference configuration (exact).
bool allPositive(const TetMesh& mesh) {
    for (const Tet& t : mesh.tets())
        if (orient3d(mesh.ref(t[0]), mesh.ref(t[1]), mesh.ref(t[2]), mesh.ref(t[3])) <= 0)
            return false;
    return true;
}

/// The tets as sorted node sets, sorted: compares meshes up to node order within tets.
std::vector<Tet> tetSets(const TetMesh& mesh) {
    std::vector<Tet> sets = mesh.tets();
    for (Tet& t : sets)
        std::sort(t.begin(), t.end());
    std::sort(sets.begin(), sets.end());
    return sets;
}

double massSum(const TetMesh& mesh) {
    double sum = 0;
    for (double m : mesh.masses())
        sum += m;
    return sum;
}

bool contains(const Status& s, const QString& text) {
    return QString::fromStdString(s.message()).contains(text);
}

} // namespace

class TestMeshIo : public QObject {
    Q_OBJECT

private slots:
    void tetMeshPathsByExtension();
    void vtuRoundTripIsExact();
    void vtuHasTheContractArrays();
    void vtuOptionalArraysGetDefaults();
    void vtuWriteIsAtomic();
    void gmshNonContiguousTagsAndInvertedTet();
    void tetgen_data();
    void tetgen();
    void readTetMeshDispatchesByExtension_data();
    void readTetMeshDispatchesByExtension();
    void badInputs_data();
    void badInputs();
    void zeroCompressionBlockSizeIsRejected();
    void damagedFilesNeverCrash_data();
    void damagedFilesNeverCrash();

private:
    QTemporaryDir m_scratch; // for generating test data in _data functions
};

void TestMeshIo::vtuRoundTripIsExact() {
    QTemporaryDir dir;
    QVERIFY(dir.isValid());
    const QString path = dir.filePath("sample.vtu");
    const TetMesh mesh = makeSampleMesh();
    const Status w = writeVtu(path.toStdString(), mesh);
    QVERIFY2(w.ok(), w.message().c_str());
    const QByteArray before = readBytes(path);

    TetMesh back;
    const Status r = readVtu(path.toStdString(), back);
    QVERIFY2(r.ok(), r.message().c_str());
    QVERIFY(sameMesh(mesh, back)); // every double bit for bit, tets in the same order
    QCOMPARE(readBytes(path), before);
}

void TestMeshIo::vtuHasTheContractArrays() {
    // Read back with VTK's reader alone, as ParaView or another tool would.
    QTemporaryDir dir;
    QVERIFY(dir.isValid());
    const QString path = dir.filePath("sample.vtu");
    const TetMesh mesh = makeSampleMesh();
    const Status w = writeVtu(path.toStdString(), mesh);
    QVERIFY2(w.ok(), w.message().c_str());

    auto reader = vtkSmartPointer<vtkXMLUnstructuredGridReader>::New();
    reader->SetFileName(path.toStdString().c_str());
    reader->Update();
    vtkUnstructuredGrid* grid = reader->GetOutput();
    const QString problem = gridContractProblem(grid, mesh, {0, 0, 1});
    QVERIFY2(problem.isEmpty(), qPrintable(problem));
}

void TestMeshIo::vtuOptionalArraysGetDefaults() {
    // A plain VTK tet grid without our point data: reference = points, velocity = 0, masses
    // lumped from the default density, so they sum to density * volume.
    QTemporaryDir dir;
    QVERIFY(dir.isValid());
    const QString path = dir.filePath("plain.vtu");
    QVERIFY(writeBytes(path, vtkGridBytes(dir.filePath("scratch.vtu"), kCorner,
                                          {{VTK_TETRA, {0, 1, 2, 3}}, {VTK_TETRA, {1, 2, 3, 4}}})));
    TetMesh mesh;
    const Status r = readVtu(path.toStdString(), mesh);
    QVERIFY2(r.ok(), r.message().c_str());
    QCOMPARE(mesh.nodeCount(), 5);
    QCOMPARE(mesh.tetCount(), 2);
    for (int n = 0; n < 5; ++n) {
        QVERIFY(mesh.referencePositions()[n] == kCorner[n]);
        QVERIFY(mesh.positions()[n] == kCorner[n]);
        QVERIFY(mesh.velocities()[n] == Vec3::Zero());
        QVERIFY(mesh.masses()[n] > 0);
    }
    const double volume = 1.0 / 6 + 2.0 / 6;
    QCOMPARE(mesh.totalReferenceVolume(), volume);
    QVERIFY(std::abs(massSum(mesh) - Material{}.density * volume) <= 1e-15);
}

void TestMeshIo::vtuWriteIsAtomic() {
    QTemporaryDir dir;
    QVERIFY(dir.isValid());
    const QString path = dir.filePath("out.vtu");
    QVERIFY(writeBytes(path, "previous"));
    const Status w = writeVtu(path.toStdString(), makeSampleMesh());
    QVERIFY2(w.ok(), w.message().c_str());
    QCOMPARE(entries(dir.path()), QStringList{"out.vtu"});
    QVERIFY(readBytes(path).startsWith("<?xml") || readBytes(path).startsWith("<VTKFile"));

    const QString bad = dir.filePath("missing-folder/out.vtu");
    const Status e = writeVtu(bad.toStdString(), makeSampleMesh());
    QVERIFY(!e.ok());
    QVERIFY2(contains(e, bad), e.message().c_str());
    QCOMPARE(entries(dir.path()), QStringList{"out.vtu"});
}

void TestMeshIo::gmshNonContiguousTagsAndInvertedTet() {
    QTemporaryDir dir;
    QVERIFY(dir.isValid());
    const QString path = dir.filePath("two.msh");
    QVERIFY(writeBytes(path, kGmsh));
    TetMesh mesh;
    const Status r = readGmsh(path.toStdString(), mesh);
    QVERIFY2(r.ok(), r.message().c_str());
    QCOMPARE(mesh.nodeCount(), 5); // node 99 is used by no tet
    QCOMPARE(mesh.tetCount(), 2);
    for (int n = 0; n < 5; ++n) {
        QVERIFY(mesh.referencePositions()[n] == kUnitPositions[n]);
        QVERIFY(mesh.positions()[n] == kUnitPositions[n]);
        QVERIFY(mesh.velocities()[n] == Vec3::Zero());
    }
    QVERIFY(allPositive(mesh));
    QCOMPARE(tetSets(mesh), (std::vector<Tet>{{0, 1, 2, 3}, {1, 2, 3, 4}}));
    QCOMPARE(mesh.totalReferenceVolume(), 0.5);
    QVERIFY(std::abs(massSum(mesh) - Material{}.density * 0.5) <= 1e-15);
    QCOMPARE(readBytes(path), QByteArray(kGmsh));
}

void TestMeshIo::tetgen_data() {
    QTest::addColumn<int>("base");
    QTest::addColumn<int>("perTet");
    QTest::addColumn<QString>("open");
    QTest::newRow("1-based, open .node") << 1 << 4 << "node";
    QTest::newRow("1-based, open .ele") << 1 << 4 << "ele";
    QTest::newRow("0-based, open .node") << 0 << 4 << "node";
    QTest::newRow("0-based, open .ele") << 0 << 4 << "ele";
    QTest::newRow("10-node tets") << 1 << 10 << "node";
}

void TestMeshIo::tetgen() {
    QFETCH(int, base);
    QFETCH(int, perTet);
    QFETCH(QString, open);
    QTemporaryDir dir;
    QVERIFY(dir.isValid());
    const QByteArray node = tetgenNode(base), ele = tetgenEle(base, perTet);
    QVERIFY(writeBytes(dir.filePath("m.1.node"), node));
    QVERIFY(writeBytes(dir.filePath("m.1.ele"), ele));
    TetMesh mesh;
    const Status r = readTetMesh(dir.filePath("m.1." + open).toStdString(), mesh);
    QVERIFY2(r.ok(), r.message().c_str());
    QCOMPARE(mesh.nodeCount(), 5);
    QCOMPARE(mesh.tetCount(), 2);
    for (int n = 0; n < 5; ++n)
        QVERIFY(mesh.referencePositions()[n] == kUnitPositions[n]);
    QVERIFY(allPositive(mesh));
    QCOMPARE(tetSets(mesh), (std::vector<Tet>{{0, 1, 2, 3}, {1, 2, 3, 4}}));
    QVERIFY(std::abs(massSum(mesh) - Material{}.density * 0.5) <= 1e-15);
    QCOMPARE(readBytes(dir.filePath("m.1.node")), node);
    QCOMPARE(readBytes(dir.filePath("m.1.ele")), ele);
}

void TestMeshIo::readTetMeshDispatchesByExtension_data() {
    QTest::addColumn<QString>("name");
    QTest::addColumn<QString>("format");
    QTest::newRow("vtu") << "a.vtu"
                         << "vtu";
    QTest::newRow("VTU") << "A.VTU"
                         << "vtu";
    QTest::newRow("msh") << "a.msh"
                         << "msh";
    QTest::newRow("Msh") << "a.Msh"
                         << "msh";
}

void TestMeshIo::readTetMeshDispatchesByExtension() {
    QFETCH(QString, name);
    QFETCH(QString, format);
    QTemporaryDir dir;
    QVERIFY(dir.isValid());
    const QString path = dir.filePath(name);
    if (format == "vtu") {
        const Status w = writeVtu(dir.filePath("src.vtu").toStdString(), makeSampleMesh());
        QVERIFY2(w.ok(), w.message().c_str());
        QVERIFY(QFile::rename(dir.filePath("src.vtu"), path));
    } else {
        QVERIFY(writeBytes(path, kGmsh));
    }
    TetMesh mesh;
    const Status r = readTetMesh(path.toStdString(), mesh);
    QVERIFY2(r.ok(), r.message().c_str());
    QVERIFY(mesh.tetCount() >= 2);
}

void TestMeshIo::badInputs_data() {
    QTest::addColumn<QString>("name");       // the file given to readTetMesh
    QTest::addColumn<QByteArray>("content"); // null: the file does not exist
    QTest::addColumn<QString>("sibling");    // TetGen: the other file of the pair
    QTest::addColumn<QByteArray>("siblingContent");
    QTest::addColumn<QString>("expected"); // part of the message
    QTest::addColumn<QString>("named");    // the file the message must name

    auto row = [](const char* tag, const QString& name, const QByteArray& content,
                  const QString& expected) {
        QTest::newRow(tag) << name << content << QString() << QByteArray() << expected << name;
    };
    auto pair = [](const char* tag, const QString& name, const QByteArray& content,
                   const QString& sibling, const QByteArray& siblingContent,
                   const QString& expected, const QString& named) {
        QTest::newRow(tag) << name << content << sibling << siblingContent << expected << named;
    };

    // --- any format
    row("missing vtu", "missing.vtu", QByteArray(), "no such file");
    row("missing msh", "missing.msh", QByteArray(), "no such file");
    row("missing node", "missing.node", QByteArray(), "no such file");
    row("unknown extension", "mesh.xyz", "whatever", "unknown tet mesh extension '.xyz'");
    row("no extension", "mesh", "whatever", "no file extension");

    // --- .vtu
    const QString scratch = m_scratch.filePath("scratch.vtu");
    QVERIFY(writeVtu(m_scratch.filePath("valid.vtu").toStdString(), makeSampleMesh()).ok());
    const QByteArray valid = readBytes(m_scratch.filePath("valid.vtu"));
    QVERIFY(valid.size() > 200);
    row("vtu empty", "empty.vtu", "", "empty file");
    row("vtu truncated", "cut.vtu", valid.left(valid.size() / 2), "cut.vtu");
    row("vtu garbage", "junk.vtu", QByteArray("\x89PNG\r\n\x1a\n\0\0\0\rIHDR\xff\xfe", 18),
        "not a readable VTK unstructured grid");
    row("vtu plain text", "text.vtu", "hello, I am not XML\n",
        "not a readable VTK unstructured grid");
    row("vtu NaN coordinate", "nan.vtu",
        vtkGridBytes(scratch, {{0, 0, 0}, {1, 0, 0}, {0, std::nan(""), 0}, {0, 0, 1}},
                     {{VTK_TETRA, {0, 1, 2, 3}}}),
        "not finite");
    row("vtu triangle cell", "tri.vtu",
        vtkGridBytes(scratch, kCorner, {{VTK_TETRA, {0, 1, 2, 3}}, {VTK_TRIANGLE, {1, 2, 3}}}),
        "cell 1 has VTK cell type 5 (vtkTriangle)");
    row("vtu index out of range", "range.vtu",
        vtkGridBytes(scratch, kCorner, {{VTK_TETRA, {0, 1, 2, 3}}, {VTK_TETRA, {1, 2, 3, 10}}}),
        "refers to node 10");
    row("vtu inverted tet", "inverted.vtu",
        vtkGridBytes(scratch, kCorner, {{VTK_TETRA, {0, 1, 2, 3}}, {VTK_TETRA, {1, 3, 2, 4}}}),
        "tet 1 is inverted");
    row("vtu flat tet", "flat.vtu",
        vtkGridBytes(scratch, {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {1, 1, 0}},
                     {{VTK_TETRA, {0, 1, 2, 3}}}),
        "tet 0 has zero volume");
    {
        auto mass = vtkSmartPointer<vtkDoubleArray>::New();
        mass->SetName("mass");
        mass->SetNumberOfComponents(3); // wrong: mass is a scalar
        mass->SetNumberOfTuples(5);
        mass->Fill(1.0);
        row("vtu mass with 3 components", "mass3.vtu",
            vtkGridBytes(scratch, kCorner, {{VTK_TETRA, {0, 1, 2, 3}}}, mass),
            "point array 'mass' has 3 components");
    }
    {
        auto mass = vtkSmartPointer<vtkDoubleArray>::New();
        mass->SetName("mass");
        mass->SetNumberOfValues(5);
        mass->Fill(-1.0);
        row("vtu negative mass", "negmass.vtu",
            vtkGridBytes(scratch, kCorner, {{VTK_TETRA, {0, 1, 2, 3}}}, mass),
            "masses must be finite and >= 0");
    }
    row("vtu control ascii", "control.vtu", asciiVtu("4"), ""); // sanity: must read (see below)
    row("vtu huge declared count", "huge.vtu", asciiVtu("4000000000000"),
        "NumberOfPoints=\"4000000000000\"");
    row("vtu no cells", "nocells.vtu", vtkGridBytes(scratch, kCorner, {}), "no cells");

    // --- .msh
    const QByteArray head = "$MeshFormat\n4.1 0 8\n$EndMeshFormat\n";
    row("msh empty", "empty.msh", "", "empty file");
    row("msh garbage", "junk.msh", QByteArray("\x01\x02\xff\xfe garbage \0 bytes", 20),
        "not a Gmsh mesh file");
    // (Gmsh 2.2 and binary files read since issue 21; test_mesh_format_gmsh has their refusals.)
    row("msh v4.0", "v40.msh", "$MeshFormat\n4.0 0 8\n$EndMeshFormat\n",
        "Gmsh format 4.0 is not supported");
    row("msh binary floats", "bin.msh",
        QByteArray("$MeshFormat\n4.1 1 4\n\x01\0\0\0\n$EndMeshFormat\n", 40),
        "data-size 4 is not supported");
    const QByteArray gmsh(kGmsh);
    row("msh truncated in nodes", "cut.msh", gmsh.left(gmsh.lastIndexOf("1 1 1")),
        "unexpected end of file in $Nodes");
    row("msh truncated in elements", "cut.msh", gmsh.left(gmsh.lastIndexOf("105 3")),
        "element block of 2 elements, but only 16 bytes follow");
    row("msh truncated before end", "cut.msh", gmsh.left(gmsh.lastIndexOf("$EndElements")),
        "unexpected end of file in $Elements");
    row("msh huge node count", "hugenodes.msh",
        head + "$Nodes\n1 999999999999 1 999999999999\n0 1 0 999999999999\n1\n",
        "declares 1 blocks and 999999999999 nodes");
    row("msh huge block", "hugeblock.msh",
        head + "$Nodes\n1 2 1 2\n0 1 0 4000000000\n1\n2\n0 0 0\n1 0 0\n",
        "exceeds the declared total");
    row("msh huge element count", "hugeelements.msh",
        head + "$Nodes\n1 4 1 4\n3 1 0 4\n1\n2\n3\n4\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n$EndNodes\n"
               "$Elements\n1 4000000000 1 4000000000\n3 1 4 4000000000\n1 1 2 3 4\n",
        "declares 1 blocks and 4000000000 elements");
    const QByteArray nodes4 =
        head + "$Nodes\n1 4 1 4\n3 1 0 4\n1\n2\n3\n4\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n$EndNodes\n";
    row("msh NaN coordinate", "nan.msh",
        head + "$Nodes\n1 4 1 4\n3 1 0 4\n1\n2\n3\n4\n0 0 0\nnan 0 0\n0 1 0\n0 0 1\n$EndNodes\n",
        "node 2 has a non-finite coordinate");
    row("msh unknown node", "range.msh",
        nodes4 + "$Elements\n1 1 1 1\n3 1 4 1\n7 1 2 3 77\n$EndElements\n",
        "element 7 refers to node 77");
    row("msh zero volume", "flat.msh",
        head + "$Nodes\n1 4 1 4\n3 1 0 4\n1\n2\n3\n4\n0 0 0\n1 0 0\n0 1 0\n1 1 0\n$EndNodes\n"
               "$Elements\n1 1 1 1\n3 1 4 1\n9 1 2 3 4\n$EndElements\n",
        "element 9 has zero volume");
    row("msh only triangles", "tri.msh",
        nodes4 + "$Elements\n1 1 1 1\n2 1 2 1\n1 1 2 3\n$EndElements\n",
        "no 4-node tetrahedra (Gmsh element type 4); element types found: 2");
    row("msh no elements", "noelements.msh", nodes4, "no $Elements section");
    row("msh unterminated section", "open.msh", head + "$Comments\nblah\n", "has no $EndComments");

    // --- TetGen .node/.ele
    pair("tetgen missing ele", "lonely.node", tetgenNode(1), "", QByteArray(), "no such file",
         "lonely.ele");
    pair("tetgen empty node", "e.node", "# only a comment\n", "e.ele", tetgenEle(1), "empty file",
         "e.node");
    pair("tetgen first index 2", "b.node", "1 3 0 0\n2 0 0 0\n", "b.ele", tetgenEle(1),
         "first point index is 2", "b.node");
    pair("tetgen NaN", "n.ele", tetgenEle(1), "n.node",
         "5 3 0 0\n1 0 0 0\n2 1 0 0\n3 0 1 0\n4 0 0 nan\n5 1 1 1\n",
         "point 4 has a non-finite coordinate", "n.node");
    pair("tetgen index out of range", "r.node", tetgenNode(1), "r.ele", "1 4 0\n1 1 2 3 9\n",
         "refers to point 9", "r.ele");
    pair("tetgen huge count", "h.node", "4000000000 3 0 0\n1 0 0 0\n", "h.ele", tetgenEle(1),
         "declares 4000000000 points", "h.node");
    pair("tetgen truncated ele", "t.ele", "2 4 0\n1 1 2 3 4\n# no second tet\n", "t.node",
         tetgenNode(1), "unexpected end of file", "t.ele");
    pair("tetgen 2-D", "d.node", "3 2 0 0\n1 0 0\n2 1 0\n3 0 1\n", "d.ele", tetgenEle(1),
         "dimension 2", "d.node");
}

void TestMeshIo::badInputs() {
    QFETCH(QString, name);
    QFETCH(QByteArray, content);
    QFETCH(QString, sibling);
    QFETCH(QByteArray, siblingContent);
    QFETCH(QString, expected);
    QFETCH(QString, named);
    QTemporaryDir dir;
    QVERIFY(dir.isValid());
    const QString path = dir.filePath(name);
    if (!content.isNull())
        QVERIFY(writeBytes(path, content));
    if (!sibling.isEmpty() && !siblingContent.isNull())
        QVERIFY(writeBytes(dir.filePath(sibling), siblingContent));
    const QStringList filesBefore = entries(dir.path());

    TetMesh out = makeSampleMesh();
    const TetMesh original = out;
    StderrCapture capture;
    const Status s = readTetMesh(path.toStdString(), out);
    const QByteArray printed = capture.text();

    if (name == "control.vtu") { // the well-formed twin of "vtu huge declared count"
        QVERIFY2(s.ok(), s.message().c_str());
        QCOMPARE(out.tetCount(), 1);
        return;
    }
    QVERIFY(!s.ok());
    QVERIFY2(contains(s, dir.filePath(named)), s.message().c_str());
    QVERIFY2(contains(s, expected), s.message().c_str());
    QVERIFY2(printed.isEmpty(), printed.constData());
    QVERIFY(sameMesh(out, original));
    // Inputs are untouched and nothing was created next to them.
    if (!content.isNull())
        QCOMPARE(readBytes(path), content);
    if (!sibling.isEmpty() && !siblingContent.isNull())
        QCOMPARE(readBytes(dir.filePath(sibling)), siblingContent);
    QCOMPARE(entries(dir.path()), filesBefore);
}

void TestMeshIo::zeroCompressionBlockSizeIsRejected() {
    // Regression: VTK 9.1 divides by the block size of a compressed array's header without
    // checking it, so a zero there (one damaged byte) killed the process with SIGFPE.
    QTemporaryDir dir;
    QVERIFY(dir.isValid());
    const QString path = dir.filePath("zero-block.vtu");
    QVERIFY(writeVtu(path.toStdString(), makeSampleMesh()).ok());
    QByteArray bytes = readBytes(path);
    QVERIFY(bytes.contains("compressor=\"vtkZLibDataCompressor\""));
    QVERIFY(bytes.contains("header_type=\"UInt64\""));
    // Header of the first array: [blocks][block size][last block size][sizes], UInt64 each.
    const int data = static_cast<int>(bytes.indexOf('_', bytes.indexOf("<AppendedData"))) + 1;
    QVERIFY(data > 0);
    for (int k = 8; k < 16; ++k)
        bytes[data + k] = 0;
    QVERIFY(writeBytes(path, bytes));
    TetMesh mesh;
    const Status s = readVtu(path.toStdString(), mesh);
    QVERIFY(!s.ok());
    QVERIFY2(contains(s, path + ": damaged compressed data"), s.message().c_str());
    QVERIFY2(contains(s, "block size of 0"), s.message().c_str());
}

void TestMeshIo::damagedFilesNeverCrash_data() {
    QTest::addColumn<QString>("name");
    QTest::addColumn<QByteArray>("valid");
    QVERIFY(writeVtu(m_scratch.filePath("fuzz.vtu").toStdString(), makeSampleMesh()).ok());
    QTest::newRow("vtu as written") << "f.vtu" << readBytes(m_scratch.filePath("fuzz.vtu"));
    // The other encodings VTK (and so ParaView and friends) can write.
    enum Mode { Uncompressed, InlineBase64, Ascii, AppendedBase64, Lz4UInt32 };
    const std::pair<const char*, Mode> modes[] = {{"vtu uncompressed", Uncompressed},
                                                  {"vtu inline base64", InlineBase64},
                                                  {"vtu ascii", Ascii},
                                                  {"vtu appended base64", AppendedBase64},
                                                  {"vtu lz4, 32-bit headers", Lz4UInt32}};
    for (const auto& [tag, mode] : modes) {
        const QString file = m_scratch.filePath("mode.vtu");
        auto writer = vtkSmartPointer<vtkXMLUnstructuredGridWriter>::New();
        writer->SetFileName(file.toStdString().c_str());
        writer->SetInputData(toUnstructuredGrid(makeSampleMesh()));
        writer->SetDataModeToAppended();
        writer->EncodeAppendedDataOff();
        if (mode == Uncompressed)
            writer->SetCompressorTypeToNone();
        if (mode == InlineBase64)
            writer->SetDataModeToBinary();
        if (mode == Ascii)
            writer->SetDataModeToAscii();
        if (mode == AppendedBase64)
            writer->EncodeAppendedDataOn();
        if (mode == Lz4UInt32) {
            writer->SetCompressorTypeToLZ4();
            writer->SetHeaderTypeToUInt32();
        }
        QVERIFY(writer->Write() == 1);
        TetMesh check;
        QVERIFY(readVtu(file.toStdString(), check).ok()); // the undamaged file reads
        QVERIFY(sameMesh(check, makeSampleMesh()));
        QTest::newRow(tag) << "f.vtu" << readBytes(file);
    }
    QTest::newRow("msh") << "f.msh" << QByteArray(kGmsh);
    QTest::newRow("tetgen node") << "f.node" << tetgenNode(1);
    QTest::newRow("tetgen ele") << "f.ele" << tetgenEle(1);
}

void TestMeshIo::damagedFilesNeverCrash() {
    // Every truncation and many random corruptions (fixed seed) of a valid file: the reader
    // either succeeds with a valid mesh or reports an error naming the file; never crashes,
    // never prints.
    QFETCH(QString, name);
    QFETCH(QByteArray, valid);
    QTemporaryDir dir;
    QVERIFY(dir.isValid());
    const QString path = dir.filePath(name);
    if (name.endsWith(".node"))
        QVERIFY(writeBytes(dir.filePath("f.ele"), tetgenEle(1)));
    if (name.endsWith(".ele"))
        QVERIFY(writeBytes(dir.filePath("f.node"), tetgenNode(1)));

    std::vector<QByteArray> variants;
    const int n = static_cast<int>(valid.size());
    const int step = std::max(1, n / 150);
    for (int len = 0; len < n; len += (len < 64 ? 1 : step))
        variants.push_back(valid.left(len));
    // Random bytes anywhere, and digits, spaces or bit flips in the first kilobyte of the
    // binary data or of the file, where the sizes and headers are.
    std::mt19937 rng(20240607);
    const int dataStart = std::max(0, static_cast<int>(valid.indexOf("<AppendedData")));
    for (int i = 0; i < 300; ++i) {
        QByteArray v = valid;
        const bool anywhere = i % 2 == 0;
        const int flips = 1 + static_cast<int>(rng() % 8);
        for (int f = 0; f < flips; ++f) {
            const int at = anywhere ? static_cast<int>(rng() % n)
                                    : (dataStart + static_cast<int>(rng() % 1024)) % n;
            switch (rng() % 4) {
            case 0:
                v[at] = static_cast<char>(rng() % 256);
                break;
            case 1:
                v[at] = static_cast<char>('0' + rng() % 10);
                break;
            case 2:
                v[at] = ' ';
                break;
            default:
                v[at] = static_cast<char>(v[at] ^ (1 << (rng() % 8)));
                break;
            }
        }
        variants.push_back(v);
    }

    int failures = 0;
    StderrCapture capture;
    for (const QByteArray& bytes : variants) {
        QVERIFY(writeBytes(path, bytes));
        TetMesh mesh;
        const Status s = readTetMesh(path.toStdString(), mesh);
        if (s.ok()) {
            QVERIFY(mesh.tetCount() > 0);
            QVERIFY(checkTetIndices(mesh.nodeCount(), mesh.tets()).empty());
            QVERIFY(allPositive(mesh));
        } else {
            ++failures;
            QVERIFY2(QString::fromStdString(s.message()).contains(dir.path()), s.message().c_str());
        }
        QCOMPARE(readBytes(path), bytes);
    }
    const QByteArray printed = capture.text();
    QVERIFY2(printed.isEmpty(), printed.left(2000).constData());
    QVERIFY(failures > 0);
}

void TestMeshIo::tetMeshPathsByExtension() {
    for (const char* yes : {"a.vtu", "dir.x/b.MSH", "c.node", "d.Ele", "/abs/e.vtu"})
        QVERIFY2(isTetMeshPath(yes), yes);
    for (const char* no : {"a.obj", "b.stl", "c.vtu.gz", "vtu", "d.", "", "e.json"})
        QVERIFY2(!isTetMeshPath(no), no);
}

QTEST_GUILESS_MAIN(TestMeshIo)
#include "test_mesh_io.moc"
