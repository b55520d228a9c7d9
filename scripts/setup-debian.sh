#!/usr/bin/env bash
# Installs everything the build and the tests need on Debian bookworm, and unpacks
# MeshLab 2020.09's source (plugin headers, vcglib, filter_mls) into third_party/.
# Idempotent: a second run only checks and returns in about a second.
set -euo pipefail

root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
src_dir="$root/third_party/meshlab-src"

packages=(
  build-essential cmake pkg-config dpkg-dev
  meshlab
  qtbase5-dev libqt5opengl5-dev libqt5xmlpatterns5-dev qttools5-dev-tools
  libglew-dev libglu1-mesa-dev libeigen3-dev libcurl4-openssl-dev
  libgtest-dev googletest
  xvfb xauth xdotool x11-apps
  python3
  slurm-wlm munge
  debootstrap lintian man-db
)

as_root() {
  if [ "$(id -u)" -eq 0 ]; then "$@"; else sudo "$@"; fi
}

missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}\n' "$p" 2>/dev/null | grep -q '^install ok installed$' || missing+=("$p")
done

# MeshLab's source package comes from the mirror this machine already installs bookworm from
# (its own apt sources say which); the source entry is written once, beside them.
srclist=/etc/apt/sources.list.d/curvature-inpaint-src.sources
need_update=0
# shellcheck source=debian-mirror.sh
. "$root/scripts/debian-mirror.sh"
if [ ! -f "$srclist" ]; then
  mirror=$(debian_mirror)
  as_root tee "$srclist" >/dev/null <<SRC
Types: deb-src
URIs: $mirror
Suites: bookworm
Components: main
Signed-By: /usr/share/keyrings/debian-archive-keyring.gpg
SRC
  need_update=1
fi

if [ "$need_update" -eq 1 ] || [ ${#missing[@]} -gt 0 ]; then
  echo "setup: apt-get update" >&2
  as_root apt-get update -qq
fi
if [ ${#missing[@]} -gt 0 ]; then
  echo "setup: installing ${missing[*]}" >&2
  log=$(mktemp)
  as_root env DEBIAN_FRONTEND=noninteractive apt-get install -y -qq --no-install-recommends \
    "${missing[@]}" >"$log" 2>&1 || { cat "$log" >&2; exit 1; }
  rm -f "$log"
fi

if [ ! -f "$src_dir/vcglib/vcg/complex/algorithms/hole.h" ] || [ ! -f "$src_dir/src/common/interfaces.h" ]; then
  echo "setup: fetching MeshLab's source package" >&2
  tmp=$(mktemp -d)
  ( cd "$tmp" && apt-get source -qq --download-only meshlab >/dev/null && dpkg-source -x --no-check ./*.dsc unpacked >/dev/null ) || {
    # Retry once after refreshing the source lists: a stale list names files the mirror dropped.
    as_root apt-get update -qq
    ( cd "$tmp" && rm -rf ./* && apt-get source -qq --download-only meshlab >/dev/null && dpkg-source -x --no-check ./*.dsc unpacked >/dev/null )
  }
  rm -rf "$src_dir"
  mkdir -p "$(dirname "$src_dir")"
  mv "$tmp/unpacked" "$src_dir"
  rm -rf "$tmp"
fi
echo "setup: ready (MeshLab source in ${src_dir#"$root"/})" >&2
