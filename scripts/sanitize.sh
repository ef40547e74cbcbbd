#!/usr/bin/env bash
# The test suite built with AddressSanitizer and UndefinedBehaviorSanitizer (gcc's) in
# build-asan/, and run: any invalid access, leak of ours or undefined behaviour fails the
# test it happens in. Leaks inside the system libraries (Mesa's llvmpipe, X11, fontconfig,
# VTK's and OpenVDB's one-time registries) are suppressed by scripts/lsan.supp, each
# entry saying why; nothing of lathesim's own is.
#
#   scripts/sanitize.sh [CTEST ARGS…]     e.g. -R 'interp|job' to run part of it
#
# SANITIZE_JOBS sets the build's parallelism (default: the CPUs).
set -euo pipefail
cd "$(dirname "$0")/.."

build=build-asan
flags="-fsanitize=address,undefined -fno-sanitize-recover=undefined -fno-omit-frame-pointer"
cmake -S . -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo -DLATHESIM_BENCHMARKS=OFF \
  -DCMAKE_CXX_FLAGS="$flags" -DCMAKE_C_FLAGS="$flags" -DCMAKE_EXE_LINKER_FLAGS="-fsanitize=address,undefined" \
  -DCMAKE_CXX_FLAGS_RELWITHDEBINFO="-O1 -g" >/dev/null
cmake --build "$build" --parallel "${SANITIZE_JOBS:-$(nproc)}"

export ASAN_OPTIONS="detect_leaks=1:detect_stack_use_after_return=0:check_initialization_order=1:strict_init_order=1"
export UBSAN_OPTIONS="print_stacktrace=1:halt_on_error=1"
export LSAN_OPTIONS="suppressions=$PWD/scripts/lsan.supp:print_suppressions=0"
ctest --test-dir "$build" --output-on-failure --parallel "$(nproc)" --timeout 900 "$@"
