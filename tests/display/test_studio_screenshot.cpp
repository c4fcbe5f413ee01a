// Runs the real resect-studio binary: under Xvfb it must render the samples (screenshot not
// blank), under the `offscreen` platform it must fall back to the placeholder and still
// write a screenshot, and bad input must give exit code 2 with a message on stderr.

#include "image_stats.h"
#include "widgets/vtk_viewport.h"

#include <QDir>
#include <QFile>
#include <QFileInfo>
#include <QImage>
#include <QProcess>
#include <QProcessEnvironment>
#include <QStandardPaths>
#include <QTemporaryDir>
#include <QTest>

#include <cmath>

using namespace resect;

namespace {

constexpr int kProcessTimeoutMs = 300'000;

/// The viewport's background as 8-bit RGB, as OpenGL writes it.
QRgb viewportBackground() {
    const auto& bg = VtkViewport::kBackground;
    return qRgb(int(std::lround(bg[0] * 255)), int(std::lround(bg[1] * 255)),
                int(std::lround(bg[2] * 255)));
}

struct RunResult {
    bool finished = false;
    int exitCode = -1;
    QString stdErr;
};

RunResult run(const QString& program, const QStringList& arguments,
              const QProcessEnvironment& environment) {
    QProcess process;
    process.setProcessEnvironment(environment);
    process.start(program, arguments);
    RunResult result;
    if (!process.waitForStarted(30'000)) {
        result.stdErr =
            QStringLiteral("could not start %1: %2").arg(program, process.errorString());
        return result;
    }
    result.finished = process.waitForFinished(kProcessTimeoutMs);
    if (!result.finished)
        process.kill();
    result.exitCode = process.exitStatus() == QProcess::NormalExit ? process.exitCode() : -1;
    result.stdErr = QString::fromLocal8Bit(process.readAllStandardError());
    return result;
}

QString describe(const RunResult& r) {
    return QStringLiteral("finished %1, exit code %2, stderr:\n%3")
        .arg(r.finished)
        .arg(r.exitCode)
        .arg(r.stdErr);
}

QProcessEnvironment environmentWithPlatform(const QString& platform) {
    QProcessEnvironment env = QProcessEnvironment::systemEnvironment();
    if (platform.isEmpty())
        env.remove(QStringLiteral("QT_QPA_PLATFORM"));
    else
        env.insert(QStringLiteral("QT_QPA_PLATFORM"), platform);
    return env;
}

/// The 3-D view's part of the window: between the authoring dock on the left and the
/// panels on the right, below the menu bar, above the status bar (1280 x 800 window).
QRect viewRegion(const QImage& image) {
    return QRect(int(0.24 * image.width()), int(0.06 * image.height()), int(0.34 * image.width()),
                 int(0.86 * image.height()));
}

/// Pixels of the overlay's colour scale (hue 0 red .. 120 green), by hue band.
struct QualityHues {
    int red = 0, yellow = 0, green = 0;
};
QualityHues qualityHues(const QImage& image, const QRect& region) {
    QualityHues h;
    const QRect r = region.intersected(image.rect());
    for (int y = r.top(); y <= r.bottom(); ++y)
        for (int x = r.left(); x <= r.right(); ++x) {
            const QColor c = QColor::fromRgb(image.pixel(x, y));
            if (c.hsvSaturation() < 80 || c.value() < 60)
                continue; // background, edges, shadows
            const int hue = c.hsvHue();
            if (hue >= 0 && hue < 25)
                ++h.red;
            else if (hue >= 25 && hue < 75)
                ++h.yellow;
            else if (hue >= 75 && hue <= 140)
                ++h.green;
        }
    return h;
}

} // namespace

class TestStudioScreenshot : public QObject {
    Q_OBJECT

private slots:
    void rendersSampleUnderXvfb_data();
    void rendersSampleUnderXvfb();
    void offscreenFallsBackToPlaceholder();
    void badInputExitsTwo_data();
    void badInputExitsTwo();
};

void TestStudioScreenshot::rendersSampleUnderXvfb_data() {
    QTest::addColumn<QString>("sample");
    QTest::addColumn<QStringList>("source");
    QTest::newRow("polyp") << QStringLiteral("polyp") << QStringList{QStringLiteral("--sample"), QStringLiteral("polyp")};
    QTest::newRow("myoma") << QStringLiteral("myoma") << QStringList{QStringLiteral("--sample"), QStringLiteral("myoma")};
    // The bundled resection: three strokes cut the polyp's head off; the tets are coloured by
    // radius ratio (the default quality overlay), so the small elements along the cut show.
    QTest::newRow("cut polyp") << QStringLiteral("cut_polyp")
                               << QStringList{QStringLiteral("--open"),
                                              QStringLiteral(RESECT_SOURCE_DIR "/resources/scenarios/polyp-resection.json")};
}

void TestStudioScreenshot::rendersSampleUnderXvfb() {
    QFETCH(QString, sample);
    QFETCH(QStringList, source);
    // A missing xvfb-run is a broken test environment, not a reason to skip.
    const QString xvfbRun = QStandardPaths::findExecutable(QStringLiteral("xvfb-run"));
    QVERIFY2(!xvfbRun.isEmpty(), "xvfb-run not found on PATH (Debian package xvfb)");

    // Kept in the build tree so that a failing run leaves the image to look at.
    const QString dir = QStringLiteral(RESECT_BINARY_DIR "/tests/display");
    QVERIFY(QDir().mkpath(dir));
    const QString png = dir + QStringLiteral("/studio_%1.png").arg(sample);
    QFile::remove(png);

    // (-n: the search for a free display starts away from xvfb-run's default 99, where a
    // server we cannot see may be running; tests/display/CMakeLists.txt. -noreset: the
    // server does not reset between clients; app/cli/plotter.cpp.)
    const QStringList arguments = QStringList{QStringLiteral("-a"), QStringLiteral("-n"), QStringLiteral("389"), QStringLiteral("-s"),
                                              QStringLiteral("-screen 0 1280x1024x24 -noreset"),
                                              QStringLiteral(RESECT_STUDIO_EXE)} +
                                  source + QStringList{QStringLiteral("--screenshot"), png};
    const RunResult r = run(xvfbRun, arguments, environmentWithPlatform(QStringLiteral("xcb")));
    QVERIFY2(r.finished && r.exitCode == 0, qPrintable(describe(r)));

    QImage image;
    QVERIFY2(image.load(png), qPrintable(png));
    QVERIFY(image.width() > 0 && image.height() > 0);

    // The middle of the window is the 3-D view: it must show the view's background around
    // a lit, quality-coloured mesh.
    const ImageStats stats = analyseRegion(image, viewRegion(image), viewportBackground(), 6);
    qInfo().noquote() << png << describe(stats);
    // What surrounds the mesh is the 3-D view's own background (VTK rendered into the window,
    // not the placeholder, not Qt's fill showing through a transparent frame), and the mesh
    // is framed in it, many shades of it.
    const QString problem = renderedViewProblem(stats, viewportBackground());
    QVERIFY2(problem.isEmpty(), qPrintable(png + QStringLiteral(": ") + problem));
    // The quality overlay: red-to-green by radius ratio. The samples' tets are mostly
    // yellow-green; the cut polyp has worse elements along its cut, so warmer hues appear.
    const QualityHues hues = qualityHues(image, viewRegion(image));
    qInfo().noquote() << png << "hues:" << hues.green << "green," << hues.yellow << "yellow," << hues.red << "red";
    QVERIFY2(hues.green + hues.yellow > 500, "no quality-coloured mesh in the view");
    if (sample == QLatin1String("cut_polyp"))
        QVERIFY2(hues.red + hues.yellow > 50, "the cut shows no lower-quality elements");
}

void TestStudioScreenshot::offscreenFallsBackToPlaceholder() {
    QTemporaryDir tmp;
    QVERIFY(tmp.isValid());
    const QString png = tmp.filePath(QStringLiteral("offscreen.png"));
    const RunResult r = run(
        QStringLiteral(RESECT_STUDIO_EXE),
        {QStringLiteral("--sample"), QStringLiteral("polyp"), QStringLiteral("--screenshot"), png},
        environmentWithPlatform(QStringLiteral("offscreen")));
    QVERIFY2(r.finished && r.exitCode == 0, qPrintable(describe(r)));
    QImage image;
    QVERIFY(image.load(png));
    QVERIFY(image.width() > 0 && image.height() > 0);
    // No temporary left next to the result (QSaveFile renames atomically).
    QCOMPARE(QDir(tmp.path()).entryList(QDir::Files), QStringList{QStringLiteral("offscreen.png")});
}

void TestStudioScreenshot::badInputExitsTwo_data() {
    QTest::addColumn<QStringList>("arguments");
    QTest::addColumn<QString>("mentions");
    QTest::newRow("unknown sample") << QStringList{"--sample", "spleen"} << "spleen";
    QTest::newRow("unknown option") << QStringList{"--colour", "red"} << "colour";
    QTest::newRow("missing value") << QStringList{"--open"} << "open";
    QTest::newRow("positional") << QStringList{"mesh.vtu"} << "mesh.vtu";
    QTest::newRow("missing file") << QStringList{"--open", "/nonexistent/none.vtu"}
                                  << "/nonexistent/none.vtu";
    QTest::newRow("sample and open")
        << QStringList{"--sample", "polyp", "--open", "x.vtu"} << "--open";
    QTest::newRow("screenshot directory missing")
        << QStringList{"--screenshot", "/nonexistent/dir/shot.png"} << "/nonexistent/dir";
    // Fails while loading, after the window is up; @TMP@ is replaced by a temporary folder.
    QTest::newRow("corrupt mesh") << QStringList{"--open", "@TMP@/corrupt.vtu", "--screenshot",
                                                 "@TMP@/never.png"}
                                  << "corrupt.vtu";
}

void TestStudioScreenshot::badInputExitsTwo() {
    QFETCH(QStringList, arguments);
    QFETCH(QString, mentions);
    QTemporaryDir tmp;
    QVERIFY(tmp.isValid());
    {
        QFile corrupt(tmp.filePath(QStringLiteral("corrupt.vtu")));
        QVERIFY(corrupt.open(QIODevice::WriteOnly));
        corrupt.write("<VTKFile type=\"UnstructuredGrid\"> this is not a mesh");
    }
    for (QString& a : arguments)
        a.replace(QStringLiteral("@TMP@"), tmp.path());

    const RunResult r = run(QStringLiteral(RESECT_STUDIO_EXE), arguments,
                            environmentWithPlatform(QStringLiteral("offscreen")));
    QVERIFY2(r.finished && r.exitCode == 2, qPrintable(describe(r)));
    QVERIFY2(r.stdErr.contains(mentions), qPrintable(describe(r)));
    QVERIFY(!QFileInfo::exists(tmp.filePath(QStringLiteral("never.png"))));
}

QTEST_GUILESS_MAIN(TestStudioScreenshot)
#include "test_studio_screenshot.moc"
