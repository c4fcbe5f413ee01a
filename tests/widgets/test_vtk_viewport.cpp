// VtkViewport under the `offscreen` platform: no OpenGL, so the placeholder is shown and
// the scene data and camera model must work without it.

#include "core/mesh/box_mesh.h"
#include "core/mesh/tet_mesh.h"
#include "core/mesh/triangle_surface.h"
#include "widgets/opengl_support.h"
#include "widgets/camera_ray.h"
#include "widgets/vtk_viewport.h"

#include <QApplication>
#include <QGuiApplication>
#include <QLabel>
#include <QSignalSpy>
#include <QTest>
#include <QWheelEvent>

#include <vtkActor.h>
#include <vtkCamera.h>
#include <vtkImageData.h>
#include <vtkScalarBarActor.h>
#include <vtkSmartPointer.h>
#include <vtkTexture.h>

#include <array>
#include <cmath>

using namespace resect;

namespace {

/// One cube of six tets spanning the box (core/mesh/box_mesh.h).
TetMesh boxMesh(const Vec3& lo, const Vec3& hi) {
    return makeBoxTetMesh(lo, hi, 1, 1, 1);
}

TriangleSurface tetrahedronSurface(double scale, const Vec3& offset) {
    TriangleSurface s;
    s.positions = {offset, offset + Vec3(scale, 0, 0), offset + Vec3(0, scale, 0),
                   offset + Vec3(0, 0, scale)};
    s.triangles = {{0, 2, 1}, {0, 1, 3}, {0, 3, 2}, {1, 2, 3}};
    return s;
}

Vec3 cameraPosition(vtkCamera* camera) {
    double p[3];
    camera->GetPosition(p);
    return {p[0], p[1], p[2]};
}

Vec3 cameraFocalPoint(vtkCamera* camera) {
    double p[3];
    camera->GetFocalPoint(p);
    return {p[0], p[1], p[2]};
}

} // namespace

class TestVtkViewport : public QObject {
    Q_OBJECT

private slots:
    void framingKeepsClearOfAVisibleLegend() {
        // Issue 19: in a narrow view the framed tissue reached the colour legend (a scalar bar
        // from 0.8 of the width rightwards). With a legend shown, framing keeps the tissue left
        // of it; without one, the tissue uses the width.
        VtkViewport view;
        view.resize(300, 600);
        view.show();
        QVERIFY(QTest::qWaitForWindowExposed(&view));
        const TetMesh mesh = makeBoxTetMesh(Vec3::Zero(), Vec3(10, 10, 10), 3, 3, 3);
        view.setTetMesh(mesh);
        const auto rightEdge = [&] {
            double right = 0;
            for (const Vec3& p : mesh.referencePositions())
                if (const auto pixel = worldToPixel(view.camera(), view.size(), p))
                    right = std::max(right, pixel->x());
            return right / view.width();
        };
        view.resetCamera();
        const double bare = rightEdge();
        auto bar = vtkSmartPointer<vtkScalarBarActor>::New();
        view.addProp(bar);
        view.resetCamera();
        const double withLegend = rightEdge();
        QVERIFY2(withLegend < 0.8, qPrintable(QString::number(withLegend)));
        QVERIFY2(bare > 0.8, qPrintable(QString::number(bare)));
        bar->SetVisibility(false); // a hidden legend takes no room
        view.resetCamera();
        QCOMPARE(rightEdge(), bare);
        view.removeProp(bar);
    }

    void offscreenHasNoRendering();
    void placeholderIsShown();
    void setTetMeshShowsBoundary();
    void resetCameraFramesBounds_data();
    void resetCameraFramesBounds();
    void mouseDragOrbitsCamera();
    void middleDragPansCamera();
    void wheelZoomsCamera();
    void setSurfaceAndClear();
    void emptySceneKeepsCamera();
    void surfaceWithTextureCoordinatesIsTextured();
};

