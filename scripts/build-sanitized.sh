#!/usr/bin/env bash
# Builds with clang, AddressSanitizer and UndefinedBehaviorSanitizer:
#   build-sanitized.sh            the unit tests and the libFuzzer targets, once for both, into
#                                 build-sanitize/ (scripts/run-sanitizers.sh, run-fuzz.sh --runs)
#   build-sanitized.sh --explore  the libFuzzer targets alone into build-fuzz/, for exploring runs
# The shared build records edge coverage only: libFuzzer's comparison tracing makes the unit tests
# twice as slow (docs/robustness.md). The exploring build has it.
# -O2 with line tables only: the reports keep their file and line.
set -euo pipefail
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
bash "$root/scripts/setup-debian.sh"
if ! dpkg-query -W -f='${Status}\n' clang 2>/dev/null | grep -q '^install ok installed$'; then
  if [ "$(id -u)" -eq 0 ]; then sudo=(); else sudo=(sudo); fi
  "${sudo[@]}" env DEBIAN_FRONTEND=noninteractive apt-get install -y -qq --no-install-recommends clang >/dev/null
fi
fuzz_targets=(fuzz_backend_responses fuzz_coarse_fill fuzz_filter_parameters fuzz_mesh_file)
if [ "${1:-}" = "--explore" ]; then
  dir="$root/build-fuzz" coverage="-fsanitize=fuzzer-no-link" targets=("${fuzz_targets[@]}") testing=OFF
else
  dir="$root/build-sanitize" coverage="-fsanitize-coverage=inline-8bit-counters,pc-table"
  targets=(vcg_ext_tests hole_fill_tests "${fuzz_targets[@]}") testing=ON
fi
sanitizers="-fsanitize=address,undefined -fsanitize=float-cast-overflow -fno-sanitize-recover=undefined"
cmake -S "$root" -B "$dir" -DCMAKE_BUILD_TYPE=RelWithDebInfo \
  -DCMAKE_C_COMPILER=clang -DCMAKE_CXX_COMPILER=clang++ \
  -DCMAKE_CXX_FLAGS="$coverage $sanitizers -fno-omit-frame-pointer" \
  -DCMAKE_CXX_FLAGS_RELWITHDEBINFO="-O2 -gline-tables-only -DNDEBUG" \
  -DCMAKE_EXE_LINKER_FLAGS="-fsanitize=address,undefined" \
  -DCURVATURE_INPAINT_FUZZ=ON -DBUILD_TESTING=$testing >/dev/null
cmake --build "$dir" -j2 --target "${targets[@]}"
