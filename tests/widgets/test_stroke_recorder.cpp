// StrokeRecorder (widgets/stroke_recorder.h): recording a tool stroke with the mouse in a
// VtkViewport under the offscreen platform (camera maths only, no OpenGL), with an injected
// clock so the time stamps are deterministic.

#include "core/mesh/box_mesh.h"
#include "core/sweep/sweep_surface.h"
#include "scenario/scenario_sweeps.h"
#include "widgets/camera_ray.h"
#include "widgets/stroke_recorder.h"
#include "widgets/surface_pick.h"
#include "widgets/vtk_viewport.h"

#include <QSignalSpy>
#include <QTest>

#include <vtkCamera.h>
#include <vtkPolyData.h>

#include <cmath>
#include <numbers>
#include <random>

using namespace resect;

namespace {

/// A loop electrode: a half circle of radius 1 in the tool's x-z plane, chord along x,
/// bulging towards -z; 9 points.
ToolSpec loopTool(double size) {
    ToolSpec tool;
    tool.size = size;
    for (int k = 0; k <= 8; ++k) {
        const double a = std::numbers::pi * k / 8.0;
        tool.curve.emplace_back(std::cos(a), 0.0, -std::sin(a));
    }
    return tool;
}

Vec3 cameraPosition(vtkCamera* camera) {
    double p[3];
    camera->GetPosition(p);
    return {p[0], p[1], p[2]};
}

/// True if a and b agree to `relative` of max(|b|, scale).
bool close(const Vec3& a, const Vec3& b, double scale, double relative = 1e-9) {
    return (a - b).norm() <= relative * std::max(b.norm(), scale);
}

/// The sweep of `stroke` with `tool` (scenario_sweeps.h: SweepSurface::fromCurves).
Status sweepOf(const ToolSpec& tool, const Stroke& stroke) {
    Scenario scenario;
    scenario.tool = tool;
    scenario.strokes.push_back(stroke);
    SweepSurface sweep;
    return strokeSweep(scenario, 0, sweep);
}

/// A shown viewport with a box mesh (the camera framed on it) and an armed recorder whose
/// clock is `clock`.
struct Scene {
    explicit Scene(double* clock, double scale = 1.0)
        : mesh(makeBoxTetMesh(Vec3::Zero(), Vec3(2, 1, 1) * scale, 4, 2, 2)),
          recorder(&view), tool(loopTool(0.2 * scale)) {
        view.resize(640, 480);
        view.show();
        view.setTetMesh(mesh);
        recorder.setToolSpec(tool);
        recorder.setStrokeName("pass");
        recorder.setClock([clock] { return *clock; });
        recorder.setRecording(true);
        view.setTool(&recorder);
    }
    VtkViewport view;
    TetMesh mesh;
    StrokeRecorder recorder;
    ToolSpec tool;
};

} // namespace

class TestStrokeRecorder : public QObject {
    Q_OBJECT

private slots:
    void orientationPutsTheLoopAcrossTheDrag() {
        const ToolSpec tool = loopTool(1.0);
        const Vec3 view = Vec3(0.3, -1.0, 0.2).normalized();
        const Vec3 drag = Vec3(1.0, 0.5, -0.4); // not perpendicular to the view
        const Eigen::Vector4d q = strokeOrientation(tool, drag, view);
        QVERIFY(std::abs(q.norm() - 1) < 1e-12);
        ToolPose pose;
        pose.orientation = q;
        const std::vector<Vec3> c = toolCurveAt(tool, pose);
        const Vec3 d = (drag - drag.dot(view) * view).normalized();
        // The loop's plane is perpendicular to the drag ...
        for (const Vec3& p : c)
            QVERIFY(std::abs((p - c.front()).dot(d)) < 1e-12);
        // ... its chord lies in the view plane, and it bulges away from the viewer.
        QVERIFY(std::abs((c.back() - c.front()).dot(view)) < 1e-12);
        QVERIFY((c[4] - 0.5 * (c.front() + c.back())).dot(view) > 0.9);
        // Unusable directions give the identity, never NaN.
        QCOMPARE(strokeOrientation(tool, view, view), Eigen::Vector4d(1, 0, 0, 0));
        QCOMPARE(strokeOrientation(tool, Vec3::Zero(), view), Eigen::Vector4d(1, 0, 0, 0));
        const Vec3 nan(std::nan(""), 0, 0);
        QCOMPARE(strokeOrientation(tool, nan, view), Eigen::Vector4d(1, 0, 0, 0));
        // A tool of one point still gives a rotation.
        ToolSpec dot;
        dot.curve = {Vec3(1, 2, 3)};
        QVERIFY(std::abs(strokeOrientation(dot, drag, view).norm() - 1) < 1e-12);
    }

