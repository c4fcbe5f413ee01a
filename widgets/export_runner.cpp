#include "widgets/export_runner.h"

#include <QDir>
#include <QProgressDialog>

#include <algorithm>
#include <cmath>
#include <memory>

namespace resect {

ExportRunner::ExportRunner(QObject* parent) : QObject(parent) {}

ExportRunner::~ExportRunner() {
    // The worker's queued reports to this object are dropped with it once it is joined.
    m_cancel = true;
    if (m_thread.joinable())
        m_thread.join();
}

bool ExportRunner::start(const Scenario& scenario, const QString& outDir,
                         const ExportOptions& options) {
    return launch(
        [scenario, out = outDir.toStdString(), options](ExportSummary& summary,
                                                        const ExportProgress& progress) {
            return exportTrainerPackage(scenario, out, options, summary, progress);
        },
        outDir);
}

bool ExportRunner::start(const QString& scenarioPath, const QString& outDir,
                         const ExportOptions& options) {
    return launch(
        [path = scenarioPath.toStdString(), out = outDir.toStdString(),
         options](ExportSummary& summary, const ExportProgress& progress) {
            return exportTrainerPackage(path, out, options, summary, progress);
        },
        outDir);
}

bool ExportRunner::launch(Job job, const QString& outDir) {
    if (m_running)
        return false;
    if (m_thread.joinable())
        m_thread.join();
    m_cancel = false;
    m_running = true;
    m_outDir = outDir;
    m_lastPercent = -1;
    m_lastStage.clear();
    m_thread = std::thread([this, job = std::move(job)] {
        auto summary = std::make_shared<ExportSummary>();
        const Status status = job(*summary, [this](double fraction, const std::string& stage) {
            reportProgress(fraction, stage);
            return !m_cancel.load();
        });
        QMetaObject::invokeMethod(
            this, [this, status, summary] { finish(status, std::move(*summary)); },
            Qt::QueuedConnection);
    });
    return true;
}

void ExportRunner::reportProgress(double fraction, const std::string& stage) {
    // Worker thread: send only changes, queued to the runner's thread.
    const int percent = static_cast<int>(std::lround(std::clamp(fraction, 0.0, 1.0) * 100));
    if (percent == m_lastPercent && stage == m_lastStage)
        return;
    m_lastPercent = percent;
    m_lastStage = stage;
    QMetaObject::invokeMethod(
        this,
        [this, percent, text = QString::fromStdString(stage)] {
            emit progress(percent, stageText(text));
        },
        Qt::QueuedConnection);
}

void ExportRunner::finish(Status status, ExportSummary summary) {
    if (m_thread.joinable())
        m_thread.join();
    m_running = false;
    m_summary = std::move(summary);
    QString message;
    QStringList files;
    if (status.ok()) {
        const QDir dir(QString::fromStdString(m_summary.outDir));
        for (const std::string& f : m_summary.files)
            files << dir.filePath(QString::fromStdString(f));
        const int n = static_cast<int>(files.size());
        message = m_summary.expectationsPassed
                      ? tr("Exported %n file(s) to %1; the expectations passed.", nullptr, n)
                            .arg(dir.path())
                      : tr("Exported %n file(s) to %1; some expectations failed.", nullptr, n)
                            .arg(dir.path());
    } else if (m_summary.failure == ExportFailure::Cancelled) {
        message = tr("Export to %1 cancelled.").arg(m_outDir);
    } else {
        message = tr("Export failed: %1").arg(QString::fromStdString(status.message()));
    }
    emit finished(status.ok(), message, files);
}

void ExportRunner::cancel() {
    if (m_running)
        m_cancel = true;
}

QProgressDialog* ExportRunner::showProgressDialog(QWidget* parent) {
    if (!m_running)
        return nullptr;
    auto* dialog =
        new QProgressDialog(tr("Exporting the trainer package..."), tr("Cancel"), 0, 100, parent);
    dialog->setObjectName(QStringLiteral("exportProgressDialog"));
    dialog->setWindowTitle(tr("Export for the trainer"));
    dialog->setWindowModality(Qt::WindowModal);
    dialog->setAutoClose(false);
    dialog->setAutoReset(false);
    dialog->setMinimumDuration(0);
    connect(dialog, &QProgressDialog::canceled, this, &ExportRunner::cancel);
    connect(this, &ExportRunner::progress, dialog, [dialog](int percent, const QString& stage) {
        dialog->setValue(percent);
        dialog->setLabelText(stage);
    });
    connect(this, &ExportRunner::finished, dialog, [dialog] {
        dialog->close();
        dialog->deleteLater();
    });
    dialog->show();
    return dialog;
}

QString ExportRunner::stageText(const QString& stage) {
    const qsizetype colon = stage.indexOf(QLatin1Char(':'));
    const QString key = colon < 0 ? stage : stage.left(colon);
    const QString name = colon < 0 ? QString() : stage.mid(colon + 1);
    if (key == QLatin1String("checking"))
        return tr("Checking the output folder...");
    if (key == QLatin1String("meshing"))
        return tr("Meshing %1...").arg(name);
    if (key == QLatin1String("writing"))
        return tr("Writing the mesh and surface of %1...").arg(name);
    if (key == QLatin1String("replaying"))
        return tr("Replaying the strokes on %1...").arg(name);
    if (key == QLatin1String("writing-result"))
        return tr("Writing the result of %1...").arg(name);
    if (key == QLatin1String("packaging"))
        return tr("Writing the scenario and the report...");
    if (key == QLatin1String("manifest"))
        return tr("Writing the manifest...");
    if (key == QLatin1String("finishing"))
        return tr("Moving the package into place...");
    if (key == QLatin1String("done"))
        return tr("Done.");
    return stage;
}

} // namespace resect
