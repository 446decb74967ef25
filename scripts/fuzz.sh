#!/usr/bin/env bash
# Fuzzes the .node/xy parsers and the triangulators with libFuzzer (clang++, AddressSanitizer,
# UndefinedBehaviorSanitizer); every result is checked with the exact validator.
#   bash scripts/fuzz.sh [SECONDS]   (default 60, shared by the two targets)
# Builds in build-fuzz. The corpus grows in build-fuzz/corpus/<target> (seeded from
# tests/fuzz/corpus/<target>); a crash is saved in build-fuzz/artifacts/ and the script fails:
# add the input to tests/test_regressions.cpp, fix the bug, and run again.
set -euo pipefail
cd "$(dirname "$0")/.."
seconds=${1:-60}
half=$(( seconds / 2 > 0 ? seconds / 2 : 1 ))
cmake -S . -B build-fuzz -DDT_FUZZ=ON -DCMAKE_CXX_COMPILER=clang++ \
      -DCMAKE_BUILD_TYPE=RelWithDebInfo > /dev/null
cmake --build build-fuzz -j"$(nproc)" --target fuzz_parse fuzz_triangulate
rm -rf build-fuzz/artifacts
mkdir -p build-fuzz/artifacts
export UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1
for target in fuzz_parse fuzz_triangulate; do
  corpus=build-fuzz/corpus/$target
  mkdir -p "$corpus"
  seeds=tests/fuzz/corpus/$target
  echo "=== $target: ${half} s"
  # -max_len: inputs above a few kB only repeat what small ones find.
  set +e
  build-fuzz/tests/fuzz/$target "$corpus" "$seeds" -max_total_time="$half" -max_len=4096 \
      -timeout=20 -rss_limit_mb=2048 -print_final_stats=1 \
      -artifact_prefix=build-fuzz/artifacts/$target- 2>&1 | grep -v '^#[0-9]'
  status=${PIPESTATUS[0]}
  set -e
  if [ "$status" -ne 0 ] || ls build-fuzz/artifacts/$target-* > /dev/null 2>&1; then
    echo "fuzz: $target found a failing input:" build-fuzz/artifacts/$target-*
    exit 1
  fi
done
echo "fuzz: no failure in ${seconds} s"