void TestVtkViewport::offscreenHasNoRendering() {
    QCOMPARE(QGuiApplication::platformName(), QStringLiteral("offscreen"));
    QString reason;
    QVERIFY(!openGlAvailable(&reason));
    QVERIFY(!reason.isEmpty());
    VtkViewport viewport;
    QVERIFY(!viewport.hasRendering());
    QVERIFY(!viewport.renderingUnavailableReason().isEmpty());
}

void TestVtkViewport::placeholderIsShown() {
    VtkViewport viewport;
    viewport.resize(400, 300);
    viewport.show();
    QVERIFY(QTest::qWaitForWindowExposed(&viewport));
    auto* placeholder = viewport.findChild<QLabel*>(QStringLiteral("viewportPlaceholder"));
    QVERIFY(placeholder != nullptr);
    QVERIFY(placeholder->isVisible());
    QVERIFY(placeholder->text().contains(QStringLiteral("unavailable")));

    viewport.setTetMesh(boxMesh(Vec3(0, 0, 0), Vec3(1, 1, 1)));
    QVERIFY(placeholder->text().contains(QStringLiteral("6 tets")));

    const QImage image = viewport.grabImage();
    QVERIFY(!image.isNull());
    QVERIFY(image.width() > 0 && image.height() > 0);
}

void TestVtkViewport::setTetMeshShowsBoundary() {
    VtkViewport viewport;
    viewport.setTetMesh(boxMesh(Vec3(-1, -2, -3), Vec3(1, 2, 3)));
    const Bounds b = viewport.sceneBounds();
    QVERIFY(validBounds(b));
    const Bounds expected{-1, 1, -2, 2, -3, 3};
    for (int i = 0; i < 6; ++i)
        QCOMPARE(b[i], expected[i]);

    // An empty mesh clears the scene without crashing.
    viewport.setTetMesh(TetMesh());
    QVERIFY(!validBounds(viewport.sceneBounds()));
}

void TestVtkViewport::resetCameraFramesBounds_data() {
    QTest::addColumn<double>("scale");
    QTest::addColumn<double>("offset");
    QTest::newRow("unit") << 1.0 << 0.0;
    QTest::newRow("millimetres, offset") << 20.0 << 35.0;
    QTest::newRow("tiny") << 1e-6 << 1e-6;
    QTest::newRow("huge, far") << 1e6 << -3e6;
}

void TestVtkViewport::resetCameraFramesBounds() {
    QFETCH(double, scale);
    QFETCH(double, offset);
    VtkViewport viewport;
    viewport.resize(400, 300);
    const Vec3 lo = Vec3(offset, offset, offset);
    const Vec3 hi = lo + scale * Vec3(1.0, 2.0, 0.5);
    viewport.setTetMesh(boxMesh(lo, hi));

    QSignalSpy cameraSpy(&viewport, &VtkViewport::cameraChanged);
    // Move the camera away first so that the reset has something to do.
    viewport.camera()->SetFocalPoint(offset - 7 * scale, offset, offset);
    viewport.resetCamera();
    QCOMPARE(cameraSpy.count(), 1);

    const Vec3 centre = 0.5 * (lo + hi);
    const Vec3 fp = cameraFocalPoint(viewport.camera());
    // Relative to the magnitude: the displayed points may be stored in single precision.
    const double tolerance = 1e-6 * (scale + std::abs(offset));
    QVERIFY2((fp - centre).norm() <= tolerance,
             qPrintable(QStringLiteral("focal point off by %1").arg((fp - centre).norm())));

    // The whole bounding sphere is in front of the camera and inside the clipping range.
    const double radius = 0.5 * (hi - lo).norm();
    const double distance = viewport.camera()->GetDistance();
    QVERIFY(distance > radius);
    double range[2];
    viewport.camera()->GetClippingRange(range);
    QVERIFY(range[0] > 0);
    QVERIFY(range[0] <= distance - radius + tolerance);
    QVERIFY(range[1] >= distance + radius - tolerance);
    // ... and fits the view angle: the sphere's angular radius is at most half the angle.
    const double halfAngle = std::asin(radius / distance) * 180.0 / 3.14159265358979323846;
    QVERIFY(halfAngle <= 0.5 * viewport.camera()->GetViewAngle() + 1e-9);
}

