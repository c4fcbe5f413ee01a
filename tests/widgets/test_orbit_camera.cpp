// OrbitCamera: the viewport's camera maths, checked without any window or OpenGL.

#include "widgets/orbit_camera.h"

#include <QTest>

#include <vtkCamera.h>

#include <Eigen/Core>

#include <cmath>
#include <limits>
#include <numbers>

using namespace resect;

namespace {

using V = Eigen::Vector3d;

V position(vtkCamera* c) {
    double p[3];
    c->GetPosition(p);
    return {p[0], p[1], p[2]};
}

V focalPoint(vtkCamera* c) {
    double p[3];
    c->GetFocalPoint(p);
    return {p[0], p[1], p[2]};
}

V directionOfProjection(vtkCamera* c) {
    double p[3];
    c->GetDirectionOfProjection(p);
    return {p[0], p[1], p[2]};
}

double degrees(double radians) {
    return radians * 180.0 / std::numbers::pi;
}

} // namespace

class TestOrbitCamera : public QObject {
    Q_OBJECT

private slots:
    void resetFitsSphere_data();
    void resetFitsSphere();
    void resetKeepsViewDirection();
    void invalidBoundsLeaveCameraAlone();
    void orbitTurnsAroundFocalPoint();
    void panFollowsCursorInViewPlane();
    void zoomDollies();
};

void TestOrbitCamera::resetFitsSphere_data() {
    QTest::addColumn<double>("aspect");
    QTest::addColumn<double>("scale");
    QTest::newRow("wide") << 2.0 << 1.0;
    QTest::newRow("square") << 1.0 << 20.0;
    QTest::newRow("tall") << 0.4 << 1e-5;
    QTest::newRow("tall, huge") << 0.5 << 1e5;
}

void TestOrbitCamera::resetFitsSphere() {
    QFETCH(double, aspect);
    QFETCH(double, scale);
    OrbitCamera orbit;
    const Bounds b{-scale, 3 * scale, 0, scale, 10 * scale, 12 * scale};
    orbit.reset(b, aspect);
    vtkCamera* c = orbit.camera();

    const V centre(scale, 0.5 * scale, 11 * scale);
    const double radius = 0.5 * std::sqrt(16.0 + 1.0 + 4.0) * scale;
    QVERIFY((focalPoint(c) - centre).norm() <= 1e-12 * scale * 12);

    // The sphere's angular radius fits half the narrower field of view, tightly.
    const double d = c->GetDistance();
    const double sphereHalfAngle = degrees(std::asin(radius / d));
    const double vertical = 0.5 * c->GetViewAngle();
    const double narrow =
        aspect >= 1 ? vertical
                    : degrees(std::atan(std::tan(vertical * std::numbers::pi / 180) * aspect));
    QVERIFY(sphereHalfAngle <= narrow + 1e-9);
    QVERIFY(sphereHalfAngle >= narrow - 1e-6);

    double range[2];
    c->GetClippingRange(range);
    QVERIFY(range[0] > 0 && range[0] <= d - radius);
    QVERIFY(range[1] >= d + radius);
}

void TestOrbitCamera::resetKeepsViewDirection() {
    OrbitCamera orbit;
    orbit.setViewDirection({1, 1, 0}, {0, 0, 1});
    orbit.reset({0, 1, 0, 1, 0, 1}, 1.0);
    const V dop = directionOfProjection(orbit.camera());
    QVERIFY((dop - V(1, 1, 0).normalized()).norm() < 1e-12);
    double up[3];
    orbit.camera()->GetViewUp(up);
    QVERIFY(std::abs(up[2] - 1.0) < 1e-12);
}

void TestOrbitCamera::invalidBoundsLeaveCameraAlone() {
    OrbitCamera orbit;
    const V before = position(orbit.camera());
    orbit.reset({1, -1, 1, -1, 1, -1}, 1.0);
    orbit.reset({0, std::nan(""), 0, 1, 0, 1}, 1.0);
    QVERIFY((position(orbit.camera()) - before).norm() == 0.0);
}

void TestOrbitCamera::orbitTurnsAroundFocalPoint() {
    OrbitCamera orbit;
    orbit.setViewDirection({0, 1, 0}, {0, 0, 1});
    orbit.reset({-1, 1, -1, 1, -1, 1}, 1.0);
    vtkCamera* c = orbit.camera();
    const V fp = focalPoint(c);
    const double d = c->GetDistance();
    const V dop0 = directionOfProjection(c);

    // A horizontal drag of half the viewport height turns by 90 degrees about the up axis.
    orbit.orbit(250, 0, 500);
    QVERIFY((focalPoint(c) - fp).norm() < 1e-12);
    QVERIFY(std::abs(c->GetDistance() - d) < 1e-9 * d);
    const V dop1 = directionOfProjection(c);
    QVERIFY(std::abs(dop0.dot(dop1)) < 1e-9);
    QVERIFY(std::abs(dop1.z()) < 1e-9);

    // A vertical drag tilts; the view up stays orthogonal to the view direction.
    orbit.orbit(0, 100, 500);
    double up[3];
    c->GetViewUp(up);
    QVERIFY(std::abs(V(up[0], up[1], up[2]).dot(directionOfProjection(c))) < 1e-9);
    QVERIFY(std::abs(c->GetDistance() - d) < 1e-9 * d);

    // Degenerate viewport: nothing happens.
    const V p = position(c);
    orbit.orbit(10, 10, 0);
    QVERIFY((position(c) - p).norm() == 0.0);
}

void TestOrbitCamera::panFollowsCursorInViewPlane() {
    OrbitCamera orbit;
    orbit.setViewDirection({0, 0, -1}, {0, 1, 0});
    orbit.reset({-1, 1, -1, 1, -1, 1}, 1.0);
    vtkCamera* c = orbit.camera();
    const V fp = focalPoint(c);
    const V p = position(c);
    const double worldHeight =
        2 * c->GetDistance() * std::tan(0.5 * c->GetViewAngle() * std::numbers::pi / 180);

    // Dragging right by a full viewport height moves the scene right by the view height at
    // the focal plane, i.e. the camera left (-x when looking down -z with y up).
    orbit.pan(400, 0, 400);
    const V shift = focalPoint(c) - fp;
    QVERIFY((shift - V(-worldHeight, 0, 0)).norm() < 1e-9 * worldHeight);
    QVERIFY(((position(c) - p) - shift).norm() < 1e-12);

    // Dragging down (Qt's +y) moves the camera up.
    orbit.pan(0, 200, 400);
    QVERIFY(focalPoint(c).y() - fp.y() > 0.49 * worldHeight);
}

void TestOrbitCamera::zoomDollies() {
    OrbitCamera orbit;
    orbit.reset({-1, 1, -1, 1, -1, 1}, 1.0);
    vtkCamera* c = orbit.camera();
    const double d = c->GetDistance();
    orbit.zoom(2.0);
    QVERIFY(std::abs(c->GetDistance() - 0.5 * d) < 1e-12 * d);
    orbit.zoom(0.0);
    orbit.zoom(-1.0);
    orbit.zoom(std::numeric_limits<double>::infinity());
    QVERIFY(std::abs(c->GetDistance() - 0.5 * d) < 1e-12 * d);
}

QTEST_GUILESS_MAIN(TestOrbitCamera)
#include "test_orbit_camera.moc"
