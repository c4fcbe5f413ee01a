// ExportRunner (widgets/export_runner.h) on the tiny scenario of tests/scenario/tiny_scenario.h:
// start() returns at once with the export running on another thread, progress arrives on the
// GUI thread rising to 100, finished(true) lists the package's files, which exist; cancel()
// right after start() gives finished(false) and no folder at all; a file as the output gives
// a message naming it; a second start() while running is refused; the progress dialog's
// Cancel button cancels and the dialog goes away; destroying a running runner cancels it
// and leaves nothing behind.
#include "widgets/export_runner.h"

#include "../scenario/tiny_scenario.h"

#include <QApplication>
#include <QDir>
#include <QFileInfo>
#include <QPointer>
#include <QProgressDialog>
#include <QPushButton>
#include <QSignalSpy>
#include <QTemporaryDir>
#include <QTest>
#include <QThread>

using namespace resect;

namespace {

constexpr int kTimeoutMs = 120'000;
// Simulated seconds for the tests that cancel a running export: the replay takes far longer
// than the test takes to cancel (checked every 64 steps), so the export is still running when
// the cancel comes. With the default 0.01 s it could finish first under load, and then
// rightly report success (seen: progressDialogCancelButtonCancels, about 1 run in 4 under a
// parallel ctest).
constexpr double kLongRun = 100;

QStringList entries(const QString& dir) {
    return QDir(dir).entryList(QDir::AllEntries | QDir::Hidden | QDir::NoDotAndDotDot, QDir::Name);
}

} // namespace

class TestExportRunner : public QObject {
    Q_OBJECT
private slots:
    void exportsOnAWorkerThread() {
        QTemporaryDir dir;
        const QString scenario = test::writeTinyScenario(dir.path());
        const QString out = dir.filePath("package");
        ExportRunner runner;
        QList<int> percents;
        bool onGuiThread = true;
        connect(&runner, &ExportRunner::progress, this, [&](int percent, const QString& stage) {
            percents << percent;
            onGuiThread = onGuiThread && QThread::currentThread() == qApp->thread();
            QVERIFY(!stage.isEmpty());
        });
        QSignalSpy finished(&runner, &ExportRunner::finished);
        QVERIFY(runner.start(scenario, out));
        QVERIFY(runner.isRunning()); // start() did not wait for the export
        QVERIFY(!runner.start(scenario, dir.filePath("other"))); // one at a time
        QTRY_COMPARE_WITH_TIMEOUT(finished.count(), 1, kTimeoutMs);
        QVERIFY(!runner.isRunning());
        const QList<QVariant> result = finished.takeFirst();
        QVERIFY2(result[0].toBool(), qPrintable(result[1].toString()));
        QVERIFY2(result[1].toString().contains(QDir(out).absolutePath()),
                 qPrintable(result[1].toString()));
        const QStringList files = result[2].toStringList();
        QCOMPARE(files.size(), 9);
        QCOMPARE(QFileInfo(files.last()).fileName(), QString("manifest.json"));
        for (const QString& f : files)
            QVERIFY2(QFileInfo(f).isFile() &&
                         QFileInfo(f).absolutePath().startsWith(QDir(out).absolutePath()),
                     qPrintable(f));
        QVERIFY(onGuiThread);
        QVERIFY(!percents.isEmpty());
        QCOMPARE(percents.last(), 100);
        for (int i = 1; i < percents.size(); ++i)
            QVERIFY(percents[i] >= percents[i - 1]);
        QCOMPARE(runner.summary().failure, ExportFailure::None);
        QVERIFY(runner.summary().expectationsPassed);
        QVERIFY(!QDir(dir.path()).exists("other"));
        QCOMPARE(entries(dir.path()),
                 (QStringList{"box.json", "box.obj", "box.vtu", "cut.json", "package"}));
    }

