#!/usr/bin/env bash
# The whole test suite: sets up, builds, runs ctest (unit tests, the command-line tool, the
# plugin in meshlabserver).
set -euo pipefail
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
bash "$root/scripts/setup-debian.sh"
bash "$root/scripts/build.sh"
ctest --test-dir "$root/build" --output-on-failure -j2
