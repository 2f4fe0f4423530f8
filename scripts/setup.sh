#!/usr/bin/env bash
# Installs what the build and the tests need, and fetches MeshLab's source for the
# installed MeshLab version through a private apt configuration (the system's apt
# settings stay untouched). Idempotent: the source unpacks once and is reused.
#   usage: scripts/setup.sh [BUILD_DIR]      (default: ./build)
set -euo pipefail
here=$(cd "$(dirname "$0")/.." && pwd)
build=${1:-$here/build}
mkdir -p "$build"
build=$(cd "$build" && pwd)

SUDO=""
if [ "$(id -u)" -ne 0 ]; then SUDO="sudo"; fi

pkgs=(meshlab cmake g++ make pkg-config dpkg-dev
      qtbase5-dev libqt5opengl5-dev libqt5xmlpatterns5-dev libqt5svg5-dev
      libglew-dev libglu1-mesa-dev libeigen3-dev nlohmann-json3-dev
      googletest libgtest-dev libbenchmark-dev
      clang libclang-rt-14-dev
      xvfb xauth xdotool imagemagick x11-utils python3)
missing=()
for p in "${pkgs[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "ok installed" || missing+=("$p")
done
if [ ${#missing[@]} -gt 0 ]; then
  echo "[setup] installing: ${missing[*]}"
  $SUDO apt-get update -qq
  DEBIAN_FRONTEND=noninteractive $SUDO apt-get install -y -qq "${missing[@]}" >/dev/null
fi

ver=$(dpkg-query -W -f='${Version}' meshlab)
src="$build/meshlab-src"
if [ -f "$src/.version" ] && [ "$(cat "$src/.version")" = "$ver" ]; then
  echo "[setup] MeshLab source $ver already in $src"
  exit 0
fi

echo "[setup] fetching MeshLab source $ver with a private apt configuration"
apt="$build/apt"
rm -rf "$apt" "$src"
mkdir -p "$apt/lists/partial" "$apt/archives/partial" "$apt/download" "$apt/sources.list.d"
# Same mirror and suites as the system's own lists, but deb-src, in our own files.
uris=$(grep -h -E '^(URIs:|deb )' /etc/apt/sources.list.d/*.sources /etc/apt/sources.list 2>/dev/null \
        | grep -v security | head -n1 | sed -E 's/^URIs: *//; s/^deb +(\[[^]]*\] +)?([^ ]+).*/\2/' || true)
[ -n "$uris" ] || uris="http://deb.debian.org/debian"
cat > "$apt/sources.list" <<LIST
deb-src [signed-by=/usr/share/keyrings/debian-archive-keyring.gpg] $uris bookworm main
LIST
aptopts=(-o Dir::Etc::SourceList="$apt/sources.list"
         -o Dir::Etc::SourceParts="$apt/sources.list.d"
         -o Dir::State::Lists="$apt/lists"
         -o Dir::Cache::Archives="$apt/archives"
         -o Dir::Cache="$apt/cache"
         -o Debug::NoLocking=1)
mkdir -p "$apt/cache"
apt-get "${aptopts[@]}" update -qq
( cd "$apt/download" && apt-get "${aptopts[@]}" source -qq "meshlab=$ver" >/dev/null )
dir=$(find "$apt/download" -maxdepth 1 -mindepth 1 -type d -name 'meshlab-*' | head -n1)
[ -n "$dir" ] || { echo "[setup] apt-get source meshlab produced no source tree" >&2; exit 1; }
mv "$dir" "$src"
echo "$ver" > "$src/.version"
rm -rf "$apt/download"
echo "[setup] MeshLab source $ver in $src"
