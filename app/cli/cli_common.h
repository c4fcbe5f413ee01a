#pragma once
// Shared pieces of the `resect` command line: argument parsing with clear errors, exit
// codes (0 success, 2 bad input, 1 internal failure) and JSON output.

#include "core/status.h"
#include "scenario/mesh_io.h"

#include <QJsonObject>

#include <optional>
#include <string>
#include <vector>

namespace resect::cli {

enum ExitCode { kOk = 0, kInternal = 1, kBadInput = 2 };

/// Thrown inside a command, caught once in main(): one line on stderr and the exit code.
struct CliError {
    int code;
    std::string message;
};

[[noreturn]] void badInput(const std::string& message);
/// Throws CliError(kBadInput) with the status message if it failed.
void requireOk(const Status& status);

/// Arguments of one subcommand. Options are "--name value" or "--name=value"; everything
/// taken is removed, and finish() rejects whatever is left.
class Args {
public:
    explicit Args(std::vector<std::string> args) : m_args(std::move(args)) {}

    std::optional<std::string> option(const std::string& name);
    std::vector<std::string> options(const std::string& name);  ///< repeated option
    /// An option followed by `count` values ("--fix-box x0 y0 z0 x1 y1 z1"); values may start
    /// with '-' (negative numbers) but not with "--".
    std::optional<std::vector<std::string>> optionValues(const std::string& name, int count);
    /// optionValues parsed as finite numbers; the error names the option.
    std::optional<std::vector<double>> numbers(const std::string& name, int count,
                                               const std::string& what);
    std::string requiredOption(const std::string& name);
    bool flag(const std::string& name);
    /// A finite number in [min, max]; the error names the option and the bad value.
    std::optional<double> number(const std::string& name, double min, double max);
    std::optional<int> integer(const std::string& name, int min, int max);
    /// Remaining arguments that do not start with "--".
    std::vector<std::string> positionals();
    /// Fails on any unknown option left over.
    void finish() const;

private:
    std::vector<std::string> m_args;
};

/// Compact-indented JSON on stdout.
void printJson(const QJsonObject& object);
/// Writes JSON atomically (temporary file, then rename).
Status writeJson(const std::string& path, const QJsonObject& object);
/// Bad input if `out` names the same existing file as `input` (never overwrite inputs).
void requireDistinct(const std::string& input, const std::string& out);

/// A tet mesh to write: its path and format.
struct MeshOutput {
    std::string path;
    MeshFormat format = MeshFormat::Vtu;
};
/// Checks a tet mesh output before any work: the format is `formatKey`'s (--mesh-format) or
/// the extension's default; bad input (exit 2) names `option` and what is wrong (no or an
/// unknown extension, a format that does not fit it).
MeshOutput meshOutput(const std::string& path, const std::optional<std::string>& formatKey,
                      const std::string& option = "--out");
/// The files a tet mesh path stands for: itself, and for TetGen (.node/.ele) both of the pair.
std::vector<std::string> meshFiles(const std::string& path);
/// requireDistinct for tet meshes: no file of the output (a TetGen pair: both) may be a file
/// of the input.
void requireDistinctMesh(const std::string& input, const std::string& out);
/// Writes the mesh; a failure is bad input naming the file (requireOk).
void writeMeshOutput(const MeshOutput& out, const TetMesh& mesh);
/// One line on stderr ("note: ...") if the read dropped elements or merged duplicates.
void printReadNotes(const std::string& path, const MeshReadReport& report);

int runInfo(Args args);
int runConvert(Args args);
int runMesh(Args args);
int runDemo(Args args);
int runCut(Args args);
int runSimulate(Args args);
int runTable1(Args args);
int runRun(Args args);
int runExport(Args args);
int runBench(Args args);
int runBenchSim(Args& args);  ///< resect bench sim (command_bench_sim.cpp)
int runBenchStudy(Args& args);  ///< resect bench [--quick] --out DIR (command_bench_study.cpp)

} // namespace resect::cli
