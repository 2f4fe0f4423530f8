#!/usr/bin/env bash
# The filter plugin for PyMeshLab's own MeshLab: a virtual environment with PyMeshLab (pinned
# below) from PyPI, and the filter plugin of this source tree built for the MeshLab inside the
# wheel: its version and scalar type (what `pymeshlab.print_pymeshlab_version()` reports, e.g.
# "based on MeshLab 2025.07d": d = double), the headers of that MeshLab release's source, and
# linked to the wheel's libmeshlab-common.so (the Qt 5.15 of the system at build time; the
# wheel's Qt 5.15 at run time). Load it with pymeshlab.load_plugin(<printed path>).
#   usage: scripts/pymeshlab.sh [BUILD_DIR] [MESHLAB_SOURCE_DIR]
#     BUILD_DIR           default ./build; the venv and the build go to BUILD_DIR/pymeshlab/
#     MESHLAB_SOURCE_DIR  a MeshLab source tree of the wheel's MeshLab release; default the
#                         MeshLab 2025.07 source of the forky root (scripts/debian_root.sh forky)
set -euo pipefail
PYMESHLAB_VERSION=2025.7.post1
here=$(cd "$(dirname "$0")/.." && pwd)
build=${1:-$here/build}
mkdir -p "$build/pymeshlab"
build=$(cd "$build" && pwd)
top=$build/pymeshlab
src=${2:-$build/forky/root/opt/gs/build/meshlab-src}
venv=$top/venv
py=$venv/bin/python

if ! "$py" -c "import importlib.metadata as m, sys; sys.exit(m.version('pymeshlab') != '$PYMESHLAB_VERSION')" 2>/dev/null; then
  echo "[pymeshlab] virtual environment $venv with pymeshlab==$PYMESHLAB_VERSION"
  python3 -m venv "$venv"
  "$venv/bin/pip" install -q --disable-pip-version-check "pymeshlab==$PYMESHLAB_VERSION"
fi
# The wheel's MeshLab: version and scalar type (a trailing "d" = double), and its library folder.
info=$("$py" -c "import pymeshlab; pymeshlab.print_pymeshlab_version()" 2>/dev/null | grep -o 'based on MeshLab [0-9.]*d\?' || true)
mlver=$(echo "$info" | grep -o '[0-9]\{4\}\.[0-9]\{2\}' || true)
[ -n "$mlver" ] || { echo "[pymeshlab] the wheel does not say its MeshLab version" >&2; exit 1; }
scalar=float
[ "${info%d}" != "$info" ] && scalar=double
lib=$("$py" -c "import os, pymeshlab; print(os.path.join(os.path.dirname(pymeshlab.__file__), 'lib'))")
echo "[pymeshlab] PyMeshLab $PYMESHLAB_VERSION: MeshLab $mlver, scalar $scalar, libraries in $lib"
[ -f "$src/ML_VERSION" ] || { echo "[pymeshlab] no MeshLab source in $src (run scripts/debian_root.sh forky, or pass one)" >&2; exit 1; }

cmake -S "$here" -B "$top/build" -DCMAKE_BUILD_TYPE=Release -DMESHLAB_SOURCE_DIR="$src" \
      -DGS_MESHLAB_HOST_VERSION="$mlver" -DGS_MESHLAB_SCALAR="$scalar" -DGS_MESHLAB_LIB_DIR="$lib" \
      -DGS_BUILD_TESTS=OFF -DGS_BUILD_BENCH=OFF -DGS_BUILD_CLI=OFF > "$top/configure.log" 2>&1 ||
  { cat "$top/configure.log" >&2; exit 1; }
grep -E "Building against" "$top/configure.log" | sed 's/^-- /[pymeshlab] /'
# Only the filter plugin: PyMeshLab has no GUI, so no edit tools.
nice -n 10 cmake --build "$top/build" -j2 --target filter_geometric_snake > "$top/build.log" 2>&1 ||
  { grep -E -A3 "error" "$top/build.log" | head -n 60 >&2; exit 1; }
echo "[pymeshlab] plugin: $top/build/plugins/libfilter_geometric_snake.so"
