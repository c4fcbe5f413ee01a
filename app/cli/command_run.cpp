// resect run SCENARIO [--report R.json]: replay strokes, cuts and simulation, evaluate the
// expectations. Exit 0 when all pass, 3 when one fails, 2 on bad input, 1 on internal failure.
#include "app/cli/cli_common.h"

#include "scenario/scenario_load.h"
#include "scenario/scenario_run.h"

#include <cstdio>

namespace resect::cli {

namespace {
constexpr int kExpectationFailed = 3;
} // namespace

/// Loads and validates a scenario: every error on stderr, exit 2 if there is one; warnings
/// are printed and do not stop.
Scenario loadScenarioOrFail(const std::string& path) {
    Scenario scenario;
    ScenarioDiagnostics diag;
    const Status s = loadScenario(path, scenario, diag);
    for (const ScenarioIssue& issue : diag.issues())
        if (issue.severity == ScenarioIssue::Severity::Warning)
            std::fprintf(stderr, "warning: %s: %s: %s\n", path.c_str(), issue.path.c_str(), issue.message.c_str());
    if (!s.ok()) {
        for (const ScenarioIssue& issue : diag.issues())
            if (issue.severity == ScenarioIssue::Severity::Error)
                std::fprintf(stderr, "error: %s: %s: %s\n", path.c_str(), issue.path.c_str(), issue.message.c_str());
        throw CliError{kBadInput, s.message()};
    }
    return scenario;
}

/// Plans and replays every tissue (planning errors are bad input, replay errors internal).
ScenarioRun runScenarioOrFail(const Scenario& scenario) {
    ScenarioRun run;
    for (const TissueSpec& tissue : scenario.tissues) {
        ReplayPlan plan;
        if (Status s = planTissue(scenario, tissue, plan); !s.ok())
            throw CliError{kBadInput, s.message()};
        TissueRun t;
        t.name = tissue.name;
        if (Status s = replay(std::move(plan), t.outcome); !s.ok())
            throw CliError{kInternal, "tissue '" + tissue.name + "': " + s.message()};
        run.tissues.push_back(std::move(t));
    }
    run.expectations = evaluateExpectations(scenario, run.tissues);
    return run;
}

int runRun(Args args) {
    const std::optional<std::string> report = args.option("--report");
    const auto files = args.positionals();
    args.finish();
    if (files.size() != 1)
        badInput("expected exactly one SCENARIO file");
    if (report)
        requireDistinct(files[0], *report);
    const Scenario scenario = loadScenarioOrFail(files[0]);
    const ScenarioRun run = runScenarioOrFail(scenario);
    for (const TissueRun& t : run.tissues) {
        const ReplayOutcome& o = t.outcome;
        std::printf("%s: %d -> %d tets, %d pieces, resected %.3g, min radius ratio %.3g, %lld steps of %.3g s%s\n",
                    t.name.c_str(), o.tetsBefore, o.mesh.tetCount(), o.pieces, o.resectedVolumeFraction,
                    o.minRadiusRatio, o.steps, o.dt, o.finite ? "" : " (diverged)");
        if (!o.failure.empty())
            std::printf("  %s\n", o.failure.c_str());
        if (!o.cutFailure.empty())
            std::fprintf(stderr, "resect run: tissue '%s': %s (the replay stopped there; the report shows the tissue before that cut)\n",
                         t.name.c_str(), o.cutFailure.c_str());
    }
    for (const ExpectationResult& e : run.expectations)
        std::printf("%s %s (%s): %.6g, expected %.6g\n", e.passed ? "PASS" : "FAIL", e.kind.c_str(), e.tissue.c_str(),
                    e.actual, e.expected);
    if (report) {
        QJsonObject r = scenarioRunJson(run);
        r["scenario"] = QString::fromStdString(files[0]);
        requireOk(writeJson(*report, r));
    }
    if (!run.cutsSucceeded())
        return kInternal;  // (like a diverged `simulate`: the report is still written)
    return run.allPassed() ? kOk : kExpectationFailed;
}

} // namespace resect::cli
