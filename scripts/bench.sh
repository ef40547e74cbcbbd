#!/usr/bin/env bash
# Benchmark: seed 000's Φ125×112 program at 0.1 mm and 0.05 mm: from one `lathesim run` each,
# the floor (building the bar's level set once), simulate, mesh, render, writing and the whole
# run, as ratios to the floor; the STL at 0.05 mm; a Φ300×600 bar at 0.2 mm: peak memory
# against the grid's own. Then simulate against its floor (Google Benchmark). Then threads at 0.1 mm:
# parts/g76-m30x2 (M30×2×30 by G76, ten passes) per thread pass against its bar's floor, and
# a CAM-style thread of 3,600 chained G32 blocks of 0.1 mm: its time per pass. Then the parts/
# batch against the same programs run one `lathesim run` (or `check`) after another.
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/setup.sh lathesim lathesim_bench >/dev/null
part=parts/seed000-face-taper
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT

# The floor: building the bar as a level set once from its analytic distance (Google
# Benchmark: BM_Floor for seed 000's bar, BM_LargeBarFloor for the large one; its wall time and
# its process's CPU time, means of three), measured in this run just before the run it is the
# floor of.
floor_of() {  # benchmark, voxel in mm
  local um
  um=$(awk -v v="$2" 'BEGIN { printf "%d", v * 1000 + 0.5 }')
  build/lathesim_bench --benchmark_filter="^$1/$um/" --benchmark_format=csv 2>/dev/null |
    awk -F, -v name="\"$1/$um/" 'index($1, name) == 1 { print $3, $4 }'
}

# One `lathesim run` with every output: each step's own wall time from its report.json (steps
# overlap: stock.vdb is written while the part is meshed, the pictures drawn while the files
# are written), the whole process's wall and CPU time (user + sys) from outside, and each as a
# ratio to the floor's: wall to wall, CPU to CPU (the steadier on a shared machine).
field() { grep -o "\"$1\": [-0-9.e+]*" "$tmp/run/report.json" | head -1 | awk '{print $2}'; }
run_figures() {  # label, the floor's "wall CPU" seconds, then the run's arguments
  local label=$1 floor=$2 TIMEFORMAT='%R %U %S' times
  shift 2
  rm -rf "$tmp/run"
  times=$( { time build/lathesim run "$@" --out "$tmp/run" >/dev/null 2>&1; } 2>&1 )
  awk -v label="$label" -v floor="$floor" -v simulate="$(field simulate)" -v mesh="$(field mesh)" \
      -v render="$(field render)" -v write="$(field write)" -v times="$times" 'BEGIN {
    split(times, t, " ")
    split(floor, f, " ")
    n = split(simulate " " mesh " " render " " write " " t[1], step, " ")
    printf "%-10s %8.2f", label, f[1]
    for (i = 1; i <= n; i++) printf "  %7.2f %5.1fx", step[i], step[i] / f[1]
    printf "  %7.2f %5.1fx (floor %.2f)\n", t[2] + t[3], (t[2] + t[3]) / f[2], f[2]
  }'
}
memory_line() {
  awk -v peak="$(field peak_memory_mb)" -v grid="$(field grid_memory_mb)" \
    'BEGIN { printf "peak memory %.0f MB = %.2fx the grid'"'"'s own %.0f MB", peak, peak / grid, grid }'
}
volume_line() {
  awk -v mesh="$(field mesh_volume_mm3)" -v level="$(field final_volume_mm3)" -v tol="$(field volume_tolerance_mm3)" \
    'BEGIN { printf "final volume %.0f mm³, the mesh %+.1f mm³ from it (tolerance %.1f)", level, mesh - level, tol }'
}
header() {
  printf '%-10s %8s  %14s  %14s  %14s  %14s  %14s  %14s\n' voxel_mm floor_s simulate mesh render write "whole (wall)" "whole (cpu)"
}

echo "== lathesim run on $part, every output: seconds and ratio to the floor (building the bar's level set once, same run)"
header
for voxel in 0.1 0.05; do
  run_figures $voxel "$(floor_of BM_Floor $voxel)" $part/program.nc --setup $part/setup.toml --voxel $voxel
done
closed=closed
grep -q "not closed" "$tmp/run/report.json" && closed="NOT CLOSED"
echo "  at 0.05 mm: part.stl $(stat -c %s "$tmp/run/part.stl" | awk '{printf "%.1f", $1 / 1e6}') MB (asked < 50), $closed;" \
  "$(volume_line); $(memory_line)"

echo
echo "== a large bar: Φ300×600 at 0.2 mm (faced, then four G90 passes), every output"
cat > "$tmp/large.nc" <<'NC'
G00 X310 Z5 M3 S300;
G94 X0 Z0 F200;
G90 X290 Z-400 F300;
X280;
X270 Z-200;
X260;
G00 X320 Z50;
M30;
NC
cat > "$tmp/large.toml" <<'TOML'
[stock]
diameter = 300
length = 600
face_z = 2

