#!/usr/bin/env bash
# Peak memory of `lathesim expand` (or `run`, or `check`) on long programs: 100 000, 300 000 and
# 1 000 000 one-move G01 blocks, and 1 000 000 blocks with a G71/G70 cycle and a subprogram
# called every 1000 blocks. Prints each program's size, blocks, rows (expand: the CSV's; run and
# check: report.json's blocks), wall time and peak RSS (max resident set, /usr/bin/time -v).
# Usage: scripts/long_program_memory.sh [LATHESIM [expand | run [OUTPUTS] | check]]
#   (default build/lathesim expand; run simulates at 0.5 mm voxels and writes OUTPUTS, default
#   report: `--outputs OUTPUTS`, or with OUTPUTS `default` what a plain run writes: the pictures,
#   report.html, toolpath.vtp…; check does the same against a Φ41 drawing, with its default
#   outputs, the deviation pictures too). BLOCKS="100000 300000" measures those lengths only, and
#   CALLS=no leaves out the program with G71 and M98 (a default run of a million blocks takes
#   minutes).
set -euo pipefail
cd "$(dirname "$0")/.."
lathesim=${1:-build/lathesim}
command=${2:-expand}
outputs=${3:-report}
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT

straight() {  # blocks
  awk -v n="$1" 'BEGIN {
    print "G99 M03 S800"; print "G00 X40 Z2"
    for (i = 0; i < n; i++) printf "G01 X%d Z-%d F0.1\n", i % 2 ? 40 : 42, i % 50
    print "M30" }'
}
cycles_and_calls() {  # blocks
  awk -v n="$1" 'BEGIN {
    print "G99 M03 S800"; print "G00 X44 Z2"
    print "G71 U1.5 R0.5"; print "G71 P10 Q20 U0.4 W0.1 F0.25"
    print "N10 G00 X20"; print "G01 Z-10 F0.1"; print "X30 Z-20"; print "N20 X44"
    print "G70 P10 Q20"; print "G00 X44 Z2"
    for (i = 0; i < n - 16; i++)
      if (i % 1000 == 999) print "M98 P21000"
      else printf "G01 X%d Z-%d F0.1\n", i % 2 ? 40 : 42, i % 50
    print "M30"; print "O1000"; print "G01 U-2. F0.1"; print "G00 U2."; print "M99" }'
}

# check's drawing: a Φ41 shaft from Z0 to Z-110 on the default Φ125×112 bar, closed via the axis.
printf '[[profile]]\nx = 41\nz = 0\n[[profile]]\nx = 41\nz = -110\n' >"$tmp/drawing.toml"

rows() {  # what the command wrote for each move or block
  if [ "$command" = expand ]; then echo $(( $(wc -l <"$tmp/out.csv") - 1 ))
  else grep -c '"removed_volume_mm3"' "$tmp/run/report.json"; fi
}

measure() {  # label, program file
  local out
  if [ "$command" = expand ]; then
    /usr/bin/time -v "$lathesim" expand "$2" >"$tmp/out.csv" 2>"$tmp/time.txt" || { tail -3 "$tmp/time.txt"; exit 1; }
  else
    rm -rf "$tmp/run"
    local args=(run "$2" --voxel 0.5 --out "$tmp/run")
    [ "$command" = check ] && args=(check "$2" --target "$tmp/drawing.toml" --voxel 0.5 --out "$tmp/run")
    [ "$command" = run ] && [ "$outputs" != default ] && args+=(--outputs "$outputs")
    local status=0
    /usr/bin/time -v "$lathesim" "${args[@]}" >/dev/null 2>"$tmp/time.txt" || status=$?
    # check's exit status 3: the part is not within the drawing's tolerance, as expected here
    if [ $status != 0 ] && ! { [ "$command" = check ] && [ $status = 3 ]; }; then tail -3 "$tmp/time.txt"; exit 1; fi
  fi
  out=$(awk -F': ' '/Maximum resident/ {rss = $2} /Elapsed/ {wall = $2} END {print rss, wall}' "$tmp/time.txt")
  printf '%-22s %5.0f MB program %8d blocks %8d rows  %s s  peak %6.1f MB\n' "$1" \
    "$(( $(stat -c %s "$2") ))e-6" "$(wc -l <"$2")" "$(rows)" \
    "$(echo "$out" | cut -d' ' -f2)" "$(echo "$out" | awk '{print $1 / 1024}')"
}

for n in ${BLOCKS:-100000 300000 1000000}; do
  straight "$n" >"$tmp/straight-$n.nc"
  measure "$n one-move blocks" "$tmp/straight-$n.nc"
done
[ "${CALLS:-yes}" = no ] && exit 0
cycles_and_calls 1000000 >"$tmp/calls.nc"
measure "1M with G71 and M98" "$tmp/calls.nc"
