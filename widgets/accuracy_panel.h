#pragma once
// AccuracyPanel: "Accuracy vs time" for the open scenario. Runs the accuracy study
// (scenario/accuracy_study.h runAccuracyStudyOn) on the scenario's tissue and cut on a worker
// thread, with progress and cancel, shows the rows in an AccuracyChart, and lets the author
// click a point to see its settings and adopt its method, triangulation, d, snapping and
// relaxation steps as the scenario's cut settings (adoptRequested; the main window hands
// them to ScenarioDocument::setCutSettings, one undoable edit).
//
// The study never runs on the GUI thread: Run starts a std::thread; its progress and result
// are posted back with queued calls. Cancel sets a flag the study's progress callback returns,
// so the study stops at its next row or repeat. One study at a time (Run while running is
// ignored); the destructor cancels a running study and waits for it.

#include "core/sweep/sweep_surface.h"
#include "scenario/accuracy_study.h"
#include "scenario/scenario_document.h"

#include <QString>
#include <QWidget>

#include <atomic>
#include <memory>
#include <string>
#include <thread>
#include <vector>

class QComboBox;
class QLabel;
class QProgressBar;
class QPushButton;

namespace resect {

class AccuracyChart;
class EmbeddedSurface;
class TetMesh;

class AccuracyPanel : public QWidget {
    Q_OBJECT

public:
    explicit AccuracyPanel(QWidget* parent = nullptr);
    /// Cancels a running study and waits for it.
    ~AccuracyPanel() override;

    /// What the study cuts: the tissue (e.g. TissueSession::base()->mesh(), the uncut tissue,
    /// which current() is too when the scenario has no cut yet; shared without a copy through
    /// an aliasing shared_ptr to the TissueState), the sweep (the scenario's first cut, or
    /// loopScoopSweep when it has none), the name shown in the rows and, optionally, the
    /// embedded surface bound to the mesh (its cut is timed as surface_ms). Takes effect at
    /// the next Run; a running study keeps its own tissue; the rows shown stay.
    void setTissue(std::shared_ptr<const TetMesh> mesh, SweepSurface sweep, const QString& name,
                   std::shared_ptr<const EmbeddedSurface> surface = {});
    /// As above from a copy of the mesh.
    void setTissue(const TetMesh& mesh, SweepSurface sweep, const QString& name);
    /// No tissue: Run is disabled.
    void clearTissue();
    /// Forgets the study shown (a new document): cancels a running one (its result is
    /// dropped), clears the rows, the chart, the selection and the status line.
    void clearResults();
    bool hasTissue() const { return m_mesh != nullptr; }

    /// The cut settings that Adopt starts from (the scenario's current ones): adoptRequested
    /// carries these with the chosen row's method, triangulation, d, snap and relax_steps.
    void setBaseCutSettings(const CutSettings& settings) { m_baseSettings = settings; }
    /// `base` with the settings of `row` ("subdivision": Subdivision, keeping base's
    /// triangulation; "hybrid-standard" / "hybrid-enhanced": Hybrid with that triangulation).
    static CutSettings cutSettingsForRow(const StudyRow& row, const CutSettings& base = {});

    /// Adds (or replaces) a "Custom" preset with this configuration and selects it (tests use
    /// a configuration smaller than "tiny"). config.meshes is not used.
    void setCustomConfig(const StudyConfig& config);
    /// The configuration of the selected preset ("tiny", "quick" or the custom one).
    StudyConfig studyConfig() const;

    bool isRunning() const { return m_running; }
    /// The rows of the last study (those done before a cancel or failure, too).
    const std::vector<StudyRow>& rows() const { return m_rows; }
    /// The selected row, -1 for none.
    int selectedRow() const { return m_selected; }
    /// Selects a row (as a click on its point does); -1 or an invalid index clears.
    void selectRow(int row);
    AccuracyChart* chart() const { return m_chart; }

public slots:
    /// Starts the study on the tissue; ignored while one runs or without a tissue.
    void run();
    /// Asks the running study to stop; studyFinished(false, ...) follows. No-op when idle.
    void cancel();
    /// Emits adoptRequested for the selected row; no-op without one.
    void adoptSelected();

signals:
    /// A study ended (always after run() started one): ok, or why not ("... cancelled.",
    /// or the study's error).
    void studyFinished(bool ok, const QString& message);
    /// The author adopts a row's settings (Adopt or a double click on a point).
    void adoptRequested(const CutSettings& settings);
    /// The selection changed (-1: none).
    void rowSelected(int row);

private:
    void reportProgress(double fraction, const std::string& stage);
    void finish(Status status, std::vector<StudyRow> rows);
    void updateState();
    void showIdleStatus();
    QString rowSummary(int row) const;

    std::shared_ptr<const TetMesh> m_mesh;
    std::shared_ptr<const EmbeddedSurface> m_surface;
    SweepSurface m_sweep;
    QString m_name;
    CutSettings m_baseSettings;
    StudyConfig m_customConfig;
    bool m_hasCustom = false;

    std::thread m_thread;
    std::atomic<bool> m_cancel{false};
    bool m_running = false;
    bool m_dropResult = false; ///< clearResults() during a study: its result is not shown
    bool m_studied = false; ///< a study has finished (its message stays in the status line)
    // Last progress posted (worker thread only), to post only changes.
    int m_lastPermille = -1;
    std::string m_lastStage;

    std::vector<StudyRow> m_rows;
    int m_selected = -1;

    QComboBox* m_preset = nullptr;
    QComboBox* m_costAxis = nullptr;
    QPushButton* m_run = nullptr;
    QPushButton* m_cancelButton = nullptr;
    QProgressBar* m_progress = nullptr;
    QLabel* m_status = nullptr;
    AccuracyChart* m_chart = nullptr;
    QLabel* m_selection = nullptr;
    QPushButton* m_adopt = nullptr;
};

} // namespace resect
