#!/usr/bin/env bash
# The test command: setup (apt packages + MeshLab source), build in build/, install the
# plugins into MeshLab's plugin folder, run every CTest test of build/ (host, program, GUI, the
# Debian roots, PyMeshLab), then the hardening stage (scripts/test_sanitize.sh, in build-asan/):
# the unit tests under ASan + UBSan, the fuzzers, TSan. Exits non-zero on any failure. Runs as
# root in CI (no display needed: xvfb-run).
#   usage: scripts/test.sh [extra ctest args, e.g. -L host]
#   The hardening stage is skipped when ctest args are given, or with GS_SANITIZE=0; build/ then
#   holds the unit tests too (Release), so `scripts/test.sh -L unit` runs them there.
set -euo pipefail
here=$(cd "$(dirname "$0")/.." && pwd)
cd "$here"
# Each stage's line says how far in it starts (seconds since this script began): what CI's time goes to.
export GS_TEST_T0=${GS_TEST_T0:-$(date +%s)}
at() { echo "[test] $* (at $(( $(date +%s) - GS_TEST_T0 )) s)"; }
SUDO=""
if [ "$(id -u)" -ne 0 ]; then SUDO="sudo"; fi

bash scripts/setup.sh "$here/build"
# The Debian roots' system (debootstrap + apt: ~4 min each on a fresh machine, mostly downloads
# and unpacking) is made in the background while the host build compiles; ctest's
# debian13_prepare and forky_prepare then only build the plugins in them.
roots=()
if [ "$(id -u)" -eq 0 ] && [ $# -eq 0 ]; then
  for r in trixie forky; do
    bash scripts/debian_root.sh "$r" "$here/build" --prepare-only > "$here/build/root-$r.log" 2>&1 &
    roots+=($!)
  done
fi
at "configure + build (build/)"
# No benchmarks here (no test runs them; ~6 min of a fresh CI's build): scripts/eval.sh builds
# its own, and -DGS_BUILD_BENCH=ON adds them to build/. The unit tests are compiled once: in
# build-asan/ when the hardening stage runs (asserts on, every ASan/UBSan report fails them),
# else here.
harden=0 unit=ON
if [ "${GS_SANITIZE:-1}" != 0 ] && [ $# -eq 0 ]; then harden=1 unit=OFF; fi
cmake -S . -B build -DCMAKE_BUILD_TYPE=Release -DGS_UNITY_BUILD=ON -DGS_BUILD_BENCH=OFF -DGS_BUILD_UNIT_TESTS=$unit
cmake --build build -j2
at "install plugins"
$SUDO cmake --install build
for p in "${roots[@]}"; do wait "$p" || true; done # a failure shows in *_prepare (its log: build/root-*.log)
at "ctest"
cd build
ctest --output-on-failure -j2 "$@"
cd "$here"
if [ "$harden" = 1 ]; then
  bash scripts/test_sanitize.sh
fi
at "all tests passed"
