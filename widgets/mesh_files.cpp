#include "widgets/mesh_files.h"

#include <QCoreApplication>
#include <QFile>
#include <QFileInfo>
#include <QMetaObject>
#include <QPointer>

namespace resect {
namespace {

QString patterns(std::string_view extensions) {
    QString out;
    for (const QString& ext : QString::fromUtf8(extensions.data(), qsizetype(extensions.size()))
                                  .split(QLatin1Char(' '), Qt::SkipEmptyParts))
        out += (out.isEmpty() ? QString() : QStringLiteral(" ")) + QLatin1Char('*') + ext;
    return out;
}

QString saveFilter(const MeshFormatInfo& f) {
    return QString::fromUtf8(f.name.data(), qsizetype(f.name.size())) + QStringLiteral(" (") +
           patterns(f.extensions) + QLatin1Char(')');
}

} // namespace

QString tetMeshOpenFilter() {
    QStringList all;
    for (const MeshFormatInfo& f : meshFormats())
        for (const QString& p : patterns(f.extensions).split(QLatin1Char(' ')))
            if (!all.contains(p))
                all << p;
    return QCoreApplication::translate("resect::MeshFiles", "Tet meshes (%1)").arg(all.join(QLatin1Char(' ')));
}

QString tetMeshOpenFilters() {
    QStringList filters{tetMeshOpenFilter()};
    for (const MeshFileFamily& f : meshFileFamilies())
        filters << QString::fromUtf8(f.name.data(), qsizetype(f.name.size())) + QStringLiteral(" (") +
                       patterns(f.extensions) + QLatin1Char(')');
    return filters.join(QStringLiteral(";;"));
}

QStringList tetMeshSaveFilters() {
    QStringList filters;
    for (const MeshFormatInfo& f : meshFormats())
        filters << saveFilter(f);
    return filters;
}

std::optional<MeshFormat> formatOfSaveFilter(const QString& filter) {
    for (const MeshFormatInfo& f : meshFormats())
        if (saveFilter(f) == filter)
            return f.format;
    return std::nullopt;
}

QString withMeshExtension(const QString& path, MeshFormat format) {
    const MeshFormatInfo& f = meshFormatInfo(format);
    const QString suffix = QLatin1Char('.') + QFileInfo(path).suffix().toLower();
    const QStringList extensions =
        QString::fromUtf8(f.extensions.data(), qsizetype(f.extensions.size())).split(QLatin1Char(' '));
    if (extensions.contains(suffix))
        return path;
    return path + extensions.front();
}

MeshFileWriter::MeshFileWriter(QObject* parent) : QObject(parent) {}

MeshFileWriter::~MeshFileWriter() {
    if (m_thread.joinable())
        m_thread.join();
}

bool MeshFileWriter::start(std::shared_ptr<const TetMesh> mesh, const QString& path, MeshFormat format) {
    if (m_running || !mesh)
        return false;
    if (m_thread.joinable())
        m_thread.join();
    m_running = true;
    QPointer<MeshFileWriter> self(this);
    const std::string file = QFile::encodeName(path).toStdString();
    m_thread = std::thread([self, mesh = std::move(mesh), file, path, format] {
        const Status s = writeTetMesh(file, *mesh, format);
        const bool ok = s.ok();
        const QString message = ok ? path : QString::fromStdString(s.message());
        // Back on the writer's thread; the destructor joins, so `self` is alive here, but
        // the queued call may arrive after it is gone: QPointer guards that.
        QMetaObject::invokeMethod(
            QCoreApplication::instance(),
            [self, ok, message] {
                if (!self)
                    return;
                self->m_running = false;
                emit self->finished(ok, message);
            },
            Qt::QueuedConnection);
    });
    return true;
}

} // namespace resect
