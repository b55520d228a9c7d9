#!/usr/bin/env bash
# Runs the unit tests (the geometry, and the whole method on MeshLab's mesh type) built with
# AddressSanitizer and UndefinedBehaviorSanitizer by scripts/build-sanitized.sh, each binary in
# two shards at once (one per core); any report fails the script.
set -euo pipefail
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
bash "$root/scripts/build-sanitized.sh"
export ASAN_OPTIONS=detect_leaks=1:abort_on_error=1 UBSAN_OPTIONS=print_stacktrace=1
logs=$(mktemp -d)
trap 'rm -rf "$logs"' EXIT
for tests in vcg_ext_tests hole_fill_tests; do
  pids=()
  for shard in 0 1; do
    GTEST_TOTAL_SHARDS=2 GTEST_SHARD_INDEX=$shard "$root/build-sanitize/bin/$tests" --gtest_brief=1 \
      >"$logs/$tests.$shard" 2>&1 &
    pids+=($!)
  done
  for shard in 0 1; do
    if ! wait "${pids[$shard]}"; then
      cat "$logs/$tests.$shard" >&2
      echo "sanitizers: $tests, shard $shard of 2, failed" >&2
      exit 1
    fi
    grep -E "^\[  PASSED  \]|tests? from .* ran" "$logs/$tests.$shard" | sed "s/^/$tests $shard: /" >&2
  done
done
