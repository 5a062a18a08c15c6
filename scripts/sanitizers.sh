#!/usr/bin/env bash
# Builds the whole suite with AddressSanitizer + UndefinedBehaviorSanitizer in
# ./build-asan and runs every test there. Any report fails the run: ASan
# aborts on its first error, and -fno-sanitize-recover makes UBSan do the same.
#
#   bash scripts/sanitizers.sh [ctest options]
#
# -O1 -g keeps the build and the suite short while keeping stack traces exact.
# The Python tests run Debian's (uninstrumented) python3, which loads the
# instrumented ShadeLab modules: the sanitizer runtimes must then come first,
# so those tests start through `env LD_PRELOAD=libasan:libubsan`.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/install-deps.sh

flags="-O1 -g -fsanitize=address,undefined -fno-omit-frame-pointer -fno-sanitize-recover=undefined"
preload="$(g++ -print-file-name=libasan.so):$(g++ -print-file-name=libubsan.so)"
cmake -S . -B build-asan --log-level=WARNING \
  -DCMAKE_BUILD_TYPE=Sanitize \
  -DCMAKE_C_FLAGS_SANITIZE="$flags" -DCMAKE_CXX_FLAGS_SANITIZE="$flags" \
  -DCMAKE_EXE_LINKER_FLAGS_SANITIZE="-fsanitize=address,undefined" \
  -DCMAKE_SHARED_LINKER_FLAGS_SANITIZE="-fsanitize=address,undefined" \
  -DCMAKE_MODULE_LINKER_FLAGS_SANITIZE="-fsanitize=address,undefined" \
  -DSHADELAB_WERROR=ON -DSHADELAB_BUILD_BENCHMARKS=OFF \
  "-DSHADELAB_TEST_PYTHON=env;LD_PRELOAD=${preload};/usr/bin/python3"
cmake --build build-asan --parallel "$(nproc)"

# Leak checking is off: Mesa's GL driver, loaded for every render and
# unloaded before exit, leaves 240 bytes per process that LeakSanitizer can
# only attribute to "<unknown module>" (so no suppression can name it), and
# CPython with VTK's wrapping keeps its objects alive until exit by design.
# Every other ASan check (heap, stack, use after free/return, initialization
# order) and every UBSan check stays on and fatal. strict_string_checks stays
# at its default (off): with it, libxkbcommon's strndup of a counted,
# unterminated X atom name (Qt's start-up, every viewer test) is reported.
export ASAN_OPTIONS="detect_leaks=0:abort_on_error=1:detect_stack_use_after_return=1:check_initialization_order=1"
export UBSAN_OPTIONS="print_stacktrace=1:halt_on_error=1"
cd build-asan
# install.* builds a downstream project against the installed libraries with
# its own, uninstrumented flags, which cannot link instrumented libraries; the
# main build runs it.
bash ../scripts/with-display.sh ctest --output-on-failure --parallel "$(nproc)" -E '^install\.' "$@"
