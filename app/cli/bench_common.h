#pragma once
// Shared by the `resect bench` subcommands that write a CSV, a markdown summary and a plot:
// small output helpers, and the resection runner of `resect bench resection`
// (command_bench_resection.cpp), also used by `resect bench realtime`: bodies meshed as the
// product meshes them, the tissue anchored at its base with resected pieces removed, and scoop k
// of a resection (resectionScoop, a loop scoop) cut through Tissue::cut.

#include "app/cli/cli_common.h"

#include "core/tissue/tissue.h"
#include "scenario/atomic_file.h"

#include <chrono>
#include <cstdio>
#include <string>
#include <vector>

namespace resect::cli {

inline double secondsSince(std::chrono::steady_clock::time_point t0) {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

/// printf's rendering of one number.
inline std::string format(const char* f, double v) {
    char buf[64];
    std::snprintf(buf, sizeof buf, f, v);
    return buf;
}

/// Writes atomically; an internal failure (exit 1) if it cannot.
inline void writeText(const std::string& path, const std::string& text) {
    if (const Status s = writeFileAtomically(path, text); !s.ok())
        throw CliError{kInternal, s.message()};
}

// ---------------------------------------------------------------- the resection runner

struct Body {
    std::string name; ///< the sample's name or the surface file's base name
    TetMesh mesh;     ///< with masses (Eq. 3)
    Vec3 axis;        ///< (x, y) the scoops pass through
    double meshSeconds = 0;
};

/// Loads every sample (names as sampleFromName knows them) and surface file, then meshes each
/// (meshAnatomy's defaults): all before anything is written. Bad input (one line on stderr) if
/// one fails; the meshing notes go to stderr, each line prefixed by `who`.
std::vector<Body> loadBodies(const std::vector<std::string>& samples,
                             const std::vector<std::string>& surfaces, const char* who);

/// The tissue of a body as the resection starts: anchored at its base, resected pieces removed.
Tissue anchoredTissue(const Body& body);

/// Cuts scoop k (k = 0, 1, ...) of the resection of `body` out of `tissue` (Tissue::cut).
Status cutScoop(Tissue& tissue, const Body& body, int k, const CutOptions& options, TissueCut* out);

} // namespace resect::cli
