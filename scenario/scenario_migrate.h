#pragma once
// Migration of older scenario layouts to the current one (kScenarioVersion = 1).
//
// Version 0, the first hand-written layout, differs from version 1 as follows:
//   v0                                          v1
//   "title", "author", "description"            "metadata": {...} (+ learning_objectives,
//     at the top level                            difficulty: new, defaults)
//   "tissue": {...} (one tissue, no name)       "tissues": [{"name": "tissue", ...}]
//     "edge_length", "seed"                       "meshing": {"edge_length", "seed"}
//     "density", "stiffness", "damping"           "material": {...}
//     "fixed_box": [x0, y0, z0, x1, y1, z1]       "fixed_regions": [{"min", "max"}]
//   "tool": {"points", "scale"}                 "tool": {"curve", "size"}
//   "strokes": [[pose, ...], ...]               "strokes": [{"poses": [pose, ...]}]
//     pose "rotation": [w, x, y, z]               pose "orientation": [w, x, y, z]
//   "sweeps": ["file.json", ...]                "sweeps": [{"file": "file.json"}]
//   "cut": {"threshold", ...}                   "cut_settings": {"d", ...}
//   "effects": ["gravity", ...] (names only)    "effects": [{"name", "parameters": {}}]
//   "integrator": "explicit" | "implicit",      "simulation": {"integrator":
//     "time_step", "duration" at the top          "symplectic-euler" | "backward-euler", ...}
//   "expect": {"pieces": n,                     "expectations": [{"kind": "pieces_at_least",
//              "min_radius_ratio": r}             "value": n}, {"kind":
//                                                 "min_radius_ratio_at_least", "value": r}]
// Any other field is carried over to the corresponding place and then treated like any
// field of a version-1 document (kept, and warned about if unknown).

#include "scenario/scenario_diagnostics.h"

#include <QJsonObject>

namespace resect {

/// Rewrites a version-0 document as version 1. Adds a warning at "version" saying so (and
/// that later paths refer to the version-1 layout); structural problems that prevent the
/// rewrite (e.g. "tissue" not an object) are errors with their version-0 path, and the
/// offending part is left out.
QJsonObject migrateScenarioV0(const QJsonObject& v0, ScenarioDiagnostics& diag);

} // namespace resect
