#pragma once
// Whether an X display with GLX can be opened (VTK 9.1 on Debian renders through GLX and
// aborts without one). Kept apart from the plotting code: Xlib's macros (Status, None, ...)
// clash with the project's names.

#include <string>

namespace resect::plot {

/// Empty if DISPLAY names an X server that can be opened and has the GLX extension; else
/// what is missing, as one sentence.
std::string displayProblem();

} // namespace resect::plot