[machine]
start = [400, 100]
initial_feed_mode = "per_minute"
travel_x = [-10.0, 420.0]
travel_z = [-700.0, 200.0]

[[tool]]
number = 1
polygon = [[0, 0], [10, 1], [12, 12], [1, 10]]
TOML
header
run_figures 0.2 "$(floor_of BM_LargeBarFloor 0.2)" "$tmp/large.nc" --setup "$tmp/large.toml" --voxel 0.2
echo "  $(memory_line) (asked <= 2.5x); $(volume_line)"

echo
echo "== simulate vs floor (Google Benchmark, mean of 3, same run)"
build/lathesim_bench --benchmark_filter='BM_Floor|BM_Simulate' --benchmark_format=csv 2>/dev/null > "$tmp/bench.csv"
awk -F, '
  /^"BM_Floor\/[0-9]+\/iterations/    { split($1, a, "/"); floor[a[2]] = $3; floorCpu[a[2]] = $4 }
  /^"BM_Simulate\/[0-9]+\/iterations/ { split($1, a, "/"); sim[a[2]] = $3; simCpu[a[2]] = $4 }
  END {
    # simulate = building the bar + every cut + the final volume; the cuts alone are
    # simulate minus one floor. The ratio is of wall times; the last column is the same
    # ratio of CPU time over all threads, steadier on a shared machine.
    printf "%-9s %10s %12s %16s %14s %20s\n", "voxel_mm", "floor_s", "simulate_s", "simulate/floor", "cuts/floor", "cpu simulate/floor"
    for (um = 200; um >= 100; um -= 100)
      printf "%-9s %10.3f %12.3f %16.2f %14.2f %20.2f\n", um / 1000, floor[um], sim[um], sim[um] / floor[um], (sim[um] - floor[um]) / floor[um], simCpu[um] / floorCpu[um]
  }' "$tmp/bench.csv"

echo
echo "== threads at 0.1 mm (Google Benchmark, same run): per thread pass against the bar's floor"
passes=$(build/lathesim expand parts/g76-m30x2/program.nc --setup parts/g76-m30x2/setup.toml | grep -c ',thread,')
build/lathesim_bench --benchmark_filter='G76|ShortPasses' --benchmark_format=csv 2>/dev/null > "$tmp/threads.csv"
awk -F, -v passes="$passes" '
  /^"BM_G76Floor/          { floor = $3; floorCpu = $4 }
  /^"BM_G76Relief/         { relief = $3; reliefCpu = $4 }
  /^"BM_G76Simulate/       { sim = $3; simCpu = $4 }
  /^"BM_ShortPassesFloor/  { shortFloor = $3; shortFloorCpu = $4 }
  /^"BM_ShortPasses\//     { short = $3; shortCpu = $4 }
  END {
    # A pass: (simulate − the relief cut before the G76) / passes; the ratio of CPU time over
    # all threads is the steadier one on a shared machine.
    printf "%-34s %10s %12s %14s %18s\n", "", "floor_s", "simulate_s", "per pass_s", "pass/floor (cpu)"
    printf "%-34s %10.3f %12.3f %14.4f %11.2f (%.2f)\n", "g76-m30x2, " passes " passes", floor, sim, (sim - relief) / passes, (sim - relief) / passes / floor, (simCpu - reliefCpu) / passes / floorCpu
    printf "%-34s %10.3f %12.3f %14.5f %11.3f (%.3f)\n", "3,600 chained G32 of 0.1 mm", shortFloor, short, (short - shortFloor) / 3600, (short - shortFloor) / 3600 / shortFloor, (shortCpu - shortFloorCpu) / 3600 / shortFloorCpu
  }' "$tmp/threads.csv"

echo
echo "== long programs at 0.1 mm (Google Benchmark, same run): a Φ50×80 bar's floor against programs of short moves"
build/lathesim_bench --benchmark_filter='BM_LongFloor|BM_Contour2000|BM_CamProgram' --benchmark_format=csv 2>/dev/null > "$tmp/long.csv"
build/lathesim_bench --benchmark_filter='BM_MoveLength' --benchmark_format=csv 2>/dev/null > "$tmp/moves.csv"
awk -F, '
  FNR == 1 { delete column; for (i = 1; i <= NF; i++) column[$i] = i; next }
  /^"BM_LongFloor/   { floor = $3; floorCpu = $4 }
  /^"BM_Contour2000/ { contour = $3; contourCpu = $4; contourMoves = $column["\"moves\""] }
  /^"BM_CamProgram/  { cam = $3; camCpu = $4; camMoves = $column["\"moves\""] }
  /^"BM_MoveLength/  { split($1, a, "/"); n++; length_um[n] = a[2]; moves[n] = $column["\"moves\""]
                       perMove[n] = $column["\"ms_per_move\""]; perMm[n] = $column["\"ms_per_mm\""] }
  END {
    # simulate includes building the bar once: per move is (simulate − floor) / moves.
    printf "%-44s %8s %10s %12s %16s %12s %20s\n", "", "moves", "floor_s", "simulate_s", "simulate/floor", "ms per move", "cpu simulate/floor"
    printf "%-44s %8d %10.3f %12.3f %16.2f %12.3f %20.2f\n", "2,000 G01 of 0.03 mm (wavy Φ44 on Φ50)", contourMoves, floor, contour, contour / floor, 1000 * (contour - floor) / contourMoves, contourCpu / floorCpu
    printf "%-44s %8d %10.3f %12.3f %16.2f %12.3f %20.2f\n", "CAM: G71 at 0.2 mm depth, lines and arcs", camMoves, floor, cam, cam / floor, 1000 * (cam - floor) / camMoves, camCpu / floorCpu
    print ""
    print "what a move costs against its length (one 3 mm deep cut over 12 mm of Z posted as moves of that length):"
    printf "%-10s %8s %14s %12s\n", "move_mm", "moves", "ms per move", "ms per mm"
    for (i = 1; i <= n; i++) printf "%-10.3f %8d %14.3f %12.2f\n", length_um[i] / 1000, moves[i], perMove[i], perMm[i]
  }' "$tmp/long.csv" "$tmp/moves.csv"

