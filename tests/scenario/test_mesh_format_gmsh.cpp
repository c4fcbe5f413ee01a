// Gmsh .msh (issue 21): files made by the gmsh binary (tests/data/gmsh, regenerated with
// gmsh when it is installed) in 2.2 and 4.1, ASCII and binary, with physical groups,
// second-order and mixed elements; our own files re-saved by gmsh; exact round trips of all
// four variants at several scales; and every refusal, each naming the file, the place and
// what is wrong, with the output mesh and report untouched.

#include "scenario/mesh_io.h"

#include "scenario_test_util.h"

#include "core/mesh/box_mesh.h"
#include "core/mesh/predicates.h"
#include "core/mesh/topology.h"

#include <QElapsedTimer>
#include <QProcess>
#include <QStandardPaths>
#include <QTemporaryDir>
#include <QtTest>

#include <cmath>
#include <cstring>
#include <limits>

using namespace resect;
using namespace resect::test;

namespace {

const QString kData = QStringLiteral(RESECT_SOURCE_DIR "/tests/data/gmsh/");
/// The Gmsh version that made the checked-in files: a regenerated file has the same counts
/// only when made by the same version.
const QString kGmshVersion = QStringLiteral("4.8.4");

double tetVolume(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d) {
    return (b - a).cross(c - a).dot(d - a) / 6.0;
}

/// Sum of the tets' signed volumes in the reference configuration.
double referenceVolume(const TetMesh& mesh) {
    double sum = 0;
    for (const Tet& t : mesh.tets())
        sum += tetVolume(mesh.ref(t[0]), mesh.ref(t[1]), mesh.ref(t[2]), mesh.ref(t[3]));
    return sum;
}

/// True if every tet is positively oriented in the reference configuration (exact).
bool allPositive(const TetMesh& mesh) {
    for (const Tet& t : mesh.tets())
        if (orient3d(mesh.ref(t[0]), mesh.ref(t[1]), mesh.ref(t[2]), mesh.ref(t[3])) <= 0)
            return false;
    return true;
}

/// "dim:tag:name:tets" per group, comma-separated.
QString groupsText(const MeshReadReport& r) {
    QStringList parts;
    for (const MeshReadReport::Group& g : r.groups)
        parts << QStringLiteral("%1:%2:%3:%4")
                     .arg(g.dimension)
                     .arg(g.tag)
                     .arg(QString::fromStdString(g.name))
                     .arg(g.tets);
    return parts.join(", ");
}

/// "what count" per dropped kind, comma-separated.
QString droppedText(const MeshReadReport& r) {
    QStringList parts;
    for (const MeshReadReport::Dropped& d : r.dropped)
        parts << QString::fromStdString(d.what) + " " + QString::number(d.count);
    return parts.join(", ");
}

QString notesText(const MeshReadReport& r) {
    QStringList parts;
    for (const std::string& n : r.notes)
        parts << QString::fromStdString(n);
    return parts.join("; ");
}

/// Two boxes side by side whose touching faces coincide (9 node pairs at x = scale) but
/// share no node, as a cut leaves them; deformed by a smooth displacement of the reference
/// position (so the coincident pairs coincide in both configurations), with velocities and
/// masses that need all 17 digits.
TetMesh makeCutLikeMesh(double scale) {
    const TetMesh left = makeBoxTetMesh(Vec3(0, 0, 0), Vec3(1, 1, 1) * scale, 2, 2, 2);
    const TetMesh right = makeBoxTetMesh(Vec3(1, 0, 0) * scale, Vec3(2, 1, 1) * scale, 2, 2, 2);
    // The nodes of the two pieces alternate (as when a cut appends separated nodes), so that
    // a piece's nodes are not one run: node i of the left box is 2i, of the right 2i + 1.
    const int half = left.nodeCount();
    std::vector<Vec3> ref(static_cast<std::size_t>(2 * half));
    for (int n = 0; n < half; ++n) {
        ref[static_cast<std::size_t>(2 * n)] = left.ref(n);
        ref[static_cast<std::size_t>(2 * n + 1)] = right.ref(n);
    }
    std::vector<Tet> tets;
    for (int side = 0; side < 2; ++side)
        for (Tet t : (side == 0 ? left : right).tets()) {
            for (int& n : t)
                n = 2 * n + side;
            tets.push_back(t);
        }
    TetMesh mesh = TetMesh::fromArrays(ref, tets);
    for (int n = 0; n < mesh.nodeCount(); ++n) {
        const Vec3 u = ref[static_cast<std::size_t>(n)] / scale;
        const double s = std::sqrt(2.0 + u.x() + 2 * u.y() + 3 * u.z());
        mesh.positions()[n] =
            ref[static_cast<std::size_t>(n)] + scale * Vec3(0.01 * s, -1e-3 / s, 1e-9 * s);
        const double w = std::sqrt(2.0 + n);
        mesh.velocities()[n] = Vec3(w, -1.0 / w, std::cbrt(w)) * scale;
        mesh.masses()[n] = 1e-4 * w * scale * scale * scale;
    }
    return mesh;
}

/// Pairs of nodes at the same current position.
int coincidentPairs(const TetMesh& mesh) {
    std::vector<std::array<double, 3>> p;
    for (const Vec3& v : mesh.positions())
        p.push_back({v.x(), v.y(), v.z()});
    std::sort(p.begin(), p.end());
    int pairs = 0;
    for (std::size_t i = 1; i < p.size(); ++i)
        pairs += p[i] == p[i - 1];
    return pairs;
}

/// Runs gmsh with `arguments`; true if it exits with 0. The output is attached on failure.
bool runGmsh(const QString& gmsh, const QStringList& arguments, const QString& workDir,
             QString* output = nullptr) {
    QProcess p;
    p.setWorkingDirectory(workDir);
    p.setProcessChannelMode(QProcess::MergedChannels);
    p.start(gmsh, arguments);
    const bool ok =
        p.waitForFinished(120000) && p.exitStatus() == QProcess::NormalExit && p.exitCode() == 0;
    if (output)
        *output = QString::fromLocal8Bit(p.readAll());
    return ok;
}

struct Variant {
    const char* name;
    int version;
    bool binary;
    const char* format;
};
constexpr Variant kVariants[] = {{"msh22", 22, false, "Gmsh 2.2 ASCII"},
                                 {"msh22-binary", 22, true, "Gmsh 2.2 binary"},
                                 {"msh41", 41, false, "Gmsh 4.1 ASCII"},
                                 {"msh41-binary", 41, true, "Gmsh 4.1 binary"}};

// --- little builders for refusal inputs

QByteArray le32(std::int32_t v) {
    return QByteArray(reinterpret_cast<const char*>(&v), 4);
}
QByteArray le64(std::uint64_t v) {
    return QByteArray(reinterpret_cast<const char*>(&v), 8);
}
QByteArray f64(double v) {
    return QByteArray(reinterpret_cast<const char*>(&v), 8);
}

/// A valid 2.2 ASCII file with one tet; `nodes` and `elements` replace the sections' bodies.
QByteArray ascii22(const QByteArray& nodes = "4\n1 0 0 0\n2 1 0 0\n3 0 1 0\n4 0 0 1\n",
                   const QByteArray& elements = "1\n1 4 2 1 1 1 2 3 4\n",
                   const QByteArray& extra = "") {
    return "$MeshFormat\n2.2 0 8\n$EndMeshFormat\n$Nodes\n" + nodes + "$EndNodes\n$Elements\n" +
           elements + "$EndElements\n" + extra;
}

/// A valid 2.2 binary file with one tet (nodes 1..4, element 1 with tags 1 1).
QByteArray binary22(std::int32_t endianness = 1, int dataSize = 8) {
    QByteArray b = "$MeshFormat\n2.2 1 " + QByteArray::number(dataSize) + "\n" + le32(endianness) +
                   "\n$EndMeshFormat\n$Nodes\n4\n";
    const double xyz[4][3] = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
    for (int n = 0; n < 4; ++n)
        b += le32(n + 1) + f64(xyz[n][0]) + f64(xyz[n][1]) + f64(xyz[n][2]);
    b += "\n$EndNodes\n$Elements\n1\n" + le32(4) + le32(1) + le32(2);
    b += le32(1) + le32(1) + le32(1) + le32(1) + le32(2) + le32(3) + le32(4);
    b += "\n$EndElements\n";
    return b;
}

/// A valid 4.1 binary file with one tet; `numNodes` is what the $Nodes header declares.
QByteArray binary41(std::uint64_t numNodes = 4, std::int32_t elementType = 4) {
    QByteArray b = "$MeshFormat\n4.1 1 8\n" + le32(1) + "\n$EndMeshFormat\n$Nodes\n";
    b += le64(1) + le64(numNodes) + le64(1) + le64(4);
    b += le32(3) + le32(1) + le32(0) + le64(4);
    for (int n = 1; n <= 4; ++n)
        b += le64(static_cast<std::uint64_t>(n));
    const double xyz[4][3] = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
    for (const auto& p : xyz)
        b += f64(p[0]) + f64(p[1]) + f64(p[2]);
    b += "\n$EndNodes\n$Elements\n" + le64(1) + le64(1) + le64(1) + le64(1);
    b += le32(3) + le32(1) + le32(elementType) + le64(1);
    b += le64(1) + le64(1) + le64(2) + le64(3) + le64(4);
    b += "\n$EndElements\n";
    return b;
}

/// A $NodeData view (ASCII) named `name` with `components` and the given value lines.
QByteArray nodeView(const QByteArray& name, int components, const QByteArray& lines, int count) {
    return "$NodeData\n1\n\"" + name + "\"\n1\n0\n3\n0\n" + QByteArray::number(components) + "\n" +
           QByteArray::number(count) + "\n" + lines + "$EndNodeData\n";
}

} // namespace

