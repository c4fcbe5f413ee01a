#include "main_window.h"

#include "widgets/accuracy_panel.h"
#include "widgets/authoring_panel.h"
#include "widgets/cut_panel.h"
#include "widgets/cut_preview.h"
#include "widgets/display_toolbar.h"
#include "widgets/document_opener.h"
#include "widgets/export_runner.h"
#include "widgets/fixed_region_editor.h"
#include "widgets/fixed_region_tool.h"
#include "widgets/language.h"
#include "widgets/mesh_files.h"
#include "widgets/quality_panel.h"
#include "widgets/scenario_document.h"
#include "widgets/shown_tissue.h"
#include "widgets/simulation_controller.h"
#include "widgets/simulation_panel.h"
#include "widgets/surface_pick.h"
#include "widgets/sweep_edit_tool.h"
#include "widgets/tet_inspector.h"
#include "widgets/tissue_session.h"
#include "widgets/vtk_viewport.h"

#include "scenario/cut_study.h"
#include "scenario/scenario_sweeps.h"

#include <QAction>
#include <QActionGroup>
#include <QCloseEvent>
#include <QDesktopServices>
#include <QDockWidget>
#include <QFile>
#include <QFileDialog>
#include <QFileInfo>
#include <QKeySequence>
#include <QLabel>
#include <QMenuBar>
#include <QProgressDialog>
#include <QPushButton>
#include <QScrollArea>
#include <QSettings>
#include <QStatusBar>
#include <QToolBar>
#include <QUndoStack>
#include <QUrl>

#include <algorithm>
#include <cmath>

