#include "widgets/accuracy_panel.h"

#include "core/embed/embedded_surface.h"
#include "core/mesh/tet_mesh.h"
#include "widgets/accuracy_chart.h"

#include <QComboBox>
#include <QGridLayout>
#include <QHBoxLayout>
#include <QLabel>
#include <QLocale>
#include <QProgressBar>
#include <QPushButton>
#include <QVBoxLayout>

#include <algorithm>
#include <cmath>

namespace resect {

namespace {

// Preset keys (the combo's item data).
const QString kTiny = QStringLiteral("tiny");
const QString kQuick = QStringLiteral("quick");
const QString kCustom = QStringLiteral("custom");

} // namespace

AccuracyPanel::AccuracyPanel(QWidget* parent) : QWidget(parent) {
    setObjectName(QStringLiteral("accuracyPanel"));

    m_preset = new QComboBox(this);
    m_preset->setObjectName(QStringLiteral("studyPreset"));
    m_preset->addItem(tr("Tiny (seconds)"), kTiny);
    m_preset->addItem(tr("Quick (minutes)"), kQuick);
    m_preset->setToolTip(tr("How many settings the study tries and how often it repeats each cut"));

    m_costAxis = new QComboBox(this);
    m_costAxis->setObjectName(QStringLiteral("costAxis"));
    m_costAxis->addItem(tr("Simulation cost"),
                        static_cast<int>(AccuracyChart::CostAxis::SimMsPerSecond));
    m_costAxis->addItem(tr("Cut time"), static_cast<int>(AccuracyChart::CostAxis::CutMs));
    m_costAxis->setToolTip(
        tr("The cost on the horizontal axis: compute time per simulated second of the cut "
           "tissue, or the time of the cut itself"));

    m_run = new QPushButton(tr("Run"), this);
    m_run->setObjectName(QStringLiteral("runStudy"));
    m_run->setToolTip(tr("Cut copies of the tissue with every method and setting of the preset"));
    m_cancelButton = new QPushButton(tr("Cancel"), this);
    m_cancelButton->setObjectName(QStringLiteral("cancelStudy"));

    m_progress = new QProgressBar(this);
    m_progress->setObjectName(QStringLiteral("studyProgress"));
    m_progress->setRange(0, 1000);
    m_progress->setValue(0);
    m_progress->setTextVisible(false);
    m_status = new QLabel(this);
    m_status->setObjectName(QStringLiteral("studyStatus"));
    m_status->setWordWrap(true);

    m_chart = new AccuracyChart(this);

    m_selection = new QLabel(this);
    m_selection->setObjectName(QStringLiteral("selectedSettings"));
    m_selection->setWordWrap(true);
    m_selection->setTextInteractionFlags(Qt::TextSelectableByMouse);
    m_selection->setMinimumHeight(2 * m_selection->fontMetrics().lineSpacing() +
                                  4); // wraps to two lines
    m_adopt = new QPushButton(tr("Adopt"), this);
    m_adopt->setObjectName(QStringLiteral("adoptSettings"));
    m_adopt->setToolTip(
        tr("Use the selected point's method, d, snapping and relaxation as the scenario's cut "
           "settings"));

    // Two short rows instead of one long one, so that the panel fits a dock a third of a
    // 1280-pixel window wide without cutting off Cancel and Adopt.
    auto* controls = new QGridLayout;
    controls->addWidget(new QLabel(tr("Preset:"), this), 0, 0);
    controls->addWidget(m_preset, 0, 1);
    controls->addWidget(m_run, 0, 2);
    controls->addWidget(new QLabel(tr("Cost:"), this), 1, 0);
    controls->addWidget(m_costAxis, 1, 1);
    controls->addWidget(m_cancelButton, 1, 2);
    controls->setColumnStretch(1, 1);
    auto* selection = new QHBoxLayout;
    selection->addWidget(m_selection, 1);
    selection->addWidget(m_adopt, 0, Qt::AlignTop);
    auto* layout = new QVBoxLayout(this);
    layout->addLayout(controls);
    layout->addWidget(m_progress);
    layout->addWidget(m_status);
    layout->addWidget(m_chart, 1);
    layout->addLayout(selection);
    m_preset->setSizeAdjustPolicy(QComboBox::AdjustToMinimumContentsLengthWithIcon);
    m_costAxis->setSizeAdjustPolicy(QComboBox::AdjustToMinimumContentsLengthWithIcon);
    m_preset->setMinimumContentsLength(8);
    m_costAxis->setMinimumContentsLength(8);

    connect(m_run, &QPushButton::clicked, this, &AccuracyPanel::run);
    connect(m_cancelButton, &QPushButton::clicked, this, &AccuracyPanel::cancel);
    connect(m_adopt, &QPushButton::clicked, this, &AccuracyPanel::adoptSelected);
    connect(m_costAxis, &QComboBox::currentIndexChanged, this, [this] {
        m_chart->setCostAxis(
            static_cast<AccuracyChart::CostAxis>(m_costAxis->currentData().toInt()));
    });
    connect(m_chart, &AccuracyChart::rowClicked, this, &AccuracyPanel::selectRow);
    connect(m_chart, &AccuracyChart::rowDoubleClicked, this, [this](int row) {
        selectRow(row);
        adoptSelected();
    });
    updateState();
    showIdleStatus();
}

AccuracyPanel::~AccuracyPanel() {
    // Queued reports to this object are dropped with it once the worker is joined.
    m_cancel = true;
    if (m_thread.joinable())
        m_thread.join();
}

void AccuracyPanel::setTissue(std::shared_ptr<const TetMesh> mesh, SweepSurface sweep,
                              const QString& name, std::shared_ptr<const EmbeddedSurface> surface) {
    m_mesh = std::move(mesh);
    m_sweep = std::move(sweep);
    m_name = name;
    m_surface = std::move(surface);
    updateState();
    showIdleStatus();
}

void AccuracyPanel::setTissue(const TetMesh& mesh, SweepSurface sweep, const QString& name) {
    setTissue(std::make_shared<const TetMesh>(mesh), std::move(sweep), name);
}

void AccuracyPanel::clearTissue() {
    m_mesh.reset();
    m_surface.reset();
    m_sweep = SweepSurface();
    m_name.clear();
    updateState();
    showIdleStatus();
}

void AccuracyPanel::clearResults() {
    if (m_running) {
        m_cancel = true;
        m_dropResult = true;
    }
    m_rows.clear();
    m_chart->setRows({});
    m_selected = -1;
    m_studied = false;
    m_progress->setValue(0);
    updateState();
    showIdleStatus();
    emit rowSelected(-1);
}

CutSettings AccuracyPanel::cutSettingsForRow(const StudyRow& row, const CutSettings& base) {
    CutSettings s = base;
    if (row.method == "subdivision") {
        s.method = CutMethod::Subdivision;
    } else {
        s.method = CutMethod::Hybrid;
        s.triangulation = row.method == "hybrid-standard" ? FaceTriangulation::Standard
                                                          : FaceTriangulation::Enhanced;
    }
    s.d = row.d;
    s.snap = row.snap;
    s.relaxSteps = row.relaxSteps;
    return s;
}

void AccuracyPanel::setCustomConfig(const StudyConfig& config) {
    m_customConfig = config;
    m_hasCustom = true;
    int index = m_preset->findData(kCustom);
    if (index < 0) {
        m_preset->addItem(tr("Custom"), kCustom);
        index = m_preset->count() - 1;
    }
    m_preset->setCurrentIndex(index);
}

StudyConfig AccuracyPanel::studyConfig() const {
    const QString key = m_preset->currentData().toString();
    if (key == kCustom && m_hasCustom)
        return m_customConfig;
    return key == kQuick ? quickConfig() : tinyConfig();
}

void AccuracyPanel::selectRow(int row) {
    if (row < 0 || row >= static_cast<int>(m_rows.size()))
        row = -1;
    m_selected = row;
    m_chart->setSelectedRow(row);
    updateState();
    emit rowSelected(row);
}

void AccuracyPanel::run() {
    if (m_running || !m_mesh)
        return;
    if (m_thread.joinable())
        m_thread.join();
    m_cancel = false;
    m_dropResult = false;
    m_running = true;
    m_lastPermille = -1;
    m_lastStage.clear();
    m_rows.clear();
    m_chart->setRows({});
    m_selected = -1;
    m_progress->setValue(0);
    m_status->setText(tr("Starting the study..."));
    updateState();
    emit rowSelected(-1);

    m_thread = std::thread([this, mesh = m_mesh, surface = m_surface, sweep = m_sweep,
                            name = m_name.toStdString(), config = studyConfig()] {
        std::vector<StudyRow> rows;
        const Status status = runAccuracyStudyOn(
            *mesh, sweep, name, config, rows,
            [this](double fraction, const std::string& stage) {
                reportProgress(fraction, stage);
                return !m_cancel.load();
            },
            surface && !surface->empty() ? surface.get() : nullptr);
        QMetaObject::invokeMethod(
            this,
            [this, status, rows = std::move(rows)]() mutable { finish(status, std::move(rows)); },
            Qt::QueuedConnection);
    });
}

void AccuracyPanel::reportProgress(double fraction, const std::string& stage) {
    // Worker thread: post only changes, queued to the panel's thread.
    const int permille = static_cast<int>(std::lround(std::clamp(fraction, 0.0, 1.0) * 1000));
    if (permille == m_lastPermille && stage == m_lastStage)
        return;
    m_lastPermille = permille;
    m_lastStage = stage;
    QMetaObject::invokeMethod(
        this,
        [this, permille, text = QString::fromStdString(stage)] {
            if (!m_running)
                return;
            m_progress->setValue(permille);
            m_status->setText(tr("Running: %1").arg(text));
        },
        Qt::QueuedConnection);
}

void AccuracyPanel::finish(Status status, std::vector<StudyRow> rows) {
    if (m_thread.joinable())
        m_thread.join();
    m_running = false;
    if (m_dropResult) {
        // The study was of a document that is gone.
        m_dropResult = false;
        updateState();
        showIdleStatus();
        emit studyFinished(false, tr("Study cancelled: another document was opened."));
        return;
    }
    m_studied = true;
    m_rows = std::move(rows);
    m_chart->setRows(m_rows);
    m_selected = -1;
    const int n = static_cast<int>(m_rows.size());
    QString message;
    if (status.ok()) {
        m_progress->setValue(m_progress->maximum());
        message = tr("Study finished: %n row(s).", nullptr, n);
    } else if (status.message() == "cancelled") {
        message = tr("Study cancelled after %n row(s).", nullptr, n);
    } else {
        message = tr("Study failed: %1").arg(QString::fromStdString(status.message()));
    }
    m_status->setText(message);
    updateState();
    emit studyFinished(status.ok(), message);
}

void AccuracyPanel::cancel() {
    if (m_running) {
        m_cancel = true;
        m_status->setText(tr("Cancelling..."));
    }
}

void AccuracyPanel::adoptSelected() {
    if (m_selected < 0 || m_selected >= static_cast<int>(m_rows.size()))
        return;
    emit adoptRequested(
        cutSettingsForRow(m_rows[static_cast<std::size_t>(m_selected)], m_baseSettings));
}

QString AccuracyPanel::rowSummary(int row) const {
    if (row < 0 || row >= static_cast<int>(m_rows.size()))
        return tr("Click a point of the chart to see its settings; drag a rectangle to zoom, double-click to show all.");
    const StudyRow& r = m_rows[static_cast<std::size_t>(row)];
    const QLocale locale;
    const auto num = [&](double v) { return locale.toString(v, 'g', 3); };
    return tr("%1, d = %2, snapping %3, %n relaxation step(s): error max %4 mean edge lengths, %5 "
              "tets, cut %6 ms, "
              "simulation %7 ms per simulated second",
              nullptr, r.relaxSteps)
        .arg(AccuracyChart::methodLabel(r.method), num(r.d), r.snap ? tr("on") : tr("off"),
             num(r.sweepErrorMax))
        .arg(r.tets)
        .arg(num(r.cutMs), num(r.simMsPerSecond));
}

void AccuracyPanel::updateState() {
    m_run->setEnabled(!m_running && m_mesh != nullptr);
    m_cancelButton->setEnabled(m_running);
    m_preset->setEnabled(!m_running);
    m_adopt->setEnabled(m_selected >= 0);
    m_selection->setText(rowSummary(m_selected));
}

void AccuracyPanel::showIdleStatus() {
    // Only before the first study: afterwards its message stays (new tissues arrive whenever
    // the document changes, e.g. right after Adopt).
    if (m_running || m_studied)
        return;
    m_status->setText(m_mesh ? tr("Ready: %1 (%n tet(s)).", nullptr, m_mesh->tetCount()).arg(m_name)
                             : tr("Open a scenario with a tissue to run the study."));
}

} // namespace resect
