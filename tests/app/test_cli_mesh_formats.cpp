// Issue 21 end to end: the `resect` commands write a tet mesh in the format OUT's name says
// (or --mesh-format names), refuse an unknown or unfitting one with exit 2 before any work,
// never overwrite an input (a TetGen pair counts as one input), and `resect convert` /
// `resect info` go through every format.
#include "core/mesh/box_mesh.h"
#include "core/mesh/masses.h"
#include "core/mesh/material.h"
#include "core/mesh/topology.h"
#include "scenario/mesh_io.h"

#include "cli_runner.h"

#include <QDir>
#include <QFile>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QTemporaryDir>
#include <QTest>

using namespace resect;
using resect::testing::Run;
using resect::testing::runCli;
using resect::testing::sha256;

namespace {

/// Two boxes side by side whose touching faces have distinct nodes at the same positions
/// (what a cut leaves): 2 pieces.
TetMesh twoTouchingBoxes() {
    const TetMesh a = makeBoxTetMesh(Vec3(0, 0, 0), Vec3(1, 1, 1), 2, 2, 2);
    const TetMesh b = makeBoxTetMesh(Vec3(1, 0, 0), Vec3(2, 1, 1), 2, 2, 2);
    std::vector<Vec3> points(a.referencePositions().begin(), a.referencePositions().end());
    points.insert(points.end(), b.referencePositions().begin(), b.referencePositions().end());
    std::vector<Tet> tets = a.tets();
    for (Tet t : b.tets()) {
        for (int& v : t)
            v += a.nodeCount();
        tets.push_back(t);
    }
    TetMesh m = TetMesh::fromArrays(std::move(points), std::move(tets));
    computeLumpedMasses(m, Material{}.density);
    return m;
}

const QByteArray kCube =
    "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nv 0 0 1\nv 1 0 1\nv 1 1 1\nv 0 1 1\n"
    "f 1 3 2\nf 1 4 3\nf 1 2 6\nf 1 6 5\nf 2 3 7\nf 2 7 6\nf 3 4 8\nf 3 8 7\nf 4 1 5\nf 4 5 8\n"
    "f 5 6 7\nf 5 7 8\n";

const QByteArray kSweep = R"({"curves": [[[0.5, -1, -1], [0.5, 2, -1]], [[0.5, -1, 2], [0.5, 2, 2]]]})";

} // namespace

class TestCliMeshFormats : public QObject {
    Q_OBJECT
    QTemporaryDir m_dir;
    QString path(const QString& name) const { return m_dir.filePath(name); }

private slots:
    void initTestCase() {
        QVERIFY(m_dir.isValid());
        QVERIFY(writeTetMesh(path("two.vtu").toStdString(), twoTouchingBoxes()).ok());
        QVERIFY(resect::testing::writeFile(path("cube.obj"), kCube));
        QVERIFY(resect::testing::writeFile(path("sweep.json"), kSweep));
    }

    void meshWritesTheFormatItsNameSays_data() {
        QTest::addColumn<QString>("out");
        QTest::addColumn<QString>("key");
        QTest::addColumn<QByteArray>("head");
        QTest::newRow("msh is Gmsh 4.1") << "c.msh" << "" << QByteArray("$MeshFormat\n4.1 0 8");
        QTest::newRow("msh 2.2") << "c22.msh" << "msh22" << QByteArray("$MeshFormat\n2.2 0 8");
        QTest::newRow("msh 2.2 binary") << "c22b.msh" << "msh22-binary" << QByteArray("$MeshFormat\n2.2 1 8");
        QTest::newRow("msh 4.1 binary") << "c41b.msh" << "msh41-binary" << QByteArray("$MeshFormat\n4.1 1 8");
        QTest::newRow("vtk") << "c.vtk" << "" << QByteArray("# vtk DataFile Version");
        QTest::newRow("vtk ascii") << "ca.vtk" << "vtk-ascii" << QByteArray("# vtk DataFile Version");
        QTest::newRow("medit") << "c.mesh" << "" << QByteArray("MeshVersionFormatted");
        QTest::newRow("vtu") << "c.vtu" << "" << QByteArray("<VTKFile");
    }
    void meshWritesTheFormatItsNameSays() {
        QFETCH(QString, out);
        QFETCH(QString, key);
        QFETCH(QByteArray, head);
        QStringList args{"mesh", path("cube.obj"), "--out", path(out), "--edge-length", "0.5"};
        if (!key.isEmpty())
            args << "--mesh-format" << key;
        const Run r = runCli(args);
        QVERIFY2(r.code == 0, qPrintable(r.err));
        QFile f(path(out));
        QVERIFY(f.open(QIODevice::ReadOnly));
        const QByteArray bytes = f.readAll();
        QVERIFY2(bytes.trimmed().startsWith(head), bytes.left(40).constData());
        TetMesh m;
        QVERIFY(readTetMesh(path(out).toStdString(), m).ok());
        QVERIFY(r.out.contains(QStringLiteral("%1 tets").arg(m.tetCount())));
    }

