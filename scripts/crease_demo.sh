#!/usr/bin/env bash
# The edit tool in the real MeshLab GUI, as a person would use it, scripted: MeshLab opens
# data/fandisk.ply with the Geometric Snake tool started (GS_SNAKE_AUTOSTART, as run.sh
# does), four clicks beside the curved crease, Enter builds the snake, R runs it; after 15 s
# a screenshot goes to docs/img/fandisk_crease.png and MeshLab's Log lines are printed
# (the snake's samples, the Run's operations, compute and wall time). Needs the plugins installed.
set -euo pipefail
here=$(cd "$(dirname "$0")/.." && pwd)
work=$(mktemp -d)
cp "$here/data/fandisk.ply" "$work/"          # the sidecar file goes next to this copy
export XDG_RUNTIME_DIR="$work/runtime"; mkdir -p "$XDG_RUNTIME_DIR"; chmod 700 "$XDG_RUNTIME_DIR"
export HOME="$work"                            # fresh MeshLab settings: default window layout
# the tool's panel floats over the layer dialog (MeshLab's settings), so the 3D view keeps the
# default layout's size and place (it docks left of the view otherwise)
mkdir -p "$work/.config/VCG"
printf '[GeometricSnake]\nPanel\\area=2\nPanel\\floating=true\nPanel\\geometry=@Rect(880 60 390 820)\n' \
  > "$work/.config/VCG/MeshLab_64bit_fp.conf"
GS_SNAKE_AUTOSTART=1 LIBGL_ALWAYS_SOFTWARE=1 xvfb-run -a -s "-screen 0 1280x900x24" bash -c '
  meshlab "$0/fandisk.ply" > "$0/meshlab.log" 2>&1 &
  for i in $(seq 60); do grep -q "Started Mode Geometric Snake" "$0/meshlab.log" 2>/dev/null && break; sleep 0.5; done
  sleep 2
  t0=$(date +%s.%N)
  for p in "310 443" "343 401" "377 376" "415 359"; do xdotool mousemove $p click 1; sleep 0.5; done
  xdotool key Return; sleep 0.5; xdotool key r
  for i in $(seq 60); do grep -q "converged after" "$0/meshlab.log" && break; sleep 0.5; done
  t1=$(date +%s.%N)
  sleep 1
  import -window root -crop 853x723+0+0 "$0/shot.png"
  echo "clicks to converged snake: $(echo "$t1 - $t0" | bc) s"
  kill %1' "$work"
grep -E "Geometric snake" "$work/meshlab.log" || { echo "no snake in MeshLab's log" >&2; exit 1; }
mkdir -p "$here/docs/img"
cp "$work/shot.png" "$here/docs/img/fandisk_crease.png"
echo "screenshot: docs/img/fandisk_crease.png"
rm -rf "$work"