void TestVtkViewport::mouseDragOrbitsCamera() {
    VtkViewport viewport;
    viewport.resize(400, 300);
    viewport.show();
    QVERIFY(QTest::qWaitForWindowExposed(&viewport));
    viewport.setTetMesh(boxMesh(Vec3(0, 0, 0), Vec3(2, 2, 2)));

    const Vec3 before = cameraPosition(viewport.camera());
    const Vec3 focalBefore = cameraFocalPoint(viewport.camera());
    const double distanceBefore = viewport.camera()->GetDistance();
    QSignalSpy cameraSpy(&viewport, &VtkViewport::cameraChanged);

    QTest::mousePress(&viewport, Qt::LeftButton, Qt::NoModifier, QPoint(200, 150));
    QTest::mouseMove(&viewport, QPoint(230, 150));
    QTest::mouseMove(&viewport, QPoint(260, 170));
    QTest::mouseRelease(&viewport, Qt::LeftButton, Qt::NoModifier, QPoint(260, 170));

    QVERIFY(cameraSpy.count() >= 1);
    const Vec3 after = cameraPosition(viewport.camera());
    QVERIFY2((after - before).norm() > 1e-3 * distanceBefore, "the drag did not move the camera");
    // Orbiting turns around the focal point: it stays put and the distance is kept.
    QVERIFY((cameraFocalPoint(viewport.camera()) - focalBefore).norm() < 1e-9);
    QVERIFY(std::abs(viewport.camera()->GetDistance() - distanceBefore) < 1e-9 * distanceBefore);

    // After the release, moving the mouse does nothing.
    const Vec3 released = cameraPosition(viewport.camera());
    QTest::mouseMove(&viewport, QPoint(100, 100));
    QVERIFY((cameraPosition(viewport.camera()) - released).norm() < 1e-12);
}

void TestVtkViewport::middleDragPansCamera() {
    VtkViewport viewport;
    viewport.resize(400, 300);
    viewport.show();
    QVERIFY(QTest::qWaitForWindowExposed(&viewport));
    viewport.setTetMesh(boxMesh(Vec3(0, 0, 0), Vec3(2, 2, 2)));

    const Vec3 position = cameraPosition(viewport.camera());
    const Vec3 focal = cameraFocalPoint(viewport.camera());
    QTest::mousePress(&viewport, Qt::MiddleButton, Qt::NoModifier, QPoint(200, 150));
    QTest::mouseMove(&viewport, QPoint(240, 120));
    QTest::mouseRelease(&viewport, Qt::MiddleButton, Qt::NoModifier, QPoint(240, 120));

    const Vec3 shiftPosition = cameraPosition(viewport.camera()) - position;
    const Vec3 shiftFocal = cameraFocalPoint(viewport.camera()) - focal;
    QVERIFY(shiftFocal.norm() > 1e-6);
    // Panning translates camera and focal point together, within the view plane.
    QVERIFY((shiftPosition - shiftFocal).norm() < 1e-9);
    double dop[3];
    viewport.camera()->GetDirectionOfProjection(dop);
    QVERIFY(std::abs(shiftFocal.dot(Vec3(dop[0], dop[1], dop[2]))) < 1e-9);
}

