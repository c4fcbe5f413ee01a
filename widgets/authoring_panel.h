#pragma once
// AuthoringPanel: buttons that author cuts in a VtkViewport with the SweepEditTool (draw a
// sweep surface), the StrokeRecorder (record a tool stroke, dragged across the view or pulled
// towards the camera) and the StrokePlayer (replay the last stroke). The panel owns the three
// and makes the first two the viewport's tool while their button is down; a status line says
// what to do next or what is wrong, also while a stroke is being dragged (the recorder's
// hints).
//
// Buttons (objectName): "Draw sweep" (drawSweepButton, checkable), "End curve"
// (endCurveButton), "Record stroke" (recordStrokeButton, checkable: the Drag motion), "Pull
// loop" (pullLoopButton, checkable: the Pull motion, the loop pulled from behind the tissue
// towards the camera), "Finish" (finishButton: hands on the drawn sweep when it is valid),
// "Clear" (clearButton), "Play stroke" (playStrokeButton: replays the last recorded stroke).
// The status line is authoringStatus.
//
// What the author makes is handed on by sweepFinished() and strokeRecorded(); adding it to
// the document (with undo) is up to the receiver.

#include "core/mesh/triangle_surface.h"
#include "scenario/scenario_document.h"

#include <QPointer>
#include <QWidget>

class QLabel;
class QPushButton;

namespace resect {

class StrokePlayer;
class StrokeRecorder;
class SweepEditTool;
class VtkViewport;

class AuthoringPanel : public QWidget {
    Q_OBJECT

public:
    explicit AuthoringPanel(VtkViewport* viewport, QWidget* parent = nullptr);
    ~AuthoringPanel() override;

    /// The tool recorded and replayed (copied).
    void setToolSpec(const ToolSpec& tool);
    /// The tissue that new sweep points and stroke depths are picked on (copied).
    void setPickSurface(const TriangleSurface& surface);
    void clearPickSurface();

    SweepEditTool& sweepEditor() { return *m_editor; }
    StrokeRecorder& strokeRecorder() { return *m_recorder; }
    StrokePlayer& strokePlayer() { return *m_player; }
    /// The last stroke recorded (no poses before the first).
    const Stroke& lastStroke() const { return m_lastStroke; }
    QString statusText() const;
    /// Back to the start (a new document): drawing and recording stop, the drawn curves, the
    /// recorded stroke and its replay are cleared, and the status line says what to do.
    void reset();

signals:
    /// "Finish" with a valid drawn sweep.
    void sweepFinished(const resect::SweepSpec& sweep);
    /// A stroke was recorded.
    void strokeRecorded(const resect::Stroke& stroke);

private:
    void setDrawing(bool on);
    /// Arms the recorder with `motion` (on) or disarms it (off).
    void setRecording(bool on, int motion);
    void finish();
    void clearAll();
    void playStroke();
    void onStrokeRecorded(const Stroke& stroke);
    void onRecordingFailed(const QString& reason);
    void updateSweepStatus();
    void setStatus(const QString& text);

    QPointer<VtkViewport> m_viewport;
    SweepEditTool* m_editor = nullptr;
    StrokeRecorder* m_recorder = nullptr;
    StrokePlayer* m_player = nullptr;
    Stroke m_lastStroke;
    ToolSpec m_tool;

    QPushButton* m_draw = nullptr;
    QPushButton* m_endCurve = nullptr;
    QPushButton* m_record = nullptr;
    QPushButton* m_pull = nullptr;
    QPushButton* m_finish = nullptr;
    QPushButton* m_clear = nullptr;
    QPushButton* m_play = nullptr;
    QLabel* m_status = nullptr;
};

} // namespace resect
