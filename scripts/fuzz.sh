#!/usr/bin/env bash
# The libFuzzer harnesses (tests/fuzz): built with clang, ASan and UBSan in build-fuzz/ (only
# geometry, interp and the readers: no OpenVDB, no VTK), seeded from parts/ and the
# bad-program corpus.
#
#   scripts/fuzz.sh build                      configure and build build-fuzz/
#   scripts/fuzz.sh smoke [RUNS]               every harness RUNS inputs (default 2000) from its
#                                              seeds, fixed random seed: the test command's step
#   scripts/fuzz.sh run HARNESS [OPTIONS…]     one harness on its growing corpus
#                                              (build-fuzz/corpus/HARNESS), libFuzzer OPTIONS as
#                                              given, e.g. -max_total_time=3600
#
# Harnesses: lexer interpreter setup drawing iso_codes. A crash is written to build-fuzz/
# as crash-<hash>; replay it with build-fuzz/tests/fuzz/HARNESS_fuzz FILE.
set -euo pipefail
cd "$(dirname "$0")/.."

harnesses=(lexer interpreter setup drawing iso_codes)
build=build-fuzz
flags="-fsanitize=fuzzer-no-link,address,undefined -fno-sanitize-recover=undefined -fno-omit-frame-pointer -gline-tables-only -O1"

build() {
  cmake -S . -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo -DLATHESIM_FUZZ_ONLY=ON \
    -DCMAKE_C_COMPILER=clang -DCMAKE_CXX_COMPILER=clang++ \
    -DCMAKE_CXX_FLAGS="$flags" -DCMAKE_CXX_FLAGS_RELWITHDEBINFO="" >/dev/null
  cmake --build "$build" --parallel "${FUZZ_JOBS:-$(nproc)}"
}

# The seed corpus of a harness, made afresh from the repository's files.
seeds() {
  local harness=$1 dir="$build/seeds/$1"
  rm -rf "$dir" && mkdir -p "$dir"
  local n=0
  case $harness in
    lexer)
      for f in parts/*/*.nc tests/interp/bad/*.nc; do cp "$f" "$dir/$((n++))"; done ;;
    interpreter)  # four choice bytes (dialect, control, block skip, travel), then the program
      for f in parts/*/*.nc tests/interp/bad/*.nc; do
        { printf '\0\0\0\0'; cat "$f"; } >"$dir/$((n++))"
      done ;;
    setup)
      for f in parts/*/setup.toml; do cp "$f" "$dir/$((n++))"; done ;;
    drawing)
      for f in parts/*/drawing.toml; do cp "$f" "$dir/$((n++))"; done ;;
    iso_codes)  # a choice byte (the tip), then INSERT|HOLDER or a comment naming a tool
      while IFS= read -r line; do printf '\n%s' "$line" >"$dir/$((n++))"; done <tests/fuzz/seeds/iso_codes.txt ;;
  esac
  echo "$dir"
}

options() {  # what every run gets: the G-code words as a dictionary, limits on time and memory (and
            # the interpreter without the entropic schedule)
  local harness=$1
  local own=()
  [[ $harness == lexer || $harness == interpreter ]] && own=(-dict=tests/fuzz/gcode.dict)
  # The interpreter's inputs reach ~30 000 coverage features: libFuzzer's entropic schedule
  # then spends most of each run counting them (perf: 55-67% of the time in
  # InputCorpus::UpdateFeatureFrequency). Without it the harness ran 3.5 times as many inputs
  # in the same 20 s from the same corpus, and reached more coverage.
  [[ $harness == interpreter ]] && own+=(-entropic=0)
  echo "${own[@]}" -timeout=10 -rss_limit_mb=2048 -max_len=8192 -print_final_stats=1
}

case "${1:-smoke}" in
  build) build ;;
  smoke)
    runs=${2:-2000}
    build
    for h in "${harnesses[@]}"; do
      echo "fuzz smoke: $h, $runs runs"
      # shellcheck disable=SC2046
      "$build/tests/fuzz/${h}_fuzz" $(options "$h") -runs="$runs" -seed=1 "$(seeds "$h")" 2>"$build/smoke-$h.log" ||
        { tail -n 60 "$build/smoke-$h.log"; echo "fuzz smoke: $h FAILED (log: $build/smoke-$h.log)"; exit 1; }
      grep -E '^stat::number_of_executed_units|^Done' "$build/smoke-$h.log" | tr '\n' ' '; echo
    done
    echo "fuzz smoke: ${#harnesses[@]} harnesses passed" ;;
  run)
    h=${2:?harness: ${harnesses[*]}}
    shift 2
    [[ -x "$build/tests/fuzz/${h}_fuzz" ]] || build
    mkdir -p "$build/corpus/$h"
    # shellcheck disable=SC2046
    exec "$build/tests/fuzz/${h}_fuzz" $(options "$h") -artifact_prefix="$build/" "$@" "$build/corpus/$h" "$(seeds "$h")" ;;
  *) sed -n '2,16p' "$0"; exit 2 ;;
esac
