// Fuzz target "sweep": sweep surface files (scenario/sweep_io.h), parsed from the bytes.

#include "fuzz/fuzz_inputs.h"

#include "scenario/sweep_io.h"

namespace resect::fuzz {
namespace {

Outcome sweepInput(std::span<const std::uint8_t> input) {
    const std::string name = "fuzz-sweep.json";
    const QByteArray bytes(reinterpret_cast<const char*>(input.data()),
                           static_cast<qsizetype>(input.size()));
    SweepSurface sweep;
    if (Status s = parseSweep(bytes, name, sweep); !s) {
        if (sweep.curveCount() != 0)
            return Outcome::broken("the sweep was changed by a failed read");
        return rejected(s, {name});
    }
    if (std::string bad = checkSweep(sweep); !bad.empty())
        return Outcome::broken(bad);
    return Outcome::accepted();
}

} // namespace

RESECT_FUZZ_TARGET(sweep, sweepInput);

} // namespace resect::fuzz
