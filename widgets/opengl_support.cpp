#include "widgets/opengl_support.h"

#include <QGuiApplication>
#include <QOffscreenSurface>
#include <QOpenGLContext>
#include <QtGlobal>

#include <optional>

namespace resect {

QSurfaceFormat vtkSurfaceFormat() {
    QSurfaceFormat format;
    format.setRenderableType(QSurfaceFormat::OpenGL);
    format.setVersion(kVtkGlMajor, kVtkGlMinor);
    format.setProfile(QSurfaceFormat::CoreProfile);
    format.setRedBufferSize(8);
    format.setGreenBufferSize(8);
    format.setBlueBufferSize(8);
    format.setAlphaBufferSize(8);
    format.setDepthBufferSize(24);
    format.setStencilBufferSize(8);
    format.setSamples(0);
    format.setSwapBehavior(QSurfaceFormat::DoubleBuffer);
    format.setSwapInterval(0);
    return format;
}

namespace {

struct Probe {
    bool available = false;
    QString reason;
};

Probe probeOpenGl() {
    const QString platform = QGuiApplication::platformName();
    if (platform.isEmpty())
        return {false, QStringLiteral("no QGuiApplication")};
    if (platform == QLatin1String("offscreen") || platform == QLatin1String("minimal"))
        return {false, QStringLiteral("the Qt platform '%1' has no OpenGL").arg(platform)};
    const QByteArray disabled = qgetenv("RESECT_NO_OPENGL");
    if (!disabled.isEmpty() && disabled != "0")
        return {false, QStringLiteral("OpenGL disabled by RESECT_NO_OPENGL")};

    QOpenGLContext context;
    context.setFormat(vtkSurfaceFormat());
    if (!context.create())
        return {false, QStringLiteral("cannot create an OpenGL context")};
    const QSurfaceFormat got = context.format();
    if (got.renderableType() == QSurfaceFormat::OpenGLES ||
        got.version() < qMakePair(kVtkGlMajor, kVtkGlMinor)) {
        return {false, QStringLiteral("OpenGL %1.%2 found, VTK needs desktop OpenGL %3.%4")
                           .arg(got.majorVersion())
                           .arg(got.minorVersion())
                           .arg(kVtkGlMajor)
                           .arg(kVtkGlMinor)};
    }
    QOffscreenSurface surface;
    surface.setFormat(context.format());
    surface.create();
    if (!surface.isValid() || !context.makeCurrent(&surface))
        return {false, QStringLiteral("cannot make an OpenGL context current")};
    context.doneCurrent();
    return {true, {}};
}

} // namespace

bool openGlAvailable(QString* reason) {
    // Probed once per process: the platform cannot gain or lose OpenGL while running.
    static std::optional<Probe> cached;
    if (!cached && QGuiApplication::instance() != nullptr)
        cached = probeOpenGl();
    const Probe probe = cached ? *cached : Probe{false, QStringLiteral("no QGuiApplication")};
    if (!probe.available && reason != nullptr)
        *reason = probe.reason;
    return probe.available;
}

} // namespace resect