class TestMeshFormatGmsh : public QObject {
    Q_OBJECT

private slots:
    void gmshFiles_data();
    void gmshFiles();
    void asciiAndBinaryGiveTheSameMesh();
    void regeneratedByGmsh();
    void roundTrip_data();
    void roundTrip();
    void resavedByGmsh_data();
    void resavedByGmsh();
    void ourViewsAndOtherViews();
    void secondOrderAndDuplicatesInTwoPointTwo();
    void parametricNodes();
    void binaryPointsWithoutTags();
    void entitiesOfOurFile();
    void refusals_data();
    void refusals();
    void writerRefusals();
    void manyKindsAndGroupsReadInLinearTime();
    void fuzzSeeds_data();
    void fuzzSeeds();

private:
    QTemporaryDir m_dir;
};

void TestMeshFormatGmsh::gmshFiles_data() {
    QTest::addColumn<QString>("file");
    QTest::addColumn<QString>("format");
    QTest::addColumn<int>("nodes"); // used by tets, as read
    QTest::addColumn<int>("tets");
    QTest::addColumn<double>("volume");
    QTest::addColumn<QString>("groups");
    QTest::addColumn<QString>("dropped");
    QTest::addColumn<QString>("note");

    // Counts: the files' $Nodes headers and the tet elements counted by a separate script
    // (box: 48 nodes, 110 tets, 22 triangles in "bottom"; two regions: 78 nodes, 200 tets,
    // each listed twice by 2.2 for "both"; mixed: 45 nodes, 100 tets, 8 points, 24 lines,
    // 84 triangles). Second order: the same box with mid-edge nodes (251 in the file).
    const QString boxGroups = "2:2:bottom:0, 3:1:tissue:110";
    for (const char* f : {"box_22.msh", "box_22_bin.msh", "box_41.msh", "box_41_bin.msh"}) {
        const QString file(f);
        const QString format = QString("Gmsh ") + (file.contains("22") ? "2.2" : "4.1") +
                               (file.contains("bin") ? " binary" : " ASCII");
        QTest::newRow(f) << file << format << 48 << 110 << 1.0 << boxGroups << "3-node triangle 22"
                         << "";
    }
    for (const char* f : {"box_order2_22.msh", "box_order2_41.msh"})
        QTest::newRow(f) << QString(f)
                         << (QString(f).contains("22") ? "Gmsh 2.2 ASCII" : "Gmsh 4.1 ASCII") << 48
                         << 110 << 1.0 << boxGroups << "6-node triangle 22"
                         << "read 110 10-node tetrahedra as their 4 corner nodes";
    QTest::newRow("two_regions_22.msh")
        << "two_regions_22.msh"
        << "Gmsh 2.2 ASCII" << 78 << 200 << 2.0 << "3:1:lower:100, 3:2:upper:100, 3:3:both:0"
        << ""
        << "removed 200 duplicate tetrahedra";
    QTest::newRow("two_regions_41_bin.msh")
        << "two_regions_41_bin.msh"
        << "Gmsh 4.1 binary" << 78 << 200 << 2.0 << "3:1:lower:100, 3:2:upper:100, 3:3:both:0"
        << ""
        << "";
    QTest::newRow("mixed_41.msh") << "mixed_41.msh"
                                  << "Gmsh 4.1 ASCII" << 45 << 100 << 1.0 << ""
                                  << "1-node point 8, 2-node line 24, 3-node triangle 84"
                                  << "";
    QTest::newRow("mixed_22_bin.msh") << "mixed_22_bin.msh"
                                      << "Gmsh 2.2 binary" << 45 << 100 << 1.0 << ""
                                      << "1-node point 8, 2-node line 24, 3-node triangle 84"
                                      << "";
}

