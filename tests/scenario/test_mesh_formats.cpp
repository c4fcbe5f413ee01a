// Issue 21: every tet mesh format, through the one entry point the commands and the studio
// use (readTetMesh / writeTetMesh / chooseMeshWriteFormat). A mesh cut in two pieces (its
// separated nodes coincide in pairs) and then deformed is written in every format at
// scales 1e-3, 1 and 1e3 and read back: the same tets on the same positions, the same
// number of nodes and pieces, and the node data each format carries, exactly. Our .vtk and
// .vtu are read by VTK's own readers. The per-format details and refusals are in
// test_mesh_format_gmsh and test_mesh_format_vtk_medit.

#include "core/mesh/box_mesh.h"
#include "core/mesh/masses.h"
#include "core/mesh/material.h"
#include "core/mesh/topology.h"
#include "core/sweep/sweep_surface.h"
#include "core/tissue/tissue.h"
#include "scenario/mesh_io.h"

#include "grid_contract.h"

#include <vtkCellData.h>
#include <vtkDataArray.h>
#include <vtkPointData.h>
#include <vtkSmartPointer.h>
#include <vtkUnstructuredGrid.h>
#include <vtkUnstructuredGridReader.h>
#include <vtkXMLUnstructuredGridReader.h>

#include <QFile>
#include <QTemporaryDir>
#include <QtTest>

#include <algorithm>
#include <array>
#include <tuple>
#include <vector>

using namespace resect;
using resect::test::gridContractProblem;

namespace {

/// A box of 4 x 3 x 3 cells from `lo`, edge `scale`, cut through by a tilted plane into two
/// pieces (the hybrid cut, snapped, neither relaxed nor improved), then deformed (current != reference) and given
/// velocities.
TetMesh cutDeformedBox(double scale) {
    const Vec3 lo = scale * Vec3(0.1234567, -0.7654321, 0.333);
    TetMesh box = makeBoxTetMesh(lo, lo + scale * Vec3(4, 3, 3), 4, 3, 3);
    Tissue tissue;
    if (!Tissue::create(std::move(box), {}, Material{}, {}, tissue).ok())
        return {};
    const Vec3 c = lo + scale * Vec3(2.1, 1.5, 1.5), n = Vec3(1, 0.2, 0.1).normalized();
    const Vec3 a = n.unitOrthogonal(), b = n.cross(a);
    const double s = 4 * scale;
    SweepSurface sweep;
    if (!SweepSurface::fromStartEnd({c - s * a - s * b, c + s * a - s * b},
                                    {c - s * a + s * b, c + s * a + s * b}, sweep)
             .ok())
        return {};
    // Without relaxation and improvement the separated nodes stay where they were split:
    // pairs of distinct nodes at one position.
    CutOptions options;
    options.relaxSteps = 0;
    options.improve = false;
    if (!tissue.cut(sweep, options).ok())
        return {};
    TetMesh mesh = tissue.mesh();
    for (int i = 0; i < mesh.nodeCount(); ++i) {
        const Vec3 r = mesh.ref(i);
        mesh.positions()[i] = r + 0.01 * Vec3(r.y(), -r.x(), 0.5 * r.z()) + scale * Vec3(0.3, 0, 0);
        mesh.velocities()[i] = Vec3(0.1 * i, -0.25, 1.0 / (i + 3));
    }
    return mesh;
}

using Row = std::array<double, 10>; // position, reference, velocity, mass

/// The node data as sorted rows (node order is the writer's to choose).
std::vector<Row> nodeRows(const TetMesh& m, bool reference, bool velocity, bool mass) {
    std::vector<Row> rows;
    for (int i = 0; i < m.nodeCount(); ++i) {
        const Vec3 p = m.pos(i), r = reference ? m.ref(i) : Vec3::Zero(),
                   v = velocity ? m.velocities()[i] : Vec3::Zero();
        rows.push_back({p.x(), p.y(), p.z(), r.x(), r.y(), r.z(), v.x(), v.y(), v.z(),
                        mass ? m.masses()[i] : 0.0});
    }
    std::sort(rows.begin(), rows.end());
    return rows;
}

using TetRow = std::array<std::array<double, 3>, 4>;

/// Each tet as its four current positions, sorted; the list sorted.
std::vector<TetRow> tetRows(const TetMesh& m) {
    std::vector<TetRow> rows;
    for (const Tet& t : m.tets()) {
        TetRow row;
        for (int k = 0; k < 4; ++k)
            row[k] = {m.pos(t[k]).x(), m.pos(t[k]).y(), m.pos(t[k]).z()};
        std::sort(row.begin(), row.end());
        rows.push_back(row);
    }
    std::sort(rows.begin(), rows.end());
    return rows;
}

double currentVolume(const TetMesh& m) {
    double v = 0;
    for (const Tet& t : m.tets())
        v += signedVolume(m.pos(t[0]), m.pos(t[1]), m.pos(t[2]), m.pos(t[3]));
    return v;
}

/// Nodes at the same position as another node (the pairs a cut separates).
int coincidentNodes(const TetMesh& m) {
    std::vector<std::array<double, 3>> p;
    for (int i = 0; i < m.nodeCount(); ++i)
        p.push_back({m.ref(i).x(), m.ref(i).y(), m.ref(i).z()});
    std::sort(p.begin(), p.end());
    int n = 0;
    for (std::size_t i = 1; i < p.size(); ++i)
        n += p[i] == p[i - 1];
    return n;
}

bool carriesReference(MeshFormat f) { return f != MeshFormat::Medit; }
bool carriesVelocity(MeshFormat f) { return f != MeshFormat::Medit && f != MeshFormat::TetGen; }
bool carriesMass(MeshFormat f) { return f != MeshFormat::Medit; }

} // namespace

