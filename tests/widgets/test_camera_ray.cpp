// Camera maths for picking and strokes (widgets/camera_ray.h) and the viewport's tool hook
// (widgets/viewport_tool.h), under the offscreen platform.

#include "widgets/camera_ray.h"
#include "widgets/orbit_camera.h"
#include "widgets/viewport_tool.h"
#include "widgets/vtk_viewport.h"

#include <QMouseEvent>
#include <QTest>

#include <vtkActor.h>
#include <vtkCamera.h>

using namespace resect;

namespace {

/// Records what it was given; consumes presses with the left button only.
class RecordingTool : public ViewportTool {
public:
    bool mousePress(VtkViewport&, QMouseEvent* e) override {
        ++presses;
        return e->button() == Qt::LeftButton;
    }
    bool mouseMove(VtkViewport&, QMouseEvent* e) override {
        ++moves;
        last = e->position();
        return e->buttons() != Qt::NoButton;
    }
    bool mouseRelease(VtkViewport&, QMouseEvent*) override {
        ++releases;
        return true;
    }
    void deactivated(VtkViewport&) override { ++deactivations; }
    int presses = 0, moves = 0, releases = 0, deactivations = 0;
    QPointF last;
};

} // namespace

class TestCameraRay : public QObject {
    Q_OBJECT

private slots:
    void projectionRoundTrip_data() {
        QTest::addColumn<double>("scale");
        QTest::addColumn<bool>("parallel");
        QTest::newRow("mm perspective") << 1.0 << false;
        QTest::newRow("1e-4 perspective") << 1e-4 << false;
        QTest::newRow("1e4 perspective") << 1e4 << false;
        QTest::newRow("mm parallel") << 1.0 << true;
    }
    void projectionRoundTrip() {
        QFETCH(double, scale);
        QFETCH(bool, parallel);
        OrbitCamera cam;
        cam.setViewDirection({-0.45, 1.0, -0.35}, {0, 0, 1});
        cam.reset({-scale, scale, -2 * scale, 2 * scale, 0, scale}, 4.0 / 3.0);
        cam.camera()->SetParallelProjection(parallel);
        const QSize size(640, 480);
        const Vec3 points[] = {Vec3(0, 0, 0.5 * scale), Vec3(scale, -scale, 0),
                               Vec3(-0.3 * scale, 1.7 * scale, scale)};
        for (const Vec3& p : points) {
            const auto pixel = worldToPixel(cam.camera(), size, p);
            QVERIFY(pixel.has_value());
            // The ray through that pixel passes through the point.
            const Ray ray = pixelRay(cam.camera(), size, *pixel);
            QVERIFY(std::abs(ray.direction.norm() - 1) < 1e-12);
            const Vec3 toP = p - ray.origin;
            const double off = (toP - toP.dot(ray.direction) * ray.direction).norm();
            QVERIFY2(off < 1e-9 * scale, qPrintable(QString::number(off)));
            QVERIFY(toP.dot(ray.direction) > 0);
            // And the view-plane point through p under that pixel is p.
            const auto onPlane = pixelOnViewPlane(cam.camera(), size, *pixel, p);
            QVERIFY(onPlane.has_value());
            QVERIFY((*onPlane - p).norm() < 1e-9 * scale);
        }
        // The focal point is at the centre of the view; y grows downwards.
        const auto centre = worldToPixel(cam.camera(), size, focalPoint(cam.camera()));
        QVERIFY(centre.has_value());
        QVERIFY(std::abs(centre->x() - 320) < 1e-6 && std::abs(centre->y() - 240) < 1e-6);
        double up[3];
        cam.camera()->GetViewUp(up);
        const Vec3 above = focalPoint(cam.camera()) + 0.1 * scale * Vec3(up[0], up[1], up[2]);
        QVERIFY(worldToPixel(cam.camera(), size, above)->y() < 240);
    }

    void behindTheCameraHasNoPixel() {
        OrbitCamera cam;
        cam.reset({-1, 1, -1, 1, -1, 1}, 1.0);
        double p[3];
        cam.camera()->GetPosition(p);
        const Vec3 behind = Vec3(p[0], p[1], p[2]) - 10 * viewDirection(cam.camera());
        QVERIFY(!worldToPixel(cam.camera(), QSize(100, 100), behind).has_value());
    }

    void toolGetsMouseEventsFirst() {
        VtkViewport view;
        view.resize(400, 300);
        view.show();
        QVERIFY(QTest::qWaitForWindowExposed(&view));
        auto* props = vtkActor::New();
        view.addProp(props);
        view.addProp(props); // once only
        view.removeProp(props);
        props->Delete();

        double before[3];
        view.camera()->GetPosition(before);
        RecordingTool tool;
        view.setTool(&tool);
        QTest::mousePress(&view, Qt::LeftButton, {}, QPoint(100, 100));
        QTest::mouseMove(&view, QPoint(150, 120));
        QTest::mouseRelease(&view, Qt::LeftButton, {}, QPoint(150, 120));
        QCOMPARE(tool.presses, 1);
        QCOMPARE(tool.releases, 1);
        double after[3];
        view.camera()->GetPosition(after);
        // The tool consumed the drag: the camera did not orbit.
        QCOMPARE(after[0], before[0]);
        QCOMPARE(after[1], before[1]);

        // A right-button drag is not consumed: the camera zooms.
        QTest::mousePress(&view, Qt::RightButton, {}, QPoint(100, 100));
        QTest::mouseMove(&view, QPoint(100, 60));
        QTest::mouseRelease(&view, Qt::RightButton, {}, QPoint(100, 60));
        QCOMPARE(tool.presses, 2);
        QCOMPARE(tool.releases, 1);
        view.camera()->GetPosition(after);
        QVERIFY(after[0] != before[0] || after[1] != before[1] || after[2] != before[2]);

        view.setTool(nullptr);
        QCOMPARE(tool.deactivations, 1);
        QTest::mousePress(&view, Qt::LeftButton, {}, QPoint(100, 100));
        QCOMPARE(tool.presses, 2);
        QTest::mouseRelease(&view, Qt::LeftButton, {}, QPoint(100, 100));
    }
};

QTEST_MAIN(TestCameraRay)
#include "test_camera_ray.moc"
