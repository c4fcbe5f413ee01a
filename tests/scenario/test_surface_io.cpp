// Triangle surfaces through assimp: every writable format round-trips a closed cube (same
// counts after welding, same vertices, same enclosed volume and orientation, uvs where the
// format has them); reading welds STL facets, triangulates polygons, drops lines and points
// and applies node transforms; bad inputs give errors naming the file and print nothing;
// failed writes leave no file behind.

#include "scenario/surface_io.h"
#include "core/embed/cut_surface.h"

#include "scenario_test_util.h"

#include <QTemporaryDir>
#include <assimp/Importer.hpp>
#include <assimp/scene.h>
#include <QtTest>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <random>

using namespace resect;
using namespace resect::test;

namespace {

/// The cube [0,2]^3 moved by (1.5, -0.25, 3) (all coordinates exact in float): vertex i has
/// x = bit 0, y = bit 1, z = bit 2 of i; 12 outward counter-clockwise triangles; volume 8;
/// a distinct uv per vertex.
TriangleSurface makeCube(bool withUvs) {
    TriangleSurface s;
    const Vec3 offset(1.5, -0.25, 3.0);
    for (int i = 0; i < 8; ++i) {
        s.positions.push_back(offset + 2.0 * Vec3(i & 1, (i >> 1) & 1, (i >> 2) & 1));
        if (withUvs)
            s.uvs.emplace_back(0.125 * i, 1.0 - 0.0625 * i);
    }
    s.triangles = {{0, 2, 1}, {1, 2, 3}, {4, 5, 6}, {5, 7, 6}, {0, 1, 4}, {1, 5, 4},
                   {2, 6, 3}, {3, 6, 7}, {0, 4, 2}, {2, 4, 6}, {1, 3, 5}, {3, 7, 5}};
    return s;
}

/// Index of the vertex of `s` at position p (exact), or -1.
int findVertex(const TriangleSurface& s, const Vec3& p) {
    for (int i = 0; i < s.vertexCount(); ++i)
        if (s.positions[i] == p)
            return i;
    return -1;
}

/// Each triangle as its corner positions, rotated so the smallest corner comes first
/// (keeps the orientation), sorted: equal for two surfaces with the same oriented
/// triangles whatever their vertex numbering.
std::vector<std::array<std::array<double, 3>, 3>> orientedTriangles(const TriangleSurface& s) {
    using P = std::array<double, 3>;
    std::vector<std::array<P, 3>> result;
    for (const Tri& t : s.triangles) {
        std::array<P, 3> c;
        for (int k = 0; k < 3; ++k) {
            const Vec3& p = s.positions[t[k]];
            c[k] = {p.x(), p.y(), p.z()};
        }
        const auto first = std::min_element(c.begin(), c.end()) - c.begin();
        std::rotate(c.begin(), c.begin() + first, c.end());
        result.push_back(c);
    }
    std::sort(result.begin(), result.end());
    return result;
}

bool contains(const Status& s, const QString& text) {
    return QString::fromStdString(s.message()).contains(text);
}

/// A glTF 2.0 file with one tetrahedron mesh (float positions, uint16 indices, data URI)
/// instanced by two nodes: node 0 translated by (10, 0, 0); node 1 scaled by 2 and
/// translated by (0, 10, 0), as the child of node 2, translated by (0, 0, 5).
QByteArray gltfWithTransforms() {
    QByteArray buffer;
    const float positions[12] = {0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1};
    const quint16 indices[12] = {1, 2, 3, 0, 3, 2, 0, 1, 3, 0, 2, 1}; // outward
    buffer.append(reinterpret_cast<const char*>(positions), sizeof positions);
    buffer.append(reinterpret_cast<const char*>(indices), sizeof indices);
    return R"({
  "asset": {"version": "2.0"},
  "scene": 0,
  "scenes": [{"nodes": [0, 2]}],
  "nodes": [
    {"mesh": 0, "translation": [10, 0, 0]},
    {"mesh": 0, "translation": [0, 10, 0], "scale": [2, 2, 2]},
    {"children": [1], "translation": [0, 0, 5]}
  ],
  "meshes": [{"primitives": [{"attributes": {"POSITION": 0}, "indices": 1, "mode": 4}]}],
  "buffers": [{"byteLength": 72, "uri": "data:application/octet-stream;base64,)" +
           buffer.toBase64() + R"("}],
  "bufferViews": [
    {"buffer": 0, "byteOffset": 0, "byteLength": 48, "target": 34962},
    {"buffer": 0, "byteOffset": 48, "byteLength": 24, "target": 34963}
  ],
  "accessors": [
    {"bufferView": 0, "componentType": 5126, "count": 4, "type": "VEC3",
     "min": [0, 0, 0], "max": [1, 1, 1]},
    {"bufferView": 1, "componentType": 5123, "count": 12, "type": "SCALAR"}
  ]
}
)";
}

} // namespace

