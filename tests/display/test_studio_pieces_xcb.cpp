// Seeing the cut, in pixels (issue 19, item 1): the studio's main window with real OpenGL
// under Xvfb (CTest wraps this binary in xvfb-run). After a cut through the polyp's stalk, the
// rendered view coloured by piece shows both pieces in their palette colours, and exploding
// moves the pieces' screen centroids apart.

#include "image_stats.h"

#include "main_window.h"

#include "widgets/cut_panel.h"
#include "widgets/cut_preview.h"
#include "widgets/opengl_support.h"
#include "widgets/piece_colors.h"
#include "widgets/shown_tissue.h"
#include "widgets/tissue_display.h"
#include "widgets/tissue_session.h"
#include "widgets/vtk_viewport.h"

#include "tests/widgets/sweep_fixtures.h"

#include <QApplication>
#include <QColor>
#include <QPushButton>
#include <QSignalSpy>
#include <QStandardPaths>
#include <QSurfaceFormat>
#include <QTest>

#include <cmath>
#include <functional>

using namespace resect;

namespace {

constexpr int kWaitMs = 180'000;

/// Pixels of one piece's colour: count and centroid (pixels).
struct Blob {
    int pixels = 0;
    QPointF centroid;
};

/// The pixels whose hue is that of `colour` (within 12 degrees), clearly coloured and lit: a
/// face of that piece, whatever its shading.
Blob blobOf(const QImage& image, const Rgb& colour) {
    const QColor target = QColor::fromRgbF(float(colour[0]), float(colour[1]), float(colour[2]));
    const int hue = target.hsvHue();
    Blob b;
    double sx = 0, sy = 0;
    for (int y = 0; y < image.height(); ++y)
        for (int x = 0; x < image.width(); ++x) {
            const QColor c = QColor::fromRgb(image.pixel(x, y));
            if (c.hsvSaturation() < 70 || c.value() < 70 || c.hsvHue() < 0)
                continue;
            const int d = std::abs(c.hsvHue() - hue);
            if (std::min(d, 360 - d) > 12)
                continue;
            ++b.pixels;
            sx += x;
            sy += y;
        }
    if (b.pixels > 0)
        b.centroid = QPointF(sx / b.pixels, sy / b.pixels);
    return b;
}

/// Waits for the viewport to render a frame after `action`, then grabs it.
QImage renderAfter(VtkViewport& viewport, const std::function<void()>& action) {
    QSignalSpy frames(&viewport, &VtkViewport::frameRendered);
    action();
    viewport.requestRender();
    if (!frames.wait(10'000))
        return {};
    return viewport.grabImage();
}

QString where(const char* name) {
    return QStringLiteral(RESECT_BINARY_DIR "/tests/display/studio_pieces_%1.png")
        .arg(QString::fromLatin1(name));
}

} // namespace

class TestStudioPiecesXcb : public QObject {
    Q_OBJECT

private slots:
    void initTestCase() {
        QStandardPaths::setTestModeEnabled(true);
        QString reason;
        QVERIFY2(openGlAvailable(&reason), qPrintable(reason));
    }

    void piecesAreColouredAndExplodeApart() {
        MainWindow window;
        window.setErrorDialogsEnabled(false);
        window.setUnsavedChangesAnswer(QMessageBox::Discard);
        window.resize(1280, 800);
        window.show();
        QVERIFY(QTest::qWaitForWindowExposed(&window));
        QSignalSpy loaded(&window, &MainWindow::meshLoaded);
        window.openSample(Sample::Polyp);
        QVERIFY(loaded.wait(kWaitMs));
        QVERIFY(window.cutPreview().waitForIdle(kWaitMs));
        VtkViewport& view = *window.viewport();
        QVERIFY2(view.hasRendering(), qPrintable(view.renderingUnavailableReason()));

        // A cut through the stalk (at about 9.5 of the polyp's 20 mm), applied.
        window.cutPreview().setPendingSweep(
            test::planeSweep(window.session().base()->mesh(), 0.47, 0.1));
        QVERIFY(window.cutPreview().waitForIdle(kWaitMs));
        auto* apply = window.cutPanel()->findChild<QPushButton*>(QStringLiteral("applyCut"));
        QVERIFY(apply && apply->isEnabled());
        QTest::mouseClick(apply, Qt::LeftButton);
        QVERIFY(window.cutPreview().waitForIdle(kWaitMs));
        QCOMPARE(window.session().current()->pieces, 2);

        TissueDisplay& display = window.shownTissue().display();
        display.setResected(TissueDisplay::Resected::Shown);
        const Rgb stalk = piecePalette(0), head = piecePalette(1);

        // The quality colouring has neither piece's hue in any amount (blue is not on its scale).
        const QImage quality =
            renderAfter(view, [&] { display.setColorMode(TetColorMode::Quality); });
        QVERIFY(!quality.isNull());
        quality.save(where("quality"));
        QVERIFY2(blobOf(quality, stalk).pixels < 100,
                 qPrintable(QString::number(blobOf(quality, stalk).pixels)));

        // By piece: both pieces show in their colours.
        const QImage pieces = renderAfter(view, [&] { display.setColorMode(TetColorMode::Piece); });
        QVERIFY(!pieces.isNull());
        pieces.save(where("piece"));
        const ImageStats stats = analyseRegion(pieces, pieces.rect(), qRgb(28, 33, 43), 6);
        qInfo().noquote() << describe(stats);
        const Blob stalk0 = blobOf(pieces, stalk), head0 = blobOf(pieces, head);
        qInfo() << "stalk" << stalk0.pixels << stalk0.centroid << "head" << head0.pixels
                << head0.centroid;
        QVERIFY2(stalk0.pixels > 500, qPrintable(QString::number(stalk0.pixels)));
        QVERIFY2(head0.pixels > 500, qPrintable(QString::number(head0.pixels)));
        // The head above the stalk (z is up in the starting view).
        QVERIFY(head0.centroid.y() < stalk0.centroid.y());

        // Exploded: the screen centroids move apart.
        const QImage exploded = renderAfter(view, [&] { display.setExplode(1.0); });
        QVERIFY(!exploded.isNull());
        exploded.save(where("exploded"));
        const Blob stalk1 = blobOf(exploded, stalk), head1 = blobOf(exploded, head);
        qInfo() << "exploded: stalk" << stalk1.pixels << stalk1.centroid << "head" << head1.pixels
                << head1.centroid;
        QVERIFY(stalk1.pixels > 500 && head1.pixels > 500);
        const double before = QLineF(stalk0.centroid, head0.centroid).length();
        const double after = QLineF(stalk1.centroid, head1.centroid).length();
        QVERIFY2(after > before + 20 && after > 1.3 * before,
                 qPrintable(QString("%1 -> %2 px").arg(before).arg(after)));
    }
};

int main(int argc, char* argv[]) {
    // As in the studio: the VTK-suitable format before the application exists.
    QSurfaceFormat::setDefaultFormat(vtkSurfaceFormat());
    QApplication app(argc, argv);
    TestStudioPiecesXcb test;
    return QTest::qExec(&test, argc, argv);
}

#include "test_studio_pieces_xcb.moc"