    void cancelRightAfterStartLeavesNoFolder() {
        QTemporaryDir dir;
        const QString scenario = test::writeTinyScenario(dir.path(), kLongRun);
        const QStringList before = entries(dir.path());
        const QString out = dir.filePath("package");
        ExportRunner runner;
        QSignalSpy finished(&runner, &ExportRunner::finished);
        QVERIFY(runner.start(scenario, out));
        runner.cancel();
        QTRY_COMPARE_WITH_TIMEOUT(finished.count(), 1, kTimeoutMs);
        const QList<QVariant> result = finished.takeFirst();
        QVERIFY(!result[0].toBool());
        QVERIFY(result[2].toStringList().isEmpty());
        QCOMPARE(runner.summary().failure, ExportFailure::Cancelled);
        QVERIFY(!QFileInfo::exists(out));
        QCOMPARE(entries(dir.path()), before); // no temporary folder either
        // The runner is reusable afterwards (on the short scenario: this one runs to the end).
        QTemporaryDir shortDir;
        QVERIFY(runner.start(test::writeTinyScenario(shortDir.path()), out));
        QTRY_COMPARE_WITH_TIMEOUT(finished.count(), 1, kTimeoutMs);
        QVERIFY(finished.takeFirst()[0].toBool());
        QVERIFY(QFileInfo(out).isDir());
    }

    void fileAsOutputIsNamed() {
        QTemporaryDir dir;
        const QString scenario = test::writeTinyScenario(dir.path());
        const QString file = dir.filePath("box.obj");
        ExportRunner runner;
        QSignalSpy finished(&runner, &ExportRunner::finished);
        QVERIFY(runner.start(scenario, file));
        QTRY_COMPARE_WITH_TIMEOUT(finished.count(), 1, kTimeoutMs);
        const QList<QVariant> result = finished.takeFirst();
        QVERIFY(!result[0].toBool());
        QVERIFY2(result[1].toString().contains(file) &&
                     result[1].toString().contains("not a folder"),
                 qPrintable(result[1].toString()));
        QCOMPARE(runner.summary().failure, ExportFailure::BadInput);
    }

    void progressDialogCancelButtonCancels() {
        QTemporaryDir dir;
        const QString scenario = test::writeTinyScenario(dir.path(), kLongRun);
        const QStringList before = entries(dir.path());
        ExportRunner runner;
        QSignalSpy finished(&runner, &ExportRunner::finished);
        QVERIFY(!runner.showProgressDialog(nullptr)); // nothing running
        QVERIFY(runner.start(scenario, dir.filePath("package")));
        QPointer<QProgressDialog> dialog = runner.showProgressDialog(nullptr);
        QVERIFY(dialog);
        QCOMPARE(dialog->objectName(), QString("exportProgressDialog"));
        QCOMPARE(dialog->maximum(), 100);
        QPushButton* cancel = dialog->findChild<QPushButton*>();
        QVERIFY(cancel);
        cancel->click();
        QTRY_COMPARE_WITH_TIMEOUT(finished.count(), 1, kTimeoutMs);
        QVERIFY(!finished.takeFirst()[0].toBool());
        QTRY_VERIFY(dialog.isNull()); // closed and deleted
        QCOMPARE(entries(dir.path()), before);
    }

    void stageTextsAreReadable() {
        QCOMPARE(ExportRunner::stageText("replaying:polyp"),
                 QString("Replaying the strokes on polyp..."));
        QCOMPARE(ExportRunner::stageText("meshing:a:b"), QString("Meshing a:b..."));
        QCOMPARE(ExportRunner::stageText("something-new"), QString("something-new"));
    }

    void destroyingARunningRunnerCancels() {
        QTemporaryDir dir;
        const QString scenario = test::writeTinyScenario(dir.path(), kLongRun);
        const QStringList before = entries(dir.path());
        {
            ExportRunner runner;
            QVERIFY(runner.start(scenario, dir.filePath("package")));
        }
        QCOMPARE(entries(dir.path()), before);
        QCoreApplication::processEvents(); // the dropped reports must not reach anything
    }
};

QTEST_MAIN(TestExportRunner)
#include "test_export_runner.moc"
