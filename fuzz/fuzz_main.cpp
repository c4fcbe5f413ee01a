// libFuzzer entry point of fuzz_<name> (RESECT_FUZZ_TARGET_NAME, set by fuzz/CMakeLists.txt):
// runs the target's input function and aborts on Broken, which libFuzzer then reports as
// a crash and saves the input. Rejected and Accepted inputs are both fine.

#include "fuzz/fuzz_inputs.h"

#include <cstdio>
#include <cstdlib>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    static const resect::fuzz::Target* const target =
        resect::fuzz::findTarget(RESECT_FUZZ_TARGET_NAME);
    if (!target) {
        std::fprintf(stderr, "fuzz harness: no target named %s\n", RESECT_FUZZ_TARGET_NAME);
        std::abort();
    }
    const resect::fuzz::Outcome outcome = target->run({data, size});
    if (outcome.kind == resect::fuzz::Outcome::Kind::Broken) {
        std::fprintf(stderr, "fuzz_%s: invariant violated: %s\n", RESECT_FUZZ_TARGET_NAME,
                     outcome.message.c_str());
        std::abort();
    }
    return 0;
}
