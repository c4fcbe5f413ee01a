// SweepEditTool (widgets/sweep_edit_tool.h) and its display adapters (SweepActor,
// HandleActor): drawing a start and an end curve with the mouse in a VtkViewport under the
// offscreen platform (camera maths only, no OpenGL).

#include "core/mesh/box_mesh.h"
#include "widgets/authoring_panel.h"
#include "widgets/camera_ray.h"
#include "widgets/stroke_player.h"
#include "widgets/stroke_recorder.h"
#include "widgets/surface_pick.h"
#include "widgets/sweep_actor.h"
#include "widgets/sweep_edit_tool.h"
#include "widgets/vtk_viewport.h"

#include <QLabel>
#include <QPushButton>
#include <QSignalSpy>
#include <QTest>

#include <vtkActor.h>
#include <vtkCamera.h>
#include <vtkPolyData.h>
#include <vtkProperty.h>

#include <cmath>

using namespace resect;

namespace {

using Curve = SweepEditTool::Curve;

Vec3 cameraPosition(vtkCamera* camera) {
    double p[3];
    camera->GetPosition(p);
    return {p[0], p[1], p[2]};
}

bool close(const Vec3& a, const Vec3& b, double relative = 1e-9) {
    return (a - b).norm() <= relative * std::max(1.0, b.norm());
}

void click(QWidget* w, const QPoint& p, Qt::KeyboardModifiers mods = {}) {
    QTest::mousePress(w, Qt::LeftButton, mods, p);
    QTest::mouseRelease(w, Qt::LeftButton, mods, p);
}

QPoint roundPixel(const QPointF& p) {
    return {int(std::lround(p.x())), int(std::lround(p.y()))};
}

struct Scene {
    Scene() : mesh(makeBoxTetMesh(Vec3::Zero(), Vec3(2, 1, 1), 4, 2, 2)), editor(&view) {
        view.resize(640, 480);
        view.show();
        view.setTetMesh(mesh);
        editor.setName("drawn");
        view.setTool(&editor);
    }
    VtkViewport view;
    TetMesh mesh;
    SweepEditTool editor;
};

} // namespace

