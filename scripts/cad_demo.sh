#!/usr/bin/env bash
# A snake on a generated CAD tessellation in the real MeshLab GUI: data/cad_block.ply (every
# vertex on a crease, flat faces of slivers) with a closed snake on its bore's top rim, built
# as the edit tool builds it: five clicks 2.5-3.5 units off the rim on the top face (surface
# points, not vertices), crease energy, Shift+Enter, Run. The session comes from the unit test
# CadEditTool (GS_CAD_SESSION) as the tool's sidecar file; MeshLab opens the block with the
# tool started (GS_SNAKE_AUTOSTART), the tool restores the session, and a screenshot goes to
# docs/img/cad_block_snake.png. Needs the plugins installed and the unit tests built (build/).
set -euo pipefail
here=$(cd "$(dirname "$0")/.." && pwd)
build=${BUILD_DIR:-$here/build}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cp "$here/data/cad_block.ply" "$work/"
GS_CAD_SESSION="$work/cad_block.ply.snakes.json" "$build/tests/test_cad_tessellation" \
  --gtest_filter='CadEditTool.*' | grep '^\[cad\]'
export XDG_RUNTIME_DIR="$work/runtime"; mkdir -p "$XDG_RUNTIME_DIR"; chmod 700 "$XDG_RUNTIME_DIR"
export HOME="$work"                            # fresh MeshLab settings: default window layout
# the tool's panel floats over the layer dialog (MeshLab's settings), so the 3D view keeps the
# default layout's size and place (it docks left of the view otherwise)
mkdir -p "$work/.config/VCG"
printf '[GeometricSnake]\nPanel\\area=2\nPanel\\floating=true\nPanel\\geometry=@Rect(880 60 390 820)\n' \
  > "$work/.config/VCG/MeshLab_64bit_fp.conf"
LIBGL_ALWAYS_SOFTWARE=1 xvfb-run -a -f "$work/xauth" -s "-screen 0 1280x1000x24" bash -c '
  meshlab "$0/cad_block.ply" > "$0/meshlab.log" 2>&1 &
  win=""
  for i in $(seq 60); do win=$(xdotool search --name "MeshLab 20" 2>/dev/null | tail -n1); [ -n "$win" ] && break; sleep 0.5; done
  sleep 2; xdotool windowmove "$win" 0 0 windowsize "$win" 1280 1000; sleep 2
  # a three-quarter view from the front: drag the trackball (left button) before the tool starts
  xdotool mousemove 430 300 mousedown 1
  for i in $(seq 1 10); do xdotool mousemove $((430 - 2 * i)) $((300 + 8 * i)); sleep 0.05; done
  xdotool mouseup 1; sleep 1
  # Edit menu -> Geometric Snake (as tests/host/test_edit_gui.py): the tool restores the sidecar
  xdotool mousemove 70 10 click 1; sleep 1; xdotool mousemove 141 84 click 1
  for i in $(seq 60); do grep -q "Started Mode Geometric Snake" "$0/meshlab.log" 2>/dev/null && break; sleep 0.5; done
  xdotool mousemove 1270 990; sleep 3
  import -window root -crop 853x723+0+0 "$0/shot.png"
  kill %1' "$work"
grep -E "Geometric snake|Restored" "$work/meshlab.log" || { echo "no snake in MeshLab's log" >&2; exit 1; }
mkdir -p "$here/docs/img"
cp "$work/shot.png" "$here/docs/img/cad_block_snake.png"
echo "screenshot: docs/img/cad_block_snake.png"
