#pragma once
// Tet mesh files in the studio (issue 21): the file dialogs' filters, built from the one
// list of formats (scenario/mesh_io.h meshFormats()), and MeshFileWriter, which writes a
// copy of a mesh on a worker thread ("Export mesh as...").

#include "scenario/mesh_io.h"

#include <QObject>
#include <QString>
#include <QStringList>

#include <memory>
#include <optional>
#include <thread>

namespace resect {

/// "Tet meshes (*.vtu *.msh *.vtk *.mesh *.node *.ele)" (translated name, every readable
/// extension), for the Open and Import dialogs.
QString tetMeshOpenFilter();
/// tetMeshOpenFilter(), then one filter per format by name ("Gmsh 2.2 and 4.1, ASCII and
/// binary (*.msh)", ...), joined with ";;" for a file dialog.
QString tetMeshOpenFilters();
/// One filter per writable format, by name: "Gmsh 4.1 ASCII (*.msh)", ... (meshFormats()
/// order, the project's .vtu first).
QStringList tetMeshSaveFilters();
/// The format of a filter from tetMeshSaveFilters(), or nothing.
std::optional<MeshFormat> formatOfSaveFilter(const QString& filter);
/// `path` as written in `format`: unchanged if its extension is one of the format's, else
/// with the format's first extension appended ("liver" -> "liver.msh").
QString withMeshExtension(const QString& path, MeshFormat format);

/// Writes tet meshes on a worker thread, one at a time. The mesh is copied by the caller
/// (a shared pointer to a copy), so the studio can go on cutting and simulating. The write
/// is atomic (a failed or abandoned write leaves the target as it was). Destroying the
/// writer waits for a running write.
class MeshFileWriter : public QObject {
    Q_OBJECT
public:
    explicit MeshFileWriter(QObject* parent = nullptr);
    ~MeshFileWriter() override;

    /// Starts writing; false (and nothing happens) if a write is running.
    bool start(std::shared_ptr<const TetMesh> mesh, const QString& path, MeshFormat format);
    bool isRunning() const { return m_running; }

signals:
    /// On the writer's thread. ok: `message` is the path written; else why not.
    void finished(bool ok, const QString& message);

private:
    std::thread m_thread;
    bool m_running = false;
};

} // namespace resect