class TestMeshFormats : public QObject {
    Q_OBJECT
    QTemporaryDir m_dir;

private slots:
    void everyFormatRoundTrips_data();
    void everyFormatRoundTrips();
    void vtkReadersReadOurFiles_data();
    void vtkReadersReadOurFiles();
    void writeFormatIsChosenByExtensionAndKey_data();
    void writeFormatIsChosenByExtensionAndKey();
    void writeRefusesAPathThatDoesNotFitTheFormat();
    void formatTableIsConsistent();
};

void TestMeshFormats::everyFormatRoundTrips_data() {
    QTest::addColumn<int>("format");
    QTest::addColumn<double>("scale");
    for (const MeshFormatInfo& f : meshFormats())
        for (double scale : {1e-3, 1.0, 1e3})
            QTest::addRow("%s scale %g", std::string(f.key).c_str(), scale)
                << static_cast<int>(f.format) << scale;
}

void TestMeshFormats::everyFormatRoundTrips() {
    QFETCH(int, format);
    QFETCH(double, scale);
    const MeshFormat f = static_cast<MeshFormat>(format);
    const MeshFormatInfo& info = meshFormatInfo(f);
    const TetMesh mesh = cutDeformedBox(scale);
    QVERIFY(mesh.tetCount() > 0);
    const Components before = connectedComponents(mesh);
    QCOMPARE(before.count, 2);
    const int coincident = coincidentNodes(mesh);
    QVERIFY2(coincident > 10, qPrintable(QStringLiteral("the cut must separate nodes that coincide: %1 of %2").arg(coincident).arg(mesh.nodeCount())));

    const std::string ext(info.extensions.substr(0, info.extensions.find(' ')));
    const std::string path = m_dir.filePath(QStringLiteral("m%1").arg(format)).toStdString() + ext;
    QVERIFY2(writeTetMesh(path, mesh, f).ok(), writeTetMesh(path, mesh, f).message().c_str());
    TetMesh back;
    MeshReadReport report;
    const Status read = readTetMesh(path, back, &report);
    QVERIFY2(read.ok(), read.message().c_str());
    QVERIFY2(!report.format.empty(), "the report names the format read");

    QCOMPARE(back.nodeCount(), mesh.nodeCount());
    QCOMPARE(back.tetCount(), mesh.tetCount());
    QCOMPARE(connectedComponents(back).count, 2);
    QCOMPARE(coincidentNodes(back), carriesReference(f) ? coincident : coincidentNodes(back));
    QVERIFY(tetRows(back) == tetRows(mesh));
    QCOMPARE(currentVolume(back), currentVolume(mesh));

    const bool ref = carriesReference(f), vel = carriesVelocity(f), mass = carriesMass(f);
    QVERIFY(nodeRows(back, ref, vel, mass) == nodeRows(mesh, ref, vel, mass));
    if (!ref) // reference = the positions read
        for (int i = 0; i < back.nodeCount(); ++i)
            QCOMPARE(back.ref(i), back.pos(i));
    if (!mass) { // masses from the default density on the (reference =) positions read
        TetMesh expected = back;
        computeLumpedMasses(expected, Material{}.density);
        for (int i = 0; i < back.nodeCount(); ++i)
            QCOMPARE(back.masses()[i], expected.masses()[i]);
    }
    // The piece count survives a second round (nothing merged on the way).
    QVERIFY(writeTetMesh(path, back, f).ok());
    TetMesh again;
    QVERIFY(readTetMesh(path, again).ok());
    QVERIFY(tetRows(again) == tetRows(mesh));
}

