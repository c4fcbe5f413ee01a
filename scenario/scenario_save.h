#pragma once
// Saving a scenario document (layout in scenario_document.h).

#include "core/status.h"
#include "scenario/scenario_document.h"

#include <QByteArray>

#include <string>

namespace resect {

/// The document as indented JSON text, paths as stored.
QByteArray scenarioJsonText(const Scenario& scenario);

/// Writes the document to `path`:
///  - relative paths are rewritten relative to the file's folder (rebaseScenarioPaths from
///    scenario.baseDir; an empty baseDir is the current folder), so that they keep naming
///    the same files;
///  - the rewritten document is validated exactly as loading would (validateScenario); a
///    document with errors is not written (the message is the first error);
///  - writing is atomic (atomic_file.h): a temporary file next to `path`, then a rename, so
///    a failed save (invalid document, unwritable folder, full disk) leaves an existing
///    file as it was.
/// Loading the written file gives a document equal (==) to `scenario`, up to the rewritten
/// paths.
Status saveScenario(const std::string& path, const Scenario& scenario);

} // namespace resect
