#!/usr/bin/env bash
# Makes the Debian package of one build: `cmake --install` below /usr into a staging folder,
# the binaries stripped, Debian's copyright and changelog beside the docs, and as dependencies
# the MeshLab release built against plus the libraries dpkg-shlibdeps finds. Runs on the system
# the build was made on (bookworm for 2020.09, the release's Debian root for the others), as
# scripts/package.sh calls it.
# Usage: MAINTAINER='Name <address>' SOURCE_DATE_EPOCH=SECONDS make-deb.sh RELEASE BUILD DIST
set -euo pipefail
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
[ $# -eq 3 ] || { echo "usage: make-deb.sh RELEASE BUILD DIST" >&2; exit 2; }
release=$1 build=$2 dist=$3
: "${MAINTAINER:?MAINTAINER must name who the package is from}"
: "${SOURCE_DATE_EPOCH:?SOURCE_DATE_EPOCH must give the changelog date}"
export SOURCE_DATE_EPOCH

package=curvature-inpaint
upstream=$(sed -n 's/^CMAKE_PROJECT_VERSION:STATIC=//p' "$build/CMakeCache.txt")
meshlab_source=$(sed -n 's/^MESHLAB_SOURCE_DIR:PATH=//p' "$build/CMakeCache.txt")
built_for=$(cat "$meshlab_source/ML_VERSION" 2>/dev/null || true)
if [ "$built_for" != "$release" ]; then
  echo "make-deb: $build was built for MeshLab ${built_for:-unknown}, not $release" >&2
  exit 1
fi
version="$upstream+meshlab$release"
arch=$(dpkg --print-architecture)
suite=$(. /etc/os-release && echo "${VERSION_CODENAME:-sid}")
# The plugin ABI changes with every release: exactly this one, whatever Debian's revision.
year=${release%%.*} month=${release#*.}
next=$(printf '%s.%02d' "$year" $((10#$month + 1)))

work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
stage="$work/stage"
DESTDIR="$stage" cmake --install "$build" --prefix /usr >/dev/null
plugin=$(find "$stage/usr/lib" -name 'libfilter_curvature_inpaint.so')
tool="$stage/usr/bin/curvature-inpaint"
strip --strip-unneeded --remove-section=.comment --remove-section=.note "$plugin" "$tool"
gzip -9n "$stage/usr/share/man/man1/curvature-inpaint.1"

docs="$stage/usr/share/doc/$package"
cp "$root/packaging/copyright" "$docs/copyright"
# A native package's changelog: one entry per build, dated by the commit it was made from.
cat >"$work/changelog" <<CHANGELOG
$package ($version) $suite; urgency=medium

  * Built for MeshLab $release.

 -- $MAINTAINER  $(date -u -R -d "@$SOURCE_DATE_EPOCH")
CHANGELOG
gzip -9n <"$work/changelog" >"$docs/changelog.gz"

find "$stage" -type d -exec chmod 0755 {} +
find "$stage" -type f -exec chmod 0644 {} +
chmod 0755 "$tool"

# dpkg-shlibdeps reads debian/control; MeshLab's private library has no shlibs entry, and the
# dependency on meshlab below covers it.
mkdir -p "$work/debian"
printf 'Source: %s\n\nPackage: %s\nArchitecture: any\n' "$package" "$package" >"$work/debian/control"
shlibs=$(cd "$work" && dpkg-shlibdeps -O --ignore-missing-info -l"$(dirname "$(dirname "${plugin#"$stage"}")")" \
  "$tool" "$plugin" 2>/dev/null | sed -n 's/^shlibs:Depends=//p')
rm -rf "$work/debian"

mkdir -p "$stage/DEBIAN"
(cd "$stage" && find usr -type f -print0 | sort -z | xargs -0 md5sum) >"$stage/DEBIAN/md5sums"
cat >"$stage/DEBIAN/control" <<CONTROL
Package: $package
Version: $version
Architecture: $arch
Maintainer: $MAINTAINER
Installed-Size: $(du -sk --exclude=DEBIAN "$stage" | cut -f1)
Depends: meshlab (>= $release~), meshlab (<< $next~), $shlibs
Section: graphics
Priority: optional
Description: MeshLab filter that fills holes in 3D scans with the missing shape
 Curvature Inpaint Hole Fill fills each hole of a triangle mesh coarsely, paints
 the mean curvature around it as an image, completes the image with an
 inpainter (an embedded one by default, so it works offline) and deforms the
 fill until its curvature matches: holes get the shape that is missing instead
 of a smooth cap.
 .
 This package holds the filter plugin for MeshLab $release, its meshlabserver
 scripts and the command-line tool curvature-inpaint.
CONTROL

mkdir -p "$dist"
out="$dist/${package}_${version}_$arch.deb"
dpkg-deb --build --root-owner-group -Zxz "$stage" "$out" >/dev/null
echo "package: $out" >&2