class TestSurfaceIo : public QObject {
    Q_OBJECT

private slots:
    void roundTrip_data();
    void roundTrip();
    void cutSurfacesKeepTheirSidesAndCutFaces();
    void readWeldsStlFacets();
    void readTriangulatesAndDropsLinesAndPoints();
    void readAppliesNodeTransforms();
    void badInputs_data();
    void badInputs();
    void damagedFilesNeverCrash_data();
    void damagedFilesNeverCrash();
    void writeErrors_data();
    void writeErrors();
};

void TestSurfaceIo::roundTrip_data() {
    QTest::addColumn<QString>("name");
    QTest::addColumn<bool>("keepsUvs");
    QTest::addColumn<QStringList>("files"); // everything the write leaves in the folder
    QTest::newRow("obj") << "cube.obj" << true << QStringList{"cube.obj"};
    QTest::newRow("stl") << "cube.stl" << false << QStringList{"cube.stl"};
    QTest::newRow("ply") << "cube.ply" << false << QStringList{"cube.ply"};
    QTest::newRow("off") << "cube.off" << false << QStringList{"cube.off"};
    QTest::newRow("glb") << "cube.glb" << true << QStringList{"cube.glb"};
    QTest::newRow("gltf") << "cube.gltf" << true << QStringList{"cube.bin", "cube.gltf"};
    QTest::newRow("upper-case OBJ") << "CUBE.OBJ" << true << QStringList{"CUBE.OBJ"};
}

void TestSurfaceIo::roundTrip() {
    QFETCH(QString, name);
    QFETCH(bool, keepsUvs);
    QFETCH(QStringList, files);
    QTemporaryDir dir;
    QVERIFY(dir.isValid());
    const QString path = dir.filePath(name);
    const TriangleSurface cube = makeCube(true);
    const Status w = writeSurface(path.toStdString(), cube);
    QVERIFY2(w.ok(), w.message().c_str());
    QCOMPARE(entries(dir.path()), files); // no temporary left behind
    const QByteArray written = readBytes(path);

    TriangleSurface back;
    StderrCapture capture;
    const Status r = readSurface(path.toStdString(), back);
    const QByteArray printed = capture.text();
    QVERIFY2(r.ok(), r.message().c_str());
    QVERIFY2(printed.isEmpty(), printed.constData());
    QCOMPARE(back.vertexCount(), 8);
    QCOMPARE(back.triangleCount(), 12);
    QCOMPARE(enclosedVolume(back), 8.0); // coordinates are exact in float
    QVERIFY(orientedTriangles(back) == orientedTriangles(cube));
    if (keepsUvs) {
        QCOMPARE(back.uvs.size(), std::size_t(8));
        for (int i = 0; i < back.vertexCount(); ++i) {
            const int original = findVertex(cube, back.positions[i]);
            QVERIFY(original >= 0);
            QVERIFY2((back.uvs[i] - cube.uvs[original]).norm() < 1e-6,
                     qPrintable(QString("vertex %1: uv (%2, %3)")
                                    .arg(i)
                                    .arg(back.uvs[i].x())
                                    .arg(back.uvs[i].y())));
        }
    }
    QCOMPARE(readBytes(path), written); // reading does not touch the file

    // Writing again replaces the file, still without leftovers.
    const Status again = writeSurface(path.toStdString(), makeCube(false));
    QVERIFY2(again.ok(), again.message().c_str());
    QCOMPARE(entries(dir.path()), files);
}