    void tetgenOutputWritesThePair() {
        const Run r = runCli({"cut", path("two.vtu"), "--sweep", path("sweep.json"), "--out", path("cut.node")});
        QVERIFY2(r.code == 0, qPrintable(r.err));
        QVERIFY(QFile::exists(path("cut.node")));
        QVERIFY(QFile::exists(path("cut.ele")));
        TetMesh m;
        QVERIFY(readTetMesh(path("cut.ele").toStdString(), m).ok());
        QCOMPARE(connectedComponents(m).count, 3); // the box at x < 1 cut in two, the other whole
        // Cutting the pair into its own other half would overwrite the input.
        const QByteArray before = sha256(path("cut.node"));
        const Run again = runCli({"cut", path("cut.ele"), "--sweep", path("sweep.json"), "--out", path("cut.node")});
        QCOMPARE(again.code, 2);
        QVERIFY2(again.err.contains("refusing to overwrite an input"), qPrintable(again.err));
        QCOMPARE(sha256(path("cut.node")), before);
    }

    // The output is checked before anything else: with a missing input and a bad output,
    // the error is about the output (the input was never opened, nothing was meshed).
    void refusedBeforeAnyWork_data() {
        QTest::addColumn<QStringList>("args");
        QTest::addColumn<QString>("message");
        QTest::addColumn<QString>("notCreated");
        QTest::newRow("mesh unknown extension")
            << QStringList{"mesh", "/nonexistent/s.obj", "--out", "x.xyz"} << "cannot write a tet mesh as '.xyz'" << "x.xyz";
        QTest::newRow("mesh surface extension")
            << QStringList{"mesh", "--sample", "polyp", "--out", "p.stl"} << "cannot write a tet mesh as '.stl'" << "p.stl";
        QTest::newRow("mesh no extension")
            << QStringList{"mesh", "--sample", "polyp", "--out", "polyp"} << "no file extension" << "polyp";
        QTest::newRow("mesh format does not fit")
            << QStringList{"mesh", "/nonexistent/s.obj", "--out", "x.vtu", "--mesh-format", "msh22"} << "is written as .msh, not '.vtu'" << "x.vtu";
        QTest::newRow("mesh unknown format")
            << QStringList{"mesh", "/nonexistent/s.obj", "--out", "x.msh", "--mesh-format", "gmsh5"} << "unknown mesh format 'gmsh5'" << "x.msh";
        QTest::newRow("cut unknown extension")
            << QStringList{"cut", "/nonexistent/m.vtu", "--sweep", "s.json", "--out", "x.ply"} << "cannot write a tet mesh as '.ply'" << "x.ply";
        QTest::newRow("cut chips unknown extension")
            << QStringList{"cut", "/nonexistent/m.vtu", "--sweep", "s.json", "--out", "x.vtu", "--fix-box", "0", "0", "0", "1", "1", "1", "--resected-out", "chips.txt"}
            << "--resected-out: " << "chips.txt";
        QTest::newRow("simulate unknown extension")
            << QStringList{"simulate", "/nonexistent/m.vtu", "--steps", "1", "--out", "x.obj"} << "cannot write a tet mesh as '.obj'" << "x.obj";
        QTest::newRow("convert unknown extension")
            << QStringList{"convert", "/nonexistent/m.vtu", "--out", "x.inp"} << "cannot write a tet mesh as '.inp'" << "x.inp";
        QTest::newRow("convert format does not fit")
            << QStringList{"convert", "/nonexistent/m.vtu", "--out", "x.vtk", "--mesh-format", "medit"} << "is written as .mesh" << "x.vtk";
    }
    void refusedBeforeAnyWork() {
        QFETCH(QStringList, args);
        QFETCH(QString, message);
        QFETCH(QString, notCreated);
        QDir::setCurrent(m_dir.path());
        const Run r = runCli(args);
        QCOMPARE(r.code, 2);
        QVERIFY2(r.err.contains(message), qPrintable(r.err));
        QVERIFY2(!r.err.contains("/nonexistent"), qPrintable(r.err));
        QVERIFY(r.out.isEmpty());
        QVERIFY(!QFile::exists(path(notCreated)));
    }

