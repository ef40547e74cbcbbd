#!/usr/bin/env bash
# Benchmark: seed 000's Φ125×112 program at 0.2 mm and 0.1 mm. Prints, from one run, the
# CLI's wall time, peak memory and STL size, and simulate against its floor (building the
# bar's level set once from its analytic distance) with their ratio.
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/setup.sh >/dev/null
part=parts/seed000-face-taper
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT

echo "== lathesim run on $part (end to end: simulate, mesh, STL, PNG, VDB, report)"
printf '%-9s %10s %14s %12s\n' voxel_mm wall_s peak_memory_mb stl_mb
for voxel in 0.2 0.1; do
  start=$(date +%s.%N)
  build/lathesim run $part/program.nc --setup $part/setup.toml --voxel $voxel --out "$tmp/$voxel" >/dev/null
  end=$(date +%s.%N)
  peak=$(grep -o '"peak_memory_mb": [0-9.]*' "$tmp/$voxel/report.json" | awk '{print $2}')
  stl=$(stat -c %s "$tmp/$voxel/part.stl")
  awk -v v=$voxel -v s=$start -v e=$end -v p=$peak -v b=$stl 'BEGIN{printf "%-9s %10.2f %14.0f %12.1f\n", v, e-s, p, b/1e6}'
done

echo
echo "== simulate vs floor (Google Benchmark, mean of 3, same run)"
build/lathesim_bench --benchmark_format=csv 2>/dev/null > "$tmp/bench.csv"
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
