#!/usr/bin/env bash
# Screenshot of a closed snake round lion-head's right eye in the edit tool (issue 33): the
# issue's six clicks closed into a loop with the energy Part boundary (concave) (left), and the
# loop after R, on the eye's rim (right): docs/img/part_loop_lion_eye.png. Runs the GUI test
# host_edit_gui_part_loop on a virtual display, which photographs both (MeshLab's window at 0,0,
# 1600x1000), and crops the eye, 2x. Needs the plugin installed (scripts/run.sh or scripts/test.sh).
#   usage: scripts/screenshot_part_loop.sh [OUT.png]
set -euo pipefail
here=$(cd "$(dirname "$0")/.." && pwd)
png=${1:-$here/docs/img/part_loop_lion_eye.png}
work=$(mktemp -d /tmp/gs-part-loop-shot.XXXXXX)
trap 'rm -rf "$work"' EXIT
GS_DATA_DIR="$here/data" LIBGL_ALWAYS_SOFTWARE=1 xvfb-run -a -s "-screen 0 1600x1024x24" \
  python3 "$here/tests/host/test_edit_gui_part_loop.py" "$work/shots" >/dev/null
for s in lion_eye_part_built lion_eye_part; do
  convert "$work/shots/$s.png" -crop 320x220+656+324 +repage -scale 200% "$work/$s.crop.png"
done
mkdir -p "$(dirname "$png")"
convert "$work/lion_eye_part_built.crop.png" "$work/lion_eye_part.crop.png" +append "$png"
echo "[screenshot] wrote $png"
