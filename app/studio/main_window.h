#pragma once
// MainWindow: the studio's main window. It only assembles and routes: the document model
// (ScenarioDocument, the single source of truth with its undo stack), the tissue derived
// from it on a worker thread (TissueSession), opening only what derives (DocumentOpener),
// the pending cut and its preview (CutPreview),
// the simulation (SimulationController), what the views show of them (ShownTissue), the
// 3-D view and the panels, which all observe the document; menus and tool bars call the
// document's edits.

#include "core/mesher/samples.h"
#include "scenario/mesh_io.h"

#include <QMainWindow>
#include <QMessageBox>
#include <QString>

#include <memory>

class QAction;
class QCloseEvent;
class QLabel;
class QMenu;
class QProgressDialog;

namespace resect {

class AccuracyPanel;
class AuthoringPanel;
class CutPanel;
class CutPreview;
class DocumentOpener;
class ExportRunner;
class QualityPanel;
class ScenarioDocument;
class ShownTissue;
class MeshFileWriter;
class SimulationController;
class SimulationPanel;
class TissueSession;
class VtkViewport;

class MainWindow : public QMainWindow {
    Q_OBJECT

public:
    explicit MainWindow(QWidget* parent = nullptr);
    ~MainWindow() override;

    /// A new scenario on a built-in sample, meshed in the background.
    void openSample(Sample sample);
    /// A scenario (.json) is opened; a tet mesh (.vtu, .msh, .node, .ele) or any surface
    /// assimp reads starts a new scenario on that anatomy (a surface is meshed in the
    /// background). Asks about unsaved changes first. The document is replaced only once the
    /// new tissue and its cuts derived (DocumentOpener); a failure (loadFailed) leaves the
    /// open document and the views as they were.
    void openFile(const QString& path);
    /// Saves to the document's file, or asks for one. False if not saved.
    bool save();
    /// Saves to `path` (no dialog). False, with an error shown, if not saved.
    bool saveAs(const QString& path);

    /// Exports the document for the trainer into `outDir` (scenario/trainer_export.h) on a
    /// worker thread with a progress dialog (when dialogs are on); exportFinished() reports.
    /// False if it could not start.
    bool exportPackage(const QString& outDir, bool force = false);
    ExportRunner& exportRunner() { return *m_export; }
    /// Writes the tet mesh on show (ShownTissue::mesh: the tissue after the document's cuts,
    /// the preview or the simulated tissue, whatever the viewport draws) to `path` in
    /// `format` on a worker thread; meshExported() reports. False, with an error shown, if
    /// there is no mesh, the path does not fit the format, or a write is running.
    bool exportMesh(const QString& path, MeshFormat format);

    bool isLoading() const;
    VtkViewport* viewport() const { return m_viewport; }
    ScenarioDocument& document() { return *m_document; }
    DocumentOpener& opener() { return *m_opener; }
    TissueSession& session() { return *m_session; }
    CutPreview& cutPreview() { return *m_preview; }
    SimulationController& simulation() { return *m_simulation; }
    ShownTissue& shownTissue() { return *m_shown; }
    CutPanel* cutPanel() const { return m_cutPanel; }
    SimulationPanel* simulationPanel() const { return m_simulationPanel; }
    AuthoringPanel* authoringPanel() const { return m_authoringPanel; }
    QualityPanel* qualityPanel() const { return m_qualityPanel; }
    AccuracyPanel* accuracyPanel() const { return m_accuracyPanel; }

    /// Whether errors are shown in message boxes (default) or only signalled (tests, the
    /// command line's --screenshot).
    void setErrorDialogsEnabled(bool enabled) { m_errorDialogs = enabled; }
    /// The answer to "save the changes?" without asking (tests): Save, Discard or Cancel;
    /// NoButton (default) asks.
    void setUnsavedChangesAnswer(QMessageBox::StandardButton answer) { m_unsavedAnswer = answer; }
    /// Offers to recover an autosave a crashed session left behind (start-up); true if a
    /// document was recovered.
    bool offerRecovery();

signals:
    /// A tissue was loaded (meshed) and shown.
    void meshLoaded();
    /// Loading failed; `message` names the input and what is wrong.
    void loadFailed(const QString& message);
    /// An export ended; `files` are the package's files (absolute paths) when it succeeded.
    void exportFinished(bool ok, const QString& message, const QStringList& files);
    /// A mesh export ended: ok, `message` is the file written; else why not.
    void meshExported(bool ok, const QString& message);
    /// An error was reported to the user (shown in a box unless dialogs are off).
    void errorReported(const QString& message);

protected:
    void closeEvent(QCloseEvent* event) override;

private:
    void createActions();
    void createDocks();
    /// Asks about unsaved changes; true if it is fine to replace the document.
    bool maybeSave();
    void openFileDialog();
    void importAnatomyDialog();
    void saveAsDialog();
    void exportDialog();
    void exportMeshDialog();
    void onExportFinished(bool ok, const QString& message, const QStringList& files);
    void newFromSample(const QString& name);
    void onOpenFailed(const QString& message);
    /// A new document is shown: the views drop what belonged to the previous one.
    void resetViews();
    /// Shows what reading the loaded tissue's tet mesh left out, if anything.
    void showReadNote();
    void updateApplyAction();
    void showError(const QString& title, const QString& message);
    void updateTitle();
    void updateRecentMenu();
    void updateStatus();
    void onBusyChanged(bool busy);
    /// A meshing stage started: the load's progress dialog shows it and the work done.
    void onLoadProgress(const QString& stage, double fraction);
    void updateAccuracyPanel();
    void setLanguagePreference(const QString& code);

    ScenarioDocument* m_document = nullptr;
    TissueSession* m_session = nullptr;
    DocumentOpener* m_opener = nullptr;
    CutPreview* m_preview = nullptr;
    SimulationController* m_simulation = nullptr;
    ShownTissue* m_shown = nullptr;

    VtkViewport* m_viewport = nullptr;
    CutPanel* m_cutPanel = nullptr;
    SimulationPanel* m_simulationPanel = nullptr;
    AuthoringPanel* m_authoringPanel = nullptr;
    QualityPanel* m_qualityPanel = nullptr;
    AccuracyPanel* m_accuracyPanel = nullptr;
    ExportRunner* m_export = nullptr;
    MeshFileWriter* m_meshWriter = nullptr;
    QLabel* m_statusLabel = nullptr;
    QProgressDialog* m_progress = nullptr;
    QMenu* m_recentMenu = nullptr;
    QMenu* m_viewMenu = nullptr;
    QAction* m_showTets = nullptr;
    QAction* m_showSurface = nullptr;
    QAction* m_applyAction = nullptr;
    QString m_opening; ///< the name of what is being opened (for messages)

    bool m_errorDialogs = true;
    QMessageBox::StandardButton m_unsavedAnswer = QMessageBox::NoButton;
};

} // namespace resect
