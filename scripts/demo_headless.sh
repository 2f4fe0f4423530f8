#!/usr/bin/env bash
# Headless demo of the installed plugin through meshlabserver (no display needed: it runs
# under xvfb-run). Needs the plugin installed (scripts/run.sh does that).
#   usage: scripts/demo_headless.sh [MESH.ply]      (default: data/fandisk.ply)
# Writes build/demo/:
#   <name>_energy.ply     feature energy in vertex quality, coloured (red = feature, blue = flat)
#   <name>_seed_path.ply  same, with the seed path's vertices selected (PLY vertex flags)
#   <name>_path_layer.ply the "Seed path" layer (its vertices, in path order)
#   <name>_snake.json     the geometric snake started on that path: samples, curve, timings
#   <name>_snake.ply      the final curve as a layer of vertices and edges
#   *.mlx                 the scripts used (templates for your own)
set -euo pipefail
here=$(cd "$(dirname "$0")/.." && pwd)
mesh=$(cd "$(dirname "${1:-$here/data/fandisk.ply}")" && pwd)/$(basename "${1:-$here/data/fandisk.ply}")
[ -f "$mesh" ] || { echo "[demo] mesh not found: $mesh" >&2; exit 1; }
name=$(basename "$mesh" .ply)
out="$here/build/demo"
mkdir -p "$out"
mlhost() { python3 "$here/tests/host/mlhost.py" "$@"; }
export XDG_RUNTIME_DIR=${XDG_RUNTIME_DIR:-/tmp/runtime-$(id -u)}
mkdir -p "$XDG_RUNTIME_DIR" && chmod 700 "$XDG_RUNTIME_DIR"
server() { xvfb-run -a -s "-screen 0 640x480x24" meshlabserver "$@" > "$out/meshlabserver.log" 2>&1 \
             || { cat "$out/meshlabserver.log" >&2; echo "[demo] meshlabserver failed" >&2; exit 1; }
           grep -v -E '^(LOG:|Reading|Current Plugins|Opening a file|FilterScript|QStandardPaths|no additional memory)' \
             "$out/meshlabserver.log" | grep -E 'Feature energy|Seed path|Geometric snake|Added layer|saved' | sort -u | sed 's/^/  | /'; }

echo "[demo] 1/3 feature energy on $mesh"
mlhost mlx "$out/energy.mlx" "Compute Geometric Snake Feature Energy" EnergyType=0 SmoothingSteps=2 Colorize=true
server -i "$mesh" -o "$out/${name}_energy.ply" -m vq vc -s "$out/energy.mlx"

seeds=$(mlhost seeds "$out/${name}_energy.ply" 3)
echo "[demo] 2/3 closed seed path (feature cost) through feature vertices $seeds"
mlhost mlx "$out/seed_path.mlx" "Geometric Snake Seed Path" "Seeds=$seeds" Closed=true Cost=1 NewLayer=true
server -i "$out/${name}_energy.ply" -o "$out/${name}_seed_path.ply" -m vq vc vf \
       -o "$out/${name}_path_layer.ply" -l x -s "$out/seed_path.mlx"

# The snake: on the default fandisk, an open snake from four picks beside its curved crease
# (the vertices that clicks in the edit tool give, see scripts/crease_demo.sh); on another mesh,
# a closed snake from the seed path's seeds.
if [ "$(basename "$mesh")" = "fandisk.ply" ]; then snake_seeds="1493, 1486, 1644, 2151"; closed=false
else snake_seeds=$seeds; closed=true; fi
echo "[demo] 3/3 geometric snake (closed=$closed) from seeds $snake_seeds (local embedding, the paper's method)"
mlhost mlx "$out/snake.mlx" "Geometric Snake from Seed Vertices" "Seeds=$snake_seeds" Closed=$closed Alpha=0.05 \
  Beta=0.5 Gamma=1.0 ExternalWeight=1.0 Spacing=1.0 MaxOperations=500 Method=0 UseQuality=true \
  "OutputFile=$out/${name}_snake.json" NewLayer=true
server -i "$out/${name}_energy.ply" -o "$out/${name}_snake.ply" -l x -s "$out/snake.mlx"
python3 - "$out/${name}_snake.json" <<'PY'
import json, sys
j = json.load(open(sys.argv[1])); s = j["stats"]
print("  snake: %d samples, %d operations, %s; median %.3f ms per operation (%.3f ms per embedding, "
      "%.4f ms per update); curve of %d points on the surface"
      % (len(j["samples"]), s["operations"], "converged" if s["converged"] else "NOT converged",
         s["ms_per_operation"], s["ms_per_embedding"], s["ms_per_update"], len(j["polyline"])))
PY

echo "[demo] summary"
mlhost summary "$out/${name}_energy.ply" "$out/${name}_seed_path.ply" "$out/${name}_path_layer.ply"
echo "[demo] outputs in $out"
