#!/usr/bin/env bash
# Runs a command inside the Debian root of a newer MeshLab release (scripts/setup-meshlab-roots.sh
# makes it), with this project at /project and ../shared at /shared. The mounts live in a
# private mount namespace, so they vanish with the command, however it ends. Needs root.
# Usage: in-meshlab-root.sh RELEASE COMMAND [ARG...]   (RELEASE: 2022.02 or 2025.07)
set -euo pipefail
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
# shellcheck source=meshlab-releases.sh
. "$root/scripts/meshlab-releases.sh"
[ $# -ge 2 ] || { echo "usage: in-meshlab-root.sh RELEASE COMMAND [ARG...]" >&2; exit 2; }
release=$1
shift
dir=$(meshlab_root_dir "$release")
if [ ! -f "$dir/.debootstrap-complete" ]; then
  echo "in-meshlab-root: no Debian root for MeshLab $release: run scripts/setup-meshlab-roots.sh" >&2
  exit 1
fi
shared=$(cd "$root/.." && pwd)/shared
exec unshare --mount --propagation private -- bash -c '
  set -e
  dir=$1 project=$2 shared=$3
  shift 3
  mount -t proc proc "$dir/proc"
  mount --rbind /dev "$dir/dev"
  mount -t tmpfs tmpfs "$dir/tmp"
  mkdir -p "$dir/project" "$dir/shared"
  mount --bind "$project" "$dir/project"
  if [ -d "$shared" ]; then mount --bind "$shared" "$dir/shared"; fi
  cp /etc/resolv.conf "$dir/etc/resolv.conf"
  exec chroot "$dir" /usr/bin/env -i PATH=/usr/local/bin:/usr/bin:/bin:/usr/sbin:/sbin \
    HOME=/tmp LANG=C.UTF-8 "$@"
' in-meshlab-root "$dir" "$root" "$shared" "$@"
