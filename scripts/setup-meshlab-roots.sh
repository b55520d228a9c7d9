#!/usr/bin/env bash
# Makes the Debian roots in which the plugin is built and tested for the newer MeshLab releases
# (sid for 2025.07, trixie for 2022.02): debootstrap, then Debian's meshlab, Xvfb and the build
# dependencies inside, then `apt-get source` for that release's headers, vcglib and filter_mls,
# unpacked into third_party/meshlab-<release>/. For 2020.09 a bookworm root with Xvfb only, where
# the package test installs the package and what it pulls in (tests/package_test.py).
# Idempotent: a second run returns in seconds.
# Needs root (debootstrap, chroot) and scripts/setup-debian.sh run first.
# Usage: setup-meshlab-roots.sh [RELEASE...]   (default: PACKAGE_RELEASES in meshlab-releases.sh)
set -euo pipefail
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
# shellcheck source=meshlab-releases.sh
. "$root/scripts/meshlab-releases.sh"
# shellcheck source=debian-mirror.sh
. "$root/scripts/debian-mirror.sh"

if [ "$(id -u)" -ne 0 ]; then
  echo "setup-meshlab-roots: debootstrap and chroot need root" >&2
  exit 1
fi

# Inside each root. Debian's mirrors can serve snapshots whose Release files are past their
# Valid-Until: apt in the roots is told not to check it.
packages=(
  meshlab xvfb xauth xdotool x11-apps python3
  g++ make cmake qtbase5-dev libqt5opengl5-dev libglew-dev libglu1-mesa-dev libeigen3-dev
  libcurl4-openssl-dev dpkg-dev
)
# Where nothing is built: only what runs meshlabserver's display and the tests' helpers.
package_test_packages=(xvfb xauth python3)
apt_options=(-o Acquire::Check-Valid-Until=false -o APT::Sandbox::User=root)

run_quiet() {
  local log
  log=$(mktemp)
  "$@" >"$log" 2>&1 || { cat "$log" >&2; rm -f "$log"; return 1; }
  rm -f "$log"
}

setup_root() {
  local release=$1 suite dir stamp want mirror
  suite=$(meshlab_suite "$release")
  dir=$(meshlab_root_dir "$release")
  stamp="$dir/.curvature-inpaint-root"
  local wanted=("${packages[@]}")
  [ "$release" != 2020.09 ] || wanted=("${package_test_packages[@]}")
  want="$suite: ${wanted[*]}"
  [ "$release" = 2020.09 ] || want="$want + meshlab's recommends"
  if [ "$(cat "$stamp" 2>/dev/null)" != "$want" ]; then
    mirror=$(debian_mirror)
    if [ ! -f "$dir/.debootstrap-complete" ]; then
      echo "setup: debootstrap $suite into ${dir#"$root"/}" >&2
      rm -rf "$dir"
      mkdir -p "$(dirname "$dir")"
      run_quiet debootstrap --variant=minbase "$suite" "$dir" "$mirror"
      touch "$dir/.debootstrap-complete"
    fi
    cat >"$dir/etc/apt/sources.list" <<SOURCES
deb $mirror $suite main
deb-src $mirror $suite main
SOURCES
    printf 'Acquire::Check-Valid-Until "false";\n' >"$dir/etc/apt/apt.conf.d/50curvature-inpaint"
    echo "setup: installing ${wanted[*]} in $suite" >&2
    run_quiet "$root/scripts/in-meshlab-root.sh" "$release" apt-get "${apt_options[@]}" update -qq
    run_quiet "$root/scripts/in-meshlab-root.sh" "$release" env DEBIAN_FRONTEND=noninteractive \
      apt-get "${apt_options[@]}" install -y -qq --no-install-recommends "${wanted[@]}"
    # MeshLab's own plugins need its recommended libraries (muparser, qhull, lib3ds, OpenCTM):
    # without them it opens with a modal "Error while loading plugins." that blocks the GUI.
    [ "$release" = 2020.09 ] || run_quiet "$root/scripts/in-meshlab-root.sh" "$release" bash -c "
      recommends=\$(dpkg-query -W -f='\${Recommends}' meshlab | tr ',' '\\n' | sed 's/|.*//; s/(.*)//; s/ //g')
      DEBIAN_FRONTEND=noninteractive apt-get ${apt_options[*]} install -y -qq --no-install-recommends \$recommends"
    echo "$want" >"$stamp"
  fi
  # 2020.09's source is bookworm's, unpacked by scripts/setup-debian.sh.
  [ "$release" != 2020.09 ] || return 0

  local src="$root/third_party/meshlab-$release"
  if [ ! -f "$src/src/common/plugins/interfaces/filter_plugin.h" ]; then
    echo "setup: fetching MeshLab $release's source" >&2
    # Debian's mirror serves these releases' orig tarballs but not their .dsc: fetch the tarball
    # alone, or take the copy in ../shared/meshlab-src where apt cannot fetch it.
    local tmp tarball
    tmp=$(mktemp -d "$dir/tmp.source.XXXXXX")
    if "$root/scripts/in-meshlab-root.sh" "$release" bash -c \
      "cd /${tmp#"$dir"/} && apt-get ${apt_options[*]} source -qq --download-only --tar-only meshlab" \
      >/dev/null 2>&1; then
      tarball=$(ls "$tmp"/meshlab_*.orig.tar.*)
    else
      tarball=$(ls "$root"/../shared/meshlab-src/meshlab_"$release"*.orig.tar.* 2>/dev/null | head -1)
      [ -n "$tarball" ] || { echo "setup: no source of MeshLab $release" >&2; exit 1; }
    fi
    rm -rf "$src"
    mkdir -p "$src"
    tar -xf "$tarball" -C "$src" --strip-components=1
    rm -rf "$tmp"
    if [ "$(cat "$src/ML_VERSION")" != "$release" ]; then
      echo "setup: the source unpacked is MeshLab $(cat "$src/ML_VERSION"), not $release" >&2
      exit 1
    fi
  fi
}

releases=("$@")
[ ${#releases[@]} -gt 0 ] || releases=("${PACKAGE_RELEASES[@]}")
# The roots are made side by side: each mostly waits on downloads and the disk.
pids=()
for release in "${releases[@]}"; do
  setup_root "$release" &
  pids+=($!)
done
failed=0
for pid in "${pids[@]}"; do wait "$pid" || failed=1; done
[ "$failed" = 0 ] || { echo "setup: a Debian root could not be made (above)" >&2; exit 1; }
echo "setup: ready (Debian roots for MeshLab ${releases[*]})" >&2
