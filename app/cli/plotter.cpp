#include "app/cli/plotter.h"

#include <QCoreApplication>
#include <QFileInfo>
#include <QProcess>
#include <QRandomGenerator>
#include <QStandardPaths>
#include <QThread>

#include <cstdio>
#include <cstdlib>
#include <string>
#include <utility>

namespace resect::cli {

namespace {

// Attempts, and the pause before the second; it doubles after each failure (1, 2, 4, 8 s).
constexpr int kPlotAttempts = 5;
constexpr int kRetryPauseMs = 1000;
constexpr int kPlotterTimeoutMs = 600000;   // 10 minutes
// xvfb-run -a looks for a free display from 99 on, where another Xvfb may be running unseen (a
// server whose lock file we cannot see still owns the abstract socket of its display, and our
// client would talk to it). Each run starts its search at a random number in this range.
constexpr int kFirstDisplay = 200, kLastDisplay = 899;
// The server Xvfb is started with. -noreset: an X server resets when its last client
// disconnects and refuses connections while it does. resect-plot checks the display with a
// connection of its own before VTK opens another; on a server that resets, VTK's could come
// during the reset and abort with "bad X server connection", as on every attempt of a CI run
// (measured here: opening, closing and opening again fails 67 times in 2000 on a server
// without -noreset, never with it). resect-plot keeps its connection open too.
const char* const kXvfbServerArgs = "-screen 0 1280x1024x24 -noreset";

/// How a run went: `why` empty if it drew the plots; `lasting`: a failure another attempt
/// cannot mend (no plotter, no xvfb-run).
struct RunOutcome {
    std::string why;
    bool lasting = false;
};
RunOutcome lastingFailure(std::string why) { return {std::move(why), true}; }

/// One run; `ownDisplay`: under a fresh `xvfb-run -a` even if DISPLAY is set.
RunOutcome runOnce(const QStringList& plotterArgs, bool ownDisplay) {
    const QString plotter = QCoreApplication::applicationDirPath() + "/resect-plot";
    if (!QFileInfo(plotter).isExecutable())
        return lastingFailure("the plotter " + plotter.toStdString() + " is not built");
    QStringList args = plotterArgs;
    QString program = plotter;
    const char* display = std::getenv("DISPLAY");
    if (ownDisplay || !display || !*display) {
        const QString xvfb = QStandardPaths::findExecutable("xvfb-run");
        if (xvfb.isEmpty())
            return lastingFailure("no X display (DISPLAY is unset) and no xvfb-run to start one (install xvfb)");
        const int from = QRandomGenerator::global()->bounded(kFirstDisplay, kLastDisplay + 1);
        args = QStringList{"-a", "-n", QString::number(from), "-s", kXvfbServerArgs, plotter} + args;
        program = xvfb;
    }
    QProcess p;
    p.setProcessChannelMode(QProcess::ForwardedChannels);
    if (ownDisplay) {
        QProcessEnvironment env = QProcessEnvironment::systemEnvironment();
        env.remove("DISPLAY");
        p.setProcessEnvironment(env);
    }
    p.start(program, args);
    if (!p.waitForStarted(30000))
        return {"cannot start " + program.toStdString()};
    if (!p.waitForFinished(kPlotterTimeoutMs)) {
        p.kill();
        p.waitForFinished();
        return {"resect-plot did not finish within 10 minutes"};
    }
    if (p.exitStatus() != QProcess::NormalExit)
        return {"resect-plot crashed"};
    if (p.exitCode() != 0)
        return {"resect-plot failed (exit code " + std::to_string(p.exitCode()) + ", see its message above)"};
    return {};
}

} // namespace

std::string runPlotter(const QStringList& plotterArgs, const char* who) {
    std::string why;
    for (int attempt = 0; attempt < kPlotAttempts; ++attempt) {
        // After a failure, a display of our own: the one we were given may be gone (an Xvfb
        // that lost its display number to another started at the same moment).
        const RunOutcome run = runOnce(plotterArgs, attempt > 0);
        why = run.why;
        if (why.empty())
            return why;
        const bool again = !run.lasting && attempt + 1 < kPlotAttempts;
        std::fprintf(stderr, "%s: drawing the plots failed (%s)%s\n", who, why.c_str(), again ? "; trying again" : "");
        if (!again)
            break;
        QThread::msleep(static_cast<unsigned long>(kRetryPauseMs) << attempt);
    }
    return why;
}

} // namespace resect::cli
