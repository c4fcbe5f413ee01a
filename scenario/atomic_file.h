#pragma once
// Atomic file writing: write to a temporary file in the target's folder, then rename it
// over the target. A failed or interrupted write never leaves a half file and never
// touches an existing target.

#include "core/status.h"

#include <functional>
#include <string>
#include <string_view>

namespace resect {

/// Calls write(tmpPath) with a temporary path next to `path` (same extension, so that
/// writers choosing a format by extension still work), then renames it to `path`. If
/// write fails, or the rename fails, the temporary is removed and the error returned.
Status writeAtomically(const std::string& path,
                       const std::function<Status(const std::string& tmpPath)>& write);

/// Writes `bytes` to `path` atomically (writeAtomically); the error of a failed write is
/// "PATH: cannot write".
Status writeFileAtomically(const std::string& path, std::string_view bytes);

} // namespace resect
