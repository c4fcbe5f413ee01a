#!/usr/bin/env bash
# Installs the Debian 12 packages Resect Studio needs (only those missing), then configures
# and builds the release preset. Called by tools/run.sh and tools/test.sh; safe to re-run.
# With --tests (tools/test.sh) it also installs what only the tests use: the gmsh binary,
# which writes the Gmsh files the readers are tested on and re-saves ours (issue 21).
set -euo pipefail
cd "$(dirname "$0")/.."

PACKAGES=(
  cmake ninja-build g++ pkg-config
  qt6-base-dev qt6-tools-dev qt6-tools-dev-tools qt6-l10n-tools qt6-translations-l10n libqt6opengl6-dev libxkbcommon-dev
  libvtk9-dev libeigen3-dev libcgal-dev libassimp-dev
  xvfb xauth libgl1-mesa-dri libglx-mesa0
)
if [[ "${1:-}" == "--tests" ]]; then
  PACKAGES+=(gmsh)
fi

missing=()
for p in "${PACKAGES[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if ((${#missing[@]})); then
  echo "setup: installing ${missing[*]}"
  SUDO=""
  if [ "$(id -u)" -ne 0 ]; then SUDO="sudo"; fi
  $SUDO apt-get update -q
  DEBIAN_FRONTEND=noninteractive $SUDO apt-get install -y -q --no-install-recommends "${missing[@]}"
fi

cmake --preset release
cmake --build --preset release -j "$(nproc)"
