#!/usr/bin/env bash
# A real Debian 13 (trixie) host for the MeshLab 2022.02 build of the plugins: scripts/debian_root.sh
# for trixie (the root BUILD_DIR/debian13/root, made with debootstrap; its meshlab, the MeshLab
# 2022.02 source, and the plugins of this source tree built and installed in it). Needs root.
#   usage: scripts/debian13.sh [BUILD_DIR]          prepare + build + install (default ./build)
#          scripts/debian13.sh [BUILD_DIR] --run CMD...   run CMD inside the root (mounted)
exec bash "$(dirname "$0")/debian_root.sh" trixie "$@"