class TestSweepEditor : public QObject {
    Q_OBJECT

private slots:
    void drawStartAndEndCurves() {
        Scene scene;
        QVERIFY(QTest::qWaitForWindowExposed(&scene.view));
        vtkCamera* camera = scene.view.camera();
        const Vec3 positionBefore = cameraPosition(camera);
        const Vec3 focal = focalPoint(camera);
        const QSize size = scene.view.size();
        QSignalSpy changed(&scene.editor, &SweepEditTool::sweepChanged);
        QSignalSpy activeChanged(&scene.editor, &SweepEditTool::activeCurveChanged);

        // Three clicks: three points of the start curve on the focal plane.
        const QPoint clicks[] = {{200, 200}, {300, 190}, {400, 200}};
        for (const QPoint& c : clicks)
            click(&scene.view, c);
        QCOMPARE(changed.count(), 3);
        const auto& start = scene.editor.curve(Curve::Start);
        QCOMPARE(int(start.size()), 3);
        for (int i = 0; i < 3; ++i)
            QVERIFY(close(start[i], *pixelOnViewPlane(camera, size, clicks[i], focal)));
        QVERIFY(!scene.editor.isValid());
        QVERIFY(scene.editor.problem().contains(QStringLiteral("end curve")));
        QVERIFY(!scene.editor.sweepSpec().has_value());
        QCOMPARE(scene.editor.handleActor().count(), 3);
        QVERIFY(scene.editor.sweepActor().surface()->GetNumberOfCells() == 0);
        QCOMPARE(scene.editor.sweepActor().curves()->GetNumberOfCells(), vtkIdType(2));

        // The end curve is made active; copyStartToEnd fills it with a shifted copy.
        scene.editor.beginEndCurve();
        QVERIFY(scene.editor.curve(Curve::End).empty());
        scene.editor.copyStartToEnd(scene.editor.defaultEndOffset());
        QCOMPARE(scene.editor.activeCurve(), Curve::End);
        QCOMPARE(activeChanged.count(), 1);
        QCOMPARE(changed.count(), 4);
        const Vec3 offset = scene.editor.defaultEndOffset();
        QVERIFY(offset.norm() > 0);
        QVERIFY(std::abs(offset.dot(viewDirection(camera))) < 1e-9 * offset.norm());
        for (int i = 0; i < 3; ++i)
            QVERIFY(close(scene.editor.curve(Curve::End)[i], start[i] + offset));
        QVERIFY2(scene.editor.isValid(), qPrintable(scene.editor.problem()));
        QCOMPARE(scene.editor.sweepActor().surface()->GetNumberOfCells(), vtkIdType(4));
        QCOMPARE(scene.editor.handleActor().count(), 6);

        // Drag end handle 1: it moves in the view plane through it, keeping the grab offset.
        const Vec3 anchor = scene.editor.curve(Curve::End)[1];
        const QPoint press = roundPixel(*worldToPixel(camera, size, anchor));
        const auto handle = scene.editor.handleAt(press);
        QVERIFY(handle.has_value());
        QCOMPARE(*handle, (SweepEditTool::Handle{Curve::End, 1}));
        const QPoint release = press + QPoint(30, 40);
        QTest::mousePress(&scene.view, Qt::LeftButton, {}, press);
        QVERIFY(scene.editor.isDragging());
        QTest::mouseMove(&scene.view, press + QPoint(10, 15));
        QTest::mouseMove(&scene.view, release);
        QTest::mouseRelease(&scene.view, Qt::LeftButton, {}, release);
        QVERIFY(!scene.editor.isDragging());
        QCOMPARE(changed.count(), 5); // one undoable edit for the whole drag
        const Vec3 expected = *pixelOnViewPlane(camera, size, release, anchor) +
                              (anchor - *pixelOnViewPlane(camera, size, press, anchor));
        QVERIFY(close(scene.editor.curve(Curve::End)[1], expected));
        QVERIFY((expected - anchor).norm() > 0);
        QCOMPARE(int(scene.editor.curve(Curve::End).size()), 3); // no point added
        QCOMPARE(scene.editor.selectedHandle(), std::optional(*handle));

        // The result: a sweep spec with two curves of three points.
        QVERIFY2(scene.editor.isValid(), qPrintable(scene.editor.problem()));
        const auto spec = scene.editor.sweepSpec();
        QVERIFY(spec.has_value());
        QCOMPARE(spec->name, std::string("drawn"));
        QVERIFY(spec->file.empty());
        QCOMPARE(int(spec->curves.size()), 2);
        QCOMPARE(spec->curves[0].size(), spec->curves[1].size());
        QCOMPARE(spec->curves[1][1], scene.editor.curve(Curve::End)[1]);
        SweepSurface sweep;
        QVERIFY(SweepSurface::fromCurves(spec->curves, sweep).ok());

        // None of this moved the camera.
        QCOMPARE(cameraPosition(camera), positionBefore);
        QCOMPARE(focalPoint(camera), focal);

        // Remove and restore (as undo would).
        const auto saved = scene.editor.curves();
        QVERIFY(scene.editor.removeSelectedPoint());
        QVERIFY(!scene.editor.isValid());
        QVERIFY(scene.editor.problem().contains(QStringLiteral("same number")));
        scene.editor.setCurves(saved[0], saved[1]);
        QCOMPARE(scene.editor.curves(), saved);
        QVERIFY(scene.editor.isValid());
        scene.editor.clear();
        QVERIFY(scene.editor.curve(Curve::Start).empty());
        QCOMPARE(scene.editor.activeCurve(), Curve::Start);
        QVERIFY(scene.editor.sweepActor().empty());
        QCOMPARE(scene.editor.handleActor().count(), 0);
    }

