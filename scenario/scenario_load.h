#pragma once
// Reading and validating a scenario document (scenario_document.h describes the layout and
// every field's range). Validation reports every problem at once, each with its JSON path:
//   - malformed JSON (with the byte offset), a document that is not an object;
//   - "format" other than "resect-scenario", a "version" newer than kScenarioVersion or not
//     a non-negative integer (these stop reading: the rest could mean anything);
//   - a missing required field, a value of the wrong type, a number out of range or absurdly
//     large (coordinates beyond 1e6 mm, times beyond 1e6 s; JSON cannot hold NaN or
//     infinity, and numbers too large for a double are a JSON error), an unknown name
//     (method, integrator, effect, expectation kind, sample);
//   - strokes with fewer than two poses or time stamps that do not increase, quaternions of
//     zero length, sweep curves of different lengths, sweeps (inline, from a file, or swept
//     by a stroke's poses) that SweepSurface::fromCurves rejects;
//   - referenced files that do not exist (resolved against the scenario file's folder);
//   - inconsistencies: strokes without a tool, "fixed" without fixed regions, "damping"
//     without a coefficient, duplicate tissue or effect names, an expectation naming an
//     unknown tissue, the enhanced triangulation with the subdivision method;
//   - absurd sizes: more than 1e6 poses in all strokes (reported once; the remaining
//     strokes are not read), a stroke whose sweep would have more than 1e6 vertices (poses x
//     tool points; not built), more than 1e6 points in a sweep's curves, other lists longer
//     than 1e5 entries; and at most ScenarioDiagnostics::kMaxIssues issues are listed.
// Unknown fields are warnings and are kept (Scenario's `extra` objects). A version-0 file is
// migrated first (scenario_migrate.h) with a warning. Reading never throws and never crashes.

#include "core/status.h"
#include "scenario/scenario_diagnostics.h"
#include "scenario/scenario_document.h"

#include <QByteArray>

#include <string>

namespace resect {

/// Parses and validates a document held in memory. Relative paths are resolved against
/// `baseDir` (empty: the current folder), which becomes out.baseDir (made absolute);
/// `name` is used in the returned message. On success (no errors; warnings allowed) `out`
/// is the document; on failure `out` is unchanged and the Status is diag.firstError(name).
/// `diag` receives every issue (it is cleared first).
Status parseScenario(const QByteArray& json, const std::string& baseDir, const std::string& name,
                     Scenario& out, ScenarioDiagnostics& diag);

/// Reads the file (at most 256 MiB) and parses it with its folder as the base.
Status loadScenario(const std::string& path, Scenario& out, ScenarioDiagnostics& diag);

/// Validates a document built in memory (e.g. by an editor) exactly as loading would,
/// against scenario.baseDir.
Status validateScenario(const Scenario& scenario, ScenarioDiagnostics& diag);

} // namespace resect
