#!/usr/bin/env bash
# Sets up, builds and runs every test (labels core, scenario, gui, display; the display tests
# start their own Xvfb through xvfb-run).
set -euo pipefail
cd "$(dirname "$0")/.."
bash tools/setup.sh --tests
ctest --test-dir build/release --output-on-failure -j "$(nproc)" "$@"