void TestMeshFormats::vtkReadersReadOurFiles_data() {
    QTest::addColumn<QString>("key");
    QTest::newRow("vtu") << "vtu";
    QTest::newRow("vtk binary") << "vtk";
    QTest::newRow("vtk ascii") << "vtk-ascii";
}

void TestMeshFormats::vtkReadersReadOurFiles() {
    QFETCH(QString, key);
    const MeshFormatInfo* info = findMeshFormat(key.toStdString());
    QVERIFY(info);
    const TetMesh mesh = cutDeformedBox(1.0);
    const std::string path = m_dir.filePath("vtk-" + key).toStdString() + std::string(info->extensions);
    QVERIFY(writeTetMesh(path, mesh, info->format).ok());

    vtkSmartPointer<vtkUnstructuredGrid> grid;
    if (info->format == MeshFormat::Vtu) {
        auto reader = vtkSmartPointer<vtkXMLUnstructuredGridReader>::New();
        reader->SetFileName(path.c_str());
        reader->Update();
        grid = reader->GetOutput();
    } else {
        auto reader = vtkSmartPointer<vtkUnstructuredGridReader>::New();
        reader->SetFileName(path.c_str());
        reader->Update();
        grid = reader->GetOutput();
    }
    QVERIFY(grid);
    // The contract of DESIGN.md: points, cells and every array exactly as the mesh has them
    // (and so the same counts and volume).
    const QString problem = gridContractProblem(grid, mesh, connectedComponents(mesh).tetComponent);
    QVERIFY2(problem.isEmpty(), qPrintable(problem));
}

void TestMeshFormats::writeFormatIsChosenByExtensionAndKey_data() {
    QTest::addColumn<QString>("path");
    QTest::addColumn<QString>("key");
    QTest::addColumn<int>("format"); // -1: refused
    QTest::addColumn<QString>("message");
    const auto f = [](MeshFormat m) { return static_cast<int>(m); };
    QTest::newRow("vtu") << "a.vtu" << "" << f(MeshFormat::Vtu) << "";
    QTest::newRow("msh defaults to 4.1 ascii") << "a.msh" << "" << f(MeshFormat::Msh41) << "";
    QTest::newRow("upper case") << "A.MSH" << "" << f(MeshFormat::Msh41) << "";
    QTest::newRow("msh 2.2 binary") << "a.msh" << "msh22-binary" << f(MeshFormat::Msh22Binary) << "";
    QTest::newRow("msh 4.1 binary") << "a.msh" << "msh41-binary" << f(MeshFormat::Msh41Binary) << "";
    QTest::newRow("msh 2.2") << "a.msh" << "msh22" << f(MeshFormat::Msh22) << "";
    QTest::newRow("vtk defaults to binary") << "a.vtk" << "" << f(MeshFormat::Vtk) << "";
    QTest::newRow("vtk ascii") << "a.vtk" << "vtk-ascii" << f(MeshFormat::VtkAscii) << "";
    QTest::newRow("medit") << "dir.d/a.mesh" << "" << f(MeshFormat::Medit) << "";
    QTest::newRow("tetgen node") << "a.node" << "" << f(MeshFormat::TetGen) << "";
    QTest::newRow("tetgen ele") << "a.ele" << "tetgen" << f(MeshFormat::TetGen) << "";
    QTest::newRow("unknown extension") << "a.xyz" << "" << -1 << "cannot write a tet mesh as '.xyz'";
    QTest::newRow("surface extension") << "a.obj" << "" << -1 << "cannot write a tet mesh as '.obj'";
    QTest::newRow("no extension") << "mesh" << "" << -1 << "no file extension";
    QTest::newRow("medit binary is read-refused, not written") << "a.meshb" << "" << -1 << "cannot write a tet mesh as '.meshb'";
    QTest::newRow("folder with dot, no extension") << "dir.d/mesh" << "" << -1 << "no file extension";
    QTest::newRow("unknown key") << "a.msh" << "msh30" << -1 << "unknown mesh format 'msh30'";
    QTest::newRow("key for another extension") << "a.vtu" << "msh22" << -1 << "is written as .msh, not '.vtu'";
    QTest::newRow("vtk key on msh") << "a.msh" << "vtk-ascii" << -1 << "not '.msh'";
}