void TestMeshFormatGmsh::gmshFiles() {
    QFETCH(QString, file);
    QFETCH(QString, format);
    QFETCH(int, nodes);
    QFETCH(int, tets);
    QFETCH(double, volume);
    QFETCH(QString, groups);
    QFETCH(QString, dropped);
    QFETCH(QString, note);

    TetMesh mesh;
    MeshReadReport report;
    const Status s = readTetMesh((kData + file).toStdString(), mesh, &report);
    QVERIFY2(s.ok(), s.message().c_str());
    QCOMPARE(QString::fromStdString(report.format), format);
    QCOMPARE(mesh.nodeCount(), nodes);
    QCOMPARE(static_cast<int>(mesh.tets().size()), tets);
    QVERIFY(std::abs(referenceVolume(mesh) - volume) <= 1e-12 * volume);
    QVERIFY(allPositive(mesh));
    QCOMPARE(groupsText(report), groups);
    QCOMPARE(droppedText(report), dropped);
    if (note.isEmpty())
        QVERIFY2(report.notes.empty(), qPrintable(notesText(report)));
    else
        QVERIFY2(notesText(report).contains(note), qPrintable(notesText(report)));
    // Per tet its volume group, or nothing when the file has no volume groups.
    if (groups.contains("3:")) {
        QCOMPARE(report.tetGroup.size(), mesh.tets().size());
        QVERIFY(std::none_of(report.tetGroup.begin(), report.tetGroup.end(),
                             [](std::int64_t g) { return g == 0; }));
    } else {
        QVERIFY(report.tetGroup.empty());
    }
}

void TestMeshFormatGmsh::asciiAndBinaryGiveTheSameMesh() {
    // The same Gmsh mesh in ASCII and binary must read node for node the same; 2.2 and 4.1
    // order nodes differently but hold the same points.
    TetMesh a22, b22, a41, b41;
    QVERIFY(readGmsh((kData + "box_22.msh").toStdString(), a22).ok());
    QVERIFY(readGmsh((kData + "box_22_bin.msh").toStdString(), b22).ok());
    QVERIFY(readGmsh((kData + "box_41.msh").toStdString(), a41).ok());
    QVERIFY(readGmsh((kData + "box_41_bin.msh").toStdString(), b41).ok());
    // Gmsh writes ASCII coordinates with 16 significant digits: equal to 1e-15.
    auto close = [](const TetMesh& a, const TetMesh& b) {
        if (a.nodeCount() != b.nodeCount() || a.tets() != b.tets())
            return false;
        for (int n = 0; n < a.nodeCount(); ++n)
            if ((a.ref(n) - b.ref(n)).norm() > 1e-15 || a.pos(n) != a.ref(n))
                return false;
        return true;
    };
    QVERIFY(close(a22, b22));
    QVERIFY(close(a41, b41));
    auto sorted = [](const TetMesh& m) {
        std::vector<std::array<double, 3>> p;
        for (const Vec3& v : m.referencePositions())
            p.push_back({v.x(), v.y(), v.z()});
        std::sort(p.begin(), p.end());
        return p;
    };
    QVERIFY(sorted(b22) == sorted(b41));
}

void TestMeshFormatGmsh::regeneratedByGmsh() {
    const QString gmsh = QStandardPaths::findExecutable("gmsh");
    if (gmsh.isEmpty())
        QSKIP("no gmsh on PATH");
    QString version;
    runGmsh(gmsh, {"--version"}, m_dir.path(), &version);
    const bool sameVersion = version.trimmed() == kGmshVersion;
    QTemporaryDir dir;
    for (const QString& f : QDir(kData).entryList({"*.geo", "make.sh"}))
        QVERIFY(QFile::copy(kData + f, dir.filePath(f)));
    QProcess make;
    make.setProcessChannelMode(QProcess::MergedChannels);
    make.start("sh", {dir.filePath("make.sh"), gmsh});
    QVERIFY(make.waitForFinished(300000));
    QVERIFY2(make.exitCode() == 0, make.readAll().constData());

    const QStringList made = QDir(dir.path()).entryList({"*.msh"});
    QCOMPARE(made, QDir(kData).entryList({"*.msh"}));
    for (const QString& f : made) {
        TetMesh ours, fresh;
        MeshReadReport oursReport, freshReport;
        QVERIFY(readTetMesh((kData + f).toStdString(), ours, &oursReport).ok());
        const Status s = readTetMesh(dir.filePath(f).toStdString(), fresh, &freshReport);
        QVERIFY2(s.ok(), s.message().c_str());
        QCOMPARE(freshReport.format, oursReport.format);
        QVERIFY(std::abs(referenceVolume(fresh) - referenceVolume(ours)) <=
                1e-12 * referenceVolume(ours));
        QVERIFY(allPositive(fresh));
        QStringList kinds, freshKinds;
        for (const auto& d : oursReport.dropped)
            kinds << QString::fromStdString(d.what);
        for (const auto& d : freshReport.dropped)
            freshKinds << QString::fromStdString(d.what);
        QCOMPARE(freshKinds, kinds);
        QCOMPARE(freshReport.groups.size(), oursReport.groups.size());
        for (std::size_t g = 0; g < oursReport.groups.size(); ++g)
            QCOMPARE(freshReport.groups[g].name, oursReport.groups[g].name);
        if (sameVersion) {
            QCOMPARE(fresh.nodeCount(), ours.nodeCount());
            QCOMPARE(fresh.tets(), ours.tets());
            QCOMPARE(groupsText(freshReport), groupsText(oursReport));
        }
    }
}