/// A cube cut in two (section 5): OBJ keeps every vertex (the two sides' coincident copies
/// stay apart) and writes cut faces in their own group with the sweep's (u, v); binary glTF
/// holds the skin and the cut faces as two meshes, the cut one textured with (u, v).
void TestSurfaceIo::cutSurfacesKeepTheirSidesAndCutFaces() {
    TriangleSurface cube = makeCube(true);
    SweepSurface sweep;
    QVERIFY(SweepSurface::fromStartEnd({Vec3(0, -2, 4.1), Vec3(5, -2, 4.2)}, {Vec3(0, 3, 4.1), Vec3(5, 3, 4.2)}, sweep)
                .ok());
    SurfaceCut cut;
    const Status c = cutSurface(cube, nullptr, sweep, cut);
    QVERIFY2(c.ok(), c.message().c_str());
    QVERIFY(cut.capTriangles > 0);
    const int capCorners = [&] {
        std::vector<int> v;
        for (int f = 0; f < cube.triangleCount(); ++f)
            if (cube.isCutFace(f))
                v.insert(v.end(), cube.triangles[f].begin(), cube.triangles[f].end());
        std::sort(v.begin(), v.end());
        return int(std::unique(v.begin(), v.end()) - v.begin());
    }();
    QTemporaryDir dir;
    QVERIFY(dir.isValid());

    const QString obj = dir.filePath("cut.obj");
    const Status w = writeSurface(obj.toStdString(), cube);
    QVERIFY2(w.ok(), w.message().c_str());
    int v = 0, vt = 0, f = 0, cutFaces = 0;
    bool inCut = false;
    for (const QByteArray& line : readBytes(obj).split('\n')) {
        v += line.startsWith("v ");
        vt += line.startsWith("vt ");
        f += line.startsWith("f ");
        if (line.startsWith("g "))
            inCut = line == "g cut";
        cutFaces += inCut && line.startsWith("f ");
    }
    QCOMPARE(v, cube.vertexCount());
    QCOMPARE(vt, cube.vertexCount() + capCorners);
    QCOMPARE(f, cube.triangleCount());
    QCOMPARE(cutFaces, cut.capTriangles);
    TriangleSurface back;
    const Status r = readSurface(obj.toStdString(), back);
    QVERIFY2(r.ok(), r.message().c_str());
    QCOMPARE(back.triangleCount(), cube.triangleCount());
    QVERIFY(std::abs(enclosedVolume(back) - 8.0) < 1e-5);

    const QString glb = dir.filePath("cut.glb");
    const Status g = writeSurface(glb.toStdString(), cube);
    QVERIFY2(g.ok(), g.message().c_str());
    Assimp::Importer importer;
    const aiScene* scene = importer.ReadFile(glb.toStdString(), 0);
    QVERIFY(scene);
    QCOMPARE(scene->mNumMeshes, 2u);
    const aiMesh* skin = scene->mMeshes[0];
    const aiMesh* cap = scene->mMeshes[1];
    if (cap->mNumFaces > skin->mNumFaces)
        std::swap(skin, cap);  // the importer may reorder meshes
    QCOMPARE(int(cap->mNumFaces), cut.capTriangles);
    QCOMPARE(int(skin->mNumFaces), cube.triangleCount() - cut.capTriangles);
    QVERIFY(cap->HasTextureCoords(0));
    for (unsigned k = 0; k < cap->mNumFaces; ++k)
        for (unsigned i = 0; i < 3; ++i) {
            const unsigned idx = cap->mFaces[k].mIndices[i];
            const aiVector3D p = cap->mVertices[idx];
            const int original = findVertex(cube, Vec3(p.x, p.y, p.z));
            QVERIFY(original < 0 || original >= cut.firstNewVertex);
            // Both copies of a cut point share their (u, v): compare with the first found.
            const Vec3 q(p.x, p.y, p.z);
            for (int vtx = cut.firstNewVertex; vtx < cube.vertexCount(); ++vtx)
                if ((cube.positions[vtx] - q).norm() < 1e-5) {
                    const aiVector3D t = cap->mTextureCoords[0][idx];
                    QVERIFY((Eigen::Vector2d(t.x, t.y) - cube.cutUvs[vtx]).norm() < 1e-5);
                    break;
                }
        }
}