namespace resect {

namespace {

bool isScenarioFile(const QString& path) {
    return QFileInfo(path).suffix().compare(QLatin1String("json"), Qt::CaseInsensitive) == 0;
}

/// A dock holding `widget` in a scroll area, closable and movable.
QDockWidget* makeDock(const QString& title, const QString& name, QWidget* widget, QWidget* parent) {
    auto* dock = new QDockWidget(title, parent);
    dock->setObjectName(name);
    auto* scroll = new QScrollArea;
    scroll->setWidgetResizable(true);
    scroll->setWidget(widget);
    dock->setWidget(scroll);
    return dock;
}

} // namespace

MainWindow::MainWindow(QWidget* parent) : QMainWindow(parent) {
    setObjectName(QStringLiteral("mainWindow"));
    m_document = new ScenarioDocument(this);
    m_session = new TissueSession(*m_document, this);
    m_opener = new DocumentOpener(*m_document, *m_session, this);
    m_preview = new CutPreview(*m_document, *m_session, this);
    m_simulation = new SimulationController(*m_document, *m_session, this);

    m_viewport = new VtkViewport(this);
    m_viewport->setObjectName(QStringLiteral("viewport"));
    setCentralWidget(m_viewport);

    m_cutPanel = new CutPanel(*m_document, *m_session, *m_preview);
    m_simulationPanel = new SimulationPanel(*m_document, *m_session, *m_simulation);
    m_authoringPanel = new AuthoringPanel(m_viewport);
    m_accuracyPanel = new AccuracyPanel;
    m_qualityPanel = new QualityPanel;
    m_qualityPanel->attach(m_viewport);
    // The preview, the simulated or the current tissue: on show in the viewport and inspected
    // by the quality panel.
    m_shown = new ShownTissue(*m_session, *m_preview, *m_simulation, *m_viewport, *m_qualityPanel, this);
    createActions();
    createDocks();

    m_statusLabel = new QLabel(this);
    m_statusLabel->setObjectName(QStringLiteral("statusSummary"));
    // A normal (not permanent) widget: a temporary message (a refused edit, a save) takes its
    // place while it is shown; a permanent one that stretches left the messages no room.
    statusBar()->addWidget(m_statusLabel, 1);

    connect(m_document, &ScenarioDocument::modifiedChanged, this, &MainWindow::updateTitle);
    connect(m_document, &ScenarioDocument::fileChanged, this, &MainWindow::updateTitle);
    connect(m_document, &ScenarioDocument::documentReset, this, &MainWindow::updateTitle);
    connect(m_document, &ScenarioDocument::metadataChanged, this, &MainWindow::updateTitle);
    connect(m_document, &ScenarioDocument::recentFilesChanged, this, &MainWindow::updateRecentMenu);
    connect(m_session, &TissueSession::busyChanged, this, &MainWindow::onBusyChanged);
    connect(m_session, &TissueSession::loadProgress, this, &MainWindow::onLoadProgress);
    connect(m_session, &TissueSession::baseChanged, this, &MainWindow::updateStatus);
    connect(m_session, &TissueSession::baseChanged, this, &MainWindow::showReadNote);
    connect(m_session, &TissueSession::currentChanged, this, &MainWindow::updateStatus);
    // Every new document is framed when the session publishes its tissue (baseChanged).
    connect(m_document, &ScenarioDocument::documentReset, this, &MainWindow::resetViews);
    connect(m_shown, &ShownTissue::framed, this, [this] {
        updateStatus();
        emit meshLoaded();
    });
    // What fails to open is reported by the opener; a document's tissue fails here only when
    // it was loaded directly (a recovered autosave). Refused edits and failing cuts are shown
    // in place (the status bar and the cut panel's notice), never in a dialog.
    connect(m_opener, &DocumentOpener::failed, this, &MainWindow::onOpenFailed);
    connect(m_session, &TissueSession::failed, this, [this](const QString& message) {
        if (!m_session->base()) {
            emit loadFailed(message);
            showError(tr("The tissue could not be loaded."), message);
            return;
        }
        statusBar()->showMessage(tr("The tissue or its cuts fail: %1").arg(message), 30000);
    });
    connect(m_session, &TissueSession::editRefused, this, [this](const QString& reason) {
        statusBar()->showMessage(tr("The last edit was undone: %1").arg(reason), 20000);
    });
    m_document->setSaveCheck([this] { return m_session->saveBlocker(); });
    connect(m_simulation, &SimulationController::failed, this, [this](const QString& message) {
        statusBar()->showMessage(message, 10000);
    });
    // Authoring: what is drawn or recorded becomes the pending cut, previewed live.
    connect(m_authoringPanel, &AuthoringPanel::sweepFinished, m_preview, &CutPreview::setPendingSweep);
    connect(m_authoringPanel, &AuthoringPanel::strokeRecorded, m_preview, &CutPreview::setPendingStroke);
    connect(&m_authoringPanel->sweepEditor(), &SweepEditTool::sweepChanged, this, [this] {
        if (const auto spec = m_authoringPanel->sweepEditor().sweepSpec())
            m_preview->setPendingSweep(*spec);
    });
    connect(m_document, &ScenarioDocument::documentReset, this,
            [this] { m_authoringPanel->setToolSpec(m_document->scenario().tool); });
    connect(m_session, &TissueSession::currentChanged, this, [this] {
        // New sweep points and stroke depths are picked on the tissue's boundary.
        if (const auto current = m_session->current())
            m_authoringPanel->setPickSurface(pickSurfaceOf(current->mesh()));
        else
            m_authoringPanel->clearPickSurface();
    });
    // Accuracy vs time: the study runs on the uncut tissue with the scenario's first cut (or
    // a loop scoop through its upper part); a chosen point becomes the cut settings.
    connect(m_session, &TissueSession::baseChanged, this, &MainWindow::updateAccuracyPanel);
    connect(m_document, &ScenarioDocument::strokesChanged, this, &MainWindow::updateAccuracyPanel);
    connect(m_document, &ScenarioDocument::sweepsChanged, this, &MainWindow::updateAccuracyPanel);
    connect(m_document, &ScenarioDocument::cutSettingsChanged, this,
            [this] { m_accuracyPanel->setBaseCutSettings(m_document->scenario().cut); });
    connect(m_accuracyPanel, &AccuracyPanel::adoptRequested, m_document, &ScenarioDocument::setCutSettings);
    // Fixed regions placed in the view: the simulation dock's "Place in view" and the tool.
    auto* regionTool = new FixedRegionTool(*m_document, m_viewport, this);
    connect(m_simulationPanel->fixedRegionEditor(), &FixedRegionEditor::editInViewToggled, regionTool,
            &FixedRegionTool::setActive);
    connect(regionTool, &FixedRegionTool::activeChanged, m_simulationPanel->fixedRegionEditor(),
            &FixedRegionEditor::setEditingInView);
    // A preview's warning names the tets that limit its time step: one click shows one in the
    // quality dock's tet inspector.
    connect(m_cutPanel, &CutPanel::inspectTetRequested, this, [this](int tet) {
        m_qualityPanel->selectTet(tet);
        if (auto* dock = findChild<QDockWidget*>(QStringLiteral("qualityDock"))) {
            dock->show();
            dock->raise();
        }
    });
    connect(m_cutPanel, &CutPanel::applyFailed, this,
            [this](const QString& message) { statusBar()->showMessage(message, 10000); });
    connect(m_preview, &CutPreview::changed, this, &MainWindow::updateApplyAction);
    // No simulation behind a pending cut: the view shows the preview at rest, and a
    // simulation running on would be hidden behind it (issue 19). Playing waits until the
    // cut is applied or discarded.
    const auto holdSimulation = [this] {
        if (m_preview->hasPending() && m_simulation->isPlaying()) {
            m_simulation->pause();
            statusBar()->showMessage(
                tr("Simulation paused while a cut is previewed: apply or discard the cut, then play."), 10000);
        }
    };
    connect(m_preview, &CutPreview::changed, this, holdSimulation);
    connect(m_simulation, &SimulationController::playingChanged, this, holdSimulation);
    connect(m_session, &TissueSession::busyChanged, this, &MainWindow::updateApplyAction);
    updateApplyAction();

    m_export = new ExportRunner(this);
    connect(m_export, &ExportRunner::finished, this, &MainWindow::onExportFinished);
    m_meshWriter = new MeshFileWriter(this);
    connect(m_meshWriter, &MeshFileWriter::finished, this, [this](bool ok, const QString& message) {
        if (ok)
            statusBar()->showMessage(tr("Exported the mesh to %1").arg(message), 10000);
        else
            showError(tr("The mesh was not exported."), message);
        emit meshExported(ok, message);
    });

    m_document->setAutosaveInterval(60'000);
    updateTitle();
    updateRecentMenu();
    updateStatus();
}

MainWindow::~MainWindow() = default;

void MainWindow::createActions() {
    QMenu* file = menuBar()->addMenu(tr("&File"));
    QMenu* newMenu = file->addMenu(tr("&New from sample"));
    for (const std::string& name : sampleNames()) {
        const QString sample = QString::fromStdString(name);
        QAction* a = newMenu->addAction(sample == QLatin1String("polyp")   ? tr("&Polyp")
                                        : sample == QLatin1String("myoma") ? tr("&Myoma")
                                                                           : sample);
        a->setObjectName(QStringLiteral("newSample_") + sample);
        connect(a, &QAction::triggered, this, [this, sample] { newFromSample(sample); });
    }
    QAction* open = file->addAction(tr("&Open..."), this, &MainWindow::openFileDialog);
    open->setShortcut(QKeySequence::Open);
    open->setObjectName(QStringLiteral("openFile"));
    QAction* import = file->addAction(tr("&Import anatomy..."), this, &MainWindow::importAnatomyDialog);
    import->setObjectName(QStringLiteral("importAnatomy"));
    m_recentMenu = file->addMenu(tr("Open &recent"));
    file->addSeparator();
    QAction* saveAction = file->addAction(tr("&Save"), this, [this] { save(); });
    saveAction->setShortcut(QKeySequence::Save);
    QAction* saveAsAction = file->addAction(tr("Save &as..."), this, &MainWindow::saveAsDialog);
    saveAsAction->setShortcut(QKeySequence::SaveAs);
    file->addSeparator();
    QAction* exportAction = file->addAction(tr("&Export for the trainer..."), this, &MainWindow::exportDialog);
    exportAction->setObjectName(QStringLiteral("exportPackage"));
    QAction* exportMeshAction = file->addAction(tr("Export &mesh as..."), this, &MainWindow::exportMeshDialog);
    exportMeshAction->setObjectName(QStringLiteral("exportMesh"));
    file->addSeparator();
    QAction* quit = file->addAction(tr("&Quit"), this, &QWidget::close);
    quit->setShortcut(QKeySequence::Quit);
    // The file shortcuts work from every window of the studio, floating docks included
    // (with the default window context, Ctrl+O in an undocked panel did nothing).
    for (QAction* a : {open, saveAction, saveAsAction, quit})
        a->setShortcutContext(Qt::ApplicationShortcut);

    QMenu* edit = menuBar()->addMenu(tr("&Edit"));
    QAction* undo = m_document->undoStack()->createUndoAction(this, tr("&Undo"));
    undo->setShortcut(QKeySequence::Undo);
    undo->setObjectName(QStringLiteral("undo"));
    QAction* redo = m_document->undoStack()->createRedoAction(this, tr("&Redo"));
    redo->setShortcut(QKeySequence::Redo);
    redo->setObjectName(QStringLiteral("redo"));
    edit->addAction(undo);
    edit->addAction(redo);

    QMenu* cut = menuBar()->addMenu(tr("&Cut"));
    m_applyAction = cut->addAction(tr("&Apply pending cut"), this, [this] {
        QString error;
        if (!m_preview->apply(&error))
            statusBar()->showMessage(error, 10000);
    });
    m_applyAction->setObjectName(QStringLiteral("applyPendingCut"));
    m_applyAction->setShortcut(QKeySequence(Qt::CTRL | Qt::Key_Return));
    cut->addAction(tr("&Discard pending cut"), m_preview, &CutPreview::discard);

    QMenu* sim = menuBar()->addMenu(tr("&Simulation"));
    QAction* play = sim->addAction(tr("&Play / pause"), this, [this] {
        if (m_simulation->isPlaying())
            m_simulation->pause();
        else
            m_simulation->play();
    });
    play->setShortcut(QKeySequence(Qt::Key_Space));
    sim->addAction(tr("&Step"), m_simulation, &SimulationController::step);
    sim->addAction(tr("&Reset"), m_simulation, &SimulationController::reset);

    m_viewMenu = menuBar()->addMenu(tr("&View"));
    QAction* resetView = m_viewMenu->addAction(tr("&Reset camera"), m_viewport, &VtkViewport::restoreStartingView);
    resetView->setObjectName(QStringLiteral("resetCamera"));
    m_showTets = m_viewMenu->addAction(tr("Show &tet mesh"));
    m_showTets->setCheckable(true);
    m_showTets->setChecked(true);
    m_showSurface = m_viewMenu->addAction(tr("Show high-resolution &surface"));
    m_showSurface->setCheckable(true);
    m_showSurface->setChecked(false);
    m_shown->setTetsVisible(m_showTets->isChecked());
    m_shown->setSurfaceVisible(m_showSurface->isChecked());
    connect(m_showTets, &QAction::toggled, m_shown, &ShownTissue::setTetsVisible);
    connect(m_showSurface, &QAction::toggled, m_shown, &ShownTissue::setSurfaceVisible);
    // Seeing the cut (issue 19): colour by piece, cut faces, chips, explode, above the view.
    auto* displayBar = new DisplayToolBar(m_shown->display(), this);
    addToolBar(Qt::TopToolBarArea, displayBar);
    m_viewMenu->addMenu(displayBar->menu());
    displayBar->toggleViewAction()->setText(tr("Display &toolbar"));
    m_viewMenu->addAction(displayBar->toggleViewAction());
    m_viewMenu->addSeparator();

    QMenu* language = menuBar()->addMenu(tr("&Language"));
    auto* languages = new QActionGroup(this);
    const QString chosen = QSettings().value(QString::fromLatin1(kLanguageSettingsKey)).toString();
    QAction* system = language->addAction(tr("System default"));
    system->setCheckable(true);
    system->setChecked(chosen.isEmpty());
    languages->addAction(system);
    connect(system, &QAction::triggered, this, [this] { setLanguagePreference(QString()); });
    for (const QString& code : availableLanguages()) {
        QAction* a = language->addAction(languageName(code));
        a->setObjectName(QStringLiteral("language_") + code);
        a->setCheckable(true);
        a->setChecked(code == chosen);
        languages->addAction(a);
        connect(a, &QAction::triggered, this, [this, code] { setLanguagePreference(code); });
    }
}

void MainWindow::createDocks() {
    QDockWidget* cutDock = makeDock(tr("Cut"), QStringLiteral("cutDock"), m_cutPanel, this);
    addDockWidget(Qt::RightDockWidgetArea, cutDock);
    QDockWidget* simDock = makeDock(tr("Simulation"), QStringLiteral("simulationDock"), m_simulationPanel, this);
    addDockWidget(Qt::RightDockWidgetArea, simDock);
    tabifyDockWidget(cutDock, simDock);
    cutDock->raise();
    QDockWidget* accuracyDock =
        makeDock(tr("Accuracy vs time"), QStringLiteral("accuracyDock"), m_accuracyPanel, this);
    addDockWidget(Qt::RightDockWidgetArea, accuracyDock);
    tabifyDockWidget(simDock, accuracyDock);
    m_viewMenu->addAction(accuracyDock->toggleViewAction());
    QDockWidget* qualityDock = makeDock(tr("Quality"), QStringLiteral("qualityDock"), m_qualityPanel, this);
    addDockWidget(Qt::RightDockWidgetArea, qualityDock);
    tabifyDockWidget(simDock, qualityDock);
    cutDock->raise();
    m_viewMenu->addAction(qualityDock->toggleViewAction());
    QDockWidget* authorDock = makeDock(tr("Authoring"), QStringLiteral("authoringDock"), m_authoringPanel, this);
    addDockWidget(Qt::LeftDockWidgetArea, authorDock);
    m_viewMenu->addAction(authorDock->toggleViewAction());
    m_viewMenu->addAction(cutDock->toggleViewAction());
    m_viewMenu->addAction(simDock->toggleViewAction());
}

bool MainWindow::isLoading() const { return m_session->isBusy(); }

void MainWindow::showError(const QString& title, const QString& message) {
    emit errorReported(message);
    statusBar()->showMessage(title, 10000);
    if (!m_errorDialogs)
        return;
    auto* box = new QMessageBox(QMessageBox::Warning, tr("Resect Studio"), title, QMessageBox::Ok, this);
    box->setInformativeText(message);
    box->setAttribute(Qt::WA_DeleteOnClose);
    box->open();
}

bool MainWindow::maybeSave() {
    if (!m_document->isModified())
        return true;
    QMessageBox::StandardButton answer = m_unsavedAnswer;
    if (answer == QMessageBox::NoButton)
        answer = QMessageBox::warning(this, tr("Resect Studio"),
                                      tr("%1 has unsaved changes. Save them?").arg(m_document->displayName()),
                                      QMessageBox::Save | QMessageBox::Discard | QMessageBox::Cancel,
                                      QMessageBox::Save);
    if (answer == QMessageBox::Save)
        return save();
    return answer == QMessageBox::Discard;
}

void MainWindow::closeEvent(QCloseEvent* event) {
    if (!maybeSave()) {
        event->ignore();
        return;
    }
    m_simulation->pause();
    m_session->cancel();
    m_document->close(); // removes this document's autosave: a clean exit
    event->accept();
}

void MainWindow::newFromSample(const QString& name) {
    if (!maybeSave())
        return;
    QString error;
    m_opening = name;
    if (!m_opener->openSample(name, &error))
        showError(tr("Could not create the scenario."), error);
}

void MainWindow::openSample(Sample sample) { newFromSample(QString::fromStdString(sampleName(sample))); }

void MainWindow::openFile(const QString& path) {
    if (!maybeSave())
        return;
    QString error;
    m_opening = QFileInfo(path).fileName();
    const bool ok = isScenarioFile(path) ? m_opener->openScenario(path, &error)
                                         : m_opener->openAnatomy(path, &error);
    if (!ok)
        onOpenFailed(error);
}

void MainWindow::onOpenFailed(const QString& message) {
    emit loadFailed(message);
    showError(tr("Could not open %1.").arg(m_opening), message);
}

void MainWindow::resetViews() {
    // What was drawn, recorded, picked, studied or said about the previous document.
    m_authoringPanel->reset();
    m_accuracyPanel->clearResults();
    m_qualityPanel->inspector()->clear();
    statusBar()->clearMessage();
    // An opened document's tissue is adopted before this reset: say what its file left out.
    showReadNote();
}

void MainWindow::showReadNote() {
    // What reading the tet mesh left out (a mixed-element file keeps its tets).
    if (const auto base = m_session->base(); base && !base->readNote.isEmpty())
        statusBar()->showMessage(tr("Mesh read: %1").arg(base->readNote), 30000);
}

void MainWindow::updateApplyAction() {
    m_applyAction->setEnabled(m_preview->canApply());
}

bool MainWindow::save() {
    if (m_document->filePath().isEmpty()) {
        saveAsDialog();
        return !m_document->isModified() && !m_document->filePath().isEmpty();
    }
    QString error;
    if (!m_document->save(&error)) {
        showError(tr("The scenario was not saved."), error);
        return false;
    }
    statusBar()->showMessage(tr("Saved %1").arg(m_document->filePath()), 5000);
    return true;
}

bool MainWindow::saveAs(const QString& path) {
    QString error;
    if (!m_document->saveAs(path, &error)) {
        showError(tr("The scenario was not saved."), error);
        return false;
    }
    statusBar()->showMessage(tr("Saved %1").arg(path), 5000);
    return true;
}

void MainWindow::saveAsDialog() {
    const QString path = QFileDialog::getSaveFileName(this, tr("Save scenario"), m_document->filePath(),
                                                      tr("Scenarios (*.json)"));
    if (!path.isEmpty())
        saveAs(path.endsWith(QLatin1String(".json"), Qt::CaseInsensitive) ? path : path + QStringLiteral(".json"));
}

void MainWindow::openFileDialog() {
    const QString path = QFileDialog::getOpenFileName(
        this, tr("Open scenario or anatomy"), QString(),
        tr("Scenarios (*.json)") + QStringLiteral(";;") + tetMeshOpenFilters() + QStringLiteral(";;") +
            tr("Surfaces (*.obj *.stl *.ply *.off *.glb *.gltf *.dae *.3ds *.fbx);;All files (*)"));
    if (!path.isEmpty())
        openFile(path);
}

void MainWindow::importAnatomyDialog() {
    const QString path = QFileDialog::getOpenFileName(
        this, tr("Import anatomy"), QString(),
        tr("Surfaces (*.obj *.stl *.ply *.off *.glb *.gltf *.dae *.3ds *.fbx)") + QStringLiteral(";;") +
            tetMeshOpenFilters() + QStringLiteral(";;") + tr("All files (*)"));
    if (path.isEmpty() || !maybeSave())
        return;
    QString error;
    m_opening = QFileInfo(path).fileName();
    if (!m_opener->openAnatomy(path, &error))
        onOpenFailed(error);
}

bool MainWindow::exportPackage(const QString& outDir, bool force) {
    if (m_export->isRunning()) {
        showError(tr("The scenario was not exported."), tr("An export is already running."));
        return false;
    }
    ExportOptions options;
    options.force = force;
    options.scenarioFile = m_document->filePath().toStdString();
    if (!m_export->start(m_document->scenario(), outDir, options)) {
        showError(tr("The scenario was not exported."), tr("The export could not be started."));
        return false;
    }
    if (m_errorDialogs)
        m_export->showProgressDialog(this);
    statusBar()->showMessage(tr("Exporting to %1...").arg(outDir));
    return true;
}

void MainWindow::exportDialog() {
    // Qt's own dialog (not a platform one, which may lack it) has "Create New Folder".
    const QString dir = QFileDialog::getExistingDirectory(
        this, tr("Export for the trainer: choose or create an empty folder"), QString(),
        QFileDialog::ShowDirsOnly | QFileDialog::DontUseNativeDialog);
    if (!dir.isEmpty())
        exportPackage(dir, false);
}

void MainWindow::exportMeshDialog() {
    // Qt's own dialog: the chosen filter names the format (several share .msh and .vtk).
    QFileDialog dialog(this, tr("Export mesh as"));
    dialog.setObjectName(QStringLiteral("exportMeshDialog"));
    dialog.setAcceptMode(QFileDialog::AcceptSave);
    dialog.setOption(QFileDialog::DontUseNativeDialog);
    dialog.setNameFilters(tetMeshSaveFilters());
    if (dialog.exec() != QDialog::Accepted || dialog.selectedFiles().isEmpty())
        return;
    const std::optional<MeshFormat> format = formatOfSaveFilter(dialog.selectedNameFilter());
    if (!format)
        return;
    exportMesh(withMeshExtension(dialog.selectedFiles().front(), *format), *format);
}

bool MainWindow::exportMesh(const QString& path, MeshFormat format) {
    const QString title = tr("The mesh was not exported.");
    const TetMesh* shown = m_shown->mesh();
    if (!shown) {
        showError(title, tr("There is no tet mesh on show."));
        return false;
    }
    MeshFormat checked{};
    const std::string key(meshFormatInfo(format).key);
    if (Status s = chooseMeshWriteFormat(QFile::encodeName(path).toStdString(), key, checked); !s) {
        showError(title, QString::fromStdString(s.message()));
        return false;
    }
    if (!m_meshWriter->start(std::make_shared<const TetMesh>(*shown), path, format)) {
        showError(title, tr("A mesh export is already running."));
        return false;
    }
    statusBar()->showMessage(tr("Exporting the mesh to %1...").arg(path));
    return true;
}

void MainWindow::onExportFinished(bool ok, const QString& message, const QStringList& files) {
    if (ok) {
        const QString dir = QString::fromStdString(m_export->summary().outDir);
        const QString text = tr("Exported %n file(s) to %1", nullptr, int(files.size())).arg(dir);
        statusBar()->showMessage(text, 10000);
        // A confirmation the author cannot miss, with the way to the package (window-modal,
        // so it does not block the event loop).
        auto* done = new QMessageBox(QMessageBox::Information, tr("Export finished"), text, QMessageBox::Ok, this);
        done->setObjectName(QStringLiteral("exportConfirmation"));
        done->setInformativeText(tr("The trainer package is ready: the manifest lists every file with its SHA-256."));
        QPushButton* openFolder = done->addButton(tr("Open folder"), QMessageBox::ActionRole);
        connect(openFolder, &QPushButton::clicked, this,
                [dir] { QDesktopServices::openUrl(QUrl::fromLocalFile(dir)); });
        done->setAttribute(Qt::WA_DeleteOnClose);
        if (m_errorDialogs)
            done->open();
        else
            done->deleteLater(); // tests: the status bar and exportFinished() tell
    } else {
        showError(tr("The scenario was not exported."), message);
    }
    emit exportFinished(ok, message, files);
}

bool MainWindow::offerRecovery() {
    const QString autosave = m_document->recoverableAutosave();
    if (autosave.isEmpty())
        return false;
    const QString original = m_document->autosaveOriginalFile();
    const auto answer = QMessageBox::question(
        this, tr("Resect Studio"),
        tr("Resect Studio did not close properly. Recover the unsaved changes to %1?")
            .arg(original.isEmpty() ? tr("an untitled scenario") : original),
        QMessageBox::Yes | QMessageBox::No, QMessageBox::Yes);
    QString error;
    if (answer == QMessageBox::Yes) {
        if (m_document->recover(&error))
            return true;
        showError(tr("The autosave could not be recovered."), error);
    } else {
        m_document->discardAutosave();
    }
    return false;
}

void MainWindow::updateTitle() {
    QString title = m_document->displayName();
    const std::string& t = m_document->scenario().metadata.title;
    if (!t.empty())
        title = QString::fromStdString(t) + QStringLiteral(" (") + title + QLatin1Char(')');
    setWindowTitle(tr("%1[*] - Resect Studio").arg(title));
    setWindowModified(m_document->isModified());
}

void MainWindow::updateRecentMenu() {
    m_recentMenu->clear();
    const QStringList files = m_document->recentFiles();
    for (const QString& f : files)
        m_recentMenu->addAction(QFileInfo(f).fileName(), this, [this, f] { openFile(f); })->setToolTip(f);
    if (!files.isEmpty()) {
        m_recentMenu->addSeparator();
        m_recentMenu->addAction(tr("Clear list"), m_document, &ScenarioDocument::clearRecentFiles);
    }
    m_recentMenu->setEnabled(!files.isEmpty());
}

void MainWindow::updateStatus() {
    const auto current = m_session->current();
    if (!current) {
        m_statusLabel->setText(isLoading() ? tr("Loading...") : tr("No tissue"));
        return;
    }
    // English has no numerus forms without a translation file: "1 piece" is its own string.
    const QString pieces = current->pieces == 1 ? tr("1 piece") : tr("%n pieces", nullptr, current->pieces);
    m_statusLabel->setText(tr("%1: %2 nodes, %3 tets, %4, min radius ratio %5, stable dt %6 s")
                               .arg(current->tissueName)
                               .arg(current->mesh().nodeCount())
                               .arg(current->mesh().tetCount())
                               .arg(pieces)
                               .arg(current->quality.minRadiusRatio, 0, 'g', 3)
                               .arg(current->stableDt, 0, 'g', 3));
}

void MainWindow::onBusyChanged(bool busy) {
    updateStatus();
    if (busy) {
        if (m_progress == nullptr) {
            m_progress = new QProgressDialog(tr("Loading and meshing the tissue..."), tr("Cancel"), 0, 0, this);
            m_progress->setObjectName(QStringLiteral("loadProgress"));
            m_progress->setWindowTitle(tr("Resect Studio"));
            m_progress->setMinimumDuration(800);
            m_progress->setAutoClose(false);
            m_progress->setAutoReset(false);
            connect(m_progress, &QProgressDialog::canceled, this, [this] {
                m_session->cancel();
                // The dialog hides at once, but meshing stops only at its next check (a sliver
                // removal pass runs to its end): say so until the load has ended.
                statusBar()->showMessage(tr("Cancelling..."));
            });
        }
        return;
    }
    // A cancelled open has said why by now; a cancelled reload of the document says nothing.
    if (statusBar()->currentMessage() == tr("Cancelling..."))
        statusBar()->clearMessage();
    if (m_progress != nullptr) {
        m_progress->hide();
        m_progress->deleteLater();
        m_progress = nullptr;
    }
}

void MainWindow::onLoadProgress(const QString& stage, double fraction) {
    if (m_progress == nullptr)
        return;
    // Busy (0..0) until the mesher reports its first stage, then a percentage.
    if (m_progress->maximum() == 0)
        m_progress->setRange(0, 100);
    m_progress->setLabelText(stage);
    m_progress->setValue(static_cast<int>(std::lround(100.0 * std::clamp(fraction, 0.0, 1.0))));
}

void MainWindow::updateAccuracyPanel() {
    const auto base = m_session->base();
    if (!base) {
        m_accuracyPanel->clearTissue();
        return;
    }
    const Scenario& scenario = m_document->scenario();
    m_accuracyPanel->setBaseCutSettings(scenario.cut);
    std::vector<ScenarioCut> cuts;
    SweepSurface sweep;
    if (scenarioCuts(scenario, cuts).ok() && !cuts.empty())
        sweep = cuts.front().sweep;
    else
        sweep = loopScoopSweep(base->mesh(), 0.6);
    // Shares the session's immutable state without copying it.
    m_accuracyPanel->setTissue(std::shared_ptr<const TetMesh>(base, &base->mesh()), std::move(sweep),
                               base->tissueName, std::shared_ptr<const EmbeddedSurface>(base, &base->surface()));
}

void MainWindow::setLanguagePreference(const QString& code) {
    QSettings settings;
    if (code.isEmpty())
        settings.remove(QString::fromLatin1(kLanguageSettingsKey));
    else
        settings.setValue(QString::fromLatin1(kLanguageSettingsKey), code);
    statusBar()->showMessage(tr("The language changes when Resect Studio is started again."), 10000);
}

} // namespace resect