    void convertGoesThroughEveryFormat_data() {
        QTest::addColumn<QString>("key");
        for (const MeshFormatInfo& f : meshFormats())
            QTest::newRow(std::string(f.key).c_str()) << QString::fromUtf8(f.key.data(), f.key.size());
    }
    void convertGoesThroughEveryFormat() {
        QFETCH(QString, key);
        const MeshFormatInfo* f = findMeshFormat(key.toStdString());
        QVERIFY(f);
        const QString ext = QString::fromUtf8(f->extensions.data(), f->extensions.size()).section(' ', 0, 0);
        const QString there = path("conv-" + key + ext), back = path("back-" + key + ".vtu");
        const QByteArray input = sha256(path("two.vtu"));
        Run r = runCli({"convert", path("two.vtu"), "--out", there, "--mesh-format", key});
        QVERIFY2(r.code == 0, qPrintable(r.err));
        QVERIFY2(r.out.contains(QString::fromUtf8(f->name.data(), f->name.size())), qPrintable(r.out));
        r = runCli({"convert", there, "--out", back});
        QVERIFY2(r.code == 0, qPrintable(r.err));
        QCOMPARE(sha256(path("two.vtu")), input);
        TetMesh original, converted;
        QVERIFY(readTetMesh(path("two.vtu").toStdString(), original).ok());
        QVERIFY(readTetMesh(back.toStdString(), converted).ok());
        QCOMPARE(converted.nodeCount(), original.nodeCount()); // the touching faces stay apart
        QCOMPARE(converted.tetCount(), original.tetCount());
        QCOMPARE(connectedComponents(converted).count, 2);
        // info reads it and names the format.
        r = runCli({"info", there});
        QVERIFY2(r.code == 0, qPrintable(r.err));
        const QJsonObject info = QJsonDocument::fromJson(r.out.toUtf8()).object();
        QVERIFY2(!info["format"].toString().isEmpty(), qPrintable(r.out));
        QCOMPARE(info["tets"].toInt(), original.tetCount());
    }

    void infoListsGmshGroupsAndDroppedElements() {
        Run r = runCli({"convert", path("two.vtu"), "--out", path("groups.msh")});
        QVERIFY2(r.code == 0, qPrintable(r.err));
        r = runCli({"info", path("groups.msh")});
        QVERIFY2(r.code == 0, qPrintable(r.err));
        const QJsonObject info = QJsonDocument::fromJson(r.out.toUtf8()).object();
        QCOMPARE(info["format"].toString(), QStringLiteral("Gmsh 4.1 ASCII"));
        const QJsonArray groups = info["groups"].toArray();
        int volumeGroups = 0, tets = 0;
        for (const QJsonValue& g : groups)
            if (g.toObject()["dimension"].toInt() == 3) {
                ++volumeGroups;
                tets += g.toObject()["tets"].toInt();
                QVERIFY(g.toObject()["name"].toString().startsWith("piece "));
            }
        QCOMPARE(volumeGroups, 2);
        QCOMPARE(tets, info["tets"].toInt());

        // A mixed file: a tet and a triangle; the triangle is dropped and said so.
        const QByteArray mixed = "$MeshFormat\n2.2 0 8\n$EndMeshFormat\n$Nodes\n4\n1 0 0 0\n2 1 0 0\n3 0 1 0\n"
                                 "4 0 0 1\n$EndNodes\n$Elements\n2\n1 2 2 7 1 1 2 3\n2 4 2 7 1 1 2 3 4\n$EndElements\n";
        QVERIFY(resect::testing::writeFile(path("mixed.msh"), mixed));
        r = runCli({"info", path("mixed.msh")});
        QVERIFY2(r.code == 0, qPrintable(r.err));
        const QJsonObject m = QJsonDocument::fromJson(r.out.toUtf8()).object();
        QCOMPARE(m["tets"].toInt(), 1);
        QVERIFY2(!m["dropped"].toObject().isEmpty(), qPrintable(r.out));
        // The commands that read meshes say what they dropped.
        r = runCli({"convert", path("mixed.msh"), "--out", path("mixed.vtu")});
        QVERIFY2(r.code == 0, qPrintable(r.err));
        QVERIFY2(r.err.contains("note:") && r.err.contains("dropped 1 element"), qPrintable(r.err));
    }
};

QTEST_GUILESS_MAIN(TestCliMeshFormats)
#include "test_cli_mesh_formats.moc"
