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

    void goingBackOverTheStrokeIsRefused() {
        // Dragging forth and back sweeps the tool through its own path: the sweep would
        // intersect itself, and the recorder says so instead of handing on a bad stroke.
        double clock = 0.0;
        Scene scene(&clock);
        QVERIFY(QTest::qWaitForWindowExposed(&scene.view));
        QSignalSpy recorded(&scene.recorder, &StrokeRecorder::strokeRecorded);
        QSignalSpy failed(&scene.recorder, &StrokeRecorder::recordingFailed);
        QTest::mousePress(&scene.view, Qt::LeftButton, {}, QPoint(200, 240));
        for (int x : {230, 260, 290, 260, 230, 200, 170}) {
            clock += 0.05;
            QTest::mouseMove(&scene.view, QPoint(x, 240));
        }
        clock += 0.05;
        QTest::mouseRelease(&scene.view, Qt::LeftButton, {}, QPoint(170, 240));
        QCOMPARE(recorded.count(), 0);
        QCOMPARE(failed.count(), 1);
        QVERIFY(scene.recorder.isRecording());
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