void TestSurfaceIo::readWeldsStlFacets() {
    // ASCII STL repeats every corner per facet; welding by position gives the 4 vertices.
    QTemporaryDir dir;
    QVERIFY(dir.isValid());
    const QString path = dir.filePath("tet.stl");
    QVERIFY(writeBytes(path, R"(solid tet
facet normal 0.577 0.577 0.577
 outer loop
  vertex 1 0 0
  vertex 0 1 0
  vertex 0 0 1
 endloop
endfacet
facet normal -1 0 0
 outer loop
  vertex 0 0 0
  vertex 0 0 1
  vertex 0 1 0
 endloop
endfacet
facet normal 0 -1 0
 outer loop
  vertex 0 0 0
  vertex 1 0 0
  vertex 0 0 1
 endloop
endfacet
facet normal 0 0 -1
 outer loop
  vertex 0 0 0
  vertex 0 1 0
  vertex 1 0 0
 endloop
endfacet
endsolid tet
)"));
    TriangleSurface s;
    const Status r = readSurface(path.toStdString(), s);
    QVERIFY2(r.ok(), r.message().c_str());
    QCOMPARE(s.vertexCount(), 4);
    QCOMPARE(s.triangleCount(), 4);
    QVERIFY(s.uvs.empty());
    QCOMPARE(enclosedVolume(s), 1.0 / 6.0);
}

void TestSurfaceIo::readTriangulatesAndDropsLinesAndPoints() {
    // The cube as six quads, with a line and a point element that must be dropped.
    QTemporaryDir dir;
    QVERIFY(dir.isValid());
    const QString path = dir.filePath("quads.obj");
    QVERIFY(writeBytes(path, "# cube of side 2 as quads\n"
                             "v 0 0 0\nv 2 0 0\nv 0 2 0\nv 2 2 0\n"
                             "v 0 0 2\nv 2 0 2\nv 0 2 2\nv 2 2 2\n"
                             "f 1 3 4 2\nf 5 6 8 7\nf 1 2 6 5\nf 3 7 8 4\nf 1 5 7 3\nf 2 4 8 6\n"
                             "l 1 8\np 4\n"));
    TriangleSurface s;
    const Status r = readSurface(path.toStdString(), s);
    QVERIFY2(r.ok(), r.message().c_str());
    QCOMPARE(s.vertexCount(), 8);
    QCOMPARE(s.triangleCount(), 12);
    QCOMPARE(enclosedVolume(s), 8.0);
}

void TestSurfaceIo::readAppliesNodeTransforms() {
    QTemporaryDir dir;
    QVERIFY(dir.isValid());
    const QString path = dir.filePath("instances.gltf");
    QVERIFY(writeBytes(path, gltfWithTransforms()));
    TriangleSurface s;
    const Status r = readSurface(path.toStdString(), s);
    QVERIFY2(r.ok(), r.message().c_str());
    QCOMPARE(s.vertexCount(), 8);
    QCOMPARE(s.triangleCount(), 8);
    // Instance 0: unit tet at (10, 0, 0), volume 1/6; instance 1: scaled by 2 at (0, 10, 5),
    // volume 8/6.
    QCOMPARE(enclosedVolume(s), 1.5);
    QVERIFY(findVertex(s, Vec3(10, 0, 0)) >= 0);
    QVERIFY(findVertex(s, Vec3(11, 0, 0)) >= 0);
    QVERIFY(findVertex(s, Vec3(0, 10, 5)) >= 0);
    QVERIFY(findVertex(s, Vec3(0, 12, 5)) >= 0);
    QVERIFY(findVertex(s, Vec3(0, 10, 7)) >= 0);
    const auto box = boundingBox(s.positions);
    QVERIFY(box[0] == Vec3(0, 0, 0));
    QVERIFY(box[1] == Vec3(11, 12, 7));
}

void TestSurfaceIo::badInputs_data() {
    QTest::addColumn<QString>("name");
    QTest::addColumn<QByteArray>("content"); // null: the file does not exist
    QTest::addColumn<QString>("expected");
    QTest::newRow("missing") << "missing.obj" << QByteArray() << "no such file";
    QTest::newRow("empty obj") << "empty.obj" << QByteArray("") << "assimp cannot read the file";
    QTest::newRow("garbage stl") << "junk.stl" << QByteArray("\x00\x01\x02\xff\xfe\xfd garbage", 15)
                                 << "assimp cannot read the file";
    QTest::newRow("garbage glb") << "junk.glb" << QByteArray("glTF\x02\0\0\0\xff\xff\xff\xff", 12)
                                 << "assimp cannot read the file";
    QTest::newRow("truncated gltf")
        << "cut.gltf" << gltfWithTransforms().left(300) << "not valid glTF JSON";
    QTest::newRow("unknown format")
        << "mesh.xyz" << QByteArray("hello\n") << "assimp cannot read the file";
    QTest::newRow("only lines and points")
        << "lines.obj" << QByteArray("v 0 0 0\nv 1 0 0\nv 0 1 0\nl 1 2\nl 2 3\np 1\n")
        << "no triangles";
    QTest::newRow("NaN coordinate")
        << "nan.obj" << QByteArray("v 0 0 0\nv 1 0 0\nv 0 nan 0\nf 1 2 3\n")
        << "non-finite coordinate";
    // Regressions: damaged PLY files that made assimp 5.2 loop forever (no end_header line)
    // or abort on an assertion (a face whose vertex count is not a number).
    const QByteArray plyHead = "ply\nformat ascii 1.0\nelement vertex 4\nproperty float x\n"
                               "property float y\nproperty float z\nelement face 2\n"
                               "property list uchar int vertex_index\n";
    QTest::newRow("ply header cut short")
        << "cut.ply" << QByteArray("ply\nformat ascii 1.0\ncomment Created by Open Asset ")
        << "damaged PLY file (its header has no end_header line)";
    QTest::newRow("ply end_header glued to data")
        << "glued.ply" << plyHead + "end_header0 0 0\n1 0 0\n0 1 0\n0 0 1\n3 0 2 1\n3 0 1 3\n"
        << "damaged PLY file (its header has no end_header line)";
    // (Since the data walk of assimp_guard.cpp, rejected before assimp sees it.)
    QTest::newRow("ply face count not a number")
        << "count.ply" << plyHead + "end_header\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n3 0 2 1\n\xa0 0 1 3\n"
        << "damaged PLY file (element face 1 has the list length '?')";
    QTest::newRow("infinite coordinate")
        << "inf.obj" << QByteArray("v 0 0 0\nv 1 0 0\nv 0 1e999 0\nf 1 2 3\n")
        << "non-finite coordinate";
}

void TestSurfaceIo::badInputs() {
    QFETCH(QString, name);
    QFETCH(QByteArray, content);
    QFETCH(QString, expected);
    QTemporaryDir dir;
    QVERIFY(dir.isValid());
    const QString path = dir.filePath(name);
    if (!content.isNull())
        QVERIFY(writeBytes(path, content));
    const QStringList before = entries(dir.path());

    TriangleSurface out = makeCube(true);
    StderrCapture capture;
    const Status s = readSurface(path.toStdString(), out);
    const QByteArray printed = capture.text();
    QVERIFY(!s.ok());
    QVERIFY2(contains(s, path), s.message().c_str());
    QVERIFY2(contains(s, expected), s.message().c_str());
    QVERIFY2(printed.isEmpty(), printed.constData());
    QCOMPARE(out.vertexCount(), 8); // untouched
    QCOMPARE(out.triangleCount(), 12);
    if (!content.isNull())
        QCOMPARE(readBytes(path), content);
    QCOMPARE(entries(dir.path()), before);
}

void TestSurfaceIo::damagedFilesNeverCrash_data() {
    QTest::addColumn<QString>("name");
    for (const char* name :
         {"cube.obj", "cube.stl", "cube.ply", "cube.off", "cube.glb", "cube.gltf"})
        QTest::newRow(name) << name;
}

void TestSurfaceIo::damagedFilesNeverCrash() {
    // Truncations and random corruptions (fixed seed) of a written cube: each read either
    // succeeds with a valid surface or fails naming the file; it never crashes, hangs or
    // prints.
    QFETCH(QString, name);
    QTemporaryDir dir;
    QVERIFY(dir.isValid());
    const QString path = dir.filePath(name);
    QVERIFY(writeSurface(path.toStdString(), makeCube(true)).ok());
    const QByteArray valid = readBytes(path);
    const int n = static_cast<int>(valid.size());
    QVERIFY(n > 0);

    std::vector<QByteArray> variants;
    for (int len = 0; len < n; len += std::max(1, n / 100))
        variants.push_back(valid.left(len));
    std::mt19937 rng(777);
    for (int i = 0; i < 200; ++i) {
        QByteArray v = valid;
        const int flips = 1 + static_cast<int>(rng() % 6);
        for (int f = 0; f < flips; ++f) {
            const int at = static_cast<int>(rng() % n);
            v[at] =
                (rng() % 2) ? static_cast<char>(rng() % 256) : static_cast<char>('0' + rng() % 10);
        }
        variants.push_back(v);
    }

    int failures = 0;
    StderrCapture capture;
    for (const QByteArray& bytes : variants) {
        QVERIFY(writeBytes(path, bytes));
        TriangleSurface s;
        const Status r = readSurface(path.toStdString(), s);
        if (r.ok()) {
            QVERIFY(s.triangleCount() > 0);
            QVERIFY(s.uvs.empty() || s.uvs.size() == s.positions.size());
            for (const Vec3& p : s.positions)
                QVERIFY(p.allFinite());
            for (const Tri& t : s.triangles)
                for (int v : t)
                    QVERIFY(v >= 0 && v < s.vertexCount());
        } else {
            ++failures;
            QVERIFY2(contains(r, path), r.message().c_str());
        }
    }
    const QByteArray printed = capture.text();
    QVERIFY2(printed.isEmpty(), printed.left(2000).constData());
    QVERIFY(failures > 0);
}

void TestSurfaceIo::writeErrors_data() {
    QTest::addColumn<QString>("name");
    QTest::addColumn<int>("damage"); // 0 none, 1 bad index, 2 no triangles, 3 uv count, 4 NaN
    QTest::addColumn<QString>("expected");
    QTest::newRow("unknown extension") << "out.xyz" << 0 << "unknown surface extension '.xyz'";
    QTest::newRow("no extension") << "out" << 0 << "unknown surface extension ''";
    QTest::newRow("missing folder") << "no/such/dir/out.obj" << 0 << "temporary file";
    QTest::newRow("bad index") << "out.obj" << 1 << "triangle 3 refers to vertex 8 of 8";
    QTest::newRow("no triangles") << "out.stl" << 2 << "without triangles";
    QTest::newRow("uv count") << "out.glb" << 3 << "7 texture coordinates for 8 vertices";
    QTest::newRow("NaN") << "out.off" << 4 << "vertex 5 has a non-finite coordinate";
}

void TestSurfaceIo::writeErrors() {
    QFETCH(QString, name);
    QFETCH(int, damage);
    QFETCH(QString, expected);
    QTemporaryDir dir;
    QVERIFY(dir.isValid());
    TriangleSurface s = makeCube(true);
    if (damage == 1)
        s.triangles[3][1] = 8;
    if (damage == 2)
        s.triangles.clear();
    if (damage == 3)
        s.uvs.pop_back();
    if (damage == 4)
        s.positions[5].y() = std::numeric_limits<double>::quiet_NaN();
    // An existing target must survive a failed write.
    const QString path = dir.filePath(name);
    const bool folderExists = QFileInfo(path).dir().exists();
    if (folderExists)
        QVERIFY(writeBytes(path, "previous"));
    const QStringList before = entries(dir.path());
    const Status w = writeSurface(path.toStdString(), s);
    QVERIFY(!w.ok());
    QVERIFY2(contains(w, path), w.message().c_str());
    QVERIFY2(contains(w, expected), w.message().c_str());
    if (folderExists)
        QCOMPARE(readBytes(path), QByteArray("previous"));
    QCOMPARE(entries(dir.path()), before);
}

QTEST_GUILESS_MAIN(TestSurfaceIo)
#include "test_surface_io.moc"
