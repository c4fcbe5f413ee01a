#include "widgets/authoring_panel.h"

#include "widgets/stroke_player.h"
#include "widgets/stroke_recorder.h"
#include "widgets/sweep_edit_tool.h"
#include "widgets/vtk_viewport.h"

#include <QGridLayout>
#include <QLabel>
#include <QPushButton>
#include <QVBoxLayout>

namespace resect {

namespace {

/// What to do while the recorder is armed with `motion`.
QString recordingStatus(StrokeRecorder::Motion motion) {
    return motion == StrokeRecorder::Motion::Pull
               ? AuthoringPanel::tr("Pull loop: click on the tissue where the loop should cut "
                                    "deepest; drag to turn its opening. The loop is pulled from "
                                    "behind the tissue towards you.")
               : AuthoringPanel::tr("Recording: drag the electrode forward across the view with "
                                    "the left button.");
}

QPushButton* makeButton(const QString& text, const char* name, const QString& tip,
                        QWidget* parent) {
    auto* button = new QPushButton(text, parent);
    button->setObjectName(QString::fromLatin1(name));
    button->setToolTip(tip);
    return button;
}

} // namespace

AuthoringPanel::AuthoringPanel(VtkViewport* viewport, QWidget* parent)
    : QWidget(parent), m_viewport(viewport) {
    setObjectName(QStringLiteral("authoringPanel"));
    m_editor = new SweepEditTool(viewport, this);
    m_recorder = new StrokeRecorder(viewport, this);
    m_player = new StrokePlayer(viewport, this);

    m_draw = makeButton(tr("Draw sweep"), "drawSweepButton",
                        tr("Click the points of the start curve; hold the button to drag a "
                           "point into place. Drag any point to move it."),
                        this);
    m_draw->setCheckable(true);
    m_endCurve = makeButton(tr("End curve"), "endCurveButton",
                            tr("Draw the end curve: click, in order, where each point of the "
                               "start curve ends its path."),
                            this);
    m_record = makeButton(tr("Record stroke"), "recordStrokeButton",
                          tr("Drag the electrode across the view with the left button."), this);
    m_record->setCheckable(true);
    m_pull =
        makeButton(tr("Pull loop"), "pullLoopButton",
                   tr("Click on the tissue where the loop should cut deepest (drag to turn "
                      "its opening): the loop is pulled from behind the tissue towards you, "
                      "as a resectoscope's loop electrode, and takes off what lies inside it."),
                   this);
    m_pull->setCheckable(true);
    m_finish = makeButton(tr("Finish"), "finishButton", tr("Use the drawn sweep surface."),
                          this);
    m_clear = makeButton(tr("Clear"), "clearButton",
                         tr("Remove the drawn curves and the recorded stroke."), this);
    m_play = makeButton(tr("Play stroke"), "playStrokeButton",
                        tr("Replay the last recorded stroke."), this);
    m_status = new QLabel(this);
    m_status->setObjectName(QStringLiteral("authoringStatus"));
    m_status->setWordWrap(true);

    auto* grid = new QGridLayout;
    grid->addWidget(m_draw, 0, 0);
    grid->addWidget(m_endCurve, 0, 1);
    grid->addWidget(m_finish, 0, 2);
    grid->addWidget(m_record, 1, 0);
    grid->addWidget(m_pull, 1, 1);
    grid->addWidget(m_play, 1, 2);
    grid->addWidget(m_clear, 2, 2);
    auto* layout = new QVBoxLayout(this);
    layout->addLayout(grid);
    layout->addWidget(m_status);
    layout->addStretch();

    connect(m_draw, &QPushButton::toggled, this, &AuthoringPanel::setDrawing);
    connect(m_endCurve, &QPushButton::clicked, this, [this] {
        m_draw->setChecked(true);
        m_editor->beginEndCurve();
        updateSweepStatus();
    });
    connect(m_record, &QPushButton::toggled, this,
            [this](bool on) { setRecording(on, int(StrokeRecorder::Motion::Drag)); });
    connect(m_pull, &QPushButton::toggled, this,
            [this](bool on) { setRecording(on, int(StrokeRecorder::Motion::Pull)); });
    connect(m_finish, &QPushButton::clicked, this, &AuthoringPanel::finish);
    connect(m_clear, &QPushButton::clicked, this, &AuthoringPanel::clearAll);
    connect(m_play, &QPushButton::clicked, this, &AuthoringPanel::playStroke);
    connect(m_editor, &SweepEditTool::sweepChanged, this, &AuthoringPanel::updateSweepStatus);
    connect(m_editor, &SweepEditTool::activeCurveChanged, this,
            &AuthoringPanel::updateSweepStatus);
    connect(m_recorder, &StrokeRecorder::strokeRecorded, this,
            &AuthoringPanel::onStrokeRecorded);
    connect(m_recorder, &StrokeRecorder::recordingFailed, this,
            &AuthoringPanel::onRecordingFailed);
    connect(m_recorder, &StrokeRecorder::recordingChanged, this, [this](bool armed) {
        if (!armed) {
            m_record->setChecked(false);
            m_pull->setChecked(false);
        }
    });
    connect(m_recorder, &StrokeRecorder::hintChanged, this, [this](const QString& hint) {
        setStatus(hint.isEmpty() ? recordingStatus(m_recorder->motion()) : hint);
    });

    m_endCurve->setEnabled(false);
    m_finish->setEnabled(false);
    m_play->setEnabled(false);
    setStatus(tr("Draw a sweep surface or record a stroke."));
}

AuthoringPanel::~AuthoringPanel() {
    // The tools are children; take them off the viewport first so it never holds a
    // dangling tool (their destructors do it too, this keeps the order obvious).
    if (m_viewport != nullptr && (m_viewport->tool() == m_editor || m_viewport->tool() == m_recorder))
        m_viewport->setTool(nullptr);
}

void AuthoringPanel::setToolSpec(const ToolSpec& tool) {
    m_tool = tool;
    m_recorder->setToolSpec(tool);
}

void AuthoringPanel::setPickSurface(const TriangleSurface& surface) {
    m_editor->setPickSurface(surface);
    m_recorder->setPickSurface(surface);
}

void AuthoringPanel::clearPickSurface() {
    m_editor->clearPickSurface();
    m_recorder->clearPickSurface();
}

QString AuthoringPanel::statusText() const {
    return m_status->text();
}

void AuthoringPanel::setDrawing(bool on) {
    if (on) {
        m_record->setChecked(false);
        m_pull->setChecked(false);
        if (m_viewport != nullptr)
            m_viewport->setTool(m_editor);
        updateSweepStatus();
    } else if (m_viewport != nullptr && m_viewport->tool() == m_editor) {
        m_viewport->setTool(nullptr);
    }
    m_endCurve->setEnabled(on);
    if (m_draw->isChecked() != on)
        m_draw->setChecked(on);
}

void AuthoringPanel::setRecording(bool on, int motionValue) {
    const auto motion = static_cast<StrokeRecorder::Motion>(motionValue);
    QPushButton* button = motion == StrokeRecorder::Motion::Pull ? m_pull : m_record;
    QPushButton* other = button == m_pull ? m_record : m_pull;
    if (on) {
        m_draw->setChecked(false);
        other->setChecked(false); // disarms first; this button arms again below
        m_player->pause();
        m_recorder->setMotion(motion);
        if (m_viewport != nullptr)
            m_viewport->setTool(m_recorder);
        setStatus(recordingStatus(motion));
    } else if (other->isChecked()) {
        return; // the other motion took over the recorder
    } else if (m_viewport != nullptr && m_viewport->tool() == m_recorder) {
        m_viewport->setTool(nullptr);
    }
    m_recorder->setRecording(on);
    if (button->isChecked() != on)
        button->setChecked(on);
}

void AuthoringPanel::finish() {
    const auto spec = m_editor->sweepSpec();
    if (!spec) {
        setStatus(m_editor->problem());
        return;
    }
    emit sweepFinished(*spec);
    m_draw->setChecked(false);
    m_editor->clear();
    setStatus(tr("Sweep surface handed on."));
}

void AuthoringPanel::clearAll() {
    m_draw->setChecked(false); // clearing ends drawing: the view navigates again
    m_editor->clear();
    m_recorder->clear();
    m_player->stop();
    m_player->setStroke(m_tool, Stroke{});
    m_lastStroke = Stroke{};
    m_play->setEnabled(false);
    setStatus(tr("Draw a sweep surface or record a stroke."));
}

void AuthoringPanel::reset() {
    m_draw->setChecked(false);
    m_record->setChecked(false);
    m_pull->setChecked(false);
    clearAll();
}

void AuthoringPanel::playStroke() {
    if (m_lastStroke.poses.empty())
        return;
    m_recorder->clear();
    m_player->setStroke(m_tool, m_lastStroke);
    m_player->play();
}

void AuthoringPanel::onStrokeRecorded(const Stroke& stroke) {
    m_lastStroke = stroke;
    m_play->setEnabled(true);
    setStatus(tr("Stroke recorded: %1 poses over %2 s.")
                  .arg(stroke.poses.size())
                  .arg(stroke.poses.back().t - stroke.poses.front().t, 0, 'f', 2));
    emit strokeRecorded(stroke);
}

void AuthoringPanel::onRecordingFailed(const QString& reason) {
    setStatus(reason);
}

void AuthoringPanel::updateSweepStatus() {
    const bool valid = m_editor->isValid();
    m_finish->setEnabled(valid);
    if (!m_draw->isChecked())
        return;
    // What the next click does while a curve is being placed; the editor's problem only
    // once both curves have their points and still do not make a sweep.
    const QString next = m_editor->nextClickHint();
    if (valid)
        setStatus(tr("The sweep surface is valid: drag points to adjust it, or press Finish."));
    else if (!next.isEmpty())
        setStatus(next);
    else
        setStatus(m_editor->problem());
}

void AuthoringPanel::setStatus(const QString& text) {
    m_status->setText(text);
}

} // namespace resect
