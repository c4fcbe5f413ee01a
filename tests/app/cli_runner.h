#pragma once
// Running the real `resect` binary from tests: exit code (-2 if it crashed), stdout, stderr.
#include <QCryptographicHash>
#include <QFile>
#include <QProcess>
#include <QJsonDocument>
#include <QJsonObject>
#include <QString>
#include <QStringList>

namespace resect::testing {

struct Run {
    int code = -1;
    QString out;
    QString err;
};

inline Run runCli(const QStringList& args, int timeoutMs = 600000) {
    QProcess p;
    p.start(RESECT_CLI, args);
    Run r;
    if (!p.waitForFinished(timeoutMs)) {
        p.kill();
        r.err = "timed out";
        return r;
    }
    r.code = p.exitStatus() == QProcess::NormalExit ? p.exitCode() : -2;
    r.out = QString::fromUtf8(p.readAllStandardOutput());
    r.err = QString::fromUtf8(p.readAllStandardError());
    return r;
}

/// SHA-256 of a file's bytes (empty if unreadable): to check that inputs stay untouched.
inline QByteArray sha256(const QString& path) {
    QFile f(path);
    return f.open(QIODevice::ReadOnly) ? QCryptographicHash::hash(f.readAll(), QCryptographicHash::Sha256) : QByteArray();
}

/// The non-empty lines of a text file (none if it cannot be read).
inline QStringList readLines(const QString& path) {
    QFile f(path);
    if (!f.open(QIODevice::ReadOnly))
        return {};
    return QString::fromUtf8(f.readAll()).split('\n', Qt::SkipEmptyParts);
}

/// Writes `bytes` to a file, replacing it; false if it cannot.
inline bool writeFile(const QString& path, const QByteArray& bytes) {
    QFile f(path);
    return f.open(QIODevice::WriteOnly) && f.write(bytes) == bytes.size();
}

/// The JSON object in a file (empty if it cannot be read).
inline QJsonObject readJsonFile(const QString& path) {
    QFile f(path);
    if (!f.open(QIODevice::ReadOnly))
        return {};
    return QJsonDocument::fromJson(f.readAll()).object();
}

} // namespace resect::testing
