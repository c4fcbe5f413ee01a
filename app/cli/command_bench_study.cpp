// resect bench [--quick] --out DIR [--no-plots]
// What accuracy costs in time (scenario/accuracy_study.h): writes DIR/accuracy_time.csv,
// DIR/scaling.csv, DIR/summary.md (configuration, run time, the targets) and the
// plots DIR/*.png, drawn by the separate `resect-plot` executable (VTK charts need an X
// display with GLX: resect-plot runs directly if DISPLAY is set, else under `xvfb-run -a`).
// Without --quick: the full study. The hidden option --tiny runs the tests' configuration.
//
// Exit codes: 0 all written; 2 bad input; 1 a study failed, or the plots could not be drawn
// (no display and no xvfb-run, resect-plot missing or failing): the CSVs and summary are
// written all the same and the message says why the PNGs are missing.
#include "app/cli/cli_common.h"
#include "app/cli/plotter.h"

#include "scenario/accuracy_study.h"
#include "scenario/atomic_file.h"

#include <QCoreApplication>
#include <QDir>
#include <QFileInfo>
#include <QProcess>
#include <QThread>
#include <QStandardPaths>

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <memory>
#include <thread>

namespace resect::cli {
namespace {

void writeText(const std::string& path, const std::string& text) {
    const Status s = writeFileAtomically(path, text);
    if (!s.ok())
        throw CliError{kInternal, s.message()};
}

/// Prints a progress line on stderr whenever the stage changes.
StudyProgress printer(const char* study) {
    auto last = std::make_shared<std::string>();
    return [study, last](double fraction, const std::string& stage) {
        if (stage != *last) {
            *last = stage;
            std::fprintf(stderr, "[%s %3.0f%%] %s\n", study, 100.0 * fraction, stage.c_str());
        }
        return true;
    };
}

} // namespace

int runBenchStudy(Args& args) {
    const bool quick = args.flag("--quick");
    const bool tiny = args.flag("--tiny");
    const bool noPlots = args.flag("--no-plots");
    const auto out = args.option("--out");
    const auto rest = args.positionals();
    args.finish();
    if (!rest.empty())
        badInput("unknown study '" + rest.front() + "' (expected cut-scaling, sim, surface, or none for the full study)");
    if (!out || out->empty())
        badInput("--out DIR is required");
    if (quick && tiny)
        badInput("--quick and --tiny exclude each other");
    const QString dir = QString::fromStdString(*out);
    if (QFileInfo(dir).exists() && !QFileInfo(dir).isDir())
        badInput("--out: " + *out + " exists and is not a folder");
    if (!QDir().mkpath(dir))
        badInput("--out: cannot create the folder " + *out);
    const std::string base = QDir(dir).absolutePath().toStdString();

    const StudyConfig config = tiny ? tinyConfig() : quick ? quickConfig() : fullConfig();
    const auto t0 = std::chrono::steady_clock::now();
    const auto seconds = [](auto from) {
        return std::chrono::duration<double>(std::chrono::steady_clock::now() - from).count();
    };

    std::vector<StudyRow> accuracy;
    if (Status s = runAccuracyStudy(config, accuracy, printer("accuracy")); !s.ok())
        throw CliError{kInternal, "accuracy study: " + s.message()};
    const double accuracySeconds = seconds(t0);
    writeText(base + "/accuracy_time.csv", accuracyCsv(accuracy));

    const auto t1 = std::chrono::steady_clock::now();
    std::vector<ScalingRow> scaling;
    if (Status s = runScalingStudy(config, scaling, printer("scaling")); !s.ok())
        throw CliError{kInternal, "scaling study: " + s.message()};
    const double scalingSeconds = seconds(t1);
    writeText(base + "/scaling.csv", scalingCsv(scaling));

    const std::string targets = targetsMarkdown(evaluateTargets(accuracy, scaling));
    char line[512];
    std::snprintf(line, sizeof line,
                  "# resect bench (%s)\n\n"
                  "accuracy study: %zu rows in %.1f s; scaling study: %zu meshes in %.1f s; "
                  "hardware threads: %u.\n\n",
                  config.label.c_str(), accuracy.size(), accuracySeconds, scaling.size(), scalingSeconds,
                  std::thread::hardware_concurrency());
    writeText(base + "/summary.md", std::string(line) + targets);
    std::printf("%s\n%s", line + 2, targets.c_str());
    std::fflush(stdout);

    if (noPlots)
        return kOk;
    const auto t2 = std::chrono::steady_clock::now();
    const QString plots = QString::fromStdString(base);
    if (const std::string why = runPlotter({"--accuracy", plots + "/accuracy_time.csv", "--scaling",
                                            plots + "/scaling.csv", "--out", plots},
                                           "resect bench");
        !why.empty())
        throw CliError{kInternal, "the CSVs and summary.md are written, but no plots: " + why +
                                      " (draw them later with resect-plot, or pass --no-plots)"};
    std::printf("plots drawn in %.1f s; total %.1f s\n", seconds(t2), seconds(t0));
    return kOk;
}

} // namespace resect::cli
