// Issue 18: every surface of the checked-in scanned-style corpus (resources/corpus: noise,
// creases, terraces, graded and sliver triangles, three length scales) meshes at the
// defaults, as `resect mesh` and the studio mesh it (meshAnatomy), into a coarse simulation
// mesh: a few hundred to a few thousand tets, every dihedral angle >= 10 degrees, the
// surface's volume, valid; and the edge length decides the size (h/2 gives 4-16 x the tets).

#include "core/mesh/quality.h"
#include "core/mesh/validity.h"
#include "core/mesher/check_surface.h"
#include "scenario/anatomy.h"
#include "scenario/surface_io.h"

#include <QtTest>

#include <cmath>

using namespace resect;

namespace {

QString corpusPath(const QString& file) {
    return QStringLiteral(RESECT_SOURCE_DIR "/resources/corpus/") + file;
}

/// Meshes as the product does; fails the test on error.
void meshFile(TriangleSurface surface, double edgeLength, TetMesh& mesh, MeshingReport& report) {
    AnatomyMeshing options;
    options.meshing.edgeLength = edgeLength;
    const Status s = meshAnatomy(surface, options, mesh, nullptr, &report);
    QVERIFY2(s.ok(), s.message().c_str());
}

void verifyValid(const TetMesh& mesh) {
    const std::vector<MeshProblem> problems = checkValidity(mesh);
    QVERIFY2(problems.empty(), problems.empty() ? "" : problems.front().message.c_str());
    for (int t = 0; t < mesh.tetCount(); ++t)
        QVERIFY(mesh.referenceVolume(t) > 0.0);
}

} // namespace

class TestScanCorpus : public QObject {
    Q_OBJECT
private slots:
    void meshesAtTheDefaults_data() {
        QTest::addColumn<QString>("file");
        QTest::addColumn<double>("scale"); // applied on top of the file's own unit
        for (const char* f : {"kidney.off", "polyp.stl", "liver_lobe.obj", "femur_head.stl", "myoma.off",
                              "prostate.obj"})
            QTest::newRow(f) << QString(f) << 1.0;
        // The corpus spans 1e-3 to 1e3 by itself; two files also pushed to the far ends.
        QTest::newRow("kidney.off x 1e-3") << QString("kidney.off") << 1e-3;
        QTest::newRow("prostate.obj x 1e3") << QString("prostate.obj") << 1e3;
    }
    void meshesAtTheDefaults() {
        QFETCH(QString, file);
        QFETCH(double, scale);
        TriangleSurface surface;
        const Status read = readSurface(corpusPath(file).toStdString(), surface);
        QVERIFY2(read.ok(), read.message().c_str());
        for (Vec3& p : surface.positions)
            p *= scale;
        const double surfaceVolume = std::abs(enclosedVolume(surface));

        TetMesh mesh;
        MeshingReport report;
        meshFile(surface, 0.0, mesh, report);
        if (QTest::currentTestFailed())
            return;
        verifyValid(mesh);
        const QualitySummary q = summarizeQuality(mesh);
        qInfo("%s: %zu triangles, %d tets, worst dihedral %.2f deg, volume %+.2g %% (inscribed %+.2f %%), "
              "attempts %d, %.2f s",
              qPrintable(file), surface.triangles.size(), q.tets, q.minDihedralDeg, 100.0 * report.volumeError(),
              100.0 * (report.inscribedVolume - surfaceVolume) / surfaceVolume, report.attempts, report.seconds);
        // A coarse simulation mesh.
        QVERIFY2(q.tets >= 200 && q.tets <= 5000, qPrintable(QString::number(q.tets)));
        // Quality, enforced: every dihedral angle at least 10 degrees.
        QVERIFY2(q.minDihedralDeg >= 10.0, qPrintable(QString::number(q.minDihedralDeg)));
        QCOMPARE(report.minDihedralDeg, q.minDihedralDeg);
        // Volume within 2 % of the surface's (matching makes it far closer).
        QVERIFY2(std::abs(q.volume - surfaceVolume) <= 0.02 * surfaceVolume,
                 qPrintable(QString("%1 vs %2").arg(q.volume).arg(surfaceVolume)));
        QVERIFY(std::abs(report.volume - q.volume) <= 1e-12 * surfaceVolume);
        // Masses follow the volume: the total is the surface volume times the density.
        double mass = 0;
        for (const double m : mesh.masses())
            mass += m;
        QVERIFY2(std::abs(mass - AnatomyMeshing{}.material.density * surfaceVolume) <=
                     0.02 * AnatomyMeshing{}.material.density * surfaceVolume,
                 qPrintable(QString::number(mass)));
        // The edge length is what was asked for, not set by the noise.
        QVERIFY2(q.meanEdge >= 0.6 * report.edgeLength && q.meanEdge <= 1.4 * report.edgeLength,
                 qPrintable(QString("mean edge %1, h %2").arg(q.meanEdge).arg(report.edgeLength)));
        QVERIFY2(q.minEdge >= 0.05 * report.edgeLength,
                 qPrintable(QString("shortest edge %1, h %2").arg(q.minEdge).arg(report.edgeLength)));
    }

    void halfTheEdgeLengthGivesFourToSixteenTimesTheTets_data() {
        QTest::addColumn<QString>("file");
        for (const char* f : {"kidney.off", "polyp.stl", "liver_lobe.obj", "femur_head.stl", "myoma.off",
                              "prostate.obj"})
            QTest::newRow(f) << QString(f);
    }
    void halfTheEdgeLengthGivesFourToSixteenTimesTheTets() {
        QFETCH(QString, file);
        TriangleSurface surface;
        const Status read = readSurface(corpusPath(file).toStdString(), surface);
        QVERIFY2(read.ok(), read.message().c_str());
        TetMesh coarse, fine;
        MeshingReport rc, rf;
        meshFile(surface, 0.0, coarse, rc);
        if (QTest::currentTestFailed())
            return;
        meshFile(surface, 0.5 * rc.edgeLength, fine, rf);
        if (QTest::currentTestFailed())
            return;
        const double ratio = double(fine.tetCount()) / coarse.tetCount();
        qInfo("%s: h %.4g -> %d tets, h/2 -> %d tets (x %.2f; worst dihedral %.2f deg, %.2f s)", qPrintable(file),
              rc.edgeLength, coarse.tetCount(), fine.tetCount(), ratio, rf.minDihedralDeg, rf.seconds);
        QVERIFY2(ratio >= 4.0 && ratio <= 16.0, qPrintable(QString::number(ratio)));
        QVERIFY(rf.minDihedralDeg >= 10.0);
        verifyValid(fine);
    }
};

QTEST_GUILESS_MAIN(TestScanCorpus)
#include "test_scan_corpus.moc"
