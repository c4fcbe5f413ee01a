#pragma once
// What VTK's OpenGL2 backend needs from Qt, and whether the platform can provide it.
//
// VTK 9.1 renders with an OpenGL 3.2 core profile context. The `offscreen` Qt platform has
// no OpenGL at all (DESIGN.md, platform facts), so viewports ask openGlAvailable() first
// and show a placeholder instead of a QOpenGLWidget when it says no.

#include <QString>
#include <QSurfaceFormat>

namespace resect {

/// OpenGL 3.2 core profile, RGBA8, depth 24, stencil 8, no multisampling (VTK renders into
/// its own framebuffer and blits; multisampling there would only cost time), no vsync.
/// Set it with QSurfaceFormat::setDefaultFormat() before the QApplication is created so
/// that the window's composition context and every QOpenGLWidget share one format.
QSurfaceFormat vtkSurfaceFormat();

/// Minimum OpenGL version VTK's OpenGL2 backend accepts.
inline constexpr int kVtkGlMajor = 3;
inline constexpr int kVtkGlMinor = 2;

/// True if this process can create an OpenGL context of vtkSurfaceFormat() and make it
/// current. False on the `offscreen` and `minimal` platforms, when the environment variable
/// RESECT_NO_OPENGL is set to a non-empty value other than 0, or when context creation
/// fails or yields a version below 3.2. The probe runs once (it needs a QGuiApplication);
/// later calls return the cached answer. `reason`, if given, receives a one-line
/// explanation when the answer is false.
bool openGlAvailable(QString* reason = nullptr);

} // namespace resect