    void dragRecordsAStroke_data() {
        QTest::addColumn<double>("scale");
        QTest::newRow("mm") << 1.0;
        QTest::newRow("1e-3") << 1e-3;
        QTest::newRow("1e3") << 1e3;
    }
    void dragRecordsAStroke() {
        QFETCH(double, scale);
        double clock = 100.0;
        Scene scene(&clock, scale);
        QVERIFY(QTest::qWaitForWindowExposed(&scene.view));
        vtkCamera* camera = scene.view.camera();
        const Vec3 positionBefore = cameraPosition(camera);
        const Vec3 focal = focalPoint(camera);
        QSignalSpy recorded(&scene.recorder, &StrokeRecorder::strokeRecorded);
        QSignalSpy failed(&scene.recorder, &StrokeRecorder::recordingFailed);
        QSignalSpy armed(&scene.recorder, &StrokeRecorder::recordingChanged);

        const QPoint press(200, 240);
        QTest::mousePress(&scene.view, Qt::LeftButton, {}, press);
        QVERIFY(scene.recorder.isDragging());
        QVERIFY(scene.recorder.toolActor().isVisible());
        const QPoint moves[] = {{220, 240}, {222, 241}, /* too close: skipped */
                                {240, 245}, {260, 250}, {280, 250}, {300, 252}};
        std::vector<QPoint> sampled{press};
        for (const QPoint& m : moves) {
            clock += 0.05;
            QTest::mouseMove(&scene.view, m);
            if (m != QPoint(222, 241))
                sampled.push_back(m);
        }
        // A move without time passing is skipped too (time stamps strictly increase).
        QTest::mouseMove(&scene.view, QPoint(320, 255));
        QCOMPARE(int(scene.recorder.poses().size()), int(sampled.size()));
        // The partial sweep is shown while dragging.
        QCOMPARE(scene.recorder.sweepActor().surface()->GetNumberOfCells(),
                 vtkIdType(2 * 8 * (sampled.size() - 1)));
        clock += 0.05;
        QTest::mouseRelease(&scene.view, Qt::LeftButton, {}, QPoint(320, 255));
        sampled.emplace_back(320, 255);

        QCOMPARE(failed.count(), 0);
        QCOMPARE(recorded.count(), 1);
        const Stroke stroke = qvariant_cast<Stroke>(recorded.at(0).at(0));
        QCOMPARE(stroke.name, std::string("pass"));
        QCOMPARE(stroke.poses.size(), sampled.size());
        QCOMPARE(stroke.poses.front().t, 0.0);
        for (std::size_t i = 1; i < stroke.poses.size(); ++i)
            QVERIFY(stroke.poses[i].t > stroke.poses[i - 1].t);
        // The positions are the cursor's points on the view plane through the focal point.
        for (std::size_t i = 0; i < sampled.size(); ++i) {
            const auto expected = pixelOnViewPlane(camera, scene.view.size(), sampled[i], focal);
            QVERIFY(expected.has_value());
            QVERIFY2(close(stroke.poses[i].position, *expected, scale),
                     qPrintable(QString::number(i)));
        }
        // One orientation for the whole stroke, with the loop across the drag.
        for (const ToolPose& p : stroke.poses)
            QCOMPARE(p.orientation, stroke.poses.front().orientation);
        const std::vector<Vec3> loop = toolCurveAt(scene.tool, stroke.poses.front());
        const Vec3 view = viewDirection(camera);
        Vec3 d = stroke.poses[1].position - stroke.poses[0].position;
        d = (d - d.dot(view) * view).normalized();
        for (const Vec3& p : loop)
            QVERIFY(std::abs((p - loop.front()).dot(d)) < 1e-9 * scale);

        // The stroke sweeps a valid surface with the tool.
        Scenario scenario;
        scenario.tool = scene.tool;
        scenario.strokes.push_back(stroke);
        SweepSurface sweep;
        const Status status = strokeSweep(scenario, 0, sweep);
        QVERIFY2(status.ok(), status.message().c_str());
        QCOMPARE(sweep.curveCount(), int(stroke.poses.size()));
        QVERIFY(sweep.area() > 0);

        // Recording did not move the camera; a recorded stroke disarms the recorder.
        QCOMPARE(cameraPosition(camera), positionBefore);
        QCOMPARE(focalPoint(camera), focal);
        QVERIFY(!scene.recorder.isRecording());
        QCOMPARE(armed.count(), 1);
        QCOMPARE(armed.at(0).at(0).toBool(), false);
        // The tool stays shown at the last pose.
        const std::vector<Vec3> last = toolCurveAt(scene.tool, stroke.poses.back());
        QCOMPARE(scene.recorder.toolActor().curve().size(), last.size());
        QVERIFY(close(scene.recorder.toolActor().curve().back(), last.back(), scale));

        // Disarmed, a left drag is camera navigation again (it orbits).
        QTest::mousePress(&scene.view, Qt::LeftButton, {}, QPoint(100, 100));
        QTest::mouseMove(&scene.view, QPoint(160, 130));
        QTest::mouseRelease(&scene.view, Qt::LeftButton, {}, QPoint(160, 130));
        QCOMPARE(recorded.count(), 1);
        QVERIFY(cameraPosition(camera) != positionBefore);
    }

