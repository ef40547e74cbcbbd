#!/usr/bin/env bash
# Sets up (packages + every build target: the command, the test suite, the benchmarks; see
# setup.sh) and runs the whole test suite, then the sanitizer
# step (scripts/sanitize.sh ci: the interpreter, readers and command under ASan and UBSan)
# and the fuzz smoke step (scripts/fuzz.sh smoke: every libFuzzer harness a fixed number of
# runs from its seeds).
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/setup.sh all
ctest --test-dir build --output-on-failure --parallel "$(nproc)" --timeout 600
scripts/sanitize.sh ci
scripts/fuzz.sh smoke 2000
