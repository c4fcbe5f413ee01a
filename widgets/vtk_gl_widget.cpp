#include "widgets/vtk_gl_widget.h"

#include "widgets/opengl_support.h"

#include <QMetaObject>
#include <QOpenGLContext>

#include <vtkCommand.h>
#include <vtkGenericOpenGLRenderWindow.h>
#include <vtkOpenGLState.h>
#include <vtkRenderer.h>

#include <cmath>

namespace resect {

VtkGlWidget::VtkGlWidget(QWidget* parent)
    : QOpenGLWidget(parent), m_window(vtkSmartPointer<vtkGenericOpenGLRenderWindow>::New()),
      m_renderer(vtkSmartPointer<vtkRenderer>::New()) {
    setFormat(vtkSurfaceFormat());
    // VTK paints every pixel; no need for Qt to clear or to keep partial updates.
    setUpdateBehavior(QOpenGLWidget::NoPartialUpdate);

    m_window->SetOwnContext(false);
    m_window->SetFrameBlitModeToBlitToCurrent();
    m_window->SetMultiSamples(0);
    m_window->SetReadyForRendering(false);
    m_window->AddRenderer(m_renderer);
    m_window->AddObserver(vtkCommand::WindowMakeCurrentEvent, this, &VtkGlWidget::onMakeCurrent);
    m_window->AddObserver(vtkCommand::WindowIsCurrentEvent, this, &VtkGlWidget::onIsCurrent);
    m_window->AddObserver(vtkCommand::WindowSupportsOpenGLEvent, this,
                          &VtkGlWidget::onSupportsOpenGL);
}

VtkGlWidget::~VtkGlWidget() {
    // ~QOpenGLWidget destroys the context and would emit aboutToBeDestroyed into a
    // half-destroyed object: disconnect first, then release VTK's GPU objects while the
    // context still exists.
    if (QOpenGLContext* ctx = context())
        disconnect(ctx, nullptr, this, nullptr);
    releaseGraphics();
    m_window->RemoveAllObservers();
    m_window->RemoveRenderer(m_renderer);
}

vtkRenderer* VtkGlWidget::renderer() const {
    return m_renderer;
}

vtkGenericOpenGLRenderWindow* VtkGlWidget::renderWindow() const {
    return m_window;
}

void VtkGlWidget::initializeGL() {
    // A new context (first show, or the widget moved to another top-level window).
    m_ready = false;
    connect(context(), &QOpenGLContext::aboutToBeDestroyed, this, &VtkGlWidget::releaseGraphics,
            Qt::UniqueConnection);

    const QSurfaceFormat got = context()->format();
    if (got.renderableType() == QSurfaceFormat::OpenGLES ||
        got.version() < qMakePair(kVtkGlMajor, kVtkGlMinor)) {
        fail(QStringLiteral("the widget's OpenGL context is %1.%2, VTK needs %3.%4")
                 .arg(got.majorVersion())
                 .arg(got.minorVersion())
                 .arg(kVtkGlMajor)
                 .arg(kVtkGlMinor));
        return;
    }

    m_window->SetIsCurrent(true);
    m_window->SetMapped(1);
    m_window->SetSupportsOpenGL(1);
    // VTK reports a failed initialisation (function loading, version check) only through
    // vtkErrorMacro: catch it as an ErrorEvent while initialising.
    m_initError.clear();
    const unsigned long errorObserver =
        m_window->AddObserver(vtkCommand::ErrorEvent, this, &VtkGlWidget::onVtkError);
    m_window->OpenGLInitContext();
    m_window->RemoveObserver(errorObserver);
    if (!m_initError.isEmpty()) {
        fail(QStringLiteral("VTK could not initialise OpenGL: %1").arg(m_initError));
        return;
    }
    syncWindowSize();
    m_ready = true;
}

void VtkGlWidget::resizeGL(int, int) {
    syncWindowSize();
}

void VtkGlWidget::paintGL() {
    if (!m_ready || m_failed)
        return;
    syncWindowSize();
    int* size = m_window->GetSize();
    if (size[0] <= 0 || size[1] <= 0)
        return;

    // Qt bound the widget's framebuffer object and may have touched other state since the
    // last frame: let VTK's state cache re-read it, and restore it for Qt afterwards.
    vtkOpenGLState* state = m_window->GetState();
    state->Reset();
    state->Push();
    m_renderer->ResetCameraClippingRange();
    m_window->SetReadyForRendering(true);
    m_window->Render();
    m_window->SetReadyForRendering(false);
    state->Pop();

    ++m_frameCount;
    emit frameRendered();
}

void VtkGlWidget::releaseGraphics() {
    if (context() == nullptr || !m_ready)
        return;
    makeCurrent();
    m_window->ReleaseGraphicsResources(m_window);
    doneCurrent();
    m_ready = false;
}

void VtkGlWidget::syncWindowSize() {
    const qreal ratio = devicePixelRatioF();
    const int w = static_cast<int>(std::lround(width() * ratio));
    const int h = static_cast<int>(std::lround(height() * ratio));
    int* size = m_window->GetSize();
    if (size[0] != w || size[1] != h)
        m_window->SetSize(w, h);
}

void VtkGlWidget::fail(const QString& reason) {
    m_failed = true;
    m_ready = false;
    // Queued: the owner replaces this widget, which must not happen inside initializeGL().
    QMetaObject::invokeMethod(
        this, [this, reason] { emit initializationFailed(reason); }, Qt::QueuedConnection);
}

void VtkGlWidget::onMakeCurrent(vtkObject*, unsigned long, void*) {
    QOpenGLContext* ctx = context();
    if (ctx != nullptr && QOpenGLContext::currentContext() != ctx)
        makeCurrent();
}

void VtkGlWidget::onIsCurrent(vtkObject*, unsigned long, void* callData) {
    QOpenGLContext* ctx = context();
    if (callData != nullptr)
        *static_cast<bool*>(callData) = ctx != nullptr && QOpenGLContext::currentContext() == ctx;
}

void VtkGlWidget::onVtkError(vtkObject*, unsigned long, void* callData) {
    const char* message = static_cast<const char*>(callData);
    m_initError = message != nullptr ? QString::fromLocal8Bit(message).trimmed()
                                     : QStringLiteral("unknown error");
}

void VtkGlWidget::onSupportsOpenGL(vtkObject*, unsigned long, void* callData) {
    if (callData != nullptr)
        *static_cast<int*>(callData) = context() != nullptr ? 1 : 0;
}

} // namespace resect