    void clickWithoutDragFails() {
        double clock = 0.0;
        Scene scene(&clock);
        QVERIFY(QTest::qWaitForWindowExposed(&scene.view));
        const Vec3 positionBefore = cameraPosition(scene.view.camera());
        QSignalSpy recorded(&scene.recorder, &StrokeRecorder::strokeRecorded);
        QSignalSpy failed(&scene.recorder, &StrokeRecorder::recordingFailed);

        QTest::mousePress(&scene.view, Qt::LeftButton, {}, QPoint(300, 200));
        clock += 0.1;
        QTest::mouseRelease(&scene.view, Qt::LeftButton, {}, QPoint(300, 200));
        QCOMPARE(recorded.count(), 0);
        QCOMPARE(failed.count(), 1);
        QVERIFY(!failed.at(0).at(0).toString().isEmpty());
        // Still armed for another try; nothing left on show.
        QVERIFY(scene.recorder.isRecording());
        QVERIFY(!scene.recorder.toolActor().isVisible());
        QVERIFY(scene.recorder.sweepActor().empty());

        // A wiggle smaller than the minimum spacing records nothing either.
        QTest::mousePress(&scene.view, Qt::LeftButton, {}, QPoint(300, 200));
        clock += 0.1;
        QTest::mouseMove(&scene.view, QPoint(302, 201));
        clock += 0.1;
        QTest::mouseRelease(&scene.view, Qt::LeftButton, {}, QPoint(301, 202));
        QCOMPARE(recorded.count(), 0);
        QCOMPARE(failed.count(), 2);
        QCOMPARE(cameraPosition(scene.view.camera()), positionBefore);
    }

    void goingBackOverTheStrokeIsNotRecorded() {
        // Dragging forth and back would sweep the tool through its own path. The recorder
        // takes no pose behind the stroke's end, says so while the cursor is there, and the
        // release hands on the forward part, whose sweep is valid.
        double clock = 0.0;
        Scene scene(&clock);
        QVERIFY(QTest::qWaitForWindowExposed(&scene.view));
        QSignalSpy recorded(&scene.recorder, &StrokeRecorder::strokeRecorded);
        QSignalSpy failed(&scene.recorder, &StrokeRecorder::recordingFailed);
        QSignalSpy hints(&scene.recorder, &StrokeRecorder::hintChanged);
        QTest::mousePress(&scene.view, Qt::LeftButton, {}, QPoint(200, 240));
        for (int x : {230, 260, 290}) {
            clock += 0.05;
            QTest::mouseMove(&scene.view, QPoint(x, 240));
        }
        QCOMPARE(int(scene.recorder.poses().size()), 4);
        QCOMPARE(hints.count(), 0);
        const Vec3 end = scene.recorder.poses().back().position;
        const vtkIdType cells = scene.recorder.sweepActor().surface()->GetNumberOfCells();
        for (int x : {260, 230, 200, 170}) {
            clock += 0.05;
            QTest::mouseMove(&scene.view, QPoint(x, 240));
        }
        // Behind the end: nothing taken, the preview ends where the valid stroke ends, and
        // the author is told why.
        QCOMPARE(int(scene.recorder.poses().size()), 4);
        QCOMPARE(scene.recorder.poses().back().position, end);
        QCOMPARE(scene.recorder.sweepActor().surface()->GetNumberOfCells(), cells);
        QCOMPARE(hints.count(), 1);
        QVERIFY(hints.last().first().toString().contains(QStringLiteral("forward")));
        // Ahead again: the stroke continues and the hint clears.
        clock += 0.05;
        QTest::mouseMove(&scene.view, QPoint(320, 250));
        QCOMPARE(int(scene.recorder.poses().size()), 5);
        QCOMPARE(hints.count(), 2);
        QCOMPARE(hints.last().first().toString(), QString());
        clock += 0.05;
        QTest::mouseRelease(&scene.view, Qt::LeftButton, {}, QPoint(150, 240));
        QCOMPARE(failed.count(), 0);
        QCOMPARE(recorded.count(), 1);
        const Stroke stroke = qvariant_cast<Stroke>(recorded.at(0).at(0));
        QCOMPARE(int(stroke.poses.size()), 5);
        QVERIFY(!scene.recorder.isRecording());
        QVERIFY2(sweepOf(scene.tool, stroke).ok(), sweepOf(scene.tool, stroke).message().c_str());
    }