void TestMeshFormatGmsh::roundTrip_data() {
    QTest::addColumn<int>("variant");
    QTest::addColumn<double>("scale");
    for (int v = 0; v < 4; ++v)
        for (double scale : {1e-3, 1.0, 1e3})
            QTest::newRow(qPrintable(QString("%1 scale %2").arg(kVariants[v].name).arg(scale)))
                << v << scale;
}

void TestMeshFormatGmsh::roundTrip() {
    QFETCH(int, variant);
    QFETCH(double, scale);
    const Variant& v = kVariants[variant];
    const TetMesh mesh = makeCutLikeMesh(scale);
    const Components pieces = connectedComponents(mesh);
    QCOMPARE(pieces.count, 2);
    QCOMPARE(coincidentPairs(mesh), 9);
    const QString path = m_dir.filePath(QString("round_%1_%2.msh").arg(v.name).arg(scale));
    const Status w = writeGmsh(path.toStdString(), mesh, v.version, v.binary);
    QVERIFY2(w.ok(), w.message().c_str());
    QCOMPARE(entries(m_dir.path()).filter(".tmp").size(), 0); // nothing left over

    TetMesh back;
    MeshReadReport report;
    const Status r = readTetMesh(path.toStdString(), back, &report);
    QVERIFY2(r.ok(), r.message().c_str());
    QVERIFY(sameMesh(back, mesh)); // positions, reference, velocities, masses exact
    QCOMPARE(QString::fromStdString(report.format), QString(v.format));
    QCOMPARE(groupsText(report),
             QString("3:1:piece 0:%1, 3:2:piece 1:%2")
                 .arg(std::count(pieces.tetComponent.begin(), pieces.tetComponent.end(), 0))
                 .arg(std::count(pieces.tetComponent.begin(), pieces.tetComponent.end(), 1)));
    QCOMPARE(report.tetGroup.size(), mesh.tets().size());
    for (std::size_t t = 0; t < mesh.tets().size(); ++t)
        QCOMPARE(report.tetGroup[t], std::int64_t(pieces.tetComponent[t] + 1));
    QVERIFY(report.dropped.empty());
    QVERIFY(report.notes.empty());
    // Writing is deterministic.
    const QString again = m_dir.filePath("again.msh");
    QVERIFY(writeGmsh(again.toStdString(), back, v.version, v.binary).ok());
    QCOMPARE(readBytes(again), readBytes(path));
}

void TestMeshFormatGmsh::resavedByGmsh_data() {
    QTest::addColumn<int>("variant");
    for (int v = 0; v < 4; ++v)
        QTest::newRow(kVariants[v].name) << v;
}

void TestMeshFormatGmsh::resavedByGmsh() {
    QFETCH(int, variant);
    const QString gmsh = QStandardPaths::findExecutable("gmsh");
    if (gmsh.isEmpty())
        QSKIP("no gmsh on PATH");
    const Variant& v = kVariants[variant];
    const TetMesh mesh = makeCutLikeMesh(1.0);
    QTemporaryDir dir;
    const QString ours = dir.filePath("ours.msh");
    QVERIFY(writeGmsh(ours.toStdString(), mesh, v.version, v.binary).ok());
    for (const char* target : {"msh41", "msh22"}) {
        const QString resaved = dir.filePath(QString("resaved_%1.msh").arg(target));
        QString output;
        QVERIFY2(runGmsh(gmsh, {ours, "-save", "-format", target, "-o", resaved, "-v", "2"},
                         dir.path(), &output),
                 qPrintable(output));
        QVERIFY2(!output.contains("Error"), qPrintable(output));
        TetMesh back;
        MeshReadReport report;
        const Status r = readTetMesh(resaved.toStdString(), back, &report);
        QVERIFY2(r.ok(), r.message().c_str());
        // Coincident nodes of the two pieces stay separate: gmsh merges nothing.
        QCOMPARE(back.nodeCount(), mesh.nodeCount());
        QCOMPARE(back.tets().size(), mesh.tets().size());
        QCOMPARE(connectedComponents(back).count, 2);
        QCOMPARE(coincidentPairs(mesh), 9);
        QCOMPARE(coincidentPairs(back), 9);
        const double volume = referenceVolume(mesh);
        // Gmsh writes current positions and drops our views: the re-saved reference is
        // our current configuration.
        double current = 0;
        for (const Tet& t : mesh.tets())
            current += tetVolume(mesh.pos(t[0]), mesh.pos(t[1]), mesh.pos(t[2]), mesh.pos(t[3]));
        QVERIFY(std::abs(referenceVolume(back) - current) <= 1e-12 * volume);
        const Components pieces = connectedComponents(mesh);
        QCOMPARE(groupsText(report),
                 QString("3:1:piece 0:%1, 3:2:piece 1:%2")
                     .arg(std::count(pieces.tetComponent.begin(), pieces.tetComponent.end(), 0))
                     .arg(std::count(pieces.tetComponent.begin(), pieces.tetComponent.end(), 1)));
    }
}