void TestMeshFormats::writeFormatIsChosenByExtensionAndKey() {
    QFETCH(QString, path);
    QFETCH(QString, key);
    QFETCH(int, format);
    QFETCH(QString, message);
    MeshFormat chosen = MeshFormat::Vtu;
    const Status s = chooseMeshWriteFormat(path.toStdString(), key.toStdString(), chosen);
    if (format < 0) {
        QVERIFY(!s.ok());
        QVERIFY2(QString::fromStdString(s.message()).contains(message), s.message().c_str());
        QVERIFY2(key.isEmpty() || s.message().find(key.toStdString()) != std::string::npos ||
                     s.message().find(path.toStdString()) != std::string::npos,
                 s.message().c_str());
    } else {
        QVERIFY2(s.ok(), s.message().c_str());
        QCOMPARE(static_cast<int>(chosen), format);
        QVERIFY(isTetMeshPath(path.toStdString()));
        QVERIFY(std::string(meshFormatInfo(chosen).extensions).find(path.section('.', -1).toLower().toStdString()) !=
                std::string::npos);
    }
}

void TestMeshFormats::writeRefusesAPathThatDoesNotFitTheFormat() {
    const TetMesh mesh = cutDeformedBox(1.0);
    const QString path = m_dir.filePath("wrong.vtu");
    const Status s = writeTetMesh(path.toStdString(), mesh, MeshFormat::Msh22);
    QVERIFY(!s.ok());
    QVERIFY2(QString::fromStdString(s.message()).contains("Gmsh 2.2 ASCII"), s.message().c_str());
    QVERIFY(!QFile::exists(path));
    const Status unknown = writeTetMesh(m_dir.filePath("x.stl").toStdString(), mesh);
    QVERIFY(!unknown.ok());
    QVERIFY(!QFile::exists(m_dir.filePath("x.stl")));
}

void TestMeshFormats::formatTableIsConsistent() {
    // Keys unique, every extension has exactly one default, every format findable by key.
    std::vector<std::string> keys, defaults;
    for (const MeshFormatInfo& f : meshFormats()) {
        keys.emplace_back(f.key);
        QCOMPARE(findMeshFormat(f.key), &f);
        QCOMPARE(&meshFormatInfo(f.format), &f);
        if (f.extensionDefault)
            defaults.emplace_back(f.extensions);
        QVERIFY(!f.name.empty());
        QVERIFY(!f.carries.empty());
    }
    std::sort(keys.begin(), keys.end());
    QVERIFY(std::adjacent_find(keys.begin(), keys.end()) == keys.end());
    std::sort(defaults.begin(), defaults.end());
    QVERIFY(std::adjacent_find(defaults.begin(), defaults.end()) == defaults.end());
    for (const char* ext : {".vtu", ".msh", ".vtk", ".mesh", ".node .ele"})
        QVERIFY2(std::count(defaults.begin(), defaults.end(), ext) == 1, ext);
}

QTEST_GUILESS_MAIN(TestMeshFormats)
#include "test_mesh_formats.moc"
