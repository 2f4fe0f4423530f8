#!/usr/bin/env bash
# Screenshots of closed snakes round parts in the edit tool (issue 33), each the clicks closed
# into a loop with the energy Part boundary (concave) (left) and the loop after R (right):
# lion-head's right eye (the issue's six clicks; the loop on the eye's rim) in
# docs/img/part_loop_lion_eye.png, and bunny00's back ear (six clicks over both faces of the ear;
# the loop on the ear's base) in docs/img/part_loop_bunny_ear.png. Runs the GUI test
# host_edit_gui_part_loop on a virtual display, which photographs each (MeshLab's window at 0,0,
# 1600x1000), and crops the part, 2x. Needs the plugin installed (scripts/run.sh or scripts/test.sh).
#   usage: scripts/screenshot_part_loop.sh [OUT_DIR]      (default docs/img)
set -euo pipefail
here=$(cd "$(dirname "$0")/.." && pwd)
out=${1:-$here/docs/img}
work=$(mktemp -d /tmp/gs-part-loop-shot.XXXXXX)
trap 'rm -rf "$work"' EXIT
GS_DATA_DIR="$here/data" LIBGL_ALWAYS_SOFTWARE=1 xvfb-run -a -s "-screen 0 1600x1024x24" \
  python3 "$here/tests/host/test_edit_gui_part_loop.py" "$work/shots" >/dev/null
mkdir -p "$out"
# (the GUI test's case, the crop round the part, the image)
for c in "lion_eye_part 320x220+656+324 part_loop_lion_eye" "bunny_back_ear_round_part 240x200+540+260 part_loop_bunny_ear"; do
  set -- $c
  for s in "$1_built" "$1"; do
    convert "$work/shots/$s.png" -crop "$2" +repage -scale 200% "$work/$s.crop.png"
  done
  convert "$work/$1_built.crop.png" "$work/$1.crop.png" +append "$out/$3.png"
  echo "[screenshot] wrote $out/$3.png"
done
