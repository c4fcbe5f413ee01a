// Trainer export as a library (scenario/trainer_export.h) on a tiny scenario built here (a
// box tet mesh, a box surface, a sweep file cutting off the top, 10 ms of simulation): the
// package holds what its manifest lists with the right sizes and SHA-256; progress rises to
// 1 through the documented stages; cancelling at any stage leaves no package, no temporary
// folder and no folder created for it (a forced export cancelled at the end leaves the old
// package as it was); a non-empty folder without force is refused and untouched; a file as
// the output and a folder holding an input are refused naming them.
#include "scenario/trainer_export.h"

#include "scenario/scenario_load.h"
#include "scenario_test_util.h"
#include "tiny_scenario.h"

#include <QCryptographicHash>
#include <QDir>
#include <QDirIterator>
#include <QFileInfo>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QMap>
#include <QTemporaryDir>
#include <QTest>

using namespace resect;
using resect::test::entries;
using resect::test::readBytes;
using resect::test::writeBytes;
using resect::test::writeTinyScenario;

namespace {

QByteArray sha256Hex(const QString& path) {
    return QCryptographicHash::hash(readBytes(path), QCryptographicHash::Sha256).toHex();
}

/// Every file under `dir` (relative paths, hidden ones included) with its bytes' hash.
QMap<QString, QByteArray> snapshot(const QString& dir) {
    QMap<QString, QByteArray> files;
    QDirIterator it(dir, QDir::Files | QDir::Hidden, QDirIterator::Subdirectories);
    while (it.hasNext()) {
        const QString path = it.next();
        files[QDir(dir).relativeFilePath(path)] = sha256Hex(path);
    }
    return files;
}

} // namespace

class TestTrainerExport : public QObject {
    Q_OBJECT
private slots:
    void packageMatchesItsManifest() {
        QTemporaryDir dir;
        const QString scenario = writeTinyScenario(dir.path());
        const QByteArray before = sha256Hex(scenario);
        const QString out = dir.filePath("package");
        ExportSummary summary;
        QList<double> fractions;
        QStringList stages;
        const Status s = exportTrainerPackage(
            scenario.toStdString(), out.toStdString(), {}, summary,
            [&](double p, const std::string& stage) {
                fractions << p;
                if (stages.isEmpty() || stages.last() != QString::fromStdString(stage))
                    stages << QString::fromStdString(stage);
                return true;
            });
        QVERIFY2(s.ok(), s.message().c_str());
        QCOMPARE(summary.failure, ExportFailure::None);
        QCOMPARE(QString::fromStdString(summary.outDir), QDir(out).absolutePath());
        QVERIFY(summary.expectationsPassed);
        QCOMPARE(summary.run.tissues.size(), std::size_t(1));
        QVERIFY(summary.run.tissues[0].outcome.pieces >= 2);

        // Progress rises from 0 to 1 through the documented stages.
        QCOMPARE(fractions.first(), 0.0);
        QCOMPARE(fractions.last(), 1.0);
        for (int i = 1; i < fractions.size(); ++i)
            QVERIFY2(fractions[i] >= fractions[i - 1], qPrintable(QString::number(i)));
        QCOMPARE(stages,
                 (QStringList{"checking", "meshing:box", "writing:box", "replaying:box",
                              "writing-result:box", "packaging", "manifest", "finishing", "done"}));

        // The manifest lists every other file with its size and hash; the summary every file.
        const QJsonObject manifest =
            QJsonDocument::fromJson(readBytes(out + "/manifest.json")).object();
        QCOMPARE(manifest["format"].toString(), QString("resect-package"));
        QStringList listed;
        for (const QJsonValue& v : manifest["files"].toArray()) {
            const QJsonObject f = v.toObject();
            const QString path = out + "/" + f["path"].toString();
            listed << f["path"].toString();
            QVERIFY2(QFileInfo::exists(path), qPrintable(path));
            QCOMPARE(QFileInfo(path).size(), qint64(f["size"].toDouble()));
            QCOMPARE(sha256Hex(path), f["sha256"].toString().toLatin1());
        }
        const QStringList expected{"box-surface.obj", "box-visual.glb", "box.vtu",
                                   "result/box.glb",  "result/box.vtu", "result/report.json",
                                   "scenario.json",   "sweep-0.json"};
        QCOMPARE(listed, expected);
        QStringList reported;
        for (const std::string& f : summary.files)
            reported << QString::fromStdString(f);
        QCOMPARE(reported, expected + QStringList{"manifest.json"});
        QStringList onDisk = snapshot(out).keys();
        onDisk.sort();
        QStringList all = reported;
        all.sort();
        QCOMPARE(onDisk, all);

        // The packaged scenario loads on its own and refers to the packaged files.
        Scenario packaged;
        ScenarioDiagnostics diag;
        const Status loaded = loadScenario((out + "/scenario.json").toStdString(), packaged, diag);
        QVERIFY2(loaded.ok(), loaded.message().c_str());
        QCOMPARE(packaged.tissues[0].mesh, std::string("box.vtu"));
        QCOMPARE(packaged.sweeps[0].file, std::string("sweep-0.json"));
        // Inputs untouched, nothing else left next to the package.
        QCOMPARE(sha256Hex(scenario), before);
        QCOMPARE(entries(dir.path()),
                 (QStringList{"box.json", "box.obj", "box.vtu", "cut.json", "package"}));
    }

