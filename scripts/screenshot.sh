#!/usr/bin/env bash
# Screenshot of MeshLab showing the feature energy (red = feature, blue = flat) on a mesh,
# taken on a virtual display (Xvfb, software OpenGL): docs/img/energy.png.
# Needs the plugin installed (scripts/run.sh or scripts/test.sh).
#   usage: scripts/screenshot.sh [MESH.ply] [OUT.png]
# MeshLab 2020.09 (Debian) shows no first-start dialog here; any dialog that appears anyway
# is accepted with Return before the screenshot.
set -euo pipefail
here=$(cd "$(dirname "$0")/.." && pwd)
mesh=${1:-$here/data/fandisk.ply}
png=${2:-$here/docs/img/energy.png}
mkdir -p "$(dirname "$png")"
name=$(basename "$mesh" .ply)

if [ -n "${GS_SCREENSHOT_AS_IS:-}" ]; then # the mesh as given (e.g. a cut with its selection)
  colored=$mesh
else
  bash "$here/scripts/demo_headless.sh" "$mesh" >/dev/null
  colored="$here/build/demo/${name}_energy.ply"
fi
[ -f "$colored" ] || { echo "[screenshot] $colored was not produced" >&2; exit 1; }

inner=$(mktemp /tmp/gs-screenshot.XXXXXX.sh)
trap 'rm -f "$inner"' EXIT
cat > "$inner" <<'INNER'
set -u
colored=$1; png=$2
export LIBGL_ALWAYS_SOFTWARE=1
meshlab "$colored" > /tmp/gs-screenshot-meshlab.log 2>&1 &
pid=$!
win=""
for _ in $(seq 1 60); do
  win=$(xdotool search --onlyvisible --name "MeshLab" 2>/dev/null | head -n1 || true)
  [ -n "$win" ] && break
  sleep 1
done
[ -n "$win" ] || { echo "[screenshot] MeshLab window did not appear" >&2; kill $pid; exit 1; }
sleep 4
# Dismiss any modal dialog (a second visible top-level window), then maximise.
for w in $(xdotool search --onlyvisible --name "." 2>/dev/null); do
  [ "$w" = "$win" ] && continue
  xdotool windowactivate --sync "$w" key Return 2>/dev/null || true
done
xdotool windowsize "$win" 1280 800 windowmove "$win" 0 0 2>/dev/null || true
sleep 2
# A three-quarter view: drag the trackball (left button) up-left across the 3D view.
xdotool mousemove 430 420 mousedown 1
for i in $(seq 1 12); do xdotool mousemove $((430 - 5 * i)) $((420 + 6 * i)); sleep 0.05; done
xdotool mouseup 1 mousemove 1200 780
sleep 3
import -window root "$png"
rc=$?
kill $pid 2>/dev/null; wait $pid 2>/dev/null
exit $rc
INNER
export XDG_RUNTIME_DIR=${XDG_RUNTIME_DIR:-/tmp/runtime-$(id -u)}
mkdir -p "$XDG_RUNTIME_DIR" && chmod 700 "$XDG_RUNTIME_DIR"
xvfb-run -a -s "-screen 0 1280x800x24" bash "$inner" "$colored" "$png"
echo "[screenshot] wrote $png"
