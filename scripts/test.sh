#!/usr/bin/env bash
# The test command: setup (apt packages + MeshLab source), build in build/, install the
# plugins into MeshLab's plugin folder, run every CTest test (unit + host), then the hardening
# stage (scripts/test_sanitize.sh: ASan + UBSan unit tests and the fuzzers, in build-asan/;
# ~10 min on 2 cores). Exits non-zero on any failure. Runs as root in CI (no display needed: xvfb-run).
#   usage: scripts/test.sh [extra ctest args, e.g. -L host]
#   The hardening stage is skipped when ctest args are given, or with GS_SANITIZE=0.
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
cd "$here"
if [ "${GS_SANITIZE:-1}" != 0 ] && [ $# -eq 0 ]; then
  bash scripts/test_sanitize.sh
fi
echo "[test] all tests passed"
