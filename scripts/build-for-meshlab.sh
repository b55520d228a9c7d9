#!/usr/bin/env bash
# Builds the plugin (and plugin_filters, which checks it) and the command-line tool for the newer
# MeshLab releases, each inside its Debian root against that release's headers and
# libmeshlab-common.so, into build-<release>/ (the plugin in build-<release>/plugins/).
# Run setup-meshlab-roots.sh first.
# Usage: build-for-meshlab.sh [RELEASE...]   (default: every release in meshlab-releases.sh)
set -euo pipefail
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
# shellcheck source=meshlab-releases.sh
. "$root/scripts/meshlab-releases.sh"
releases=("$@")
[ ${#releases[@]} -gt 0 ] || releases=("${MESHLAB_RELEASES[@]}")
for release in "${releases[@]}"; do
  "$root/scripts/in-meshlab-root.sh" "$release" bash -c "
    set -e
    cmake -S /project -B /project/build-$release -DCMAKE_BUILD_TYPE=Release \
      -DMESHLAB_SOURCE_DIR=/project/third_party/meshlab-$release \
      -DCURVATURE_INPAINT_PLUGIN_ONLY=ON >/dev/null
    cmake --build /project/build-$release -j2 --target filter_curvature_inpaint plugin_filters curvature-inpaint manual_page"
  echo "build: the plugin for MeshLab $release is build-$release/plugins/libfilter_curvature_inpaint.so" >&2
done
