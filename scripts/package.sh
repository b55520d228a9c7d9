#!/usr/bin/env bash
# Makes the Debian package of each MeshLab release into dist/: 2020.09 from build/ (bookworm's
# meshlab), 2022.02 and 2025.07 from build-<release>/ inside their Debian roots. Run
# scripts/build.sh and scripts/build-for-meshlab.sh first (scripts/run-tests.sh does).
# The maintainer is $DEBFULLNAME <$DEBEMAIL> when set, else the last commit's author.
# Usage: package.sh [RELEASE...]   (default: PACKAGE_RELEASES in meshlab-releases.sh)
set -euo pipefail
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
# shellcheck source=meshlab-releases.sh
. "$root/scripts/meshlab-releases.sh"
releases=("$@")
[ ${#releases[@]} -gt 0 ] || releases=("${PACKAGE_RELEASES[@]}")

if [ -n "${DEBEMAIL:-}" ]; then
  maintainer="${DEBFULLNAME:-Curvature Inpaint Hole Fill} <$DEBEMAIL>"
else
  maintainer=$(git -C "$root" log -1 --format='%an <%ae>')
fi
epoch=${SOURCE_DATE_EPOCH:-$(git -C "$root" log -1 --format=%ct)}

mkdir -p "$root/dist"
for release in "${releases[@]}"; do
  rm -f "$root"/dist/curvature-inpaint_*+meshlab"$release"_*.deb
  if [ "$release" = 2020.09 ]; then
    cmake --build "$root/build" -j2 --target filter_curvature_inpaint curvature-inpaint manual_page >/dev/null
    MAINTAINER=$maintainer SOURCE_DATE_EPOCH=$epoch \
      bash "$root/scripts/make-deb.sh" "$release" "$root/build" "$root/dist"
  else
    "$root/scripts/in-meshlab-root.sh" "$release" env MAINTAINER="$maintainer" SOURCE_DATE_EPOCH="$epoch" \
      bash /project/scripts/make-deb.sh "$release" "/project/build-$release" /project/dist
  fi
done