    void clickingTheEndCurvePointByPoint() {
        Scene scene;
        QVERIFY(QTest::qWaitForWindowExposed(&scene.view));
        click(&scene.view, QPoint(200, 300));
        click(&scene.view, QPoint(400, 300));
        scene.editor.setActiveCurve(Curve::End);
        click(&scene.view, QPoint(210, 150));
        QVERIFY(!scene.editor.isValid());
        click(&scene.view, QPoint(420, 160));
        QCOMPARE(int(scene.editor.curve(Curve::End).size()), 2);
        QVERIFY2(scene.editor.isValid(), qPrintable(scene.editor.problem()));
        // A click on an existing handle grabs it instead of adding a point.
        click(&scene.view, QPoint(421, 161));
        QCOMPARE(int(scene.editor.curve(Curve::End).size()), 2);
        QVERIFY(scene.editor.removeLastPoint());
        QCOMPARE(int(scene.editor.curve(Curve::End).size()), 1);
    }

    void degenerateStatesAreReported() {
        Scene scene;
        const Vec3 a(0, 0, 0), b(1, 0, 0), c(2, 0, 0);
        const Vec3 up(0, 0, 1);
        // Coincident points are accepted by the editor but are not a valid sweep.
        scene.editor.setCurves({a, a, b}, {a + up, b + up, c + up});
        QCOMPARE(int(scene.editor.curve(Curve::Start).size()), 3);
        QVERIFY(!scene.editor.isValid());
        QVERIFY2(scene.editor.problem().contains(QStringLiteral("coincide")),
                 qPrintable(scene.editor.problem()));
        QVERIFY(!scene.editor.sweepSpec().has_value());
        // Start and end curve the same: zero area.
        scene.editor.setCurves({a, b, c}, {a, b, c});
        QVERIFY(!scene.editor.isValid());
        QVERIFY(!scene.editor.problem().isEmpty());
        // Too few points.
        scene.editor.setCurves({a}, {a + up});
        QVERIFY(scene.editor.problem().contains(QStringLiteral("start curve")));
        // Unequal counts.
        scene.editor.setCurves({a, b}, {a + up, b + up, c + up});
        QVERIFY(scene.editor.problem().contains(QStringLiteral("same number")));
        // Non-finite points never enter the editor.
        const Vec3 nan(std::nan(""), 0, 0);
        scene.editor.setCurves({a, nan, b}, {a + up, b + up});
        QCOMPARE(int(scene.editor.curve(Curve::Start).size()), 2);
        QVERIFY2(scene.editor.isValid(), qPrintable(scene.editor.problem()));
        scene.editor.movePoint({Curve::Start, 0}, nan);
        QCOMPARE(scene.editor.curve(Curve::Start)[0], a);
    }

    void dragOntoTheNeighbourIsInvalid() {
        // Dragging a handle exactly onto its neighbour (same view plane) makes them coincide.
        Scene scene;
        QVERIFY(QTest::qWaitForWindowExposed(&scene.view));
        vtkCamera* camera = scene.view.camera();
        const QSize size = scene.view.size();
        const Vec3 f = focalPoint(camera);
        const Vec3 p0 = *pixelOnViewPlane(camera, size, QPointF(200, 200), f);
        const Vec3 p1 = *pixelOnViewPlane(camera, size, QPointF(300, 200), f);
        const Vec3 shift = *pixelOnViewPlane(camera, size, QPointF(200, 300), f) - p0;
        scene.editor.setCurves({p0, p1}, {p0 + shift, p1 + shift});
        QVERIFY(scene.editor.isValid());
        QTest::mousePress(&scene.view, Qt::LeftButton, {}, QPoint(300, 200));
        QTest::mouseMove(&scene.view, QPoint(250, 200));
        QTest::mouseRelease(&scene.view, Qt::LeftButton, {}, QPoint(200, 200));
        QVERIFY(close(scene.editor.curve(Curve::Start)[1], p0));
        QVERIFY(!scene.editor.isValid());
        QVERIFY2(scene.editor.problem().contains(QStringLiteral("coincide")),
                 qPrintable(scene.editor.problem()));
        for (const auto& curve : scene.editor.curves())
            for (const Vec3& p : curve)
                QVERIFY(p.allFinite());
    }

