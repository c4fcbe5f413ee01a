// writeAtomically: the temporary lives next to the target with the same extension, a
// failed write leaves an existing target byte-for-byte unchanged, and no temporary file is
// ever left behind.

#include "scenario/atomic_file.h"

#include <QDir>
#include <QFile>
#include <QTemporaryDir>
#include <QtTest>

#include <filesystem>
#include <fstream>
#include <stdexcept>

using namespace resect;

namespace {

bool writeBytes(const std::string& path, const QByteArray& bytes) {
    QFile f(QString::fromStdString(path));
    return f.open(QIODevice::WriteOnly) && f.write(bytes) == bytes.size();
}

QByteArray readBytes(const QString& path) {
    QFile f(path);
    if (!f.open(QIODevice::ReadOnly))
        return {};
    return f.readAll();
}

/// Every entry of the folder, hidden ones included.
QStringList entries(const QString& dir) {
    return QDir(dir).entryList(QDir::AllEntries | QDir::Hidden | QDir::NoDotAndDotDot, QDir::Name);
}

} // namespace

class TestAtomicFile : public QObject {
    Q_OBJECT

private slots:
    void writesTargetAndLeavesNoTemporary();
    void temporaryIsHiddenSiblingWithSameExtension_data();
    void temporaryIsHiddenSiblingWithSameExtension();
    void replacesExistingTarget();
    void failedWriteKeepsExistingTarget_data();
    void failedWriteKeepsExistingTarget();
    void failedWriteCreatesNothing();
    void renameFailureIsReported();
    void missingFolderIsAnError();
    void directoryTargetIsAnError();
    void writeFileWritesTheBytesExactly();
};

void TestAtomicFile::writesTargetAndLeavesNoTemporary() {
    QTemporaryDir dir;
    QVERIFY(dir.isValid());
    const std::string target = dir.filePath("mesh.vtu").toStdString();
    const Status s = writeAtomically(target, [](const std::string& tmp) {
        return writeBytes(tmp, "payload") ? Status::success() : Status::error("cannot write");
    });
    QVERIFY2(s.ok(), s.message().c_str());
    QCOMPARE(readBytes(dir.filePath("mesh.vtu")), QByteArray("payload"));
    QCOMPARE(entries(dir.path()), QStringList{"mesh.vtu"});
}

void TestAtomicFile::temporaryIsHiddenSiblingWithSameExtension_data() {
    QTest::addColumn<QString>("name");
    QTest::addColumn<QString>("prefix");
    QTest::addColumn<QString>("extension");
    QTest::newRow("vtu") << "mesh.vtu"
                         << ".mesh.tmp-"
                         << ".vtu";
    QTest::newRow("two dots") << "case.final.obj"
                              << ".case.final.tmp-"
                              << ".obj";
    QTest::newRow("no extension") << "README"
                                  << ".README.tmp-"
                                  << "";
}

void TestAtomicFile::temporaryIsHiddenSiblingWithSameExtension() {
    QFETCH(QString, name);
    QFETCH(QString, prefix);
    QFETCH(QString, extension);
    QTemporaryDir dir;
    QVERIFY(dir.isValid());
    const std::string target = dir.filePath(name).toStdString();
    std::string seen;
    bool existedDuringWrite = false;
    const Status s = writeAtomically(target, [&](const std::string& tmp) {
        seen = tmp;
        existedDuringWrite = std::filesystem::exists(tmp);
        return writeBytes(tmp, "x") ? Status::success() : Status::error("cannot write");
    });
    QVERIFY2(s.ok(), s.message().c_str());
    const std::filesystem::path tmp(seen);
    QCOMPARE(tmp.parent_path(), std::filesystem::path(target).parent_path());
    const QString tmpName = QString::fromStdString(tmp.filename().string());
    QVERIFY2(tmpName.startsWith(prefix), qPrintable(tmpName));
    if (!extension.isEmpty())
        QCOMPARE(QString::fromStdString(tmp.extension().string()), extension);
    QVERIFY(tmp.filename() != std::filesystem::path(target).filename());
    QVERIFY(existedDuringWrite);
    QVERIFY(!std::filesystem::exists(tmp));
    QCOMPARE(entries(dir.path()), QStringList{name});
}

void TestAtomicFile::replacesExistingTarget() {
    QTemporaryDir dir;
    QVERIFY(dir.isValid());
    const std::string target = dir.filePath("a.txt").toStdString();
    QVERIFY(writeBytes(target, "old content that is longer"));
    const Status s = writeAtomically(target, [](const std::string& tmp) {
        return writeBytes(tmp, "new") ? Status::success() : Status::error("cannot write");
    });
    QVERIFY2(s.ok(), s.message().c_str());
    QCOMPARE(readBytes(dir.filePath("a.txt")), QByteArray("new"));
    QCOMPARE(entries(dir.path()), QStringList{"a.txt"});
}

void TestAtomicFile::failedWriteKeepsExistingTarget_data() {
    QTest::addColumn<bool>("throws");
    QTest::newRow("returns an error") << false;
    QTest::newRow("throws") << true;
}

