#!/usr/bin/env bash
# Runs the unit tests (the geometry, and the whole method on MeshLab's mesh type) built with
# AddressSanitizer and UndefinedBehaviorSanitizer by scripts/build-sanitized.sh; any report
# fails the script.
set -euo pipefail
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
bash "$root/scripts/build-sanitized.sh"
for tests in vcg_ext_tests hole_fill_tests; do
  ASAN_OPTIONS=detect_leaks=1:abort_on_error=1 UBSAN_OPTIONS=print_stacktrace=1 \
    "$root/build-sanitize/bin/$tests" --gtest_brief=1
done
