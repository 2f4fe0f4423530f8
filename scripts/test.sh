#!/usr/bin/env bash
# The test command: setup (apt packages + MeshLab source), build in build/, install the
# plugins into MeshLab's plugin folder, run every CTest test (unit + host).
# Exits non-zero on any failure. Runs as root in CI (no display needed: xvfb-run).
#   usage: scripts/test.sh [extra ctest args, e.g. -L host]
set -euo pipefail
here=$(cd "$(dirname "$0")/.." && pwd)
cd "$here"
SUDO=""
if [ "$(id -u)" -ne 0 ]; then SUDO="sudo"; fi

bash scripts/setup.sh "$here/build"
echo "[test] configure + build (build/)"
cmake -S . -B build -DCMAKE_BUILD_TYPE=Release
cmake --build build -j2
echo "[test] install plugins"
$SUDO cmake --install build
echo "[test] ctest"
cd build
ctest --output-on-failure -j2 "$@"
echo "[test] all tests passed"