void TestMeshFormatGmsh::ourViewsAndOtherViews() {
    // Views of other names, a second time step of "mass" and element data are ignored;
    // reference_position, mass and velocity fill the mesh (by node tag, in any order).
    const QByteArray views =
        nodeView("temperature", 1, "1 5\n2 5\n3 5\n4 5\n", 4) +
        nodeView("mass", 1, "4 0.25\n3 0.5\n2 1\n1 2\n", 4) +
        nodeView("mass", 1, "4 9\n3 9\n2 9\n1 9\n", 4) +
        nodeView("reference_position", 3, "1 0 0 0\n2 2 0 0\n3 0 2 0\n4 0 0 2\n", 4) +
        nodeView("velocity", 3, "1 1 2 3\n2 4 5 6\n3 7 8 9\n4 10 11 12\n", 4) +
        "$ElementData\n1\n\"quality\"\n1\n0\n3\n0\n1\n1\n1 0.5\n$EndElementData\n";
    const QString path = m_dir.filePath("views.msh");
    QVERIFY(writeBytes(
        path, ascii22("4\n1 0 0 0\n2 1 0 0\n3 0 1 0\n4 0 0 1\n", "1\n1 4 2 1 1 1 2 3 4\n", views)));
    TetMesh mesh;
    const Status s = readGmsh(path.toStdString(), mesh);
    QVERIFY2(s.ok(), s.message().c_str());
    QCOMPARE(mesh.masses()[0], 2.0);
    QCOMPARE(mesh.masses()[3], 0.25);
    QCOMPARE(mesh.ref(1), Vec3(2, 0, 0));
    QCOMPARE(mesh.pos(1), Vec3(1, 0, 0));
    QCOMPARE(mesh.velocities()[3], Vec3(10, 11, 12));
}

void TestMeshFormatGmsh::secondOrderAndDuplicatesInTwoPointTwo() {
    // Literal 2.2: a 10-node tet (corners 1-4, mid-edge nodes 5-10), the same tet listed again
    // for a second physical group (nodes in another order), a triangle and a hexahedron.
    QByteArray nodes = "10\n1 0 0 0\n2 1 0 0\n3 0 1 0\n4 0 0 1\n";
    for (int n = 5; n <= 10; ++n)
        nodes += QByteArray::number(n) + " 0.1 0.1 0.1\n";
    const QByteArray elements = "6\n1 11 2 7 1 1 2 3 4 5 6 7 8 9 10\n"
                                "2 4 2 8 1 4 3 2 1\n"
                                "3 2 2 0 1 1 2 3\n"
                                "4 5 2 0 1 1 2 3 4 5 6 7 8\n"
                                "5 2 2 9 1 2 3 4\n"
                                "6 99 0\n"; // an unknown type with no nodes: the line ends
    const QString path = m_dir.filePath("second.msh");
    QVERIFY(writeBytes(path, "$MeshFormat\n2.2 0 8\n$EndMeshFormat\n$PhysicalNames\n1\n3 7 "
                             "\"tissue with spaces\"\n$EndPhysicalNames\n$Nodes\n" +
                                 nodes + "$EndNodes\n$Elements\n" + elements + "$EndElements\n"));
    TetMesh mesh;
    MeshReadReport report;
    const Status s = readTetMesh(path.toStdString(), mesh, &report);
    QVERIFY2(s.ok(), s.message().c_str());
    QCOMPARE(mesh.nodeCount(), 4);
    QCOMPARE(mesh.tets().size(), std::size_t(1));
    QCOMPARE(report.tetGroup, std::vector<std::int64_t>{7});
    QCOMPARE(groupsText(report), QString("3:7:tissue with spaces:1, 3:8::0, 2:9::0"));
    QCOMPARE(droppedText(report),
             QString("3-node triangle 2, 8-node hexahedron 1, element type 99 1"));
    QVERIFY(notesText(report).contains("removed 1 duplicate tetrahedra"));
    QVERIFY(notesText(report).contains("read 1 10-node tetrahedra as their 4 corner nodes"));
    QVERIFY(QString::fromStdString(report.summary()).contains("3-node triangle 2"));
}

void TestMeshFormatGmsh::parametricNodes() {
    // 4.1 node blocks with parametric coordinates (u on a curve, u v on a surface, u v w in
    // a volume) carry extra numbers per node that the reader must skip.
    const QByteArray file = "$MeshFormat\n4.1 0 8\n$EndMeshFormat\n$Nodes\n3 4 1 4\n"
                            "1 1 1 1\n1\n0 0 0 0.25\n"
                            "2 1 1 1\n2\n1 0 0 0.5 0.75\n"
                            "3 1 1 2\n3\n4\n0 1 0 1 2 3\n0 0 1 4 5 6\n$EndNodes\n"
                            "$Elements\n1 1 1 1\n3 1 4 1\n1 1 2 3 4\n$EndElements\n";
    const QString path = m_dir.filePath("parametric.msh");
    QVERIFY(writeBytes(path, file));
    TetMesh mesh;
    const Status s = readGmsh(path.toStdString(), mesh);
    QVERIFY2(s.ok(), s.message().c_str());
    QCOMPARE(mesh.nodeCount(), 4);
    QCOMPARE(mesh.pos(1), Vec3(1, 0, 0));
    QCOMPARE(mesh.pos(3), Vec3(0, 0, 1));
}