    void cancelLeavesNothing_data() {
        QTest::addColumn<QString>("stage");
        for (const char* stage : {"checking", "meshing:box", "writing:box", "replaying:box",
                                  "writing-result:box", "packaging", "manifest", "finishing"})
            QTest::newRow(stage) << QString(stage);
    }
    void cancelLeavesNothing() {
        QFETCH(QString, stage);
        QTemporaryDir dir;
        const QString scenario = writeTinyScenario(dir.path());
        const QStringList before = entries(dir.path());
        // The package goes into folders that do not exist yet: they go again on cancel.
        const QString out = dir.filePath("new/sub/package");
        ExportSummary summary;
        int calls = 0; // reports of the stage to cancel at
        const Status s =
            exportTrainerPackage(scenario.toStdString(), out.toStdString(), {}, summary,
                                 [&](double, const std::string& now) {
                                     if (QString::fromStdString(now) != stage)
                                         return true;
                                     // The replay is cancelled from inside: at
                                     // its own first report, not at the export's.
                                     return ++calls < (stage == "replaying:box" ? 2 : 1);
                                 });
        QCOMPARE(QString::fromStdString(s.message()), QString("cancelled"));
        QCOMPARE(summary.failure, ExportFailure::Cancelled);
        QVERIFY(summary.files.empty());
        QCOMPARE(entries(dir.path()), before);
    }

    void cancelledForcedExportKeepsTheOldPackage() {
        QTemporaryDir dir;
        const QString scenario = writeTinyScenario(dir.path());
        const QString out = dir.filePath("package");
        ExportSummary summary;
        QVERIFY(exportTrainerPackage(scenario.toStdString(), out.toStdString(), {}, summary).ok());
        writeBytes(out + "/note.txt", "kept");
        const QMap<QString, QByteArray> old = snapshot(out);
        const QStringList before = entries(dir.path());
        ExportOptions force;
        force.force = true;
        const Status s = exportTrainerPackage(
            scenario.toStdString(), out.toStdString(), force, summary,
            [](double, const std::string& stage) { return stage != "finishing"; });
        QCOMPARE(QString::fromStdString(s.message()), QString("cancelled"));
        QCOMPARE(snapshot(out), old);
        QCOMPARE(entries(dir.path()), before);
        // Not cancelled, it replaces the folder as a whole.
        QVERIFY(
            exportTrainerPackage(scenario.toStdString(), out.toStdString(), force, summary).ok());
        QVERIFY(!QFileInfo::exists(out + "/note.txt"));
        QVERIFY(QFileInfo::exists(out + "/manifest.json"));
        QCOMPARE(entries(dir.path()), before);
    }

    void nonEmptyFolderWithoutForceIsRefusedAndUntouched() {
        QTemporaryDir dir;
        const QString scenario = writeTinyScenario(dir.path());
        const QString out = dir.filePath("occupied");
        QVERIFY(QDir(dir.path()).mkdir("occupied"));
        writeBytes(out + "/mine.txt", "do not touch");
        const QMap<QString, QByteArray> old = snapshot(out);
        const QStringList before = entries(dir.path());
        ExportSummary summary;
        const Status s =
            exportTrainerPackage(scenario.toStdString(), out.toStdString(), {}, summary);
        QVERIFY(!s.ok());
        QCOMPARE(summary.failure, ExportFailure::BadInput);
        QVERIFY2(s.message().find(out.toStdString()) != std::string::npos, s.message().c_str());
        QVERIFY2(s.message().find("not empty") != std::string::npos, s.message().c_str());
        QCOMPARE(snapshot(out), old);
        QCOMPARE(entries(dir.path()), before);
    }

    void badOutputsAreRefusedNamingThem() {
        QTemporaryDir dir;
        const QString scenario = writeTinyScenario(dir.path());
        const QStringList before = entries(dir.path());
        ExportSummary summary;
        // A file as the output folder.
        const QString file = dir.filePath("box.obj");
        Status s = exportTrainerPackage(scenario.toStdString(), file.toStdString(), {}, summary);
        QCOMPARE(summary.failure, ExportFailure::BadInput);
        QCOMPARE(QString::fromStdString(s.message()), file + ": exists and is not a folder");
        // The folder holding the scenario, even with force.
        ExportOptions force;
        force.force = true;
        s = exportTrainerPackage(scenario.toStdString(), dir.path().toStdString(), force, summary);
        QCOMPARE(summary.failure, ExportFailure::BadInput);
        QVERIFY2(s.message().find("an input of the scenario") != std::string::npos,
                 s.message().c_str());
        // A scenario file that does not load.
        s = exportTrainerPackage(dir.filePath("missing.json").toStdString(),
                                 dir.filePath("p").toStdString(), {}, summary);
        QCOMPARE(summary.failure, ExportFailure::BadInput);
        QVERIFY2(s.message().find("missing.json") != std::string::npos, s.message().c_str());
        QCOMPARE(entries(dir.path()), before);
    }
};

QTEST_GUILESS_MAIN(TestTrainerExport)
#include "test_trainer_export.moc"
