#!/usr/bin/env bash
# First command: setup, build, install the plugins into Debian's MeshLab, run the headless
# demo (meshlabserver: energy + seed path on data/fandisk.ply, summary printed, outputs in
# build/demo/), then, if there is a display, open MeshLab on the mesh.
#   usage: scripts/run.sh [MESH.ply]        (default: data/fandisk.ply)
set -euo pipefail
here=$(cd "$(dirname "$0")/.." && pwd)
cd "$here"
mesh=${1:-$here/data/fandisk.ply}
SUDO=""
if [ "$(id -u)" -ne 0 ]; then SUDO="sudo"; fi

bash scripts/setup.sh "$here/build"
cmake -S . -B build -DCMAKE_BUILD_TYPE=Release >/dev/null
cmake --build build -j2
$SUDO cmake --install build
echo "[run] plugins installed in $(grep -E '^GS_MESHLAB_PLUGIN_DIR' build/CMakeCache.txt | cut -d= -f2)"

bash scripts/demo_headless.sh "$mesh"

if [ -n "${DISPLAY:-}" ]; then
  echo "[run] opening MeshLab on $mesh"
  echo "[run]   Filters > Quality Measure and Computations > Compute Geometric Snake Feature Energy"
  echo "[run]   Filters > Selection > Geometric Snake Seed Path"
  # (hook: once the edit tool exists, report "tool ready" here: Edit > Geometric Snake.)
  exec meshlab "$mesh"
else
  echo "[run] no DISPLAY: headless demo only (outputs in build/demo/; open them in MeshLab elsewhere)"
fi
