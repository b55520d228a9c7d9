#!/usr/bin/env bash
# Builds, once for both, the unit tests and the libFuzzer targets with clang, AddressSanitizer
# and UndefinedBehaviorSanitizer into build-sanitize/ (scripts/run-sanitizers.sh and
# scripts/run-fuzz.sh run them). -O1 with line tables only: the reports keep their file and line,
# and the build takes about half the time of -O2 -g.
set -euo pipefail
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
bash "$root/scripts/setup-debian.sh"
if ! dpkg-query -W -f='${Status}\n' clang 2>/dev/null | grep -q '^install ok installed$'; then
  if [ "$(id -u)" -eq 0 ]; then sudo=(); else sudo=(sudo); fi
  "${sudo[@]}" env DEBIAN_FRONTEND=noninteractive apt-get install -y -qq --no-install-recommends clang >/dev/null
fi
sanitizers="-fsanitize=address,undefined -fsanitize=float-cast-overflow -fno-sanitize-recover=undefined"
cmake -S "$root" -B "$root/build-sanitize" -DCMAKE_BUILD_TYPE=RelWithDebInfo \
  -DCMAKE_C_COMPILER=clang -DCMAKE_CXX_COMPILER=clang++ \
  -DCMAKE_CXX_FLAGS="-fsanitize=fuzzer-no-link $sanitizers -fno-omit-frame-pointer" \
  -DCMAKE_CXX_FLAGS_RELWITHDEBINFO="-O2 -gline-tables-only -DNDEBUG" \
  -DCMAKE_EXE_LINKER_FLAGS="-fsanitize=address,undefined" \
  -DCURVATURE_INPAINT_FUZZ=ON >/dev/null
cmake --build "$root/build-sanitize" -j2 --target vcg_ext_tests hole_fill_tests \
  fuzz_backend_responses fuzz_coarse_fill fuzz_filter_parameters fuzz_mesh_file
