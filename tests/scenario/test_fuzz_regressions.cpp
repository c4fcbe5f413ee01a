// The fuzz harnesses (fuzz/fuzz_inputs.h) without libFuzzer: every file of fuzz/corpus/<target>/
// (the seeds) and tests/fuzz_regressions/<target>/ (inputs that once crashed, hung or broke
// an invariant) is fed to the target named by its folder. Each must give a clean error that
// names the file or a result that passes the target's invariant checks, and print nothing.

#include "fuzz/fuzz_inputs.h"

#include "scenario_test_util.h"

#include <QDir>
#include <QDirIterator>
#include <QtTest>

using namespace resect;
using namespace resect::test;

namespace {

const QString kCorpus = QStringLiteral(RESECT_SOURCE_DIR "/fuzz/corpus");
const QString kRegressions = QStringLiteral(RESECT_SOURCE_DIR "/tests/fuzz_regressions");

/// Sub-folders of `root` (one per target).
QStringList targetFolders(const QString& root) {
    return QDir(root).entryList(QDir::Dirs | QDir::NoDotAndDotDot, QDir::Name);
}

QStringList filesOf(const QString& folder) {
    QStringList files;
    QDirIterator it(folder, QDir::Files | QDir::Hidden, QDirIterator::Subdirectories);
    while (it.hasNext())
        files << it.next();
    files.sort();
    return files;
}

} // namespace

class TestFuzzRegressions : public QObject {
    Q_OBJECT

private slots:
    void everyTargetHasSeeds();
    void everyFolderNamesATarget();
    void inputs_data();
    void inputs();
};

void TestFuzzRegressions::everyTargetHasSeeds() {
    const std::vector<fuzz::Target> all = fuzz::targets();
    QVERIFY(all.size() >= 10); // sweep, vtu, msh, tetgen, six surface formats
    for (const fuzz::Target& t : all) {
        const QString folder = kCorpus + "/" + t.name;
        QVERIFY2(!filesOf(folder).isEmpty(), qPrintable("no seeds in " + folder));
        // The seeds are valid files: each must be read.
        for (const QString& file : filesOf(folder)) {
            const QByteArray bytes = readBytes(file);
            const fuzz::Outcome o = t.run({reinterpret_cast<const std::uint8_t*>(bytes.data()),
                                           static_cast<std::size_t>(bytes.size())});
            QVERIFY2(o.kind == fuzz::Outcome::Kind::Accepted,
                     qPrintable(file + ": " + QString::fromStdString(o.message)));
        }
    }
}

void TestFuzzRegressions::everyFolderNamesATarget() {
    for (const QString& root : {kCorpus, kRegressions})
        for (const QString& name : targetFolders(root))
            QVERIFY2(fuzz::findTarget(name.toStdString()),
                     qPrintable(root + "/" + name + " is not a fuzz target's name"));
}

void TestFuzzRegressions::inputs_data() {
    QTest::addColumn<QString>("target");
    QTest::addColumn<QString>("file");
    for (const QString& root : {kCorpus, kRegressions})
        for (const QString& target : targetFolders(root))
            for (const QString& file : filesOf(root + "/" + target))
                QTest::newRow(qPrintable(QDir(RESECT_SOURCE_DIR).relativeFilePath(file)))
                    << target << file;
}

void TestFuzzRegressions::inputs() {
    QFETCH(QString, target);
    QFETCH(QString, file);
    const fuzz::Target* t = fuzz::findTarget(target.toStdString());
    QVERIFY(t);
    const QByteArray bytes = readBytes(file);
    StderrCapture stderrText;
    const fuzz::Outcome o = t->run({reinterpret_cast<const std::uint8_t*>(bytes.data()),
                                    static_cast<std::size_t>(bytes.size())});
    const QByteArray printed = stderrText.text();
    QVERIFY2(o.kind != fuzz::Outcome::Kind::Broken, o.message.c_str());
    QVERIFY2(printed.isEmpty(), printed.constData());
    if (o.kind == fuzz::Outcome::Kind::Rejected)
        qDebug("%s", o.message.c_str());
}

QTEST_GUILESS_MAIN(TestFuzzRegressions)
#include "test_fuzz_regressions.moc"