void TestMeshFormatGmsh::binaryPointsWithoutTags() {
    // 2.2 binary: a block of 40 point elements without tags takes 8 bytes per element, the
    // least any element can; the count check must not ask for more.
    QByteArray b = binary22();
    QByteArray points = le32(15) + le32(40) + le32(0);
    for (int i = 0; i < 40; ++i)
        points += le32(100 + i) + le32(1 + i % 4);
    b.replace("$Elements\n1\n", "$Elements\n41\n");
    b.insert(b.indexOf("\n$EndElements"), points);
    const QString path = m_dir.filePath("points.msh");
    QVERIFY(writeBytes(path, b));
    TetMesh mesh;
    MeshReadReport report;
    const Status s = readTetMesh(path.toStdString(), mesh, &report);
    QVERIFY2(s.ok(), s.message().c_str());
    QCOMPARE(droppedText(report), QString("1-node point 40"));
}

void TestMeshFormatGmsh::entitiesOfOurFile() {
    // Our 4.1 file, parsed here independently: every node block lies in the volume entity of
    // its nodes' piece, and each entity's box is the box of its nodes (current positions).
    const TetMesh mesh = makeCutLikeMesh(1.0);
    const Components pieces = connectedComponents(mesh);
    const QString path = m_dir.filePath("entities.msh");
    QVERIFY(writeGmsh(path.toStdString(), mesh, 41, false).ok());
    const QStringList lines = QString::fromLatin1(readBytes(path)).split('\n');
    const int entities = lines.indexOf("$Entities");
    QCOMPARE(lines[entities + 1], QString("0 0 0 2"));
    for (int e = 0; e < 2; ++e) {
        Vec3 lo = Vec3::Constant(1e300), hi = -lo;
        for (int n = 0; n < mesh.nodeCount(); ++n)
            if (pieces.nodeComponent[static_cast<std::size_t>(n)] == e) {
                lo = lo.cwiseMin(mesh.pos(n));
                hi = hi.cwiseMax(mesh.pos(n));
            }
        const QStringList f = lines[entities + 2 + e].split(' ');
        QCOMPARE(f.size(), 10);
        QCOMPARE(f[0].toInt(), e + 1);
        for (int c = 0; c < 3; ++c) {
            QCOMPARE(f[1 + c].toDouble(), lo[c]);
            QCOMPARE(f[4 + c].toDouble(), hi[c]);
        }
        QCOMPARE(f.mid(7), (QStringList{"1", QString::number(e + 1), "0"}));
    }
    int at = lines.indexOf("$Nodes") + 1;
    const int blocks = lines[at++].split(' ')[0].toInt();
    QCOMPARE(blocks, mesh.nodeCount()); // the pieces' nodes alternate
    int seen = 0;
    for (int b = 0; b < blocks; ++b) {
        const QStringList header = lines[at++].split(' ');
        const int entity = header[1].toInt(), count = header[3].toInt();
        for (int i = 0; i < count; ++i) {
            const int node = lines[at + i].toInt() - 1;
            QCOMPARE(node, seen++); // mesh order
            QCOMPARE(pieces.nodeComponent[static_cast<std::size_t>(node)] + 1, entity);
        }
        at += 2 * count;
    }
    QCOMPARE(seen, mesh.nodeCount());
    QCOMPARE(lines[at], QString("$EndNodes"));
}

