#!/usr/bin/env bash
# The main job: set up, build, then open the studio with the sample polyp; without a
# display, run the headless demo (meshes the polyp, prints its quality, writes out/demo/).
set -euo pipefail
cd "$(dirname "$0")/.."
bash tools/setup.sh
if [ -n "${DISPLAY:-}${WAYLAND_DISPLAY:-}" ]; then
  exec build/release/app/resect-studio --sample polyp "$@"
fi
echo "run: no display; running the headless demo"
exec build/release/app/resect demo --sample polyp --out out/demo
