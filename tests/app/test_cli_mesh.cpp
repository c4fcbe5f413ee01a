// End-to-end tests of `resect info` and `resect mesh`: exit codes, one-line errors naming the
// problem, inputs never modified, no partial output files.
#include "core/mesh/box_mesh.h"
#include "core/mesh/masses.h"
#include "scenario/mesh_io.h"

#include "cli_runner.h"

#include <QCryptographicHash>
#include <QDir>
#include <QFile>
#include <QJsonDocument>
#include <QJsonObject>
#include <QProcess>
#include <QRegularExpression>
#include <QTemporaryDir>
#include <QTest>

using namespace resect;
using resect::testing::Run;
using resect::testing::runCli;
using resect::testing::sha256;

namespace {

void writeText(const QString& path, const QByteArray& text) {
    QFile f(path);
    QVERIFY(f.open(QIODevice::WriteOnly));
    f.write(text);
}

// A closed unit cube as OBJ (12 triangles, outward).
const QByteArray kCubeVertices = "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nv 0 0 1\nv 1 0 1\nv 1 1 1\nv 0 1 1\n";
const QByteArray kCubeFacesNoTop =
    "f 1 3 2\nf 1 4 3\n"   // bottom z=0
    "f 1 2 6\nf 1 6 5\n"   // y=0
    "f 2 3 7\nf 2 7 6\n"   // x=1
    "f 3 4 8\nf 3 8 7\n"   // y=1
    "f 4 1 5\nf 4 5 8\n";  // x=0
const QByteArray kCubeTop = "f 5 6 7\nf 5 7 8\n";

} // namespace

class TestCliMesh : public QObject {
    Q_OBJECT
    QTemporaryDir m_dir;
    QString path(const QString& name) const { return m_dir.filePath(name); }

private slots:
    void usageErrors_data() {
        QTest::addColumn<QStringList>("args");
        QTest::addColumn<QString>("message");
        QTest::newRow("no command") << QStringList{} << "usage";
        QTest::newRow("unknown command") << QStringList{"frobnicate"} << "unknown command";
        QTest::newRow("info without file") << QStringList{"info"} << "MESH";
        QTest::newRow("info missing file") << QStringList{"info", "/nonexistent/x.vtu"} << "/nonexistent/x.vtu";
        QTest::newRow("info unknown option") << QStringList{"info", "a.vtu", "--bogus"} << "--bogus";
        QTest::newRow("mesh without out") << QStringList{"mesh", "--sample", "polyp"} << "--out";
        QTest::newRow("mesh unknown sample") << QStringList{"mesh", "--sample", "liver", "--out", "x.vtu"} << "liver";
        QTest::newRow("mesh both inputs") << QStringList{"mesh", "a.obj", "--sample", "polyp", "--out", "x.vtu"} << "not both";
        QTest::newRow("edge length text") << QStringList{"mesh", "--sample", "polyp", "--out", "x.vtu", "--edge-length", "abc"} << "--edge-length";
        QTest::newRow("edge length negative") << QStringList{"mesh", "--sample", "polyp", "--out", "x.vtu", "--edge-length", "-1"} << "--edge-length";
        QTest::newRow("edge length zero") << QStringList{"mesh", "--sample", "polyp", "--out", "x.vtu", "--edge-length", "0"} << "--edge-length";
        QTest::newRow("edge length nan") << QStringList{"mesh", "--sample", "polyp", "--out", "x.vtu", "--edge-length", "nan"} << "--edge-length";
        QTest::newRow("edge length absurdly small") << QStringList{"mesh", "--sample", "polyp", "--out", "x.vtu", "--edge-length", "1e-9"} << "edge";
        QTest::newRow("min dihedral too high") << QStringList{"mesh", "--sample", "polyp", "--out", "x.vtu", "--min-dihedral", "40"} << "--min-dihedral must be between 0 and 35";
        QTest::newRow("min dihedral text") << QStringList{"mesh", "--sample", "polyp", "--out", "x.vtu", "--min-dihedral", "ten"} << "--min-dihedral";
        QTest::newRow("feature angle alone") << QStringList{"mesh", "--sample", "polyp", "--out", "x.vtu", "--feature-angle", "30"} << "--feature-angle needs --protect-features";
        QTest::newRow("feature angle zero") << QStringList{"mesh", "--sample", "polyp", "--out", "x.vtu", "--protect-features", "--feature-angle", "0"} << "--feature-angle must be between 0 and 180";
        QTest::newRow("report is the output") << QStringList{"mesh", "--sample", "polyp", "--out", "x.vtu", "--report", "x.vtu"} << "x.vtu";
        QTest::newRow("mesh missing file") << QStringList{"mesh", "/nonexistent/s.obj", "--out", "x.vtu"} << "/nonexistent/s.obj";
    }
    void usageErrors() {
        QFETCH(QStringList, args);
        QFETCH(QString, message);
        QVERIFY(m_dir.isValid());
        QDir::setCurrent(m_dir.path());
        const Run r = runCli(args);
        QCOMPARE(r.code, 2);
        QVERIFY2(r.err.contains(message, Qt::CaseInsensitive), qPrintable(r.err));
        QVERIFY2(r.err.trimmed().count('\n') == 0 || message == "usage", qPrintable(r.err));
        QVERIFY(!QFile::exists(path("x.vtu")));
    }

