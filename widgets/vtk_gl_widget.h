#pragma once
// VtkGlWidget: the Qt 6 <-> VTK bridge. A QOpenGLWidget that lets a
// vtkGenericOpenGLRenderWindow render into the widget's framebuffer with the widget's
// context (DESIGN.md, platform facts: VTK's own Qt module is built against Qt 5 on Debian
// and must never be linked).
//
// VTK does not own the context (SetOwnContext(false)); it is initialised in initializeGL()
// (OpenGLInitContext) and renders only from paintGL(), where Qt has made the context current
// and bound the widget's framebuffer object; VTK renders into its own framebuffer and blits
// into the one bound at the time (SetFrameBlitModeToBlitToCurrent). Call update() to
// request a frame. Input events are not handled here: the owning VtkViewport drives the
// camera.

#include <QOpenGLWidget>
#include <QString>

#include <vtkSmartPointer.h>

class vtkGenericOpenGLRenderWindow;
class vtkObject;
class vtkRenderer;

namespace resect {

class VtkGlWidget : public QOpenGLWidget {
    Q_OBJECT

public:
    explicit VtkGlWidget(QWidget* parent = nullptr);
    ~VtkGlWidget() override;

    vtkRenderer* renderer() const;
    vtkGenericOpenGLRenderWindow* renderWindow() const;

    /// True once initializeGL() succeeded and until a failure; false before the widget was
    /// first shown.
    bool isReady() const { return m_ready; }
    /// True if initialisation failed (initializationFailed() was emitted).
    bool hasFailed() const { return m_failed; }
    /// Number of frames VTK has rendered so far.
    int frameCount() const { return m_frameCount; }

signals:
    /// Emitted at the end of every paintGL() that rendered a VTK frame.
    void frameRendered();
    /// Emitted (queued) when the context is unusable for VTK; the widget then stays blank
    /// and its owner should replace it.
    void initializationFailed(const QString& reason);

protected:
    void initializeGL() override;
    void resizeGL(int width, int height) override;
    void paintGL() override;

private:
    void releaseGraphics();
    void syncWindowSize();
    void fail(const QString& reason);

    // VTK observer callbacks (vtkGenericOpenGLRenderWindow asks its owner about the context).
    void onMakeCurrent(vtkObject* caller, unsigned long event, void* callData);
    void onIsCurrent(vtkObject* caller, unsigned long event, void* callData);
    void onSupportsOpenGL(vtkObject* caller, unsigned long event, void* callData);
    void onVtkError(vtkObject* caller, unsigned long event, void* callData);

    vtkSmartPointer<vtkGenericOpenGLRenderWindow> m_window;
    vtkSmartPointer<vtkRenderer> m_renderer;
    bool m_ready = false;
    bool m_failed = false;
    int m_frameCount = 0;
    QString m_initError; ///< set by onVtkError() during initializeGL()
};

} // namespace resect
