#include "main_window.h"

#include "core/mesh/masses.h"
#include "core/mesh/material.h"
#include "core/mesh/quality.h"
#include "core/mesher/tetrahedralize.h"
#include "scenario/mesh_io.h"
#include "scenario/surface_io.h"
#include "widgets/vtk_viewport.h"

#include <QAction>
#include <QFile>
#include <QFileDialog>
#include <QFileInfo>
#include <QKeySequence>
#include <QLabel>
#include <QMenuBar>
#include <QMessageBox>
#include <QMetaObject>
#include <QProgressDialog>
#include <QStatusBar>

#include <exception>
#include <string>
#include <utility>

namespace resect {

namespace {

/// Extensions readTetMesh() understands; anything else is read as a surface and meshed.
bool isTetMeshFile(const QString& path) {
    const QString suffix = QFileInfo(path).suffix().toLower();
    return suffix == QLatin1String("vtu") || suffix == QLatin1String("msh") ||
           suffix == QLatin1String("node") || suffix == QLatin1String("ele");
}

/// Meshes a surface with the default options and gives the nodes lumped masses.
Status meshSurface(const TriangleSurface& surface, const std::atomic<bool>& cancel, TetMesh& out) {
    MeshingOptions options;
    options.cancel = &cancel;
    TetMesh mesh;
    Status status = tetrahedralize(surface, options, mesh);
    if (!status.ok())
        return status;
    computeLumpedMasses(mesh, Material{}.density);
    out = std::move(mesh);
    return Status::success();
}

} // namespace

MainWindow::MainWindow(QWidget* parent) : QMainWindow(parent) {
    setWindowTitle(tr("Resect Studio"));

    m_viewport = new VtkViewport(this);
    setCentralWidget(m_viewport);

    QMenu* fileMenu = menuBar()->addMenu(tr("&File"));
    m_openAction = fileMenu->addAction(tr("&Open..."));
    m_openAction->setShortcut(QKeySequence::Open);
    connect(m_openAction, &QAction::triggered, this, &MainWindow::openFileDialog);
    fileMenu->addSeparator();
    QAction* quitAction = fileMenu->addAction(tr("&Quit"));
    quitAction->setShortcut(QKeySequence::Quit);
    connect(quitAction, &QAction::triggered, this, &QMainWindow::close);

    m_statusLabel = new QLabel(this);
    statusBar()->addPermanentWidget(m_statusLabel, 1);
    updateStatus();
}

MainWindow::~MainWindow() {
    // The worker only touches its own data and posts its result to this object; stop it
    // before the object goes away (the posted result is then discarded with the object).
    m_cancel = true;
    if (m_worker.joinable())
        m_worker.join();
}

void MainWindow::openSample(Sample sample) {
    const QString name = QString::fromStdString(sampleName(sample));
    startLoad(name, [sample](const std::atomic<bool>& cancel, TetMesh& out) {
        return meshSurface(sampleSurface(sample), cancel, out);
    });
}

void MainWindow::openFile(const QString& path) {
    const std::string file = QFile::encodeName(path).toStdString();
    const QString title = QFileInfo(path).fileName();
    if (isTetMeshFile(path)) {
        startLoad(title, [file](const std::atomic<bool>&, TetMesh& out) {
            return readTetMesh(file, out);
        });
    } else {
        startLoad(title, [file](const std::atomic<bool>& cancel, TetMesh& out) {
            TriangleSurface surface;
            Status status = readSurface(file, surface);
            if (!status.ok())
                return status;
            status = meshSurface(surface, cancel, out);
            if (!status.ok())
                return Status::error(file + ": " + status.message());
            return Status::success();
        });
    }
}

template <typename Job> void MainWindow::startLoad(const QString& title, Job job) {
    if (m_worker.joinable()) {
        emit loadFailed(tr("%1: another file is still loading").arg(title));
        return;
    }
    m_cancel = false;
    m_openAction->setEnabled(false);
    statusBar()->showMessage(tr("Loading %1...").arg(title));

    m_progress =
        new QProgressDialog(tr("Loading and meshing %1...").arg(title), tr("Cancel"), 0, 0, this);
    m_progress->setWindowTitle(tr("Resect Studio"));
    m_progress->setMinimumDuration(500);
    m_progress->setAutoClose(false);
    m_progress->setAutoReset(false);
    connect(m_progress, &QProgressDialog::canceled, this, &MainWindow::cancelLoad);

    m_worker = std::thread([this, title, job = std::move(job)]() mutable {
        LoadResult result;
        result.title = title;
        try {
            const Status status = job(m_cancel, result.mesh);
            if (!status.ok())
                result.error = QString::fromStdString(status.message());
        } catch (const std::exception& e) {
            result.error = tr("%1: internal error: %2").arg(title, QString::fromUtf8(e.what()));
        } catch (...) {
            result.error = tr("%1: internal error").arg(title);
        }
        if (result.error.isEmpty())
            result.summary = summarizeQuality(result.mesh);
        QMetaObject::invokeMethod(
            this, [this, result = std::move(result)]() mutable { finishLoad(std::move(result)); },
            Qt::QueuedConnection);
    });
}

void MainWindow::finishLoad(LoadResult result) {
    if (m_worker.joinable())
        m_worker.join();
    if (m_progress != nullptr) {
        m_progress->hide();
        m_progress->deleteLater();
        m_progress = nullptr;
    }
    m_openAction->setEnabled(true);
    statusBar()->clearMessage();

    if (!result.error.isEmpty()) {
        const bool cancelled = m_cancel.load();
        statusBar()->showMessage(cancelled ? tr("Loading %1 cancelled").arg(result.title)
                                           : tr("Loading %1 failed").arg(result.title),
                                 5000);
        if (m_errorDialogs && !cancelled) {
            auto* box =
                new QMessageBox(QMessageBox::Warning, tr("Resect Studio"),
                                tr("Could not open %1.").arg(result.title), QMessageBox::Ok, this);
            box->setInformativeText(result.error);
            box->setAttribute(Qt::WA_DeleteOnClose);
            box->open();
        }
        emit loadFailed(result.error);
        return;
    }

    m_mesh = std::move(result.mesh);
    m_summary = result.summary;
    m_title = result.title;
    setWindowTitle(tr("%1 - Resect Studio").arg(m_title));
    m_viewport->setTetMesh(m_mesh);
    updateStatus();
    emit meshLoaded();
}

void MainWindow::openFileDialog() {
    const QString path =
        QFileDialog::getOpenFileName(this, tr("Open mesh or surface"), QString(),
                                     tr("Tet meshes (*.vtu *.msh *.node *.ele);;"
                                        "Surfaces (*.obj *.stl *.ply *.off *.glb *.gltf);;"
                                        "All files (*)"));
    if (!path.isEmpty())
        openFile(path);
}

void MainWindow::cancelLoad() {
    m_cancel = true;
    statusBar()->showMessage(tr("Cancelling..."));
}

void MainWindow::updateStatus() {
    if (m_mesh.empty()) {
        m_statusLabel->setText(tr("No mesh"));
        return;
    }
    m_statusLabel->setText(tr("%1: %2 nodes, %3 tets, min radius ratio %4")
                               .arg(m_title)
                               .arg(m_summary.nodes)
                               .arg(m_summary.tets)
                               .arg(m_summary.minRadiusRatio, 0, 'f', 3));
}

} // namespace resect