    void pointsLandOnTheTissue() {
        Scene scene;
        QVERIFY(QTest::qWaitForWindowExposed(&scene.view));
        vtkCamera* camera = scene.view.camera();
        scene.editor.setPickSurface(pickSurfaceOf(scene.mesh));
        click(&scene.view, QPoint(320, 240)); // the box's centre is behind this pixel
        QCOMPARE(int(scene.editor.curve(Curve::Start).size()), 1);
        const Vec3 p = scene.editor.curve(Curve::Start)[0];
        const Ray ray = pixelRay(camera, scene.view.size(), QPointF(320, 240));
        const Vec3 toP = p - ray.origin;
        QVERIFY((toP - toP.dot(ray.direction) * ray.direction).norm() < 1e-9);
        QVERIFY((p - focalPoint(camera)).dot(viewDirection(camera)) < 0); // in front
        // Off the tissue: the view plane through the curve's last point.
        click(&scene.view, QPoint(5, 5));
        const Vec3 q = scene.editor.curve(Curve::Start)[1];
        QVERIFY(std::abs((q - p).dot(viewDirection(camera))) < 1e-9);
    }

    void modifierDragsStayNavigation() {
        Scene scene;
        QVERIFY(QTest::qWaitForWindowExposed(&scene.view));
        const Vec3 before = cameraPosition(scene.view.camera());
        QTest::mousePress(&scene.view, Qt::LeftButton, Qt::AltModifier, QPoint(200, 200));
        QTest::mouseMove(&scene.view, QPoint(260, 230));
        QTest::mouseRelease(&scene.view, Qt::LeftButton, Qt::AltModifier, QPoint(260, 230));
        QVERIFY(scene.editor.curve(Curve::Start).empty());
        QVERIFY(cameraPosition(scene.view.camera()) != before); // Alt + left orbits
    }

    void panelDrivesTheTools() {
        VtkViewport view;
        view.resize(640, 480);
        view.show();
        QVERIFY(QTest::qWaitForWindowExposed(&view));
        view.setTetMesh(makeBoxTetMesh(Vec3::Zero(), Vec3(2, 1, 1), 4, 2, 2));
        AuthoringPanel panel(&view);
        ToolSpec tool;
        tool.size = 0.2;
        tool.curve = {Vec3(-1, 0, 0), Vec3(0, 0, -1), Vec3(1, 0, 0)};
        panel.setToolSpec(tool);
        auto* draw = panel.findChild<QPushButton*>(QStringLiteral("drawSweepButton"));
        auto* endCurve = panel.findChild<QPushButton*>(QStringLiteral("endCurveButton"));
        auto* record = panel.findChild<QPushButton*>(QStringLiteral("recordStrokeButton"));
        auto* finish = panel.findChild<QPushButton*>(QStringLiteral("finishButton"));
        auto* clear = panel.findChild<QPushButton*>(QStringLiteral("clearButton"));
        auto* play = panel.findChild<QPushButton*>(QStringLiteral("playStrokeButton"));
        auto* status = panel.findChild<QLabel*>(QStringLiteral("authoringStatus"));
        QVERIFY(draw && endCurve && record && finish && clear && play && status);
        QSignalSpy sweeps(&panel, &AuthoringPanel::sweepFinished);
        QSignalSpy strokes(&panel, &AuthoringPanel::strokeRecorded);

        // Draw: two start points, then the end curve point by point, finish. The status line
        // says what the next click does (and how to turn the view), never talking about the
        // end curve while the start curve is placed.
        draw->click();
        QCOMPARE(view.tool(), static_cast<ViewportTool*>(&panel.sweepEditor()));
        QVERIFY2(status->text().contains("first point of the start curve"), qPrintable(status->text()));
        QVERIFY2(status->text().contains("Alt+drag turns the view"), qPrintable(status->text()));
        click(&view, QPoint(200, 240));
        QVERIFY(!finish->isEnabled());
        QVERIFY2(status->text().contains("point 2") && !status->text().contains("end curve"), qPrintable(status->text()));
        click(&view, QPoint(400, 240));
        QVERIFY2(status->text().contains("End curve") && status->text().contains("point 3"), qPrintable(status->text()));
        endCurve->click();
        QVERIFY(panel.sweepEditor().curve(SweepEditTool::Curve::End).empty()); // no hidden copy
        QVERIFY(!finish->isEnabled());
        QVERIFY2(status->text().contains("point 1 of 2"), qPrintable(status->text()));
        click(&view, QPoint(200, 320));
        QVERIFY2(status->text().contains("point 2 of 2"), qPrintable(status->text()));
        click(&view, QPoint(400, 320));
        QVERIFY(finish->isEnabled());
        QVERIFY2(status->text().contains("valid"), qPrintable(status->text()));
        finish->click();
        QCOMPARE(sweeps.count(), 1);
        const SweepSpec spec = qvariant_cast<SweepSpec>(sweeps.at(0).at(0));
        QCOMPARE(int(spec.curves.size()), 2);
        QCOMPARE(int(spec.curves[0].size()), 2);
        QVERIFY(!draw->isChecked());
        QVERIFY(view.tool() == nullptr);

        // Record: a drag gives a stroke and the recorder disarms.
        record->click();
        QCOMPARE(view.tool(), static_cast<ViewportTool*>(&panel.strokeRecorder()));
        QTest::mousePress(&view, Qt::LeftButton, {}, QPoint(200, 200));
        for (int x = 220; x <= 300; x += 20) {
            QTest::qWait(2); // the default clock must advance between samples
            QTest::mouseMove(&view, QPoint(x, 200));
        }
        QTest::qWait(2);
        QTest::mouseRelease(&view, Qt::LeftButton, {}, QPoint(300, 200));
        QCOMPARE(strokes.count(), 1);
        QVERIFY(!record->isChecked());
        QVERIFY(!panel.strokeRecorder().isRecording());
        QVERIFY(view.tool() == nullptr);
        QVERIFY(play->isEnabled());
        QVERIFY(panel.lastStroke().poses.size() >= 2);
        play->click();
        QVERIFY(panel.strokePlayer().hasStroke());
        clear->click();
        QVERIFY(!play->isEnabled());
        QVERIFY(!panel.strokePlayer().isPlaying());

        // Clear while drawing ends drawing (it left "Draw sweep" checked and the view a
        // drawing tool).
        draw->click();
        click(&view, QPoint(200, 240));
        QVERIFY(draw->isChecked());
        clear->click();
        QVERIFY(!draw->isChecked());
        QVERIFY(view.tool() == nullptr);
        QVERIFY(panel.sweepEditor().curve(SweepEditTool::Curve::Start).empty());
    }

