#!/usr/bin/env bash
# Screenshot of MeshLab showing a part selected by a cut (issue 34): a finger of the hand of the
# segmentation benchmark (mesh 181), cut along its boundary drawn by a person, selected in red:
# docs/img/cut_finger.png. Needs build/cli/geometric-snake.
#   usage: scripts/screenshot_cut.sh [OUT.png]
set -euo pipefail
here=$(cd "$(dirname "$0")/.." && pwd)
png=${1:-$here/docs/img/cut_finger.png}
work=$(mktemp -d /tmp/gs-cut-shot.XXXXXX)
trap 'rm -rf "$work"' EXIT
mesh="$here/../shared/data/segmentation/off/181.off"
python3 "$here/scripts/eval_cut.py" --curve-only "181:1:$work/finger.json"
"$here/build/cli/geometric-snake" cut "$mesh" --curve "$work/finger.json" -o "$work/hand_finger.ply"
GS_SCREENSHOT_AS_IS=1 bash "$here/scripts/screenshot.sh" "$work/hand_finger.ply" "$png"
