#!/usr/bin/env bash
# A real Debian 13 (trixie) host for the MeshLab 2022.02 build of the plugins: makes a Debian 13
# root with debootstrap in the build tree (from Debian's own packages, cached between runs),
# installs Debian 13's meshlab and the build dependencies in it, fetches the MeshLab 2022.02
# source there (scripts/setup.sh, with the root's apt), and builds and installs the plugins of
# this source tree in it (plus gs_meshlab_check, a program that drives MeshLab's library).
# Needs root (chroot, mounts). The system's apt settings stay untouched.
#   usage: scripts/debian13.sh [BUILD_DIR]          prepare + build + install (default ./build)
#          scripts/debian13.sh [BUILD_DIR] --run CMD...   run CMD inside the root (mounted)
# The root is BUILD_DIR/debian13/root; the plugins' source and build are in its /opt/gs.
set -euo pipefail
here=$(cd "$(dirname "$0")/.." && pwd)
build=${1:-$here/build}
[ $# -gt 0 ] && shift
mkdir -p "$build/debian13"
build=$(cd "$build" && pwd)
top=$build/debian13
root=$top/root
suite=trixie
if [ "$(id -u)" -ne 0 ]; then
  echo "[debian13] needs root (debootstrap, chroot, mounts)" >&2
  exit 77
fi

# The packages of the root: MeshLab with the libraries its own plugins load (Debian only
# recommends them, and without them MeshLab 2022.02 refuses those plugins at start), the
# build dependencies of the plugins, and Xvfb for the tests.
pkgs=(meshlab lib3ds-1-3 libgmp10 libgomp1 libmpfr6 libmuparser2v5 libopenctm1 libqhull-r8.0 libxerces-c3.2t64
      cmake g++ make pkgconf qtbase5-dev libqt5opengl5-dev libglew-dev libglu1-mesa-dev libeigen3-dev
      nlohmann-json3-dev dpkg-dev xz-utils xvfb xauth xdotool x11-utils python3 ca-certificates)

# One user of the root at a time (ctest may start several tests).
exec 9>"$top/lock"
flock 9

mounted() { grep -q " $root/$1 " /proc/mounts; }
umount_all() {
  for m in dev sys proc; do
    if mounted "$m"; then umount -R "$root/$m" 2>/dev/null || umount -R -l "$root/$m" || true; fi
  done
}
mount_all() {
  mounted proc || mount -t proc proc "$root/proc"
  mounted sys || mount -t sysfs sys "$root/sys"
  if ! mounted dev; then
    mount --rbind /dev "$root/dev"
    mount --make-rslave "$root/dev"
  fi
}
trap umount_all EXIT
in_root() { chroot "$root" /usr/bin/env -i PATH=/usr/sbin:/usr/bin:/sbin:/bin HOME=/root LANG=C.UTF-8 \
                  DEBIAN_FRONTEND=noninteractive "$@"; }

if [ "${1:-}" = "--run" ]; then
  shift
  [ -f "$root/.gs-ready" ] || { echo "[debian13] no root yet: run scripts/debian13.sh first" >&2; exit 1; }
  mount_all
  in_root "$@"
  exit $?
fi

t0=$(date +%s)
# Same mirror as the system's own lists.
mirror=$(grep -h -E '^(URIs:|deb )' /etc/apt/sources.list.d/*.sources /etc/apt/sources.list 2>/dev/null \
          | grep -v security | head -n1 | sed -E 's/^URIs: *//; s/^deb +(\[[^]]*\] +)?([^ ]+).*/\2/' || true)
[ -n "$mirror" ] || mirror="http://deb.debian.org/debian"

if [ ! -f "$root/.gs-ready" ]; then
  if [ -e "$root" ]; then # a broken earlier attempt: never delete through a mount
    umount_all
    if grep -q " $root/" /proc/mounts; then echo "[debian13] $root still has mounts" >&2; exit 1; fi
    rm -rf --one-file-system "$root"
  fi
  command -v debootstrap >/dev/null || { apt-get update -qq && apt-get install -y -qq debootstrap >/dev/null; }
  echo "[debian13] debootstrap $suite from $mirror into $root"
  debootstrap --variant=minbase "$suite" "$root" "$mirror" > "$top/debootstrap.log" 2>&1 ||
    { tail -n 30 "$top/debootstrap.log" >&2; exit 1; }
  echo "[debian13] debootstrap done in $(( $(date +%s) - t0 )) s"
fi
mount_all
cp /etc/resolv.conf "$root/etc/resolv.conf" 2>/dev/null || true
if [ "$(cat "$root/.gs-ready" 2>/dev/null)" != "${pkgs[*]}" ]; then
  t1=$(date +%s)
  echo "[debian13] installing in the root: ${pkgs[*]}"
  in_root apt-get update -qq
  in_root apt-get install -y -qq --no-install-recommends "${pkgs[@]}" > "$top/install.log" 2>&1 ||
    { tail -n 30 "$top/install.log" >&2; exit 1; }
  in_root apt-get clean
  echo "${pkgs[*]}" > "$root/.gs-ready"
  echo "[debian13] packages installed in $(( $(date +%s) - t1 )) s"
fi
ver=$(in_root dpkg-query -W -f='${Version}' meshlab)
echo "[debian13] Debian $(cat "$root/etc/debian_version"), meshlab $ver"

# This source tree (the files git knows, as they are now), built and installed in the root.
commit=$(git -C "$here" rev-parse --short HEAD 2>/dev/null || echo unknown)
git -C "$here" diff --quiet HEAD 2>/dev/null || commit="$commit+changes"
rm -rf "$root/opt/gs/src"
mkdir -p "$root/opt/gs/src"
(cd "$here" && git ls-files -co --exclude-standard | grep -v '^build/' | tar -cf - -T -) | tar -xf - -C "$root/opt/gs/src"
echo "$commit" > "$root/opt/gs/src/.commit"
# MeshLab's source for the root's MeshLab (scripts/setup.sh with the root's apt; cached in
# the root's build folder), then the plugins built against it and its libmeshlab-common.so.
in_root env GS_SETUP_SOURCE_ONLY=1 bash /opt/gs/src/scripts/setup.sh /opt/gs/build | sed 's/^\[setup\]/[debian13]/'
t2=$(date +%s)
echo "[debian13] building the plugins of $commit against MeshLab $ver"
in_root cmake -S /opt/gs/src -B /opt/gs/build -DCMAKE_BUILD_TYPE=Release -DMESHLAB_SOURCE_DIR=/opt/gs/build/meshlab-src \
        -DGS_BUILD_TESTS=OFF -DGS_BUILD_BENCH=OFF -DGS_BUILD_CLI=OFF > "$top/configure.log" 2>&1 ||
  { cat "$top/configure.log" >&2; exit 1; }
grep -E "plugin API|Building against" "$top/configure.log" | sed 's/^-- /[debian13] /'
in_root cmake --build /opt/gs/build -j2 > "$top/build.log" 2>&1 || { grep -E -A3 "error" "$top/build.log" | head -n 60 >&2; exit 1; }
in_root cmake --install /opt/gs/build | sed 's/^-- /[debian13] /'
echo "[debian13] built and installed in $(( $(date +%s) - t2 )) s; total $(( $(date +%s) - t0 )) s"
