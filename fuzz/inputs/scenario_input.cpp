// Fuzz target "scenario": scenario documents (scenario/scenario_load.h), parsed from the bytes
// with the scratch folder as their base folder (referenced files are then missing, which
// validation must report, not trip over).

#include "fuzz/fuzz_inputs.h"

#include "scenario/scenario_load.h"
#include "scenario/scenario_save.h"

namespace resect::fuzz {
namespace {

Outcome scenarioInput(std::span<const std::uint8_t> input) {
    const std::string name = "fuzz-scenario.json";
    const QByteArray bytes(reinterpret_cast<const char*>(input.data()), static_cast<qsizetype>(input.size()));
    Scenario scenario;
    scenario.metadata.title = "unchanged";
    ScenarioDiagnostics diag;
    if (Status s = parseScenario(bytes, scratchDir(), name, scenario, diag); !s) {
        if (scenario.metadata.title != "unchanged" || !scenario.tissues.empty())
            return Outcome::broken("the scenario was changed by a failed read");
        if (diag.errorCount() == 0)
            return Outcome::broken("a failed read reported no error");
        return rejected(s, {name});
    }
    if (diag.errorCount() != 0)
        return Outcome::broken("an accepted document has errors");
    // An accepted document writes and reads back as the same document.
    Scenario again;
    ScenarioDiagnostics diag2;
    if (Status s = parseScenario(scenarioJsonText(scenario), scratchDir(), name, again, diag2); !s)
        return Outcome::broken("an accepted document does not read back: " + s.message());
    if (!(again == scenario))
        return Outcome::broken("an accepted document reads back different");
    return Outcome::accepted();
}

} // namespace

RESECT_FUZZ_TARGET(scenario, scenarioInput);

} // namespace resect::fuzz
