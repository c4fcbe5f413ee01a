// VtkViewport with real OpenGL: run under Xvfb on the xcb platform (CTest wraps this
// binary in xvfb-run). The viewport must render through the Qt 6 / VTK bridge, and the
// rendered frame must show the mesh.

#include "image_stats.h"

#include "core/mesh/box_mesh.h"
#include "core/mesh/tet_mesh.h"
#include "widgets/opengl_support.h"
#include "widgets/vtk_viewport.h"

#include <QApplication>
#include <QLabel>
#include <QSignalSpy>
#include <QSurfaceFormat>
#include <QTest>

#include <cmath>
#include <functional>
#include <random>

using namespace resect;

namespace {

/// A 4x4x4 box mesh whose nodes are jittered (fixed seed), so that the tets have many
/// different qualities and the faces many orientations: a rendered frame has many colours.
TetMesh jitteredBox() {
    TetMesh box = makeBoxTetMesh(Vec3(0, 0, 0), Vec3(4, 3, 2), 4, 4, 4);
    std::mt19937 random(7);
    std::uniform_real_distribution<double> jitter(-0.12, 0.12);
    std::vector<Vec3> points(box.referencePositions().begin(), box.referencePositions().end());
    for (Vec3& p : points)
        p += Vec3(jitter(random), jitter(random), jitter(random));
    return TetMesh::fromArrays(std::move(points), box.tets());
}

QRgb viewportBackground() {
    const auto& bg = VtkViewport::kBackground;
    return qRgb(int(std::lround(bg[0] * 255)), int(std::lround(bg[1] * 255)),
                int(std::lround(bg[2] * 255)));
}

/// Waits for the viewport to render a frame after `action`.
bool renderAfter(VtkViewport& viewport, const std::function<void()>& action) {
    QSignalSpy frames(&viewport, &VtkViewport::frameRendered);
    action();
    viewport.requestRender();
    return frames.wait(10'000);
}

} // namespace

class TestViewportXcb : public QObject {
    Q_OBJECT

private slots:
    void platformHasOpenGl();
    void rendersMesh();
    void dragChangesFrame();
};

void TestViewportXcb::platformHasOpenGl() {
    QCOMPARE(QGuiApplication::platformName(), QStringLiteral("xcb"));
    QString reason;
    QVERIFY2(openGlAvailable(&reason), qPrintable(reason));
}

void TestViewportXcb::rendersMesh() {
    VtkViewport viewport;
    viewport.resize(480, 360);
    QVERIFY(viewport.hasRendering());
    QVERIFY(viewport.findChild<QLabel*>(QStringLiteral("viewportPlaceholder")) == nullptr);

    QSignalSpy frames(&viewport, &VtkViewport::frameRendered);
    viewport.show();
    QVERIFY(QTest::qWaitForWindowExposed(&viewport));
    QVERIFY(renderAfter(viewport, [&] { viewport.setTetMesh(jitteredBox()); }));
    QVERIFY2(viewport.hasRendering(), qPrintable(viewport.renderingUnavailableReason()));

    const QImage image = viewport.grabImage();
    QVERIFY(!image.isNull());
    const qreal ratio = viewport.devicePixelRatioF();
    QCOMPARE(image.width(), int(std::lround(viewport.width() * ratio)));
    QCOMPARE(image.height(), int(std::lround(viewport.height() * ratio)));
    image.save(QStringLiteral(RESECT_BINARY_DIR "/tests/display/viewport_xcb.png"));

    const ImageStats stats = analyseRegion(image, image.rect(), viewportBackground(), 6);
    qInfo().noquote() << describe(stats);
    const QString problem = renderedViewProblem(stats, viewportBackground());
    QVERIFY2(problem.isEmpty(), qPrintable(problem));
}

void TestViewportXcb::dragChangesFrame() {
    VtkViewport viewport;
    viewport.resize(320, 240);
    viewport.show();
    QVERIFY(QTest::qWaitForWindowExposed(&viewport));
    QVERIFY(renderAfter(viewport, [&] { viewport.setTetMesh(jitteredBox()); }));
    const QImage before = viewport.grabImage();

    QVERIFY(renderAfter(viewport, [&] {
        QTest::mousePress(&viewport, Qt::LeftButton, Qt::NoModifier, QPoint(160, 120));
        QTest::mouseMove(&viewport, QPoint(220, 140));
        QTest::mouseRelease(&viewport, Qt::LeftButton, Qt::NoModifier, QPoint(220, 140));
    }));
    const QImage after = viewport.grabImage();
    QCOMPARE(after.size(), before.size());
    QVERIFY2(after != before, "orbiting the camera did not change the rendered frame");
}

int main(int argc, char* argv[]) {
    // As in the studio: the VTK-suitable format before the application exists.
    QSurfaceFormat::setDefaultFormat(vtkSurfaceFormat());
    QApplication app(argc, argv);
    TestViewportXcb test;
    return QTest::qExec(&test, argc, argv);
}

#include "test_viewport_xcb.moc"
