#pragma once
// Drawing plots with resect-plot (app/plot), which needs an X display with GLX: it runs directly
// if DISPLAY is set, else under `xvfb-run -a`.

#include <QStringList>

#include <string>

namespace resect::cli {

/// Runs resect-plot (next to this executable) with `plotterArgs`, up to four times: an Xvfb
/// started by `xvfb-run -a` now and then loses its display to another started at the same
/// moment (two draw at once on a shared machine), and the plotter then cannot connect; the
/// later attempts run under an `xvfb-run -a` of their own (another display), even
/// where DISPLAY was set. Empty on success, else why there is no plot (also printed to
/// stderr, prefixed by `who`, after every failed attempt).
std::string runPlotter(const QStringList& plotterArgs, const char* who);

} // namespace resect::cli
