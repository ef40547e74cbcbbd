// Simulation speed against its floor, measured in one run so that both see the same
// machine load: the floor is building the bar's level set once from its analytic distance
// (no sweep can beat it); "simulate" is the whole simulation of seed 000's program —
// building the bar, every cut, and measuring the final volume.
//
// Voxel sizes are given in micrometres (Google Benchmark arguments are integers).

#include <benchmark/benchmark.h>

#include <fstream>
#include <sstream>

#include "job/job.hpp"
#include "job/setup.hpp"
#include "interp/interpreter.hpp"
#include "sim/simulate.hpp"

namespace {

using namespace lathesim;

const std::string kPart = std::string(LATHESIM_PARTS_DIR) + "/seed000-face-taper/";

struct Seed000 {
  job::Setup setup;
  interp::Toolpath toolpath;
  sim::ToolOutlines tools;
};

const Seed000& seed000() {
  static const Seed000 loaded = [] {
    Seed000 s{*job::loadSetup(kPart + "setup.toml").setup, {}, {}};
    std::ifstream in(kPart + "program.nc");
    std::ostringstream text;
    text << in.rdbuf();
    for (const auto& tool : s.setup.tools) s.tools.emplace(tool.number, tool.outline);
    s.toolpath = interp::interpret(text.str(), "program.nc", job::interpreterOptionsOf(s.setup)).toolpath;
    return s;
  }();
  return loaded;
}

void BM_Floor(benchmark::State& state) {
  const double voxel = state.range(0) / 1000.0;
  for (auto _ : state) {
    sim::Stock stock(seed000().setup.stock, voxel);
    benchmark::DoNotOptimize(stock.activeVoxelCount());
  }
}

void BM_Simulate(benchmark::State& state) {
  const double voxel = state.range(0) / 1000.0;
  const Seed000& part = seed000();
  for (auto _ : state) {
    sim::Stock stock(part.setup.stock, voxel);
    sim::simulate(part.toolpath, part.tools, stock);
    benchmark::DoNotOptimize(stock.volumeMm3());
  }
}

// Wall time decides; the CPU column is the whole process's (all threads), which is steadier
// than wall time when other work shares the machine.
BENCHMARK(BM_Floor)->Arg(200)->Arg(100)->Unit(benchmark::kSecond)->UseRealTime()->MeasureProcessCPUTime()->Iterations(3);
BENCHMARK(BM_Simulate)->Arg(200)->Arg(100)->Unit(benchmark::kSecond)->UseRealTime()->MeasureProcessCPUTime()->Iterations(3);

}  // namespace

BENCHMARK_MAIN();
