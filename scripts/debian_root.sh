#!/usr/bin/env bash
# A real Debian system of another release as a MeshLab host for the plugins of this source tree:
# makes a root with debootstrap in the build tree (from Debian's own packages, in a package cache
# shared by all the roots of the build tree), installs that release's meshlab and the build
# dependencies in it, fetches the matching MeshLab source there (scripts/setup.sh, with the root's
# apt: Debian's signed Sources index), and builds and installs the plugins of this source tree in
# it (plus gs_meshlab_check, a program that drives MeshLab's library). Needs root (chroot,
# mounts). The system's apt settings stay untouched.
#   RELEASE  trixie  Debian 13, MeshLab 2022.02  (root BUILD_DIR/debian13/root; scripts/debian13.sh)
#            forky   Debian 14 (testing), MeshLab 2025.07  (root BUILD_DIR/forky/root)
#   usage: scripts/debian_root.sh RELEASE [BUILD_DIR]                 prepare + build + install
#          scripts/debian_root.sh RELEASE [BUILD_DIR] --run CMD...    run CMD inside the root (mounted)
#          scripts/debian_root.sh RELEASE [BUILD_DIR] --prepare-only  the root and its packages only
# The plugins' source and build are in the root's /opt/gs. Debootstrap and apt share the
# package cache BUILD_DIR/debian-cache (a .deb the other root already fetched is not fetched again).
set -euo pipefail
here=$(cd "$(dirname "$0")/.." && pwd)
release=${1:-}
[ $# -gt 0 ] && shift
build=${1:-$here/build}
[ $# -gt 0 ] && shift

# Runtime libraries MeshLab's own plugins link to (Debian only recommends them, and without them
# MeshLab refuses those plugins at start), per release; the GUI tests also take screenshots
# (xwd, in x11-apps).
case "$release" in
  trixie) name=debian13
          libs=(lib3ds-1-3 libgmp10 libgomp1 libmpfr6 libmuparser2v5 libopenctm1 libqhull-r8.0 libxerces-c3.2t64 x11-apps) ;;
  forky)  name=forky
          libs=(lib3ds-1-3 libgmp10 libgomp1 libmpfr6 libmuparser2v5 libopenctm1 libqhull-r8.0 x11-apps) ;;
  *) echo "usage: $0 trixie|forky [BUILD_DIR] [--run CMD... | --prepare-only]" >&2; exit 2 ;;
esac
# The packages of the root: MeshLab and those libraries, the plugins' build dependencies, and
# Xvfb + xdotool for the tests. --no-install-recommends keeps the root small.
pkgs=(meshlab "${libs[@]}"
      cmake g++ make pkgconf qtbase5-dev libqt5opengl5-dev libglew-dev libglu1-mesa-dev libeigen3-dev
      nlohmann-json3-dev dpkg-dev xz-utils xvfb xauth xdotool x11-utils python3 ca-certificates)

mkdir -p "$build/$name" "$build/debian-cache"
build=$(cd "$build" && pwd)
top=$build/$name
root=$top/root
cache=$build/debian-cache
tag="[$name]"
if [ "$(id -u)" -ne 0 ]; then
  echo "$tag needs root (debootstrap, chroot, mounts)" >&2
  exit 77
fi

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
  [ -f "$root/.gs-ready" ] || { echo "$tag no root yet: run scripts/debian_root.sh $release first" >&2; exit 1; }
  mount_all
  in_root "$@" 9>&- # the lock is not the command's: a server it leaves behind must not keep it
  exit $?
fi

t0=$(date +%s)
# Same mirror as the system's own lists.
mirror=$(grep -h -E '^(URIs:|deb )' /etc/apt/sources.list.d/*.sources /etc/apt/sources.list 2>/dev/null \
          | grep -v security | head -n1 | sed -E 's/^URIs: *//; s/^deb +(\[[^]]*\] +)?([^ ]+).*/\2/' || true)
[ -n "$mirror" ] || mirror="http://deb.debian.org/debian"

