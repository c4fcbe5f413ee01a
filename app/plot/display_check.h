#pragma once
// Whether an X display with GLX can be opened (VTK 9.1 on Debian renders through GLX and
// aborts without one). Kept apart from the plotting code: Xlib's macros (Status, None, ...)
// clash with the project's names.

#include <string>

namespace resect::plot {

/// Empty if DISPLAY names an X server that can be opened and has the GLX extension; else
/// what is missing, as one sentence. The connection it opens stays open until the process
/// exits: an X server started without -noreset resets when its last client disconnects and
/// refuses connections meanwhile, so closing it would race VTK's own connection (VTK then
/// aborts with "bad X server connection").
std::string displayProblem();

} // namespace resect::plot