    void infoOfBoxMesh() {
        TetMesh m = makeBoxTetMesh(Vec3::Zero(), Vec3(2, 2, 2), 2, 2, 2);
        computeLumpedMasses(m, 1e-3);
        QVERIFY(writeVtu(path("box.vtu").toStdString(), m).ok());
        const QByteArray before = sha256(path("box.vtu"));
        const Run r = runCli({"info", path("box.vtu")});
        QCOMPARE(r.code, 0);
        const QJsonObject o = QJsonDocument::fromJson(r.out.toUtf8()).object();
        QCOMPARE(o["tets"].toInt(), 48);
        QCOMPARE(o["nodes"].toInt(), 27);
        QCOMPARE(o["edges"].toInt(), 98);
        QCOMPARE(o["pieces"].toInt(), 1);
        QVERIFY(std::abs(o["volume"].toDouble() - 8.0) < 1e-12);
        QVERIFY(std::abs(o["mass"].toDouble() - 8e-3) < 1e-15);
        QVERIFY(o["stable_dt"].toDouble() > 0);
        QVERIFY(std::abs(o["volume_ratio"].toDouble() - 1.0) < 1e-9);
        QVERIFY(o["validity"].toObject()["valid"].toBool());
        QCOMPARE(o["overlap"].toDouble(-1), 0.0);
        QCOMPARE(sha256(path("box.vtu")), before);
    }

    void infoReportsOverlap() {
        // Two tets sharing no node: a corner of the second lies inside the first, 0.5 from its
        // nearest face (z = 0; the others are 1 and (4 - 2.5) / sqrt(3) away). The mesh is
        // valid in every other respect, so only the overlap tells.
        TetMesh m = TetMesh::fromArrays({Vec3(0, 0, 0), Vec3(4, 0, 0), Vec3(0, 4, 0), Vec3(0, 0, 4),
                                         Vec3(1, 1, 0.5), Vec3(1, 1, -3), Vec3(3, 1, -3), Vec3(1, 3, -3)},
                                        {{0, 1, 2, 3}, {4, 6, 5, 7}});
        QVERIFY(writeVtu(path("overlap.vtu").toStdString(), m).ok());
        const Run r = runCli({"info", path("overlap.vtu")});
        QCOMPARE(r.code, 0);
        const QJsonObject o = QJsonDocument::fromJson(r.out.toUtf8()).object();
        QVERIFY2(std::abs(o["overlap"].toDouble(-1) - 0.5) < 1e-12, qPrintable(r.out));
        QCOMPARE(o["pieces"].toInt(), 2);
    }

    void infoReportsProblems() {
        // A vtu whose second tet overlaps the first through a shared face (face in 3 tets).
        TetMesh m = TetMesh::fromArrays({Vec3(0, 0, 0), Vec3(2, 0, 0), Vec3(0, 2, 0), Vec3(0.5, 0.5, 1),
                                         Vec3(0.5, 0.5, -1), Vec3(1.5, 0.2, 2)},
                                        {{0, 1, 2, 3}, {0, 2, 1, 4}, {0, 1, 2, 5}});
        QVERIFY(writeVtu(path("bad.vtu").toStdString(), m).ok());
        const Run r = runCli({"info", path("bad.vtu")});
        QCOMPARE(r.code, 0);
        const QJsonObject v = QJsonDocument::fromJson(r.out.toUtf8()).object()["validity"].toObject();
        QVERIFY(!v["valid"].toBool());
        QCOMPARE(v["by_kind"].toObject()["over_shared_face"].toInt(), 1);
    }

