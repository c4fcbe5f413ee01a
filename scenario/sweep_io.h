#pragma once
// Sweep surface files (DESIGN.md "Sweep surface files"):
//   {"curves": [[[x,y,z], ...], [[x,y,z], ...], ...]}
// m >= 2 tool curves in time order, each with the same n + 1 >= 2 points.

#include "core/status.h"
#include "core/sweep/sweep_surface.h"

#include <QByteArray>

#include <string>

namespace resect {

/// Reads and validates a sweep file. Errors name the file and the JSON path of the first
/// problem (e.g. "cut.json: curves[1][3]: expected [x, y, z] with finite numbers").
Status readSweep(const std::string& path, SweepSurface& out);
/// The same from bytes already read; `name` is used in messages.
Status parseSweep(const QByteArray& json, const std::string& name, SweepSurface& out);
/// Writes the sweep's curves atomically.
Status writeSweep(const std::string& path, const SweepSurface& sweep);

} // namespace resect
