#include "app/plot/display_check.h"

#include <GL/glx.h>
#include <X11/Xlib.h>

#include <cstdlib>

namespace resect::plot {

std::string displayProblem() {
    const char* name = std::getenv("DISPLAY");
    if (!name || !*name)
        return "no X display (DISPLAY is unset): run under xvfb-run -a";
    // Kept open, never closed (the process's exit closes it), so that the server has a client
    // when VTK connects (display_check.h).
    static Display* const display = XOpenDisplay(nullptr);
    if (!display)
        return std::string("cannot open the X display '") + name + "'";
    int errorBase = 0, eventBase = 0;
    const bool glx = glXQueryExtension(display, &errorBase, &eventBase);
    if (!glx)
        return std::string("the X display '") + name + "' has no GLX (OpenGL)";
    return {};
}

} // namespace resect::plot
