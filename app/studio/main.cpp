// resect-studio: the desktop editor.
//
//     resect-studio [--sample polyp|myoma] [--open FILE] [--screenshot PNG] [--lang CODE]
//                   [--color-by quality|piece] [--resected shown|dimmed|hidden] [--explode F]
//
// --lang en|de|fr sets the interface language for this run; without it the preference
// saved from the Language menu applies, else the system's language (widgets/language.h).
// Without --open it meshes and shows the sample polyp (or the sample named by --sample).
// --screenshot loads, shows the window, waits for the 3-D view's first frame, writes the
// window image atomically and exits 0. Bad input: one line on stderr, exit 2; an internal
// failure (timeout, image not written): exit 1.
// --color-by, --resected and --explode set the Display toolbar's colouring, resected chips
// and explode factor (0 to 1.5) for this run (widgets/tissue_display.h).

#include "main_window.h"

#include "core/mesher/samples.h"
#include "widgets/language.h"
#include "widgets/opengl_support.h"
#include "widgets/shown_tissue.h"
#include "widgets/tissue_display.h"
#include "widgets/tissue_session.h"
#include "widgets/vtk_viewport.h"

#include <QApplication>
#include <QCommandLineParser>
#include <QDir>
#include <QFileInfo>
#include <QImage>
#include <QSaveFile>
#include <QSettings>
#include <QSurfaceFormat>
#include <QTextStream>
#include <QTimer>

#include <cstdio>
#include <optional>
#include <string>

namespace {

constexpr int kExitBadInput = 2;
constexpr int kExitInternal = 1;

/// How long --screenshot waits for loading and the first frame before giving up.
constexpr int kScreenshotTimeoutMs = 180'000;
/// Delay after the first frame before grabbing, so that the window is fully composed.
constexpr int kScreenshotSettleMs = 200;

/// The built-in sample names joined by `separator`.
QString sampleList(const char* separator) {
    std::string names;
    for (const std::string& name : resect::sampleNames())
        names += (names.empty() ? "" : separator) + name;
    return QString::fromStdString(names);
}

void printError(const QString& message) {
    std::fprintf(stderr, "resect-studio: %s\n", message.toLocal8Bit().constData());
}

/// Writes the window image to `path` through a temporary file (QSaveFile).
bool saveScreenshot(QWidget& window, const QString& path, QString& error) {
    const QImage image = window.grab().toImage();
    if (image.isNull()) {
        error = QStringLiteral("could not grab the window");
        return false;
    }
    QSaveFile file(path);
    if (!file.open(QIODevice::WriteOnly)) {
        error = QStringLiteral("%1: %2").arg(path, file.errorString());
        return false;
    }
    if (!image.save(&file, "PNG")) {
        file.cancelWriting();
        error = QStringLiteral("%1: could not encode the PNG image").arg(path);
        return false;
    }
    if (!file.commit()) {
        error = QStringLiteral("%1: %2").arg(path, file.errorString());
        return false;
    }
    return true;
}

} // namespace