    void meshSampleAndReadBack_data() {
        QTest::addColumn<QString>("sample");
        QTest::newRow("polyp") << "polyp";
        QTest::newRow("myoma") << "myoma";
    }
    void meshSampleAndReadBack() {
        QFETCH(QString, sample);
        const QString out = path(sample + ".vtu");
        const Run r = runCli({"mesh", "--sample", sample, "--out", out});
        QVERIFY2(r.code == 0, qPrintable(r.err));
        QVERIFY(r.out.contains("tets"));
        const Run info = runCli({"info", out});
        QCOMPARE(info.code, 0);
        const QJsonObject o = QJsonDocument::fromJson(info.out.toUtf8()).object();
        QVERIFY2(o["validity"].toObject()["valid"].toBool(), qPrintable(info.out));
        QVERIFY(o["tets"].toInt() >= 100 && o["tets"].toInt() <= 5000);
        QCOMPARE(o["pieces"].toInt(), 1);
        QVERIFY(o["min_radius_ratio"].toDouble() > 0.05);
    }

    void meshReportsWhatItDid() {
        // Issue 18: the report names the edge length, the attempts, the worst angle and the
        // volumes; the volume is matched to the surface's, the angle is at least the bound.
        const QString out = path("polyp-report.vtu"), report = path("polyp-report.json");
        const Run r = runCli({"mesh", "--sample", "polyp", "--out", out, "--report", report});
        QVERIFY2(r.code == 0, qPrintable(r.err));
        QVERIFY2(r.out.contains("worst dihedral") && r.out.contains("volume matched"), qPrintable(r.out));
        QFile f(report);
        QVERIFY(f.open(QIODevice::ReadOnly));
        const QJsonObject o = QJsonDocument::fromJson(f.readAll()).object();
        for (const char* key : {"tets", "edge_length", "attempts", "min_dihedral_deg", "surface_volume", "inscribed_volume",
                                "volume", "volume_error", "max_boundary_offset", "seconds", "surface_triangles"})
            QVERIFY2(o.contains(key), key);
        QVERIFY(o["min_dihedral_deg"].toDouble() >= 10.0);
        QVERIFY(std::abs(o["volume_error"].toDouble()) < 1e-9);
        QVERIFY(o["inscribed_volume"].toDouble() < 0.99 * o["surface_volume"].toDouble());
        QCOMPARE(o["attempts"].toInt(), 1);
        TetMesh m;
        QVERIFY(readTetMesh(out.toStdString(), m).ok());
        QCOMPARE(m.tetCount(), o["tets"].toInt());
        QVERIFY(std::abs(m.totalReferenceVolume() - o["surface_volume"].toDouble()) <= 1e-9 * o["surface_volume"].toDouble());
        // Without matching, the inscribed volume.
        const Run plain = runCli({"mesh", "--sample", "polyp", "--out", out, "--no-volume-match"});
        QVERIFY2(plain.code == 0, qPrintable(plain.err));
        QVERIFY(readTetMesh(out.toStdString(), m).ok());
        QVERIFY(std::abs(m.totalReferenceVolume() - o["inscribed_volume"].toDouble()) <= 1e-9 * o["surface_volume"].toDouble());
        // An unreachable bound fails with the best angle named, and writes nothing.
        const QString never = path("never.vtu");
        const Run strict = runCli({"mesh", "--sample", "polyp", "--out", never, "--min-dihedral", "30"});
        QCOMPARE(strict.code, 2);
        QVERIFY2(strict.err.contains("no mesh reached the smallest dihedral angle of 30 degrees"), qPrintable(strict.err));
        QVERIFY(!QFile::exists(never));
    }

    void meshSurfaceFileKeepsInputIntact() {
        writeText(path("cube.obj"), kCubeVertices + kCubeFacesNoTop + kCubeTop);
        const QByteArray before = sha256(path("cube.obj"));
        const Run r = runCli({"mesh", path("cube.obj"), "--out", path("cube.vtu"), "--edge-length", "0.25"});
        QVERIFY2(r.code == 0, qPrintable(r.err));
        QCOMPARE(sha256(path("cube.obj")), before);
        TetMesh m;
        QVERIFY(readTetMesh(path("cube.vtu").toStdString(), m).ok());
        QVERIFY(std::abs(m.totalReferenceVolume() - 1.0) < 0.03);
        // Refuses to overwrite its input.
        const Run same = runCli({"mesh", path("cube.obj"), "--out", path("cube.obj")});
        QCOMPARE(same.code, 2);
        QCOMPARE(sha256(path("cube.obj")), before);
    }

