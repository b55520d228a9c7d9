#!/usr/bin/env bash
# The main job on the sample mesh: sets up, builds, fills meshes/sample_holes.ply into
# out/sample_filled.ply.
set -euo pipefail
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
bash "$root/scripts/setup-debian.sh"
bash "$root/scripts/build.sh" --target curvature-inpaint
mkdir -p "$root/out"
"$root/build/bin/curvature-inpaint" coarse "$root/meshes/sample_holes.ply" "$root/out/sample_filled.ply"
echo "wrote out/sample_filled.ply"
