#!/usr/bin/env bash
# The test suite built with AddressSanitizer and UndefinedBehaviorSanitizer (gcc's) in
# build-asan/, and run: an invalid access, a leak or undefined behaviour fails the test it
# happens in. Leaks inside system libraries are suppressed by scripts/lsan.supp, each entry
# saying why; nothing of lathesim's own is.
#
#   scripts/sanitize.sh          the whole suite (ctest)
#   scripts/sanitize.sh ci       what the test command runs (scripts/test.sh), within CI's
#                                time: every geometry, interp, setup and measure test, the
#                                turning writes' route (sim_table_tests: the revolved table,
#                                its air voxels and the level set built from it), and the
#                                command's bad-input, exit-status and output-safety tests
#
# SANITIZE_JOBS sets the build's parallelism (default: the CPUs).
set -euo pipefail
cd "$(dirname "$0")/.."

scope=${1:-all}
build=build-asan
flags="-fsanitize=address,undefined -fno-sanitize-recover=undefined -fno-omit-frame-pointer"
# Line tables (-g1) are all a sanitizer's stack trace needs: full debug info made the build a
# quarter slower (sim/stock.cpp: 55 s with -g, 44 s with -g1). The tests' own sources are
# assertions over the code under test, so they are compiled unoptimised (half the compile
# time under ASan) while the code under test keeps -O1.
cmake -S . -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo -DLATHESIM_BENCHMARKS=OFF \
  -DCMAKE_CXX_FLAGS="$flags" -DCMAKE_C_FLAGS="$flags" -DCMAKE_EXE_LINKER_FLAGS="-fsanitize=address,undefined" \
  -DCMAKE_CXX_FLAGS_RELWITHDEBINFO="-O1 -g1" -DLATHESIM_TEST_COMPILE_OPTIONS="-O0" >/dev/null

export ASAN_OPTIONS="detect_leaks=1:check_initialization_order=1:strict_init_order=1"
export UBSAN_OPTIONS="print_stacktrace=1:halt_on_error=1"
export LSAN_OPTIONS="suppressions=$PWD/scripts/lsan.supp:print_suppressions=0"
# Mesa's software GL driver (swrast_dri.so, which VTK's GLX window loads) is dlclose'd when the
# window's display closes, and memory that only its globals point at then looks lost: LSan
# reported two 56-byte callocs of the driver as leaks of an address no module holds any more
# (shown as the test binary's). Loaded for the whole process, the driver's globals stay roots
# and nothing is reported: no suppression, and a leak of ours in rendering is still caught.
driver=$(compgen -G "/usr/lib/*/dri/swrast_dri.so" | head -n 1 || true)
if [[ -n $driver ]]; then
  export LD_PRELOAD="$driver${LD_PRELOAD:+ $LD_PRELOAD}"
  ASAN_OPTIONS+=":verify_asan_link_order=0"  # the driver comes before libasan
fi
jobs=${SANITIZE_JOBS:-$(nproc)}

if [[ $scope == all ]]; then
  cmake --build "$build" --parallel "$jobs"
  exec ctest --test-dir "$build" --output-on-failure --parallel "$(nproc)" --timeout 900
fi

cmake --build "$build" --parallel "$jobs" --target geometry_tests interp_tests setup_tests measure_tests sim_table_tests command_tests lathesim
# The suites run as many at a time as there are CPUs (most of them run on one thread), the
# longest first; each one's output is kept in build-asan/sanitize-NAME.log and shown when it fails.
run_suite() {  # NAME BINARY [ARGUMENTS…]
  local name=$1 log="$build/sanitize-$1.log"
  shift
  if "$@" --gtest_brief=1 >"$log" 2>&1; then
    echo "sanitize: $name passed ($(grep -Eo '[0-9]+ tests? from' "$log" | head -n 1 | cut -d' ' -f1) tests)"
  else
    cat "$log"
    echo "sanitize: $name FAILED (log: $log)"
    return 1
  fi
}
export -f run_suite
export build
# The full disk test runs the command seven times over; the file size limit test already
# takes the same failure path under the sanitizers.
xargs -P "$jobs" -L 1 bash -c 'run_suite "$@"' _ <<SUITES
sim_table $build/tests/sim/sim_table_tests
measure $build/tests/measure/measure_tests
interp $build/tests/interp/interp_tests
command $build/tests/app/command_tests --gtest_filter=-OutputFailure.FullDisk*
setup $build/tests/setup/setup_tests
geometry $build/tests/geometry/geometry_tests
SUITES