    // Mouse paths that wiggle across the drag and turn back, at three scales: the recorded
    // sweep is always one SweepSurface::fromCurves accepts (it rejects self-intersection),
    // its poses advance along the drag by at least kMinAdvanceFraction of the loop's width,
    // while a sweep through every cursor sample would intersect itself for many of them.
    void wigglingAndTurningBackAlwaysGivesAValidSweep_data() {
        QTest::addColumn<double>("scale");
        QTest::addColumn<unsigned>("seed");
        for (const double scale : {1e-3, 1.0, 1e3})
            for (unsigned seed = 1; seed <= 4; ++seed)
                QTest::addRow("scale %g seed %u", scale, seed) << scale << seed;
    }
    void wigglingAndTurningBackAlwaysGivesAValidSweep() {
        QFETCH(double, scale);
        QFETCH(unsigned, seed);
        double clock = 0.0;
        Scene scene(&clock, scale);
        QVERIFY(QTest::qWaitForWindowExposed(&scene.view));
        QSignalSpy recorded(&scene.recorder, &StrokeRecorder::strokeRecorded);
        vtkCamera* camera = scene.view.camera();
        const Vec3 focal = focalPoint(camera);
        std::mt19937 random(seed);
        std::uniform_real_distribution<double> unit(0.0, 1.0);
        int selfIntersecting = 0; // sweeps through every sample (what was recorded before)
        constexpr int kPaths = 12;
        for (int path = 0; path < kPaths; ++path) {
            scene.recorder.setRecording(true);
            // A main direction, a wiggle across it and a few turns back.
            const double angle = 2 * std::numbers::pi * unit(random);
            const QPointF dir(std::cos(angle), std::sin(angle)), across(-dir.y(), dir.x());
            const QPointF start = QPointF(320, 240) - 120 * dir;
            std::vector<QPointF> cursor{start};
            double along = 0;
            for (int i = 1; i <= 40; ++i) {
                along += (unit(random) < 0.25 ? -25.0 : 12.0) * unit(random) + 2.0;
                const double wiggle = 40 * std::sin(0.7 * i + 6 * unit(random)) * unit(random);
                cursor.push_back(start + along * dir + wiggle * across);
            }
            QTest::mousePress(&scene.view, Qt::LeftButton, {}, cursor.front().toPoint());
            for (std::size_t i = 1; i + 1 < cursor.size(); ++i) {
                clock += 0.02;
                QTest::mouseMove(&scene.view, cursor[i].toPoint());
            }
            clock += 0.02;
            QTest::mouseRelease(&scene.view, Qt::LeftButton, {}, cursor.back().toPoint());
            QCOMPARE(recorded.count(), path + 1);
            const Stroke stroke = qvariant_cast<Stroke>(recorded.last().at(0));
            QVERIFY(stroke.poses.size() >= 2);
            const Status status = sweepOf(scene.tool, stroke);
            QVERIFY2(status.ok(), status.message().c_str());
            // Every pose past the last along the drag (the loop's normal).
            const std::vector<Vec3> loop = toolCurveAt(scene.tool, stroke.poses.front());
            const Vec3 d = (loop[1] - loop[0]).cross(loop[7] - loop[0]).normalized();
            const double minAdvance = StrokeRecorder::kMinAdvanceFraction * loopWidth(scene.tool);
            const double sign =
                (stroke.poses[1].position - stroke.poses[0].position).dot(d) > 0 ? 1 : -1;
            for (std::size_t i = 1; i < stroke.poses.size(); ++i)
                QVERIFY(sign * (stroke.poses[i].position - stroke.poses[i - 1].position).dot(d) >=
                        minAdvance * (1 - 1e-9));

            // The same path sampled without the forward rule.
            Stroke every = stroke;
            every.poses.clear();
            for (std::size_t i = 0; i < cursor.size(); ++i) {
                ToolPose pose = stroke.poses.front();
                pose.t = double(i);
                pose.position = *pixelOnViewPlane(camera, scene.view.size(), cursor[i], focal);
                every.poses.push_back(pose);
            }
            selfIntersecting += !sweepOf(scene.tool, every).ok();
        }
        // The paths are hard: without the rule, many strokes would have been unusable.
        QVERIFY2(selfIntersecting >= kPaths / 2, qPrintable(QString::number(selfIntersecting)));
    }

