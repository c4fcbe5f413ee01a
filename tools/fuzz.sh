#!/usr/bin/env bash
# Runs one fuzz target (README, "Fuzzing"):
#   tools/fuzz.sh TARGET [SECONDS] [more libFuzzer options...]
# TARGET is a folder name of fuzz/corpus (sweep, vtu, msh, tetgen, surface_obj, ...).
# Needs the fuzz build (build-fuzz/, configured with -DRESECT_BUILD_FUZZERS=ON, clang).
# The working corpus grows in build-fuzz/fuzz-work/TARGET (seeded from fuzz/corpus/TARGET,
# which is never written to); crashes, hangs and leaks go to build-fuzz/fuzz-artifacts/TARGET.
# One job: the machine has two cores.
set -euo pipefail
cd "$(dirname "$0")/.."
target=${1:?usage: tools/fuzz.sh TARGET [SECONDS] [libFuzzer options...]}
seconds=${2:-300}
shift $(( $# >= 2 ? 2 : 1 ))
build=${RESECT_FUZZ_BUILD:-build-fuzz}
exe=$build/fuzz/fuzz_$target
[[ -x $exe ]] || { echo "tools/fuzz.sh: $exe not built (cmake --build $build --target fuzz_$target)" >&2; exit 2; }
work=$build/fuzz-work/$target
artifacts=$build/fuzz-artifacts/$target
mkdir -p "$work" "$artifacts"
dict=()
[[ -f fuzz/dict/$target.dict ]] && dict=(-dict=fuzz/dict/$target.dict)
export ASAN_OPTIONS=${ASAN_OPTIONS:-abort_on_error=1:detect_leaks=1}
export UBSAN_OPTIONS=${UBSAN_OPTIONS:-print_stacktrace=1:halt_on_error=1}
export LSAN_OPTIONS=${LSAN_OPTIONS:-suppressions=$PWD/fuzz/lsan.supp:print_suppressions=0}
exec "$exe" "$work" "fuzz/corpus/$target" "${dict[@]}" \
  -artifact_prefix="$artifacts/" -max_total_time="$seconds" -timeout=10 -rss_limit_mb=4096 \
  -print_final_stats=1 "$@"
