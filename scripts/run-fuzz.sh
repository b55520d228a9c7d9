#!/usr/bin/env bash
# Runs each libFuzzer target (built with clang, AddressSanitizer and UndefinedBehaviorSanitizer by
# scripts/build-sanitized.sh) from the seeds in fuzz/corpus/<target>/:
#   run-fuzz.sh SECONDS     explore for SECONDS per target, with full instrumentation
#                           (build-fuzz/; new inputs kept in build-fuzz/corpus/)
#   run-fuzz.sh --runs N    N inputs per target from a fixed seed, two targets at a time: the same
#                           run every time (CI; build-sanitize/, shared with the unit tests)
# A crash leaves its input in the build folder and fails the script.
set -euo pipefail
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
if [ "${1:-}" = "--runs" ]; then
  limit=(-seed=1 -runs="${2:?--runs needs a count}")
  fresh=1 dir=build-sanitize at_once=2
  bash "$root/scripts/build-sanitized.sh"
else
  limit=(-max_total_time="${1:-20}")
  fresh=0 dir=build-fuzz at_once=1
  bash "$root/scripts/build-sanitized.sh" --explore
fi
# Any allocation far beyond what an input of 64 kB can justify fails as std::bad_alloc, which
# the product reports as an error, instead of exhausting the machine.
export ASAN_OPTIONS=detect_leaks=0:allocator_may_return_null=1:max_allocation_size_mb=2048
export UBSAN_OPTIONS=print_stacktrace=1
cd "$root/$dir"
fuzz() {
  local target=$1
  # A deterministic run starts from the shipped seeds alone.
  if [ "$fresh" = 1 ]; then rm -rf "corpus/$target"; fi
  mkdir -p "corpus/$target"
  "./bin/$target" "${limit[@]}" -max_len=65536 -timeout=20 -rss_limit_mb=4096 -malloc_limit_mb=65536 \
    -print_final_stats=1 "corpus/$target" "$root/fuzz/corpus/$target" 2>"$target.log"
}
targets=(fuzz_backend_responses fuzz_coarse_fill fuzz_filter_parameters fuzz_mesh_file)
for ((first = 0; first < ${#targets[@]}; first += at_once)); do
  batch=("${targets[@]:first:at_once}")
  pids=()
  for target in "${batch[@]}"; do
    echo "fuzz: $target ${limit[*]}" >&2
    fuzz "$target" &
    pids+=($!)
  done
  for i in "${!batch[@]}"; do
    target=${batch[$i]}
    wait "${pids[$i]}" ||
      { tail -60 "$target.log" >&2; echo "fuzz: $target failed; see $dir/$target.log" >&2; exit 1; }
    grep -E "stat::number_of_executed_units|stat::peak_rss_mb" "$target.log" | sed "s/^/$target: /" >&2
  done
done
