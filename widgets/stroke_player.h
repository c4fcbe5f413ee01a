#pragma once
// StrokePlayer: replays a recorded stroke (scenario_document.h, Stroke) by moving the loop
// electrode (ToolActor) along it: poseAt(stroke, t) (scenario_sweeps.h) at the player's
// time, which a QTimer advances by the real time elapsed between its ticks times speed()
// while playing. setTime() scrubs. Time runs over [startTime(), endTime()], the time stamps
// of the stroke's first and last poses.

#include "scenario/scenario_document.h"
#include "widgets/tool_actor.h"

#include <QElapsedTimer>
#include <QObject>
#include <QPointer>

class QTimer;

namespace resect {

class VtkViewport;

class StrokePlayer : public QObject {
    Q_OBJECT

public:
    /// The player's tool is shown in `viewport` (may be null: no display; the prop is added
    /// now and removed when the player is destroyed).
    explicit StrokePlayer(VtkViewport* viewport = nullptr, QObject* parent = nullptr);
    ~StrokePlayer() override;

    /// Loads a stroke to play with the given tool: stops, sets the time to startTime() and
    /// shows the tool at the first pose. A stroke without poses hides the tool.
    void setStroke(const ToolSpec& tool, const Stroke& stroke);
    const Stroke& stroke() const { return m_stroke; }
    const ToolSpec& toolSpec() const { return m_tool; }
    bool hasStroke() const { return !m_stroke.poses.empty(); }

    double startTime() const;
    double endTime() const;
    double time() const { return m_time; }
    /// The tool pose at time().
    ToolPose currentPose() const;

    bool isPlaying() const;
    /// Playback speed (1 = real time); non-positive or non-finite values are ignored.
    void setSpeed(double factor);
    double speed() const { return m_speed; }
    /// Timer period while playing, ms (default kDefaultIntervalMs).
    void setInterval(int ms);

    /// Starts playing from time() (from startTime() when at the end). No stroke: no-op.
    void play();
    void pause();
    /// Pauses and returns to startTime().
    void stop();
    /// Moves to t (clamped to [startTime(), endTime()]) and shows the tool there.
    void setTime(double t);
    /// Moves on by `seconds` of stroke time; reaching endTime() while playing pauses and
    /// emits finished().
    void advance(double seconds);

    ToolActor& toolActor() { return m_toolActor; }

    static constexpr int kDefaultIntervalMs = 16;

signals:
    void timeChanged(double t);
    void playingChanged(bool playing);
    /// Playback reached the end of the stroke.
    void finished();

private:
    void tick();
    void showPose();

    QPointer<VtkViewport> m_viewport;
    ToolSpec m_tool;
    Stroke m_stroke;
    double m_time = 0;
    double m_speed = 1;
    QTimer* m_timer = nullptr;
    QElapsedTimer m_sinceTick;
    ToolActor m_toolActor;
};

} // namespace resect