    void pullRunsFromBehindTheTissueToInFront_data() {
        QTest::addColumn<double>("scale");
        QTest::newRow("mm") << 1.0;
        QTest::newRow("1e-3") << 1e-3;
        QTest::newRow("1e3") << 1e3;
    }
    void pullRunsFromBehindTheTissueToInFront() {
        QFETCH(double, scale);
        double clock = 0.0;
        Scene scene(&clock, scale);
        QVERIFY(QTest::qWaitForWindowExposed(&scene.view));
        const TriangleSurface tissue = pickSurfaceOf(scene.mesh);
        scene.recorder.setMotion(StrokeRecorder::Motion::Pull);
        QSignalSpy recorded(&scene.recorder, &StrokeRecorder::strokeRecorded);
        QSignalSpy failed(&scene.recorder, &StrokeRecorder::recordingFailed);

        // Without a tissue there is nothing to pull through: said, still armed.
        QTest::mousePress(&scene.view, Qt::LeftButton, {}, QPoint(320, 240));
        QTest::mouseRelease(&scene.view, Qt::LeftButton, {}, QPoint(320, 240));
        QCOMPARE(failed.count(), 1);
        QCOMPARE(recorded.count(), 0);
        QVERIFY(scene.recorder.isRecording());

        scene.recorder.setPickSurface(tissue);
        vtkCamera* camera = scene.view.camera();
        const QPoint press(300, 230);
        const Ray ray = pixelRay(camera, scene.view.size(), press);
        QTest::mousePress(&scene.view, Qt::LeftButton, {}, press);
        QVERIFY(scene.recorder.isDragging());
        QCOMPARE(int(scene.recorder.poses().size()), 2); // shown at once
        // Drag to the right: the loop opens towards the right of the view.
        QTest::mouseMove(&scene.view, press + QPoint(40, 0));
        QTest::mouseRelease(&scene.view, Qt::LeftButton, {}, press + QPoint(40, 0));
        QCOMPARE(failed.count(), 1);
        QCOMPARE(recorded.count(), 1);
        const Stroke stroke = qvariant_cast<Stroke>(recorded.at(0).at(0));
        QCOMPARE(int(stroke.poses.size()), 2);
        QCOMPARE(stroke.poses.front().t, 0.0);
        const std::vector<Vec3> first = toolCurveAt(scene.tool, stroke.poses.front());
        const std::vector<Vec3> last = toolCurveAt(scene.tool, stroke.poses.back());
        const int tip = 4; // the half circle's deepest point
        QCOMPARE(loopTip(scene.tool), scene.tool.curve[tip]);
        // The tip runs along the press ray, towards the camera ...
        for (const Vec3& p : {first[tip], last[tip]}) {
            const Vec3 toTip = p - ray.origin;
            QVERIFY((toTip - toTip.dot(ray.direction) * ray.direction).norm() < 1e-9 * scale);
        }
        QVERIFY((last[tip] - first[tip]).dot(ray.direction) < 0);
        // ... the loop faces the pull ...
        for (const std::vector<Vec3>* loop : {&first, &last})
            for (const Vec3& p : *loop)
                QVERIFY(std::abs((p - (*loop)[tip]).dot(ray.direction)) < 1e-9 * scale);
        // ... and opens to the right (its chord's midpoint is right of the tip).
        double right[3];
        camera->GetViewUp(right);
        const Vec3 screenRight = viewDirection(camera).cross(Vec3(right[0], right[1], right[2]));
        QVERIFY((0.5 * (first.front() + first.back()) - first[tip]).dot(screenRight) > 0.1 * scale);
        // From the margin behind every tissue point to the margin in front of them.
        double nearest = 1e300, farthest = -1e300;
        for (const Vec3& p : tissue.positions) {
            nearest = std::min(nearest, (p - ray.origin).dot(ray.direction));
            farthest = std::max(farthest, (p - ray.origin).dot(ray.direction));
        }
        const double margin = StrokeRecorder::kPullMarginFraction * loopWidth(scene.tool);
        QVERIFY(std::abs((first[tip] - ray.origin).dot(ray.direction) - (farthest + margin)) <
                1e-9 * scale);
        QVERIFY(std::abs((last[tip] - ray.origin).dot(ray.direction) - (nearest - margin)) <
                1e-9 * scale);
        QVERIFY(std::abs(stroke.poses.back().t -
                         (farthest - nearest + 2 * margin) / StrokeRecorder::kPullSpeed) <
                1e-9 * std::max(1.0, stroke.poses.back().t));
        QVERIFY2(sweepOf(scene.tool, stroke).ok(), sweepOf(scene.tool, stroke).message().c_str());
        QVERIFY(!scene.recorder.isRecording());
    }

