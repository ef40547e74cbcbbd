#!/usr/bin/env bash
# Runs every bundled part (parts/*) with two lathesim binaries and says whether their outputs
# are the same: report.json (its timings, peak memory and the last digits of
# blocks[].removed_volume_mm3 aside, which vary from run to run), toolpath.csv, part.stl,
# what was printed and the exit status. Each part is run twice: with its setup (check against
# its drawing when it has one), and with no setup at all (the machine, the bar and the tools
# read from the program).
#   scripts/same_outputs.sh OLD_LATHESIM NEW_LATHESIM [WORK_DIR]
# Exit status 0: the same; 1: a difference (printed).
set -u
old=$1 new=$2
work=${3:-$(mktemp -d)}
root=$(cd "$(dirname "$0")/.." && pwd)

# report.json without what varies between runs of the same binary.
steady_report() {
  python3 - "$1" <<'PY'
import json, sys
def scrub(v, key="", in_blocks=False):
    if isinstance(v, dict):
        return {k: scrub(x, k, in_blocks) for k, x in v.items()
                if not k.startswith("timing") and k != "peak_memory_mb"}  # measured, as the timings
    if isinstance(v, list):
        return [scrub(x, key, in_blocks or key == "blocks") for x in v]
    if in_blocks and key == "removed_volume_mm3" and isinstance(v, float):
        return float(f"{v:.9g}")
    return v
print(json.dumps(scrub(json.load(open(sys.argv[1]))), indent=1, sort_keys=True))
PY
}

run_all() {  # binary, output folder
  local bin=$1 out=$2
  for dir in "$root"/parts/*/; do
    local name=$(basename "$dir")
    local command=(run "$dir/program.nc")
    [ -f "$dir/drawing.toml" ] && command=(check "$dir/program.nc" --target "$dir/drawing.toml")
    for way in setup bare; do
      local to="$out/$name-$way" extra=()
      [ "$way" = setup ] && extra=(--setup "$dir/setup.toml")
      mkdir -p "$to"
      (cd "$root" && "$bin" "${command[@]}" "${extra[@]}" --outputs stl csv --out "$to/out" \
         >"$to/stdout" 2>"$to/stderr"; echo $? >"$to/status")
      [ -f "$to/out/report.json" ] && steady_report "$to/out/report.json" >"$to/report.steady" && rm "$to/out/report.json"
      # The run's own timings in what it prints.
      sed -i -E -e "s#$out#OUT#g" -e 's/[0-9]+(\.[0-9]+)? ?(ms|s)\b/T/g' "$to/stdout" "$to/stderr"
    done
  done
}

run_all "$old" "$work/old"
run_all "$new" "$work/new"
if diff -r "$work/old" "$work/new"; then
  echo "same outputs: $(ls "$work/old" | wc -l) runs of $(ls -d "$root"/parts/*/ | wc -l) parts ($work)"
else
  echo "outputs differ ($work)"
  exit 1
fi
