#!/usr/bin/env bash
# Runs each libFuzzer target (built with clang, AddressSanitizer and UndefinedBehaviorSanitizer by
# scripts/build-sanitized.sh, into build-sanitize/) from the seeds in fuzz/corpus/<target>/:
#   run-fuzz.sh SECONDS     explore for SECONDS per target (new inputs kept in build-sanitize/corpus/)
#   run-fuzz.sh --runs N    N inputs per target from a fixed seed: the same run every time (CI)
# A crash leaves its input in build-sanitize/ and fails the script.
set -euo pipefail
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
if [ "${1:-}" = "--runs" ]; then
  limit=(-seed=1 -runs="${2:?--runs needs a count}")
  fresh=1
else
  limit=(-max_total_time="${1:-20}")
  fresh=0
fi
bash "$root/scripts/build-sanitized.sh"
# Any allocation far beyond what an input of 64 kB can justify fails as std::bad_alloc, which
# the product reports as an error, instead of exhausting the machine.
export ASAN_OPTIONS=detect_leaks=0:allocator_may_return_null=1:max_allocation_size_mb=2048
export UBSAN_OPTIONS=print_stacktrace=1
cd "$root/build-sanitize"
for target in fuzz_backend_responses fuzz_coarse_fill fuzz_filter_parameters fuzz_mesh_file; do
  # A deterministic run starts from the shipped seeds alone.
  if [ "$fresh" = 1 ]; then rm -rf "corpus/$target"; fi
  mkdir -p "corpus/$target"
  echo "fuzz: $target ${limit[*]}" >&2
  "./bin/$target" "${limit[@]}" -max_len=65536 -timeout=20 -rss_limit_mb=4096 -malloc_limit_mb=65536 \
    -print_final_stats=1 "corpus/$target" "$root/fuzz/corpus/$target" 2>"$target.log" ||
    { tail -60 "$target.log" >&2; echo "fuzz: $target failed; see build-sanitize/$target.log" >&2; exit 1; }
  grep -E "stat::number_of_executed_units|stat::peak_rss_mb" "$target.log" | sed "s/^/$target: /" >&2
done