# The cores the machine gives right now: a CPU-bound task alone, then two at once (2.00 on
# a quiet 2-core machine; a shared one may give less, and no batch can beat that).
capacity() {
  local TIMEFORMAT=%R one two
  one=$( { time sh -c 'head -c 300000000 /dev/zero | sha256sum >/dev/null'; } 2>&1 )
  two=$( { time sh -c '(head -c 300000000 /dev/zero | sha256sum >/dev/null) & head -c 300000000 /dev/zero | sha256sum >/dev/null; wait'; } 2>&1 )
  awk -v a="$one" -v b="$two" 'BEGIN { printf "%.2f", 2 * a / b }'
}

echo
echo "== the parts/ batch against the same programs run one after another (no DISPLAY: each run starts its own Xvfb, the batch one)"
echo "cores available before: $(capacity)"
(
  unset DISPLAY
  # CPU time (user + sys) of each side and all it waited for, its Xvfb servers included: no
  # batch on C cores can take less than its CPU time / C, whatever its overhead.
  TIMEFORMAT='%U %S'
  start=$(date +%s.%N)
  { time for dir in parts/*/; do
    name=$(basename "$dir")
    command=(run "$dir/program.nc")  # as the batch does: check a part against the drawing beside it
    [ -f "$dir/drawing.toml" ] && command=(check "$dir/program.nc" --target "$dir/drawing.toml")
    build/lathesim "${command[@]}" --setup "$dir/setup.toml" --out "$tmp/one-by-one/$name" >/dev/null 2>&1 || true
  done; } 2> "$tmp/one-by-one.cpu"
  middle=$(date +%s.%N)
  { time build/lathesim batch parts --out "$tmp/batch" >/dev/null 2>&1 || true; } 2> "$tmp/batch.cpu"  # exit 1: seed004-o0006 alarms
  end=$(date +%s.%N)
  # Per job that ran: its wall time in the batch (start to result written), and the overhead
  # outside the command's own steps (report.json timing_s: parse … render): process start
  # and exit, the report, the thumbnail and the stamp.
  awk -v s="$start" -v m="$middle" -v e="$end" -v cores="$(nproc)" \
      -v oneCpu="$(awk '{ print $1 + $2 }' "$tmp/one-by-one.cpu")" -v batchCpu="$(awk '{ print $1 + $2 }' "$tmp/batch.cpu")" '
    /"elapsed_s"/  { v = $2; sub(/,$/, "", v); elapsed = v }
    /"pipeline_s"/ { v = $2; sub(/,$/, "", v); if (v != "null") { n++; wall[n] = elapsed; overhead += elapsed - v } }
    END {
      for (i = 2; i <= n; i++) for (j = i; j > 1 && wall[j] < wall[j - 1]; j--) { t = wall[j]; wall[j] = wall[j - 1]; wall[j - 1] = t }
      median = n % 2 ? wall[(n + 1) / 2] : (wall[n / 2] + wall[n / 2 + 1]) / 2
      printf "%-14s %9s %9s %6s %14s %12s %18s\n", "one_by_one_s", "batch_s", "speedup", "jobs", "median_job_s", "overhead_s", "overhead/median"
      printf "%-14.1f %9.1f %9.2f %6d %14.2f %12.3f %17.1f%%\n", m - s, e - m, (m - s) / (e - m), n, median, overhead / n, 100 * overhead / n / median
      # The batch cannot beat its CPU time spread over every core: the speed-up it could reach here.
      printf "%-14s %9s %9s %6s %24s\n", "one_by_one_cpu", "batch_cpu", "cores", "", "speedup_bound (cpu/cores)"
      printf "%-14.1f %9.1f %9d %6s %24.2f\n", oneCpu, batchCpu, cores, "", (m - s) / (batchCpu / cores)
    }' "$tmp/batch/summary.json"
)
echo "cores available after: $(capacity)"