void TestVtkViewport::wheelZoomsCamera() {
    VtkViewport viewport;
    viewport.resize(400, 300);
    viewport.show();
    QVERIFY(QTest::qWaitForWindowExposed(&viewport));
    viewport.setTetMesh(boxMesh(Vec3(0, 0, 0), Vec3(2, 2, 2)));
    const double before = viewport.camera()->GetDistance();

    const QPointF at(200, 150);
    QWheelEvent wheel(at, viewport.mapToGlobal(at), QPoint(), QPoint(0, 120), Qt::NoButton,
                      Qt::NoModifier, Qt::NoScrollPhase, false);
    QApplication::sendEvent(&viewport, &wheel);
    QVERIFY(viewport.camera()->GetDistance() < before);

    // Right drag upwards zooms in too, downwards out.
    const double mid = viewport.camera()->GetDistance();
    QTest::mousePress(&viewport, Qt::RightButton, Qt::NoModifier, QPoint(200, 150));
    QTest::mouseMove(&viewport, QPoint(200, 200));
    QTest::mouseRelease(&viewport, Qt::RightButton, Qt::NoModifier, QPoint(200, 200));
    QVERIFY(viewport.camera()->GetDistance() > mid);
}

void TestVtkViewport::setSurfaceAndClear() {
    VtkViewport viewport;
    viewport.setSurface(tetrahedronSurface(3.0, Vec3(1, 1, 1)));
    // With no tet mesh, the surface is framed.
    const Vec3 fp = cameraFocalPoint(viewport.camera());
    QVERIFY((fp - Vec3(2.5, 2.5, 2.5)).norm() < 1e-9);
    const Bounds b = viewport.sceneBounds();
    QCOMPARE(b[0], 1.0);
    QCOMPARE(b[1], 4.0);

    // The scene bounds are the union of the tet mesh and the surface.
    viewport.setTetMesh(boxMesh(Vec3(-1, -1, -1), Vec3(0, 0, 0)));
    const Bounds u = viewport.sceneBounds();
    QCOMPARE(u[0], -1.0);
    QCOMPARE(u[5], 4.0);

    viewport.clear();
    QVERIFY(!validBounds(viewport.sceneBounds()));
}

void TestVtkViewport::emptySceneKeepsCamera() {
    VtkViewport viewport;
    const Vec3 position = cameraPosition(viewport.camera());
    viewport.resetCamera();
    QVERIFY((cameraPosition(viewport.camera()) - position).norm() < 1e-12);
    // Dragging over an empty view is harmless.
    viewport.resize(200, 200);
    QTest::mousePress(&viewport, Qt::LeftButton, Qt::NoModifier, QPoint(100, 100));
    QTest::mouseMove(&viewport, QPoint(150, 120));
    QTest::mouseRelease(&viewport, Qt::LeftButton, Qt::NoModifier, QPoint(150, 120));
}

void TestVtkViewport::surfaceWithTextureCoordinatesIsTextured() {
    VtkViewport view;
    TriangleSurface s;
    s.positions = {Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0), Vec3(0, 0, 1)};
    s.triangles = {{0, 2, 1}, {0, 1, 3}, {0, 3, 2}, {1, 2, 3}};
    view.setSurface(s);
    QVERIFY(!view.surfaceActor().textured());
    QVERIFY(view.surfaceActor().actor()->GetTexture() == nullptr);
    s.uvs = {Eigen::Vector2d(0, 0), Eigen::Vector2d(1, 0), Eigen::Vector2d(0, 1), Eigen::Vector2d(1, 1)};
    view.setSurface(s);
    QVERIFY(view.surfaceActor().textured());
    vtkTexture* texture = view.surfaceActor().actor()->GetTexture();
    QVERIFY(texture != nullptr);
    texture->Update();
    auto* image = vtkImageData::SafeDownCast(texture->GetInput());
    QVERIFY(image != nullptr);
    QCOMPARE(image->GetNumberOfScalarComponents(), 3);
    // Back to a surface without coordinates: plain shading again.
    s.uvs.clear();
    view.setSurface(s);
    QVERIFY(view.surfaceActor().actor()->GetTexture() == nullptr);
}

QTEST_MAIN(TestVtkViewport)
#include "test_vtk_viewport.moc"