void TestAtomicFile::failedWriteKeepsExistingTarget() {
    QFETCH(bool, throws);
    QTemporaryDir dir;
    QVERIFY(dir.isValid());
    const std::string target = dir.filePath("scene.json").toStdString();
    const QByteArray original("{\"keep\": true}\n");
    QVERIFY(writeBytes(target, original));
    const Status s = writeAtomically(target, [&](const std::string& tmp) -> Status {
        writeBytes(tmp, "{\"half"); // a partial file, then failure
        if (throws)
            throw std::runtime_error("disk on fire");
        return Status::error("writer gave up");
    });
    // The error names the target and keeps the writer's reason.
    QVERIFY(!s.ok());
    QVERIFY2(s.message().find(target) != std::string::npos, s.message().c_str());
    const char* reason = throws ? "disk on fire" : "writer gave up";
    QVERIFY2(s.message().find(reason) != std::string::npos, s.message().c_str());
    QCOMPARE(readBytes(dir.filePath("scene.json")), original);
    QCOMPARE(entries(dir.path()), QStringList{"scene.json"});
}

void TestAtomicFile::failedWriteCreatesNothing() {
    QTemporaryDir dir;
    QVERIFY(dir.isValid());
    const std::string target = dir.filePath("new.vtu").toStdString();
    const Status s = writeAtomically(target, [&](const std::string& tmp) {
        writeBytes(tmp, "partial");
        return Status::error(target + ": failed");
    });
    QVERIFY(!s.ok());
    QCOMPARE(s.message(), target + ": failed"); // already names the target: kept as is
    QVERIFY(entries(dir.path()).isEmpty());
}

void TestAtomicFile::renameFailureIsReported() {
    // The writer "succeeds" but removes its file: the rename must fail, be reported with
    // the target's path, and leave the existing target alone.
    QTemporaryDir dir;
    QVERIFY(dir.isValid());
    const std::string target = dir.filePath("out.obj").toStdString();
    QVERIFY(writeBytes(target, "old"));
    const Status s = writeAtomically(target, [](const std::string& tmp) {
        std::filesystem::remove(tmp);
        return Status::success();
    });
    QVERIFY(!s.ok());
    QVERIFY2(s.message().find(target) != std::string::npos, s.message().c_str());
    QCOMPARE(readBytes(dir.filePath("out.obj")), QByteArray("old"));
    QCOMPARE(entries(dir.path()), QStringList{"out.obj"});
}

void TestAtomicFile::missingFolderIsAnError() {
    QTemporaryDir dir;
    QVERIFY(dir.isValid());
    const std::string target = dir.filePath("no/such/folder/out.vtu").toStdString();
    bool called = false;
    const Status s = writeAtomically(target, [&](const std::string&) {
        called = true;
        return Status::success();
    });
    QVERIFY(!s.ok());
    QVERIFY(!called);
    QVERIFY2(s.message().find(target) != std::string::npos, s.message().c_str());
    QVERIFY(entries(dir.path()).isEmpty());
}

void TestAtomicFile::directoryTargetIsAnError() {
    QTemporaryDir dir;
    QVERIFY(dir.isValid());
    QVERIFY(QDir(dir.path()).mkdir("sub.vtu"));
    const std::string target = dir.filePath("sub.vtu").toStdString();
    const Status s = writeAtomically(target, [](const std::string& tmp) {
        return writeBytes(tmp, "x") ? Status::success() : Status::error("cannot write");
    });
    QVERIFY(!s.ok());
    QVERIFY2(s.message().find(target) != std::string::npos, s.message().c_str());
    QVERIFY(QFileInfo(dir.filePath("sub.vtu")).isDir());
    QCOMPARE(entries(dir.path()), QStringList{"sub.vtu"});
}

void TestAtomicFile::writeFileWritesTheBytesExactly() {
    QTemporaryDir dir;
    QVERIFY(dir.isValid());
    const QString target = dir.filePath("report.json");
    QVERIFY(writeBytes(target.toStdString(), "old"));
    // Binary-safe: an embedded NUL and a CR LF come out as given, replacing the old file.
    const std::string bytes("a\0b\r\nc", 6);
    const Status s = writeFileAtomically(target.toStdString(), bytes);
    QVERIFY2(s.ok(), s.message().c_str());
    QCOMPARE(readBytes(target), QByteArray(bytes.data(), int(bytes.size())));
    QCOMPARE(entries(dir.path()), QStringList{"report.json"});
    // Into a missing folder: an error naming the file, nothing written.
    const std::string missing = dir.filePath("no/such/out.json").toStdString();
    const Status bad = writeFileAtomically(missing, bytes);
    QVERIFY(!bad.ok());
    QVERIFY2(bad.message().find(missing) != std::string::npos, bad.message().c_str());
    QCOMPARE(entries(dir.path()), QStringList{"report.json"});
}

QTEST_GUILESS_MAIN(TestAtomicFile)
#include "test_atomic_file.moc"
