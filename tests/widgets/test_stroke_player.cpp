// StrokePlayer (widgets/stroke_player.h) and ToolActor (widgets/tool_actor.h): replaying a
// stroke moves the loop electrode along poseAt(stroke, t).

#include "scenario/scenario_sweeps.h"
#include "widgets/stroke_player.h"
#include "widgets/tool_actor.h"
#include "widgets/vtk_viewport.h"

#include <QSignalSpy>
#include <QTest>

#include <vtkActor.h>
#include <vtkPolyData.h>

#include <cmath>

using namespace resect;

namespace {

ToolSpec barTool() {
    ToolSpec tool;
    tool.size = 2;
    tool.curve = {Vec3(0, 0, 0), Vec3(0, 0, 0.5), Vec3(0, 0.5, 0.5)};
    return tool;
}

ToolPose pose(double t, const Vec3& p) {
    ToolPose out;
    out.t = t;
    out.position = p;
    return out;
}

/// Poses at t = 1, 2, 3: (0,0,0) -> (1,0,0) -> (1,2,0), identity orientation.
Stroke lStroke() {
    Stroke s;
    s.name = "L";
    s.poses = {pose(1, Vec3(0, 0, 0)), pose(2, Vec3(1, 0, 0)), pose(3, Vec3(1, 2, 0))};
    return s;
}

bool close(const Vec3& a, const Vec3& b) {
    return (a - b).norm() < 1e-12;
}

} // namespace

class TestStrokePlayer : public QObject {
    Q_OBJECT

private slots:
    void toolActorShowsThePose() {
        ToolActor actor;
        QVERIFY(!actor.isVisible());
        const ToolSpec tool = barTool();
        const ToolPose p = pose(0, Vec3(1, 2, 3));
        actor.setPose(tool, p);
        QVERIFY(actor.isVisible());
        QVERIFY(actor.actor()->GetVisibility());
        QCOMPARE(actor.curve().size(), tool.curve.size());
        QVERIFY(close(actor.curve()[2], Vec3(1, 3, 4)));
        QCOMPARE(actor.polyline()->GetNumberOfPoints(), vtkIdType(3));
        QVERIFY(actor.radius() > 0);
        actor.setRadius(0.1);
        QCOMPARE(actor.radius(), 0.1);
        // Repeated and non-finite points are dropped; fewer than two left hides the tool.
        actor.setCurve({Vec3(0, 0, 0), Vec3(0, 0, 0), Vec3(std::nan(""), 0, 0)});
        QVERIFY(!actor.isVisible());
        QVERIFY(!actor.actor()->GetVisibility());
        actor.setPose(ToolSpec{}, p); // no tool curve
        QVERIFY(!actor.isVisible());
    }

    void scrubbingPositionsTheTool() {
        VtkViewport view;
        StrokePlayer player(&view);
        const ToolSpec tool = barTool();
        QSignalSpy times(&player, &StrokePlayer::timeChanged);
        player.setStroke(tool, lStroke());
        QCOMPARE(player.startTime(), 1.0);
        QCOMPARE(player.endTime(), 3.0);
        QCOMPARE(player.time(), 1.0);
        QCOMPARE(times.count(), 1);
        QVERIFY(player.toolActor().isVisible());
        QVERIFY(close(player.toolActor().curve()[0], Vec3(0, 0, 0)));

        const struct {
            double t, expectedT;
            Vec3 position;
        } cases[] = {{1.5, 1.5, Vec3(0.5, 0, 0)}, {2.5, 2.5, Vec3(1, 1, 0)},
                     {3.0, 3.0, Vec3(1, 2, 0)},   {7.0, 3.0, Vec3(1, 2, 0)},
                     {-2.0, 1.0, Vec3(0, 0, 0)},  {2.0, 2.0, Vec3(1, 0, 0)}};
        int expectedSignals = 1;
        for (const auto& c : cases) {
            const double before = player.time();
            player.setTime(c.t);
            if (c.expectedT != before)
                ++expectedSignals;
            QCOMPARE(times.count(), expectedSignals);
            QCOMPARE(player.time(), c.expectedT);
            QCOMPARE(times.last().at(0).toDouble(), c.expectedT);
            QVERIFY(close(player.currentPose().position, c.position));
            // The tool shown is the tool curve at that pose.
            const std::vector<Vec3> expected = toolCurveAt(tool, player.currentPose());
            QCOMPARE(player.toolActor().curve().size(), expected.size());
            for (std::size_t i = 0; i < expected.size(); ++i)
                QVERIFY(close(player.toolActor().curve()[i], expected[i]));
        }
        QVERIFY(!player.isPlaying());
        player.advance(0.25);
        QCOMPARE(player.time(), 2.25);
        player.stop();
        QCOMPARE(player.time(), 1.0);
    }

    void playingRunsToTheEnd() {
        StrokePlayer player;
        player.setStroke(barTool(), lStroke());
        player.setSpeed(20); // the 2 s stroke plays in about 0.1 s
        QSignalSpy finished(&player, &StrokePlayer::finished);
        QSignalSpy playing(&player, &StrokePlayer::playingChanged);
        QSignalSpy times(&player, &StrokePlayer::timeChanged);
        player.play();
        QVERIFY(player.isPlaying());
        QVERIFY(finished.wait(10000));
        QCOMPARE(finished.count(), 1);
        QVERIFY(!player.isPlaying());
        QCOMPARE(player.time(), 3.0);
        QCOMPARE(playing.count(), 2);
        QCOMPARE(playing.at(0).at(0).toBool(), true);
        QCOMPARE(playing.at(1).at(0).toBool(), false);
        // Time only went forwards.
        for (int i = 1; i < times.count(); ++i)
            QVERIFY(times.at(i).at(0).toDouble() > times.at(i - 1).at(0).toDouble());
        QVERIFY(close(player.toolActor().curve()[0], Vec3(1, 2, 0)));
        // Playing again starts over.
        player.play();
        QCOMPARE(player.time(), 1.0);
        player.pause();
        QVERIFY(!player.isPlaying());
    }

    void noStrokeIsHarmless() {
        StrokePlayer player;
        player.setStroke(barTool(), Stroke{});
        QVERIFY(!player.hasStroke());
        QVERIFY(!player.toolActor().isVisible());
        player.play();
        QVERIFY(!player.isPlaying());
        player.setTime(5);
        player.advance(1);
        QCOMPARE(player.time(), 0.0);
    }
};

QTEST_MAIN(TestStrokePlayer)
#include "test_stroke_player.moc"