void TestMeshFormatGmsh::refusals_data() {
    QTest::addColumn<QByteArray>("content");
    QTest::addColumn<QString>("expected"); // part of the message
    QTest::addColumn<QString>("where");    // the location the message must give

    const QByteArray b22 = binary22();
    const QByteArray b41 = binary41();
    const QByteArray nodes4 = "4\n1 0 0 0\n2 1 0 0\n3 0 1 0\n4 0 0 1\n";
    auto row = [](const char* tag, const QByteArray& content, const QString& expected,
                  const QString& where) { QTest::newRow(tag) << content << expected << where; };

    // --- the header
    row("control 2.2 ASCII", ascii22(), "", "");
    row("control 2.2 binary", b22, "", "");
    row("control 4.1 binary", b41, "", "");
    row("version 4.0", "$MeshFormat\n4.0 0 8\n$EndMeshFormat\n", "Gmsh format 4.0 is not supported",
        "");
    row("version 4", "$MeshFormat\n4 1 8\n$EndMeshFormat\n", "Gmsh format 4 is not supported", "");
    row("version 1.0 header", "$MeshFormat\n1.0 0 8\n$EndMeshFormat\n",
        "Gmsh format 1.0 is not supported", "");
    row("version 1 file", "$NOD\n1\n1 0 0 0\n$ENDNOD\n", "Gmsh format 1.0 is not supported", "");
    row("not a version", "$MeshFormat\nabc 0 8\n$EndMeshFormat\n",
        "expected \"version file-type data-size\"", "line 2");
    row("file-type 2", "$MeshFormat\n2.2 2 8\n$EndMeshFormat\n", "file-type 2 is neither",
        "line 2");
    row("data size 4", binary22(1, 4), "data-size 4 is not supported", "byte offset");
    row("big-endian", binary22(0x01000000), "the file is big-endian", "byte offset 20");
    row("endianness int 7", binary22(7), "expected the endianness check integer 1",
        "byte offset 20");
    row("no end of format", "$MeshFormat\n2.2 0 8\n$Nodes\n", "expected $EndMeshFormat", "line 3");

    // --- truncation and counts larger than the file
    row("truncated 2.2 binary nodes", b22.left(b22.indexOf("$EndNodes") - 20),
        "$Nodes declares 4 nodes, but only 94 bytes follow", "byte offset 47");
    row("truncated 4.1 binary node header", b41.left(b41.indexOf("$Nodes") + 7 + 12),
        "unexpected end of file in $Nodes", "byte offset 55");
    row("truncated 2.2 binary elements", b22.left(b22.size() - 24),
        "element block of 1 elements, but only", "byte offset");
    row("truncated 4.1 binary nodes", b41.left(b41.indexOf("$EndNodes") - 8),
        "unexpected end of file in $Nodes", "byte offset");
    row("truncated 4.1 binary elements", b41.left(b41.size() - 20),
        "element block of 1 elements, but only 34 bytes follow", "byte offset 292");
    row("truncated 4.1 binary element header", b41.left(b41.indexOf("$Elements") + 10 + 12),
        "unexpected end of file in $Elements", "byte offset");
    row("truncated 2.2 ASCII", ascii22().left(ascii22().indexOf("$EndElements") - 2),
        "expected the 4 node tags of element 1 (a 4-node tetrahedron), but the line ends",
        "line 13");
    row("2.2 ASCII node count", ascii22("1000000\n1 0 0 0\n"),
        "$Nodes declares 1000000 nodes, but only", "line 5");
    row("2.2 binary node count", QByteArray(b22).replace("$Nodes\n4\n", "$Nodes\n400000\n"),
        "$Nodes declares 400000 nodes, but only", "byte offset");
    row("2.2 element count", ascii22(nodes4, "99999999999\n1 4 2 1 1 1 2 3 4\n"),
        "$Elements declares 99999999999 elements", "line 12");
    row("4.1 binary node count", binary41(1'000'000'000'000ULL),
        "$Nodes declares 1 blocks and 1000000000000 nodes, but only", "byte offset");
    row("4.1 binary size_t beyond int64", binary41(~0ULL), "is too large", "byte offset");
    row("4.1 entities count",
        "$MeshFormat\n4.1 0 8\n$EndMeshFormat\n$Entities\n0 0 0 99999999\n$EndEntities\n",
        "$Entities declares 99999999 entities of dimension 3", "line 5");
    row("2.2 tag count", ascii22(nodes4, "1\n1 4 2000000000 1 1 1 2 3 4\n"),
        "element 1 declares 2000000000 tags", "line 13");

    // --- records
    row("node tag missing", ascii22(nodes4, "1\n1 4 2 1 1 1 2 3 77\n"),
        "element 1 refers to node 77, which is not in $Nodes", "line 13");
    row("4.1 binary node tag missing", QByteArray(b41).replace(b41.size() - 22, 8, le64(77)),
        "element 1 refers to node 77", "byte offset");
    row("NaN coordinate", ascii22("4\n1 0 0 0\n2 nan 0 0\n3 0 1 0\n4 0 0 1\n"),
        "node 2 has a non-finite coordinate", "line 7");
    row("infinite binary coordinate",
        QByteArray(b22).replace(b22.indexOf("$Nodes\n4\n") + 9 + 28 + 4, 8,
                                f64(std::numeric_limits<double>::infinity())),
        "node 2 has a non-finite coordinate", "byte offset");
    row("missing coordinate", ascii22("4\n1 0 0 0\n2 1 0\n3 0 1 0\n4 0 0 1\n"),
        "expected node coordinates \"x y z\", but the line ends", "line 7");
    row("too few element nodes", ascii22(nodes4, "1\n1 4 2 1 1 1 2 3\n"),
        "expected the 4 node tags of element 1 (a 4-node tetrahedron), but the line ends",
        "line 13");
    row("too many element nodes", ascii22(nodes4, "1\n1 4 2 1 1 1 2 3 4 4\n"),
        "element 1 has more than the 4 node tags of a 4-node tetrahedron", "line 13");
    row("duplicate node tags", ascii22("4\n1 0 0 0\n2 1 0 0\n2 0 1 0\n4 0 0 1\n"),
        "node tag 2 appears twice", "line 8");
    row("non-positive node tag", ascii22("4\n1 0 0 0\n0 1 0 0\n3 0 1 0\n4 0 0 1\n"),
        "node tag 0 is not positive", "line 7");
    row("zero volume", ascii22("4\n1 0 0 0\n2 1 0 0\n3 0 1 0\n4 1 1 0\n"),
        "element 1 has zero volume", "");
    row("unknown binary element type", binary41(4, 99),
        "element type 99 is unknown; its size in a binary file is unknown", "byte offset");
    row("only triangles", ascii22(nodes4, "1\n1 2 2 1 1 1 2 3\n"),
        "no 4-node tetrahedra (Gmsh element type 4); element types found: 2", "");
    row("elements before nodes",
        "$MeshFormat\n2.2 0 8\n$EndMeshFormat\n$Elements\n1\n1 4 2 1 1 1 2 3 4\n$EndElements\n",
        "$Elements before $Nodes", "line 4");
    row("no end of nodes", ascii22().replace("$EndNodes", "$EndNodez"), "expected $EndNodes",
        "line 10");
    row("unterminated section", ascii22() + "$Comments\nblah\n", "has no $EndComments", "");
    row("unquoted physical name",
        "$MeshFormat\n2.2 0 8\n$EndMeshFormat\n$PhysicalNames\n1\n3 1 tissue\n$EndPhysicalNames\n",
        "expected a quoted physical group name", "line 6");
    row("physical dimension 7",
        "$MeshFormat\n2.2 0 8\n$EndMeshFormat\n$PhysicalNames\n1\n7 1 \"x\"\n$EndPhysicalNames\n",
        "physical group dimension 7", "line 6");

    // --- our views
    row("view with wrong components",
        ascii22(nodes4, "1\n1 4 2 1 1 1 2 3 4\n", nodeView("mass", 3, "1 1 1 1\n", 1)),
        "node data view 'mass' has 3 components; expected 1", "line 23");
    row("view missing nodes",
        ascii22(nodes4, "1\n1 4 2 1 1 1 2 3 4\n", nodeView("mass", 1, "1 1\n2 1\n", 2)),
        "node data view 'mass' has 2 values for 4 nodes", "");
    row("view of an unknown node",
        ascii22(nodes4, "1\n1 4 2 1 1 1 2 3 4\n", nodeView("mass", 1, "1 1\n2 1\n3 1\n9 1\n", 4)),
        "node data view 'mass' has a value for node 9, which is not in $Nodes", "");
    row("view twice for a node",
        ascii22(nodes4, "1\n1 4 2 1 1 1 2 3 4\n", nodeView("mass", 1, "1 1\n2 1\n3 1\n3 1\n", 4)),
        "node data view 'mass' gives node 3 two values", "");
    row("view count",
        ascii22(nodes4, "1\n1 4 2 1 1 1 2 3 4\n", nodeView("velocity", 3, "1 1 1 1\n", 500000)),
        "node data view 'velocity' declares 500000 values, but only", "line 23");
    row("negative mass",
        ascii22(nodes4, "1\n1 4 2 1 1 1 2 3 4\n", nodeView("mass", 1, "1 1\n2 -1\n3 1\n4 1\n", 4)),
        "masses must be finite and >= 0", "");
}