int main(int argc, char* argv[]) {
    // Before the application exists, so the window's composition context and the
    // QOpenGLWidget contexts agree on one VTK-suitable format.
    QSurfaceFormat::setDefaultFormat(resect::vtkSurfaceFormat());
    QApplication app(argc, argv);
    QApplication::setOrganizationName(QStringLiteral("Resect"));
    QApplication::setApplicationName(QStringLiteral("resect-studio"));
    QApplication::setApplicationVersion(QStringLiteral("0.1.0"));

    QCommandLineParser parser;
    parser.setApplicationDescription(
        QStringLiteral("Resect Studio: author and test surgical cutting scenarios."));
    const QCommandLineOption helpOption = parser.addHelpOption();
    const QCommandLineOption versionOption = parser.addVersionOption();
    const QCommandLineOption sampleOption(
        QStringLiteral("sample"),
        QStringLiteral("Open a built-in sample (%1); the default is polyp.").arg(sampleList("|")),
        QStringLiteral("name"));
    const QCommandLineOption openOption(
        QStringLiteral("open"),
        QStringLiteral("Open a scenario (.json), a tet mesh (.vtu, .msh, .vtk, .mesh, .node/.ele) or a surface to mesh."),
        QStringLiteral("file"));
    const QCommandLineOption screenshotOption(
        QStringLiteral("screenshot"),
        QStringLiteral("Write a PNG of the window once the view has rendered, then exit."),
        QStringLiteral("png"));
    const QCommandLineOption langOption(
        QStringLiteral("lang"),
        QStringLiteral("Interface language (%1); default: the saved preference, else the system's.")
            .arg(resect::availableLanguages().join(QLatin1Char('|'))),
        QStringLiteral("code"));
    const QCommandLineOption colorByOption(
        QStringLiteral("color-by"),
        QStringLiteral("Colour the tets by quality (default) or piece."),
        QStringLiteral("quality|piece"));
    const QCommandLineOption resectedOption(
        QStringLiteral("resected"),
        QStringLiteral("Resected pieces shown, dimmed (default) or hidden."),
        QStringLiteral("shown|dimmed|hidden"));
    const QCommandLineOption explodeOption(
        QStringLiteral("explode"),
        QStringLiteral("Move the pieces apart by this factor of their distance to the centre "
                       "(0 to %1).")
            .arg(resect::TissueDisplay::kMaxExplode),
        QStringLiteral("factor"));
    parser.addOption(langOption);
    parser.addOption(sampleOption);
    parser.addOption(openOption);
    parser.addOption(screenshotOption);
    parser.addOption(colorByOption);
    parser.addOption(resectedOption);
    parser.addOption(explodeOption);

    if (!parser.parse(QApplication::arguments())) {
        printError(parser.errorText());
        return kExitBadInput;
    }
    if (parser.isSet(helpOption))
        parser.showHelp(0);
    if (parser.isSet(versionOption))
        parser.showVersion();
    if (!parser.positionalArguments().isEmpty()) {
        printError(QStringLiteral("unexpected argument '%1' (use --open FILE)")
                       .arg(parser.positionalArguments().first()));
        return kExitBadInput;
    }
    if (parser.isSet(sampleOption) && parser.isSet(openOption)) {
        printError(QStringLiteral("--sample and --open exclude each other"));
        return kExitBadInput;
    }

    // The language, before any window exists so that every string is translated.
    {
        QString error;
        const QString code =
            resect::chooseLanguage(parser.value(langOption), QSettings(), &error);
        if (code.isEmpty()) {
            printError(QStringLiteral("--lang %1: %2").arg(parser.value(langOption), error));
            return kExitBadInput;
        }
        if (!error.isEmpty())
            printError(error); // a bad saved preference: a warning, the system language is used
        if (!resect::installTranslations(app, code, &error)) {
            printError(QStringLiteral("--lang %1: %2").arg(code, error));
            return kExitBadInput;
        }
    }

    resect::Sample sample = resect::Sample::Polyp;
    QString openPath; // empty: open `sample`
    if (parser.isSet(openOption)) {
        openPath = parser.value(openOption);
        const QFileInfo info(openPath);
        if (!info.exists() || !info.isFile() || !info.isReadable()) {
            printError(QStringLiteral("--open %1: no such readable file").arg(openPath));
            return kExitBadInput;
        }
    } else if (parser.isSet(sampleOption)) {
        const QString name = parser.value(sampleOption);
        const std::optional<resect::Sample> named = resect::sampleFromName(name.toStdString());
        if (!named) {
            printError(QStringLiteral("--sample %1: unknown sample (choose %2)")
                           .arg(name, sampleList(", ")));
            return kExitBadInput;
        }
        sample = *named;
    }

    QString screenshotPath;
    if (parser.isSet(screenshotOption)) {
        screenshotPath = parser.value(screenshotOption);
        const QFileInfo info(screenshotPath);
        if (screenshotPath.isEmpty() || info.isDir() || !info.absoluteDir().exists()) {
            printError(QStringLiteral("--screenshot %1: not a file in an existing directory")
                           .arg(screenshotPath));
            return kExitBadInput;
        }
    }
    const bool screenshot = !screenshotPath.isEmpty();

    // The display settings (validated before any window exists).
    std::optional<resect::TetColorMode> colorMode;
    if (parser.isSet(colorByOption)) {
        const QString v = parser.value(colorByOption);
        if (v == QLatin1String("quality"))
            colorMode = resect::TetColorMode::Quality;
        else if (v == QLatin1String("piece"))
            colorMode = resect::TetColorMode::Piece;
        else {
            printError(QStringLiteral("--color-by %1: choose quality or piece").arg(v));
            return kExitBadInput;
        }
    }
    std::optional<resect::TissueDisplay::Resected> resected;
    if (parser.isSet(resectedOption)) {
        const QString v = parser.value(resectedOption);
        const QStringList names{QStringLiteral("shown"), QStringLiteral("dimmed"), QStringLiteral("hidden")};
        if (!names.contains(v)) {
            printError(QStringLiteral("--resected %1: choose shown, dimmed or hidden").arg(v));
            return kExitBadInput;
        }
        resected = static_cast<resect::TissueDisplay::Resected>(names.indexOf(v));
    }
    double explode = 0;
    if (parser.isSet(explodeOption)) {
        bool ok = false;
        explode = parser.value(explodeOption).toDouble(&ok);
        if (!ok || !(explode >= 0 && explode <= resect::TissueDisplay::kMaxExplode)) {
            printError(QStringLiteral("--explode %1: not a number from 0 to %2")
                           .arg(parser.value(explodeOption))
                           .arg(resect::TissueDisplay::kMaxExplode));
            return kExitBadInput;
        }
    }

    resect::MainWindow window;
    window.resize(1280, 800);
    window.setErrorDialogsEnabled(!screenshot);
    resect::TissueDisplay& display = window.shownTissue().display();
    if (colorMode)
        display.setColorMode(*colorMode);
    if (resected)
        display.setResected(*resected);
    if (explode > 0)
        display.setExplode(explode);

    if (screenshot) {
        QObject::connect(&window, &resect::MainWindow::loadFailed, &app,
                         [](const QString& message) {
                             printError(message);
                             QApplication::exit(kExitBadInput);
                         });
        auto grabAndQuit = [&window, screenshotPath] {
            QString error;
            if (!saveScreenshot(window, screenshotPath, error)) {
                printError(error);
                QApplication::exit(kExitInternal);
                return;
            }
            QApplication::exit(0);
        };
        QObject::connect(&window, &resect::MainWindow::meshLoaded, &app, [&window, grabAndQuit] {
            // The document's cuts come with the tissue; wait for anything still running.
            window.session().waitForIdle(kScreenshotTimeoutMs);
            resect::VtkViewport* viewport = window.viewport();
            if (!viewport->hasRendering()) {
                // Placeholder only: nothing to wait for beyond a normal repaint.
                QTimer::singleShot(kScreenshotSettleMs, &window, grabAndQuit);
                return;
            }
            // Wait for the first frame that shows the mesh, then let it settle.
            QObject::connect(
                viewport, &resect::VtkViewport::frameRendered, &window,
                [&window, grabAndQuit] {
                    QTimer::singleShot(kScreenshotSettleMs, &window, grabAndQuit);
                },
                Qt::SingleShotConnection);
            // If OpenGL turns out to be unusable, the placeholder is what there is to show.
            QObject::connect(
                viewport, &resect::VtkViewport::renderingUnavailable, &window,
                [&window, grabAndQuit] {
                    QTimer::singleShot(kScreenshotSettleMs, &window, grabAndQuit);
                },
                Qt::SingleShotConnection);
            viewport->requestRender();
        });
        QTimer::singleShot(kScreenshotTimeoutMs, &app, [] {
            printError(QStringLiteral("timed out waiting for the mesh and the first frame"));
            QApplication::exit(kExitInternal);
        });
    } else {
        QObject::connect(&window, &resect::MainWindow::loadFailed, &app,
                         [](const QString& message) { printError(message); });
    }

    window.show();
    // A crashed session's autosave is offered first, unless the command line names what to
    // open or only wants a screenshot.
    const bool recovered = !screenshot && openPath.isEmpty() && !parser.isSet(sampleOption) &&
                           window.offerRecovery();
    if (!recovered) {
        if (openPath.isEmpty())
            window.openSample(sample);
        else
            window.openFile(openPath);
    }
    return QApplication::exec();
}
