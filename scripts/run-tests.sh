#!/usr/bin/env bash
# The whole test suite: sets up (bookworm's packages, and the Debian roots of the MeshLab
# releases), builds (the plugin for each of the three releases, the command-line tool, the
# tests), packages (scripts/package.sh), and runs ctest (unit tests, the command-line tool, the
# plugin in meshlabserver and in each release's meshlab, each release's package).
set -euo pipefail
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
bash "$root/scripts/setup-debian.sh"
# The roots are made (downloads and disk, mostly) while this machine's build compiles.
roots_log=$(mktemp)
bash "$root/scripts/setup-meshlab-roots.sh" >"$roots_log" 2>&1 &
roots=$!
trap 'kill "$roots" 2>/dev/null || true; rm -f "$roots_log"' EXIT
bash "$root/scripts/build.sh"
wait "$roots" || { cat "$roots_log" >&2; exit 1; }
cat "$roots_log" >&2
bash "$root/scripts/build-for-meshlab.sh"
bash "$root/scripts/package.sh"
ctest --test-dir "$root/build" --output-on-failure -j2
