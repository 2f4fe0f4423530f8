#!/usr/bin/env bash
# Regenerates the evaluation (issue 5): accuracy sweep, the paper's Table 1 today, scaling,
# tables and plots under docs/eval/. See docs/evaluation.md.
#
#   scripts/eval.sh            full run (about 10-15 minutes on 2 cores)
#   scripts/eval.sh --quick    smoke run (< 2 minutes): fewer cases, no scaling benchmark;
#                              writes to docs/eval/quick/ so the full results are kept
#   scripts/eval.sh --capture  the capture-range sweep only (issue 9, a few minutes): seeds 1-6
#                              edge lengths off a crease, both methods -> docs/eval/capture.csv,
#                              results.md and docs/img/capture_range.svg (the other results kept)
#   scripts/eval.sh --parts    closed snakes on part boundaries drawn by people (issue 33, ~2 min):
#                              bench/eval/gs_parts on ../shared/data/segmentation, both energies ->
#                              docs/eval/parts.csv, parts.md, docs/img/parts_distance.svg
#   scripts/eval.sh --creases  creases on CAD meshes (issue 38, ~5 min): bench/eval/gs_creases on
#                              dense features, tessellations and the shared CAD-like meshes, both
#                              energies -> docs/eval/creases.csv, creases.md
#
# Environment: BUILD_DIR (default /work/build-eval), MESHLAB_SOURCE_DIR (default
# <repo>/build/meshlab-src), JOBS (default 2).
set -euo pipefail

ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
BUILD_DIR="${BUILD_DIR:-/work/build-eval}"
MESHLAB_SOURCE_DIR="${MESHLAB_SOURCE_DIR:-$ROOT/build/meshlab-src}"
JOBS="${JOBS:-2}"
QUICK=0
CAPTURE_ONLY=0
PARTS_ONLY=0
CREASES_ONLY=0
[[ "${1:-}" == "--quick" ]] && QUICK=1
[[ "${1:-}" == "--parts" ]] && PARTS_ONLY=1
[[ "${1:-}" == "--capture" ]] && CAPTURE_ONLY=1
[[ "${1:-}" == "--creases" ]] && CREASES_ONLY=1

OUT="$ROOT/docs/eval"
[[ $QUICK == 1 ]] && OUT="$ROOT/docs/eval/quick"
mkdir -p "$OUT"
T0=$(date +%s)

TARGETS="gs_eval bench_table1"
[[ $CAPTURE_ONLY == 1 ]] && TARGETS="gs_eval"
[[ $PARTS_ONLY == 1 ]] && TARGETS="gs_parts"
[[ $CREASES_ONLY == 1 ]] && TARGETS="gs_creases"
echo "== build ($TARGETS) in $BUILD_DIR"
mkdir -p "$BUILD_DIR"
cmake -S "$ROOT" -B "$BUILD_DIR" -DGS_BUILD_PLUGINS=OFF -DMESHLAB_SOURCE_DIR="$MESHLAB_SOURCE_DIR" \
      -DCMAKE_BUILD_TYPE=Release > "$BUILD_DIR/gs_eval_build.log" 2>&1
cmake --build "$BUILD_DIR" -j"$JOBS" --target $TARGETS >> "$BUILD_DIR/gs_eval_build.log" 2>&1

if [[ $CREASES_ONLY == 1 ]]; then
  echo "== creases on CAD meshes (dense features, tessellations, shared CAD-like meshes)"
  "$BUILD_DIR/bench/eval/gs_creases" --out "$OUT/creases.csv" 2> "$OUT/creases.log"
  grep -E "captured|done" "$OUT/creases.log"
  BEFORE=""
  for b in creases_before_s23.csv creases_before_slivers.csv creases_before_ends.csv creases_before.csv; do [ -f "$OUT/$b" ] && BEFORE="$BEFORE $OUT/$b"; done
  python3 "$ROOT/bench/eval/creases_report.py" "$OUT/creases.csv" $BEFORE > "$OUT/creases.md"
  echo "== done in $(( $(date +%s) - T0 )) s: $OUT/creases.md"
  exit 0
fi

if [[ $PARTS_ONLY == 1 ]]; then
  echo "== closed snakes on part boundaries drawn by people"
  "$BUILD_DIR/bench/eval/gs_parts" --energy normal,part --rings 2,3 --out "$OUT/parts.csv" \
    --people "$OUT/parts_people.csv" 2> "$OUT/parts.log"
  grep -E "^(normal|part|people) +ALL|done" "$OUT/parts.log"
  python3 "$ROOT/bench/eval/parts_report.py" "$OUT/parts.csv" "$OUT" "$OUT/parts_people.csv" > /dev/null
  cp "$OUT/parts_distance.svg" "$ROOT/docs/img/parts_distance.svg"
  echo "== done in $(( $(date +%s) - T0 )) s: $OUT/parts.md"
  exit 0
fi

echo "== capture range (seeds 1-6 h off a crease)"
if [[ $QUICK == 1 ]]; then
  "$BUILD_DIR/bench/eval/gs_eval" --quick --stages capture --out "$OUT/capture.csv" 2> "$OUT/capture.log"
else
  "$BUILD_DIR/bench/eval/gs_eval" --stages capture --out "$OUT/capture.csv" 2> "$OUT/capture.log"
fi
tail -1 "$OUT/capture.log"
if [[ $CAPTURE_ONLY == 1 ]]; then
  python3 "$ROOT/bench/eval/report.py" "$OUT/sweep.csv" "$OUT/bench_table1.json" "$OUT" | grep -i capture
  cp "$OUT/capture_range.svg" "$ROOT/docs/img/capture_range.svg"
  echo "== done in $(( $(date +%s) - T0 )) s: $OUT/results.md"
  exit 0
fi

echo "== accuracy sweep"
if [[ $QUICK == 1 ]]; then
  "$BUILD_DIR/bench/eval/gs_eval" --quick --out "$OUT/sweep.csv" 2> "$OUT/sweep.log"
else
  "$BUILD_DIR/bench/eval/gs_eval" --out "$OUT/sweep.csv" 2> "$OUT/sweep.log"
fi
tail -1 "$OUT/sweep.log"

echo "== Table 1 and scaling benchmark"
if [[ $QUICK == 1 ]]; then
  FILTER='BM_Table1/.*method:0'
  REPS=1
else
  FILTER='.'
  REPS=3
fi
"$BUILD_DIR/bench/bench_table1" --benchmark_filter="$FILTER" --benchmark_repetitions=$REPS \
    --benchmark_out="$OUT/bench_table1.json" --benchmark_out_format=json > "$OUT/bench_table1.txt" 2>&1
grep -E "median|^BM_" "$OUT/bench_table1.txt" | grep -v -E "_mean|_stddev|_cv" | head -40 || true

echo "== a sample through meshlabserver (the batch filter; needs the plugins installed: scripts/run.sh or test.sh)"
if command -v meshlabserver >/dev/null && ls /usr/lib/x86_64-linux-gnu/meshlab/plugins/libfilter_geometric_snake.so >/dev/null 2>&1; then
  python3 "$ROOT/bench/eval/meshlabserver_sample.py" "$OUT" | tail -10
else
  echo "   skipped: meshlabserver or the installed plugin is missing"
fi

echo "== tables and plots"
python3 "$ROOT/bench/eval/report.py" "$OUT/sweep.csv" "$OUT/bench_table1.json" "$OUT"
[[ $QUICK == 1 ]] || cp "$OUT/capture_range.svg" "$ROOT/docs/img/capture_range.svg"

echo "== done in $(( $(date +%s) - T0 )) s: $OUT/results.md"