    void pressOnTheTissueSetsTheDepth() {
        double clock = 0.0;
        Scene scene(&clock);
        QVERIFY(QTest::qWaitForWindowExposed(&scene.view));
        scene.recorder.setPickSurface(pickSurfaceOf(scene.mesh));
        vtkCamera* camera = scene.view.camera();
        const QPoint centre(320, 240);
        QSignalSpy recorded(&scene.recorder, &StrokeRecorder::strokeRecorded);
        QTest::mousePress(&scene.view, Qt::LeftButton, {}, centre);
        for (int i = 1; i <= 4; ++i) {
            clock += 0.1;
            QTest::mouseMove(&scene.view, centre + QPoint(0, 15 * i));
        }
        QTest::mouseRelease(&scene.view, Qt::LeftButton, {}, centre + QPoint(0, 60));
        QCOMPARE(recorded.count(), 1);
        const Stroke stroke = qvariant_cast<Stroke>(recorded.at(0).at(0));
        const Vec3 hit = stroke.poses.front().position;
        // The first pose is on the box's surface, on the ray through the press, in front of
        // the focal point (the box's centre).
        const Ray ray = pixelRay(camera, scene.view.size(), centre);
        const Vec3 toHit = hit - ray.origin;
        QVERIFY((toHit - toHit.dot(ray.direction) * ray.direction).norm() < 1e-9);
        const bool onBoundary = std::abs(hit.x()) < 1e-9 || std::abs(hit.x() - 2) < 1e-9 ||
                                std::abs(hit.y()) < 1e-9 || std::abs(hit.y() - 1) < 1e-9 ||
                                std::abs(hit.z()) < 1e-9 || std::abs(hit.z() - 1) < 1e-9;
        QVERIFY(onBoundary);
        const Vec3 view = viewDirection(camera);
        QVERIFY((hit - focalPoint(camera)).dot(view) < 0);
        // Every pose lies in the view plane through that hit.
        for (const ToolPose& p : stroke.poses)
            QVERIFY(std::abs((p.position - hit).dot(view)) < 1e-9);
    }

    void modifierDragsStayNavigation() {
        // While armed, Shift + left still pans the camera.
        double clock = 0.0;
        Scene scene(&clock);
        QVERIFY(QTest::qWaitForWindowExposed(&scene.view));
        const Vec3 focal = focalPoint(scene.view.camera());
        QTest::mousePress(&scene.view, Qt::LeftButton, Qt::ShiftModifier, QPoint(300, 200));
        QTest::mouseMove(&scene.view, QPoint(340, 220));
        QTest::mouseRelease(&scene.view, Qt::LeftButton, Qt::ShiftModifier, QPoint(340, 220));
        QVERIFY(!scene.recorder.isDragging());
        QVERIFY(scene.recorder.poses().empty());
        QVERIFY(focalPoint(scene.view.camera()) != focal);
    }
};

QTEST_MAIN(TestStrokeRecorder)
#include "test_stroke_recorder.moc"
