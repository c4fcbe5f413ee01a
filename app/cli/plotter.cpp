#include "app/cli/plotter.h"

#include <QCoreApplication>
#include <QFileInfo>
#include <QProcess>
#include <QRandomGenerator>
#include <QStandardPaths>
#include <QThread>

#include <cstdio>
#include <cstdlib>

namespace resect::cli {

namespace {

constexpr int kPlotAttempts = 4;
constexpr int kRetryPauseMs = 1000;          // time for a clashing Xvfb to settle
constexpr int kPlotterTimeoutMs = 600000;   // 10 minutes
// xvfb-run -a looks for a free display from 99 on, where another Xvfb may be running unseen
// (a server whose lock file we cannot see still owns the abstract socket of its display, and
// our client then talks to it: "bad X server connection" on every attempt, seen in CI). Each
// run starts its search at a random number in this range instead.
constexpr int kFirstDisplay = 200, kLastDisplay = 899;

/// One run; `ownDisplay`: under a fresh `xvfb-run -a` even if DISPLAY is set.
std::string runOnce(const QStringList& plotterArgs, bool ownDisplay) {
    const QString plotter = QCoreApplication::applicationDirPath() + "/resect-plot";
    if (!QFileInfo(plotter).isExecutable())
        return "the plotter " + plotter.toStdString() + " is not built";
    QStringList args = plotterArgs;
    QString program = plotter;
    const char* display = std::getenv("DISPLAY");
    if (ownDisplay || !display || !*display) {
        const QString xvfb = QStandardPaths::findExecutable("xvfb-run");
        if (xvfb.isEmpty())
            return "no X display (DISPLAY is unset) and no xvfb-run to start one (install xvfb)";
        const int from = QRandomGenerator::global()->bounded(kFirstDisplay, kLastDisplay + 1);
        args = QStringList{"-a", "-n", QString::number(from), "-s", "-screen 0 1280x1024x24", plotter} + args;
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
        return "cannot start " + program.toStdString();
    if (!p.waitForFinished(kPlotterTimeoutMs)) {
        p.kill();
        p.waitForFinished();
        return "resect-plot did not finish within 10 minutes";
    }
    if (p.exitStatus() != QProcess::NormalExit)
        return "resect-plot crashed";
    if (p.exitCode() != 0)
        return "resect-plot failed (exit code " + std::to_string(p.exitCode()) + ", see its message above)";
    return {};
}

} // namespace

std::string runPlotter(const QStringList& plotterArgs, const char* who) {
    std::string why;
    for (int attempt = 0; attempt < kPlotAttempts; ++attempt) {
        // After a failure, a display of our own: the one we were given may be gone (an Xvfb
        // that lost its display number to another started at the same moment).
        why = runOnce(plotterArgs, attempt > 0);
        if (why.empty())
            return why;
        std::fprintf(stderr, "%s: drawing the plots failed (%s)%s\n", who, why.c_str(),
                     attempt + 1 < kPlotAttempts ? "; trying again" : "");
        QThread::msleep(kRetryPauseMs);
    }
    return why;
}

} // namespace resect::cli
