#pragma once
// ExportRunner: runs the trainer export (scenario/trainer_export.h) on a worker thread for
// the studio, reporting progress and the result as signals on the runner's (GUI) thread;
// cancel() stops it at the next progress report, leaving no package behind. One export at a
// time; destroying the runner cancels a running export and waits for it.

#include "scenario/trainer_export.h"

#include <QObject>
#include <QString>
#include <QStringList>

#include <atomic>
#include <functional>
#include <string>
#include <thread>

class QProgressDialog;
class QWidget;

namespace resect {

class ExportRunner : public QObject {
    Q_OBJECT
public:
    explicit ExportRunner(QObject* parent = nullptr);
    ~ExportRunner() override;

    /// Starts exporting a copy of `scenario` into `outDir`; false (and nothing happens) if
    /// an export is already running. progress() and finished() follow, always finished().
    bool start(const Scenario& scenario, const QString& outDir, const ExportOptions& options = {});
    /// As above for a scenario file (loaded on the worker thread).
    bool start(const QString& scenarioPath, const QString& outDir,
               const ExportOptions& options = {});

    bool isRunning() const { return m_running; }
    /// The last finished export's summary (ExportSummary::failure tells why it failed).
    const ExportSummary& summary() const { return m_summary; }

    /// A modal progress dialog (objectName "exportProgressDialog", 0..100) following this
    /// runner, with Cancel bound to cancel(); it closes and deletes itself on finished().
    /// Call right after start().
    QProgressDialog* showProgressDialog(QWidget* parent);

    /// The translated text of a stage reported by exportTrainerPackage ("replaying:polyp"
    /// -> "Replaying polyp..."); unknown stages are returned as they are.
    static QString stageText(const QString& stage);

public slots:
    /// Asks the running export to stop; finished(false, ...) follows. No-op when idle.
    void cancel();

signals:
    /// On the runner's thread, only when the percentage (0..100) or the stage changes;
    /// `stage` is the translated text (stageText) of the export's stage.
    void progress(int percent, const QString& stage);
    /// ok: the package is complete in `message`'s folder; `files` are the package's files
    /// (absolute paths, manifest.json last). Otherwise `message` says why (naming the folder
    /// or file) and `files` is empty.
    void finished(bool ok, const QString& message, const QStringList& files);

private:
    using Job = std::function<Status(ExportSummary&, const ExportProgress&)>;
    bool launch(Job job, const QString& outDir);
    void reportProgress(double fraction, const std::string& stage);
    void finish(Status status, ExportSummary summary);

    std::thread m_thread;
    std::atomic<bool> m_cancel{false};
    bool m_running = false;
    QString m_outDir;
    ExportSummary m_summary;
    // Last progress sent (worker thread only), to send only changes.
    int m_lastPercent = -1;
    std::string m_lastStage;
};

} // namespace resect