    void sweepActorDrawsWhatItCan() {
        SweepActor actor;
        QVERIFY(actor.empty());
        QCOMPARE(actor.surfaceActor()->GetProperty()->GetOpacity(), SweepActor::kOpacity);
        const Vec3 nan(std::nan(""), 0, 0);
        // Three curves of 3 points (one NaN in the middle curve), then one of 2 points.
        actor.setCurves({{Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(2, 0, 0)},
                         {Vec3(0, 1, 0), nan, Vec3(2, 1, 0)},
                         {Vec3(0, 2, 0), Vec3(1, 2, 0), Vec3(2, 2, 0)},
                         {Vec3(0, 3, 0), Vec3(2, 3, 0)}});
        QCOMPARE(actor.curves()->GetNumberOfPoints(), vtkIdType(10));
        QCOMPARE(actor.curves()->GetNumberOfCells(), vtkIdType(2 + 0 + 2 + 1));
        // Quads between curves 0-1 and 1-2, minus the triangles touching the NaN point.
        QCOMPARE(actor.surface()->GetNumberOfCells(), vtkIdType(2 * 4 - 6));
        SweepSurface sweep;
        QVERIFY(SweepSurface::fromStartEnd({Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(2, 0, 0)},
                                           {Vec3(0, 1, 0), Vec3(1, 1, 0), Vec3(2, 1, 0)}, sweep)
                    .ok());
        actor.setSweep(sweep);
        QCOMPARE(actor.surface()->GetNumberOfCells(), vtkIdType(sweep.triangles().size()));
        QVERIFY(actor.surfaceActor()->GetVisibility());
        actor.clear();
        QVERIFY(actor.empty());
        QVERIFY(!actor.surfaceActor()->GetVisibility());
    }
};

QTEST_MAIN(TestSweepEditor)
#include "test_sweep_editor.moc"