    void badSurfaces_data() {
        QTest::addColumn<QString>("file");
        QTest::addColumn<QByteArray>("content");
        QTest::addColumn<QString>("message");
        QTest::newRow("empty file") << "empty.obj" << QByteArray() << "empty.obj";
        QTest::newRow("garbage") << "garbage.stl" << QByteArray("\x01\x02garbage\xff\xfe", 12) << "garbage.stl";
        QTest::newRow("no triangles") << "points.obj" << QByteArray("v 0 0 0\nv 1 0 0\nv 0 1 0\n") << "no (faces|triangles)";
        QTest::newRow("open surface") << "open.obj" << kCubeVertices + kCubeFacesNoTop << "border edges";
        QTest::newRow("non-finite") << "nan.off"
            << QByteArray("OFF\n4 4 0\n0 0 0\n1 0 0\n0 1 0\n0 0 nan\n3 0 2 1\n3 0 1 3\n3 1 2 3\n3 0 3 2\n")
            << "non-finite";
        // Two tetrahedron surfaces sharing the edge (v1, v2): that edge is in 4 triangles.
        QTest::newRow("non-manifold") << "nonmanifold.obj"
            << QByteArray("v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\nv 0 -1 0\nv 0 0 -1\n"
                          "f 2 3 4\nf 1 4 3\nf 1 2 4\nf 1 3 2\n"
                          "f 2 5 6\nf 1 6 5\nf 1 2 6\nf 1 5 2\n")
            << "non-manifold";
        // Two closed cubes, the second pushed halfway into the first.
        QByteArray twoCubes = kCubeVertices + kCubeFacesNoTop + kCubeTop;
        twoCubes += "v 0.5 0.5 0.5\nv 1.5 0.5 0.5\nv 1.5 1.5 0.5\nv 0.5 1.5 0.5\n"
                    "v 0.5 0.5 1.5\nv 1.5 0.5 1.5\nv 1.5 1.5 1.5\nv 0.5 1.5 1.5\n";
        for (const char* f : {"f 9 11 10\n", "f 9 12 11\n", "f 9 10 14\n", "f 9 14 13\n", "f 10 11 15\n",
                              "f 10 15 14\n", "f 11 12 16\n", "f 11 16 15\n", "f 12 9 13\n", "f 12 13 16\n",
                              "f 13 14 15\n", "f 13 15 16\n"})
            twoCubes += f;
        QTest::newRow("self-intersecting") << "selfintersecting.obj" << twoCubes << "self-intersect";
    }
    void badSurfaces() {
        QFETCH(QString, file);
        QFETCH(QByteArray, content);
        QFETCH(QString, message);
        writeText(path(file), content);
        const QByteArray before = sha256(path(file));
        const QString out = path("never.vtu");
        const Run r = runCli({"mesh", path(file), "--out", out});
        QCOMPARE(r.code, 2);
        QVERIFY2(r.err.contains(QRegularExpression(message, QRegularExpression::CaseInsensitiveOption)),
                 qPrintable(r.err));
        QCOMPARE(r.err.trimmed().count('\n'), 0);
        QVERIFY(!QFile::exists(out));
        QCOMPARE(sha256(path(file)), before);
        // No temporary file left behind.
        for (const QString& name : QDir(m_dir.path()).entryList(QDir::Files | QDir::Hidden))
            QVERIFY2(!name.contains("tmp"), qPrintable(name));
    }

    void repairClosesOpenSurface() {
        writeText(path("open2.obj"), kCubeVertices + kCubeFacesNoTop);
        const Run r = runCli({"mesh", path("open2.obj"), "--repair", "--out", path("repaired.vtu"),
                              "--edge-length", "0.25"});
        QVERIFY2(r.code == 0, qPrintable(r.err));
        QVERIFY(r.err.contains("filled 1 hole"));
        TetMesh m;
        QVERIFY(readTetMesh(path("repaired.vtu").toStdString(), m).ok());
        QVERIFY(std::abs(m.totalReferenceVolume() - 1.0) < 0.05);
    }

    void unwritableOutput() {
        const Run r = runCli({"mesh", "--sample", "myoma", "--out", "/nonexistent-dir/x.vtu"});
        QCOMPARE(r.code, 2);
        QVERIFY2(r.err.contains("/nonexistent-dir/x.vtu"), qPrintable(r.err));
    }
};

QTEST_GUILESS_MAIN(TestCliMesh)
#include "test_cli_mesh.moc"
