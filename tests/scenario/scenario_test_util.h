#pragma once
// Small helpers shared by the scenario tests: file bytes, folder listings, capturing what
// a library prints on stderr, and a hand-built tet mesh with known pieces.

#include "core/mesh/tet_mesh.h"

#include <QByteArray>
#include <QDir>
#include <QFile>
#include <QString>
#include <QStringList>
#include <QTemporaryFile>

#include <cmath>
#include <cstdio>
#include <string>
#include <unistd.h>

namespace resect::test {

inline bool writeBytes(const QString& path, const QByteArray& bytes) {
    QFile f(path);
    return f.open(QIODevice::WriteOnly | QIODevice::Truncate) && f.write(bytes) == bytes.size();
}

inline QByteArray readBytes(const QString& path) {
    QFile f(path);
    if (!f.open(QIODevice::ReadOnly))
        return {};
    return f.readAll();
}

/// Every entry of the folder, hidden ones included, sorted by name.
inline QStringList entries(const QString& dir) {
    return QDir(dir).entryList(QDir::AllEntries | QDir::Hidden | QDir::NoDotAndDotDot, QDir::Name);
}

/// Redirects file descriptor 2 into a temporary file while alive; text() returns what was
/// written (C stdio, std::cerr and direct writes alike).
class StderrCapture {
public:
    StderrCapture() {
        if (!m_file.open())
            return;
        std::fflush(stderr);
        m_saved = dup(2);
        dup2(m_file.handle(), 2);
    }
    ~StderrCapture() { restore(); }
    QByteArray text() {
        restore();
        m_file.seek(0);
        return m_file.readAll();
    }

private:
    void restore() {
        if (m_saved < 0)
            return;
        std::fflush(stderr);
        dup2(m_saved, 2);
        close(m_saved);
        m_saved = -1;
    }
    QTemporaryFile m_file;
    int m_saved = -1;
};

/// The same nodes (reference and current positions, velocities, masses) and tets in the same
/// order, every double bit for bit.
inline bool sameMesh(const TetMesh& a, const TetMesh& b) {
    if (a.nodeCount() != b.nodeCount() || a.tets() != b.tets())
        return false;
    for (int n = 0; n < a.nodeCount(); ++n)
        if (a.referencePositions()[n] != b.referencePositions()[n] ||
            a.positions()[n] != b.positions()[n] || a.velocities()[n] != b.velocities()[n] ||
            a.masses()[n] != b.masses()[n])
            return false;
    return true;
}

/// Three positively oriented tets in two pieces: tets 0 and 1 share the face (1, 2, 3);
/// tet 2 is a separate unit corner tet at x = 5. Current positions are moved away from the
/// reference, and velocities and masses are values that need all 17 digits.
inline TetMesh makeSampleMesh() {
    std::vector<Vec3> ref{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}, {1, 1, 1},
                          {5, 0, 0}, {6, 0, 0}, {5, 1, 0}, {5, 0, 1}};
    std::vector<Tet> tets{{0, 1, 2, 3}, {1, 2, 3, 4}, {5, 6, 7, 8}};
    TetMesh mesh = TetMesh::fromArrays(ref, tets);
    for (int n = 0; n < mesh.nodeCount(); ++n) {
        const double s = std::sqrt(2.0 + n);
        mesh.positions()[n] = ref[n] + Vec3(0.1 * s, -0.01 / s, 1e-9 * s);
        mesh.velocities()[n] = Vec3(s, -1.0 / s, std::cbrt(s));
        mesh.masses()[n] = 1e-4 * s;
    }
    return mesh;
}

} // namespace resect::test
