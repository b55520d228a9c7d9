#!/usr/bin/env bash
# The whole test suite: sets up (bookworm's packages, and the Debian roots of MeshLab 2022.02 and
# 2025.07), builds (the plugin for each of the three releases, the command-line tool, the tests),
# runs ctest (unit tests, the command-line tool, the plugin in meshlabserver and in each
# release's meshlab).
set -euo pipefail
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
bash "$root/scripts/setup-debian.sh"
bash "$root/scripts/setup-meshlab-roots.sh"
bash "$root/scripts/build.sh"
bash "$root/scripts/build-for-meshlab.sh"
ctest --test-dir "$root/build" --output-on-failure -j2
