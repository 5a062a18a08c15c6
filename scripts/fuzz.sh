#!/usr/bin/env bash
# Builds ShadeLab's libFuzzer targets (tests/fuzz; clang with AddressSanitizer
# and UndefinedBehaviorSanitizer) in build-fuzz/ and runs each for a fixed
# time, one after the other, starting from its seed corpus in
# tests/fuzz/seeds/. Fails on the first crash, timeout, out-of-memory or
# sanitizer report; the input that caused it is left in build-fuzz/crashes/.
#
#   bash scripts/fuzz.sh [SECONDS_PER_TARGET [TARGET ...]]
#
# SECONDS_PER_TARGET defaults to 15 (15 targets: about 4 minutes of fuzzing
# after the build). Every target runs unless some are named.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/install-deps.sh clang libclang-rt-14-dev
seconds=${1:-15}
shift || true

build=build-fuzz
CC=clang CXX=clang++ cmake -S . -B "$build" -DCMAKE_BUILD_TYPE=RelWithDebInfo -DSHADELAB_FUZZ=ON \
  -DSHADELAB_BUILD_TESTING=OFF -DSHADELAB_BUILD_BENCHMARKS=OFF \
  "-DCMAKE_CXX_FLAGS=-fsanitize=fuzzer-no-link,address,undefined" \
  "-DCMAKE_C_FLAGS=-fsanitize=fuzzer-no-link,address,undefined" \
  --log-level=WARNING > /dev/null
cmake --build "$build" -j"$(nproc)" --target shadelab_fuzz_targets

targets=("$@")
if [ ${#targets[@]} -eq 0 ]; then
  targets=($(ls tests/fuzz/seeds))
fi
mkdir -p "$build/corpus" "$build/crashes"
# Leaks are not checked: VTK 9.1's readers and OpenImageIO leak on many of
# their error paths (vtkPLY's header comments, vtkXMLReader's array
# iterators, OpenImageIO's PNG error strings), which would drown ShadeLab's.
export ASAN_OPTIONS=detect_leaks=0:allocator_may_return_null=1
export UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1
for target in "${targets[@]}"; do
  corpus="$build/corpus/$target"
  mkdir -p "$corpus"
  echo "fuzz: $target for ${seconds} s"
  # New inputs go to the work corpus; the seeds in the repository stay as they are.
  # A fixed seed: the same corpus and binary walk the same inputs in the
  # same order, so a CI run repeats what ran here rather than exploring anew.
  "$build/bin/$target" -seed=1 -max_total_time="$seconds" -timeout=10 -rss_limit_mb=2048 -max_len=65536 \
    -print_final_stats=1 -artifact_prefix="$build/crashes/$target-" "$corpus" "tests/fuzz/seeds/$target" \
    2> "$build/$target.log" || { tail -60 "$build/$target.log"; echo "fuzz: $target failed" >&2; exit 1; }
  grep -E "stat::number_of_executed_units|stat::peak_rss_mb" "$build/$target.log" | tr '\n' ' '
  echo
done