if [ ! -f "$root/.gs-debootstrapped" ] && [ ! -f "$root/.gs-ready" ]; then # (.gs-ready: an older script's root)
  if [ -e "$root" ]; then # a broken earlier attempt: never delete through a mount
    umount_all
    if grep -q " $root/" /proc/mounts; then echo "$tag $root still has mounts" >&2; exit 1; fi
    rm -rf --one-file-system "$root"
  fi
  command -v debootstrap >/dev/null || { apt-get update -qq && apt-get install -y -qq debootstrap >/dev/null; }
  # An older debootstrap has no script for a newer release (Debian 12's knows no forky): sid's fits.
  script=/usr/share/debootstrap/scripts/$release
  [ -e "$script" ] || script=/usr/share/debootstrap/scripts/sid
  echo "$tag debootstrap $release from $mirror into $root (package cache $cache)"
  # one debootstrap at a time writes the shared cache (the other root's waits: ~1 min)
  flock "$cache/.debootstrap.lock" \
    debootstrap --variant=minbase --cache-dir="$cache" "$release" "$root" "$mirror" "$script" > "$top/debootstrap.log" 2>&1 ||
    { tail -n 30 "$top/debootstrap.log" >&2; exit 1; }
  touch "$root/.gs-debootstrapped"
  echo "$tag debootstrap done in $(( $(date +%s) - t0 )) s"
fi
mount_all
cp /etc/resolv.conf "$root/etc/resolv.conf" 2>/dev/null || true
# A testing release's Release file carries a Valid-Until that a frozen mirror snapshot outlives;
# the signatures are still checked.
echo 'Acquire::Check-Valid-Until "false";' > "$root/etc/apt/apt.conf.d/99gs-valid-until"
if [ "$(cat "$root/.gs-ready" 2>/dev/null)" != "${pkgs[*]}" ]; then
  t1=$(date +%s)
  echo "$tag installing in the root: ${pkgs[*]}"
  # The shared package cache, hard-linked into the root's own apt archive and back: the .debs
  # either root fetched are not fetched again, and two roots' apt runs do not wait on one lock.
  find "$cache" -maxdepth 1 -name '*.deb' -exec cp -l -n -t "$root/var/cache/apt/archives/" {} + 2>/dev/null || true
  in_root apt-get update -qq
  in_root apt-get install -y -qq --no-install-recommends "${pkgs[@]}" > "$top/install.log" 2>&1 ||
    { tail -n 30 "$top/install.log" >&2; exit 1; }
  find "$root/var/cache/apt/archives" -maxdepth 1 -name '*.deb' -exec cp -l -n -t "$cache/" {} + 2>/dev/null || true
  in_root apt-get clean
  echo "${pkgs[*]}" > "$root/.gs-ready"
  echo "$tag packages installed in $(( $(date +%s) - t1 )) s"
fi
ver=$(in_root dpkg-query -W -f='${Version}' meshlab)
echo "$tag Debian $(cat "$root/etc/debian_version"), meshlab $ver"
[ "${1:-}" = "--prepare-only" ] && exit 0

# This source tree (the files git knows, as they are now), built and installed in the root.
commit=$(git -C "$here" rev-parse --short HEAD 2>/dev/null || echo unknown)
git -C "$here" diff --quiet HEAD 2>/dev/null || commit="$commit+changes"
rm -rf "$root/opt/gs/src"
mkdir -p "$root/opt/gs/src"
(cd "$here" && git ls-files -co --exclude-standard | grep -v '^build/' | tar -cf - -T -) | tar -xf - -C "$root/opt/gs/src"
echo "$commit" > "$root/opt/gs/src/.commit"
# MeshLab's source for the root's MeshLab (scripts/setup.sh with the root's apt; cached in
# the root's build folder), then the plugins built against it and its libmeshlab-common.so.
in_root env GS_SETUP_SOURCE_ONLY=1 bash /opt/gs/src/scripts/setup.sh /opt/gs/build | sed "s/^\[setup\]/$tag/"
t2=$(date +%s)
echo "$tag building the plugins of $commit against MeshLab $ver"
in_root cmake -S /opt/gs/src -B /opt/gs/build -DCMAKE_BUILD_TYPE=Release -DMESHLAB_SOURCE_DIR=/opt/gs/build/meshlab-src \
        -DGS_BUILD_TESTS=OFF -DGS_BUILD_BENCH=OFF -DGS_BUILD_CLI=OFF -DGS_UNITY_BUILD=ON > "$top/configure.log" 2>&1 ||
  { cat "$top/configure.log" >&2; exit 1; }
grep -E "plugin API|Building against" "$top/configure.log" | sed "s/^-- /$tag /"
in_root nice -n 10 cmake --build /opt/gs/build -j2 > "$top/build.log" 2>&1 ||
  { grep -E -A3 "error" "$top/build.log" | head -n 60 >&2; exit 1; }
in_root cmake --install /opt/gs/build | sed "s/^-- /$tag /"
echo "$tag built and installed in $(( $(date +%s) - t2 )) s; total $(( $(date +%s) - t0 )) s"
