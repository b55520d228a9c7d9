#!/usr/bin/env bash
# The whole test suite: sets up (bookworm's packages, and the Debian roots of the MeshLab
# releases), builds (the plugin for each of the three releases, the command-line tool, the
# tests), packages (scripts/package.sh), and runs ctest (unit tests, the command-line tool, the
# plugin in meshlabserver and in each release's meshlab, each release's package). Says how long
# each step took.
set -euo pipefail
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
done_step() { echo "run-tests: $1 after $SECONDS s" >&2; }
bash "$root/scripts/setup-debian.sh"
done_step "set-up"
# The roots are made (downloads and disk, mostly) while this machine's build compiles.
roots_log=$(mktemp)
bash "$root/scripts/setup-meshlab-roots.sh" >"$roots_log" 2>&1 &
roots=$!
trap 'kill "$roots" 2>/dev/null || true; rm -f "$roots_log"' EXIT
bash "$root/scripts/build.sh"
done_step "build"
wait "$roots" || { cat "$roots_log" >&2; exit 1; }
cat "$roots_log" >&2
done_step "Debian roots"
bash "$root/scripts/build-for-meshlab.sh"
done_step "builds for the newer releases"
bash "$root/scripts/package.sh"
done_step "packages"
ctest --test-dir "$root/build" --output-on-failure -j2
done_step "ctest"
