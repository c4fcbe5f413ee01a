#pragma once
// Fuzz harnesses for the readers of untrusted files (issue 7, "Hostile input").
//
// A fuzz target is a name ("vtu", "surface_obj", ...) and a function that feeds one input to
// one reader and classifies what happened. The same functions run under libFuzzer
// (fuzz_main.cpp, one executable fuzz_<name> per target) and in the regression test
// (tests/scenario/test_fuzz_regressions.cpp), which feeds them every file of
// fuzz/corpus/<name>/ and tests/fuzz_regressions/<name>/.
//
// Adding a target: a .cpp file in fuzz/inputs/ that defines
//     Outcome myInput(std::span<const std::uint8_t> input) { ... }
//     RESECT_FUZZ_TARGET(my_reader, myInput);
// and one line in fuzz/CMakeLists.txt: resect_add_fuzzer(NAME my_reader SOURCES inputs/...).

#include "core/mesh/tet_mesh.h"
#include "core/mesh/triangle_surface.h"
#include "core/status.h"
#include "core/sweep/sweep_surface.h"

#include <cstdint>
#include <initializer_list>
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace resect::fuzz {

/// What one input did to a reader.
struct Outcome {
    enum class Kind {
        Accepted, ///< read, and the result passed every invariant check
        Rejected, ///< a clean error that names the file
        Broken,   ///< a bug: an invariant of the result, or of the error, does not hold
    };
    Kind kind = Kind::Accepted;
    std::string message; ///< Rejected: the reader's error; Broken: what does not hold

    static Outcome accepted() { return {Kind::Accepted, {}}; }
    static Outcome broken(std::string what) { return {Kind::Broken, std::move(what)}; }
};

using InputFunction = Outcome (*)(std::span<const std::uint8_t> input);

struct Target {
    const char* name;
    InputFunction run;
};

/// Registers a target (done by RESECT_FUZZ_TARGET at static initialisation).
bool registerTarget(const char* name, InputFunction run);
/// Every registered target, sorted by name.
std::vector<Target> targets();
/// The target called `name`, or nullptr.
const Target* findTarget(std::string_view name);

// --- helpers for the input functions ---

/// This process's scratch folder (created under $TMPDIR or /tmp on first use, removed at
/// exit), so that parallel fuzzing jobs never share files.
const std::string& scratchDir();
/// Writes `bytes` to scratchDir()/name (replacing it) and returns the path. Aborts if it
/// cannot: then the machine, not the reader, is broken.
std::string writeScratchFile(const std::string& name, std::span<const std::uint8_t> bytes);

/// The outcome of a failed read: Rejected if the message names one of `paths` (every reader
/// promises errors that name the file), Broken otherwise.
Outcome rejected(const Status& status, std::initializer_list<std::string_view> paths);

/// Invariant checks on a reader's result: an empty string if they hold, else the first
/// violation. Tet meshes: nodes and tets present, node arrays of equal size, indices valid,
/// finite coordinates and velocities, finite non-negative masses, every tet positively
/// oriented in the reference configuration (exact predicate); with `importedMesh`
/// (Gmsh, TetGen) also every node used by a tet and every mass positive.
std::string checkTetMesh(const TetMesh& mesh, bool importedMesh);
/// Sweeps: m >= 2 curves of n + 1 >= 2 finite points, 2 n (m - 1) triangles, indices valid.
std::string checkSweep(const SweepSurface& sweep);
/// Surfaces: triangles present, indices valid, three distinct corners (the reader welds and
/// drops collapsed triangles), finite positions, uvs empty or one finite pair per vertex.
std::string checkSurface(const TriangleSurface& surface);

} // namespace resect::fuzz

/// Defines fuzz target `name` (an identifier) run by `function`.
#define RESECT_FUZZ_TARGET(name, function)                                                         \
    [[maybe_unused]] static const bool resect_fuzz_target_##name =                                 \
        ::resect::fuzz::registerTarget(#name, function)
