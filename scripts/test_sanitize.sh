#!/usr/bin/env bash
# The hardening stage of scripts/test.sh, in its own build folder build-asan/ (clang):
#  - the unit tests built with AddressSanitizer + UndefinedBehaviorSanitizer and asserts on
#    (GS_SANITIZE=ON): any report fails the test (-fno-sanitize-recover);
#  - the libFuzzer targets of fuzz/ (GS_BUILD_FUZZ=ON), each run for GS_FUZZ_SECONDS (60 s)
#    from its seed corpus fuzz/corpus/<target>/ (CTest label `fuzz`);
#  - the unit tests that run work on a second thread (named *OnASecondThread), built with
#    ThreadSanitizer (GS_SANITIZE_THREAD=ON) in build-tsan/: a race TSan sees fails them (it sees those of the small cases, see README).
# No plugins here: MeshLab itself is not built with ASan. Needs build/meshlab-src (setup.sh).
#   usage: scripts/test_sanitize.sh [extra ctest args]      env: GS_FUZZ_SECONDS (default 60)
set -euo pipefail
here=$(cd "$(dirname "$0")/.." && pwd)
cd "$here"
export GS_TEST_T0=${GS_TEST_T0:-$(date +%s)}
at() { echo "[sanitize] $* (at $(( $(date +%s) - GS_TEST_T0 )) s)"; }
src=${MESHLAB_SOURCE_DIR:-$here/build/meshlab-src}
[ -d "$src/vcglib" ] || bash scripts/setup.sh "$here/build"
at "configure + build (build-asan/, clang, ASan + UBSan, libFuzzer)"
CC=clang CXX=clang++ cmake -S . -B build-asan -DCMAKE_BUILD_TYPE=RelWithDebInfo \
  -DGS_SANITIZE=ON -DGS_UNITY_BUILD=ON -DGS_BUILD_FUZZ=ON -DGS_BUILD_PLUGINS=OFF -DGS_BUILD_BENCH=OFF -DGS_BUILD_CLI=OFF \
  -DGS_FUZZ_SECONDS="${GS_FUZZ_SECONDS:-60}" -DMESHLAB_SOURCE_DIR="$src"
cmake --build build-asan -j2
at "ctest -L 'unit|fuzz' (build-asan/)"
cd build-asan
export ASAN_OPTIONS=${ASAN_OPTIONS:-detect_leaks=1:abort_on_error=1}
export UBSAN_OPTIONS=${UBSAN_OPTIONS:-print_stacktrace=1}
ctest --output-on-failure -j2 -L 'unit|fuzz' "$@"
cd "$here"
at "configure + build (build-tsan/, clang, TSan: the tests that use a second thread)"
CC=clang CXX=clang++ cmake -S . -B build-tsan -DCMAKE_BUILD_TYPE=RelWithDebInfo -DGS_SANITIZE_THREAD=ON \
  -DGS_BUILD_PLUGINS=OFF -DGS_BUILD_BENCH=OFF -DGS_BUILD_CLI=OFF -DMESHLAB_SOURCE_DIR="$src"
cmake --build build-tsan -j2 --target test_feature_energy test_geometric_snake test_snake_controller
cd build-tsan
export TSAN_OPTIONS=${TSAN_OPTIONS:-halt_on_error=1:exitcode=66}
n=$(ctest -N -R 'OnASecondThread$' | sed -n 's/^Total Tests: //p')
[ "${n:-0}" -ge 4 ] || { echo "[sanitize] expected the *OnASecondThread tests in build-tsan/, found ${n:-0}"; exit 1; }
ctest --output-on-failure -R 'OnASecondThread$' "$@"
at "sanitizer unit tests and fuzzers clean"
