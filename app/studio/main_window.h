#pragma once
// MainWindow: the studio's main window. Thin: a VtkViewport in the middle, a status bar
// with the mesh summary, and File > Open / Quit. Loading and meshing run on a worker
// thread; the result comes back to the GUI thread through a queued call.

#include "core/mesh/quality.h"
#include "core/mesh/tet_mesh.h"
#include "core/mesher/samples.h"

#include <QMainWindow>
#include <QString>

#include <atomic>
#include <thread>

class QAction;
class QLabel;
class QProgressDialog;

namespace resect {

class VtkViewport;

class MainWindow : public QMainWindow {
    Q_OBJECT

public:
    explicit MainWindow(QWidget* parent = nullptr);
    ~MainWindow() override;

    /// Meshes a built-in sample (samples.h) in the background.
    void openSample(Sample sample);
    /// Opens a tet mesh (.vtu, .msh, .node, .ele) or, for any other extension, a surface
    /// that is read and tetrahedralized, in the background.
    void openFile(const QString& path);

    bool isLoading() const { return m_worker.joinable(); }
    VtkViewport* viewport() const { return m_viewport; }
    const TetMesh& mesh() const { return m_mesh; }

    /// Whether load errors are shown in a message box (default) or only signalled.
    void setErrorDialogsEnabled(bool enabled) { m_errorDialogs = enabled; }

signals:
    /// A mesh was loaded and handed to the viewport.
    void meshLoaded();
    /// Loading failed; `message` names the input and what is wrong.
    void loadFailed(const QString& message);

private:
    /// Result of a background load, delivered to the GUI thread.
    struct LoadResult {
        QString title;
        QString error; // empty on success
        TetMesh mesh;
        QualitySummary summary;
    };
    template <typename Job> void startLoad(const QString& title, Job job);
    void finishLoad(LoadResult result);
    void openFileDialog();
    void cancelLoad();
    void updateStatus();

    VtkViewport* m_viewport = nullptr;
    QLabel* m_statusLabel = nullptr;
    QAction* m_openAction = nullptr;
    QProgressDialog* m_progress = nullptr;

    TetMesh m_mesh;
    QualitySummary m_summary;
    QString m_title;
    bool m_errorDialogs = true;

    std::atomic<bool> m_cancel{false};
    std::thread m_worker;
};

} // namespace resect
