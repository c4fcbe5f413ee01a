// `resect run` and `resect export` end to end on the bundled polyp scenario, sped up (its
// strokes' time stamps divided by 20 and a short simulation after them) so that the test stays
// short: expectations pass (exit 0) or fail (exit 3), bad documents give exit 2 with the JSON
// path, two runs report the same apart from timings, and an exported package holds what its
// manifest lists (hashes checked), is read back by independent readers (VTK for .vtu, assimp
// for .glb) and replays to the same result.
#include "cli_runner.h"

#include "scenario/scenario_run.h"

#include <QDir>
#include <QFile>
#include <QJsonArray>
#include <QJsonDocument>
#include <QTemporaryDir>
#include <QTest>

#include <string>

#include <assimp/Importer.hpp>
#include <assimp/scene.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkUnstructuredGrid.h>
#include <vtkXMLUnstructuredGridReader.h>

using namespace resect;
using namespace resect::testing;

namespace {

void writeJsonFile(const QString& path, const QJsonObject& o) {
    QFile f(path);
    if (!f.open(QIODevice::WriteOnly))
        qFatal("cannot write %s", qPrintable(path));
    f.write(QJsonDocument(o).toJson());
}

/// The bundled polyp scenario, sped up, written to `dir`; `edit` changes it further.
QString fastPolyp(const QString& dir, const std::function<void(QJsonObject&)>& edit = {}) {
    QJsonObject s = readJsonFile(QString(RESECT_SOURCE_DIR) + "/resources/scenarios/polyp-resection.json");
    QJsonArray strokes = s["strokes"].toArray();
    for (int i = 0; i < strokes.size(); ++i) {
        QJsonObject stroke = strokes[i].toObject();
        QJsonArray poses = stroke["poses"].toArray();
        for (int k = 0; k < poses.size(); ++k) {
            QJsonObject pose = poses[k].toObject();
            pose["t"] = pose["t"].toDouble() / 20;
            poses[k] = pose;
        }
        stroke["poses"] = poses;
        strokes[i] = stroke;
    }
    s["strokes"] = strokes;
    QJsonObject sim = s["simulation"].toObject();
    sim["duration"] = 0.01;
    s["simulation"] = sim;
    if (edit)
        edit(s);
    const QString path = dir + "/polyp.json";
    writeJsonFile(path, s);
    return path;
}

} // namespace

class TestCliRun : public QObject {
    Q_OBJECT
private slots:
    void runPassesAndReportsTheSameTwice() {
        QTemporaryDir dir;
        const QString scenario = fastPolyp(dir.path());
        const QByteArray before = sha256(scenario);
        const Run a = runCli({"run", scenario, "--report", dir.filePath("a.json")});
        QVERIFY2(a.code == 0, qPrintable(a.out + a.err));
        QVERIFY(a.out.contains("PASS pieces_at_least"));
        const Run b = runCli({"run", scenario, "--report", dir.filePath("b.json")});
        QCOMPARE(b.code, 0);
        const QJsonObject ra = readJsonFile(dir.filePath("a.json")), rb = readJsonFile(dir.filePath("b.json"));
        QVERIFY(ra["passed"].toBool());
        const QJsonObject tissue = ra["tissues"].toArray()[0].toObject();
        QVERIFY(tissue["pieces"].toInt() >= 2);
        QVERIFY(tissue["steps"].toDouble() > 0);
        QVERIFY(tissue["finite"].toBool());
        QCOMPARE(tissue["effects"].toArray().size(), 5);  // only the declared effects
        QCOMPARE(stripTimings(ra), stripTimings(rb));
        QCOMPARE(sha256(scenario), before);  // the input is untouched
    }

    /// The bundled ten-scoop resection (issue 15): every pass cuts the tets and the embedded
    /// surface, and the run meets its expectations.
    void tenScoopResectionReplays() {
        QTemporaryDir dir;
        const QString report = dir.filePath("report.json");
        const Run r = runCli({"run", QString(RESECT_SOURCE_DIR) + "/resources/scenarios/polyp-resection-10.json",
                              "--report", report});
        QVERIFY2(r.code == 0, qPrintable(r.err + r.out));
        const QJsonObject rep = readJsonFile(report);
        QVERIFY(rep["passed"].toBool());
        const QJsonObject tissue = rep["tissues"].toArray().first().toObject();
        QVERIFY(tissue["pieces"].toInt() >= 4);
        QCOMPARE(tissue["inverted"].toInt(), 0);
        QVERIFY(tissue["cut"].toObject()["surface_cap_triangles"].toInt() > 0);
    }

    void failingExpectationExitsWith3() {
        QTemporaryDir dir;
        const QString scenario = fastPolyp(dir.path(), [](QJsonObject& s) {
            QJsonArray e = s["expectations"].toArray();
            e.append(QJsonObject{{"kind", "pieces_at_least"}, {"value", 50}});
            s["expectations"] = e;
        });
        const Run r = runCli({"run", scenario});
        QCOMPARE(r.code, 3);
        QVERIFY(r.out.contains("FAIL pieces_at_least"));
    }