void TestMeshFormatGmsh::refusals() {
    QFETCH(QByteArray, content);
    QFETCH(QString, expected);
    QFETCH(QString, where);
    const QString path = m_dir.filePath("bad.msh");
    QVERIFY(writeBytes(path, content));

    TetMesh mesh = makeSampleMesh();
    const TetMesh before = mesh;
    MeshReadReport report;
    report.format = "untouched";
    const Status s = readTetMesh(path.toStdString(), mesh, &report);
    if (expected.isEmpty()) { // a control row: the valid file must read
        QVERIFY2(s.ok(), s.message().c_str());
        QCOMPARE(mesh.tets().size(), std::size_t(1));
        return;
    }
    QVERIFY2(!s.ok(), "the bad file was read");
    const QString message = QString::fromStdString(s.message());
    QVERIFY2(message.startsWith(path + ": "), qPrintable(message));
    QVERIFY2(message.contains(expected), qPrintable(message));
    QVERIFY2(message.contains(where), qPrintable(message));
    QVERIFY(sameMesh(mesh, before));
    QCOMPARE(report.format, std::string("untouched"));
    QCOMPARE(readBytes(path), content); // the input file is not touched
}

void TestMeshFormatGmsh::writerRefusals() {
    const TetMesh mesh = makeSampleMesh();
    const QString path = m_dir.filePath("w.msh");
    Status s = writeGmsh(path.toStdString(), mesh, 30, false);
    QVERIFY(!s.ok());
    QVERIFY(QString::fromStdString(s.message()).contains("Gmsh version 30 cannot be written"));
    QVERIFY(!QFile::exists(path));

    s = writeGmsh(m_dir.filePath("no/such/dir/w.msh").toStdString(), mesh, 41, true);
    QVERIFY(!s.ok());
    QVERIFY(QString::fromStdString(s.message()).contains("no/such/dir/w.msh"));
}

void TestMeshFormatGmsh::manyKindsAndGroupsReadInLinearTime() {
    // 400000 elements, each of its own unknown type or physical group: bookkeeping per
    // element that searches the kinds or groups met so far would take minutes.
    constexpr int kElements = 400000;
    QByteArray elements = QByteArray::number(kElements) + "\n";
    for (int i = 1; i <= kElements; ++i) // odd: a triangle, even: an unknown type
        elements += QByteArray::number(i) + " " + QByteArray::number(i % 2 ? 2 : 1000 + i) + " 1 " +
                    QByteArray::number(i) + (i % 2 ? " 1 2 3\n" : " 1\n");
    const QString path = m_dir.filePath("kinds.msh");
    QVERIFY(writeBytes(path, ascii22("4\n1 0 0 0\n2 1 0 0\n3 0 1 0\n4 0 0 1\n", elements)));
    QElapsedTimer timer;
    timer.start();
    TetMesh mesh;
    const Status s = readGmsh(path.toStdString(), mesh);
    QVERIFY2(timer.elapsed() < 5000, qPrintable(QString::number(timer.elapsed())));
    QVERIFY(!s.ok());
    QVERIFY2(QString::fromStdString(s.message())
                 .endsWith("element types found: 2, 1002, 1004, 1006, 1008, 1010, 1012, 1014, "
                           "1016, 1018 and 199991 more"),
             s.message().c_str());
}

void TestMeshFormatGmsh::fuzzSeeds_data() {
    // The seeds of the msh fuzz target (fuzz/corpus/msh) must be valid files that reach
    // every part of the reader (gmsh itself reads them too).
    QTest::addColumn<QString>("file");
    QTest::addColumn<QString>("format");
    QTest::addColumn<int>("tets");
    QTest::addColumn<QString>("groups");
    QTest::addColumn<QString>("dropped");
    QTest::newRow("v22-ascii-groups")
        << "v22-ascii-groups.msh"
        << "Gmsh 2.2 ASCII" << 2 << "2:3:skin:0, 3:1:tissue:1, 3:2:tumour:1"
        << "3-node triangle 1";
    QTest::newRow("v22-binary") << "v22-binary.msh"
                                << "Gmsh 2.2 binary" << 2 << "3:1::2"
                                << "3-node triangle 1";
    QTest::newRow("v41-binary") << "v41-binary.msh"
                                << "Gmsh 4.1 binary" << 2 << "2:2:skin:0, 3:1:tissue:2"
                                << "3-node triangle 1";
    QTest::newRow("v41-groups") << "v41-groups.msh"
                                << "Gmsh 4.1 ASCII" << 1
                                << "1:5:edge:0, 2:2:skin:0, 3:1:tissue:1, 3:7::0"
                                << "3-node triangle 1, 2-node line 1";
}

void TestMeshFormatGmsh::fuzzSeeds() {
    QFETCH(QString, file);
    QFETCH(QString, format);
    QFETCH(int, tets);
    QFETCH(QString, groups);
    QFETCH(QString, dropped);
    TetMesh mesh;
    MeshReadReport report;
    const Status s =
        readTetMesh((QStringLiteral(RESECT_SOURCE_DIR "/fuzz/corpus/msh/") + file).toStdString(),
                    mesh, &report);
    QVERIFY2(s.ok(), s.message().c_str());
    QCOMPARE(QString::fromStdString(report.format), format);
    QCOMPARE(mesh.tetCount(), tets);
    QCOMPARE(groupsText(report), groups);
    QCOMPARE(droppedText(report), dropped);
    QVERIFY(allPositive(mesh));
}

QTEST_GUILESS_MAIN(TestMeshFormatGmsh)
#include "test_mesh_format_gmsh.moc"
