#!/usr/bin/env bash
# First command: setup, build, install the plugins into Debian's MeshLab, run the headless
# demo (meshlabserver: energy, seed path and a geometric snake on data/fandisk.ply, summary
# printed, outputs in build/demo/), then, if there is a display, open MeshLab on the mesh
# with the Geometric Snake edit tool already started.
#   usage: scripts/run.sh [MESH.ply]        (default: data/fandisk.ply)
set -euo pipefail
here=$(cd "$(dirname "$0")/.." && pwd)
cd "$here"
mesh=${1:-$here/data/fandisk.ply}
SUDO=""
if [ "$(id -u)" -ne 0 ]; then SUDO="sudo"; fi

bash scripts/setup.sh "$here/build"
# the same configuration as scripts/test.sh (one build folder serves both commands); only what
# is installed is built here, the tests and benchmarks are scripts/test.sh's
cmake -S . -B build -DCMAKE_BUILD_TYPE=Release -DGS_UNITY_BUILD=ON >/dev/null
cmake --build build -j2 --target installable
$SUDO cmake --install build
echo "[run] plugins installed in $(grep -E '^GS_MESHLAB_PLUGIN_DIR' build/CMakeCache.txt | cut -d= -f2)"

bash scripts/demo_headless.sh "$mesh"

if [ -n "${DISPLAY:-}" ]; then
  echo "[run] opening MeshLab on $mesh with the Geometric Snake tool started (Edit > Geometric Snake):"
  echo "[run]   click a few points near a crease, Enter (open) or Shift+Enter (closed) builds the snake,"
  echo "[run]   R runs it until it converges; drag a sample to move and pin it; the panel exports the curve."
  GS_SNAKE_AUTOSTART=1 exec meshlab "$mesh"
else
  echo "[run] no DISPLAY: headless demo only (outputs in build/demo/; open them in MeshLab elsewhere)"
fi