    void badDocumentsExitWith2NamingThePath_data() {
        QTest::addColumn<QString>("json");
        QTest::addColumn<QString>("expected");
        QTest::newRow("truncated") << R"({"format": "resect-scenario", "version": 1, "tissues": [)" << "polyp.json";
        QTest::newRow("negative density")
            << R"({"format": "resect-scenario", "version": 1, "tissues": [{"name": "a", "surface": "sample:polyp",
                   "material": {"density": -1}}]})"
            << "tissues[0].material.density";
        QTest::newRow("missing surface file")
            << R"({"format": "resect-scenario", "version": 1, "tissues": [{"name": "a", "surface": "nowhere.obj"}]})"
            << "tissues[0].surface";
        QTest::newRow("unknown version") << R"({"format": "resect-scenario", "version": 99, "tissues": []})" << "version";
    }
    void badDocumentsExitWith2NamingThePath() {
        QFETCH(QString, json);
        QFETCH(QString, expected);
        QTemporaryDir dir;
        QFile f(dir.filePath("polyp.json"));
        QVERIFY(f.open(QIODevice::WriteOnly));
        f.write(json.toUtf8());
        f.close();
        const Run r = runCli({"run", dir.filePath("polyp.json")});
        QCOMPARE(r.code, 2);
        QVERIFY2(r.err.contains(expected), qPrintable(r.err));
    }

    void exportedPackageIsCompleteAndReplaysTheSame() {
        QTemporaryDir dir;
        const QString scenario = fastPolyp(dir.path());
        const QString out = dir.filePath("package");
        const Run e = runCli({"export", scenario, "--out", out});
        QVERIFY2(e.code == 0, qPrintable(e.out + e.err));
        // The manifest lists every other file with its size and hash.
        const QJsonObject manifest = readJsonFile(out + "/manifest.json");
        QStringList listed;
        for (const QJsonValue& v : manifest["files"].toArray()) {
            const QJsonObject f = v.toObject();
            const QString path = out + "/" + f["path"].toString();
            listed << f["path"].toString();
            QVERIFY2(QFile::exists(path), qPrintable(path));
            QCOMPARE(QFileInfo(path).size(), qint64(f["size"].toDouble()));
            QCOMPARE(sha256(path).toHex(), f["sha256"].toString().toLatin1());
        }
        for (const char* must : {"scenario.json", "polyp.vtu", "polyp-visual.glb", "result/polyp.vtu",
                                    "result/polyp.glb", "result/report.json"})
            QVERIFY2(listed.contains(must), qPrintable(QString::fromLatin1(must) + " missing from " + listed.join(", ")));
        // Independent readers: VTK for the meshes, assimp for the surfaces.
        for (const char* vtu : {"polyp.vtu", "result/polyp.vtu"}) {
            vtkNew<vtkXMLUnstructuredGridReader> reader;
            reader->SetFileName(qPrintable(out + "/" + vtu));
            reader->Update();
            // The input polyp has 889 tets; the result is what remains after the chips left.
            QVERIFY(reader->GetOutput()->GetNumberOfCells() > (std::string(vtu) == "polyp.vtu" ? 800 : 300));
            QVERIFY(reader->GetOutput()->GetPointData()->GetArray("reference_position"));
        }
        for (const char* glb : {"polyp-visual.glb", "result/polyp.glb"}) {
            Assimp::Importer importer;
            const aiScene* s = importer.ReadFile(qPrintable(out + "/" + glb), 0);
            QVERIFY2(s && s->mNumMeshes >= 1, glb);
            QVERIFY(s->mMeshes[0]->HasTextureCoords(0));
            QVERIFY(s->mMeshes[0]->mNumFaces > 1000);
        }
        // The package replays to the recorded result.
        const Run r = runCli({"run", out + "/scenario.json", "--report", dir.filePath("replayed.json")});
        QVERIFY2(r.code == 0, qPrintable(r.out + r.err));
        QJsonObject recorded = stripTimings(readJsonFile(out + "/result/report.json"));
        QJsonObject replayed = stripTimings(readJsonFile(dir.filePath("replayed.json")));
        recorded.remove("scenario");
        replayed.remove("scenario");
        QCOMPARE(replayed, recorded);

        // A non-empty folder is refused without --force, and replaced with it.
        const Run again = runCli({"export", scenario, "--out", out});
        QCOMPARE(again.code, 2);
        QVERIFY(again.err.contains("--force"));
        const Run forced = runCli({"export", scenario, "--out", out, "--force"});
        QVERIFY2(forced.code == 0, qPrintable(forced.err));
        QVERIFY(QFile::exists(out + "/manifest.json"));
        // Never into a folder holding an input.
        const Run inputs = runCli({"export", scenario, "--out", dir.path(), "--force"});
        QCOMPARE(inputs.code, 2);
        QVERIFY(QFile::exists(scenario));
    }
};

QTEST_GUILESS_MAIN(TestCliRun)
#include "test_cli_run.moc"
