// Simulation speed against its floor, measured in one run so that both see the same
// machine load: the floor is building the bar's level set once from its analytic distance
// (no sweep can beat it); "simulate" is the whole simulation of seed 000's program —
// building the bar, every cut, and measuring the final volume.
//
// Voxel sizes are given in micrometres (Google Benchmark arguments are integers).

#include <benchmark/benchmark.h>

#include <algorithm>
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

// Threads: parts/g76-m30x2 (M30×2×30 by G76 on a Φ30 × 50 bar) at the given voxel. Its floor
// is that bar's; "relief" simulates the moves before the G76 (the relief grooved for the
// thread's run-out), so (simulate − relief) / passes is the cost of one thread pass.
struct Part {
  job::Setup setup;
  interp::Toolpath toolpath;
  sim::ToolOutlines tools;
};

Part loadPart(const std::string& name, const std::string& programText = "") {
  const std::string dir = std::string(LATHESIM_PARTS_DIR) + "/" + name + "/";
  Part p{*job::loadSetup(dir + "setup.toml").setup, {}, {}};
  std::string text = programText;
  if (text.empty()) {
    std::ifstream in(dir + "program.nc");
    std::ostringstream read;
    read << in.rdbuf();
    text = read.str();
  }
  for (const auto& tool : p.setup.tools) p.tools.emplace(tool.number, tool.outline);
  p.toolpath = interp::interpret(text, "program.nc", job::interpreterOptionsOf(p.setup)).toolpath;
  return p;
}

const Part& g76Part() {
  static const Part part = loadPart("g76-m30x2");
  return part;
}

void BM_G76Floor(benchmark::State& state) {
  for (auto _ : state) {
    sim::Stock stock(g76Part().setup.stock, state.range(0) / 1000.0);
    benchmark::DoNotOptimize(stock.activeVoxelCount());
  }
}

void BM_G76Relief(benchmark::State& state) {
  interp::Toolpath relief = g76Part().toolpath;
  const auto firstThread = std::find_if(relief.moves.begin(), relief.moves.end(),
                                        [](const auto& m) { return m.kind == interp::MoveKind::Thread; });
  // Up to the G76 block: its first pass's approach may be a dog-leg of two rapids.
  const int g76Line = firstThread->line;
  const auto g76 = std::find_if(relief.moves.begin(), relief.moves.end(),
                                [g76Line](const auto& m) { return m.line == g76Line; });
  relief.moves.erase(g76, relief.moves.end());
  for (auto _ : state) {
    sim::Stock stock(g76Part().setup.stock, state.range(0) / 1000.0);
    sim::simulate(relief, g76Part().tools, stock);
    benchmark::DoNotOptimize(stock.volumeMm3());
  }
}

void BM_G76Simulate(benchmark::State& state) {
  for (auto _ : state) {
    sim::Stock stock(g76Part().setup.stock, state.range(0) / 1000.0);
    sim::simulate(g76Part().toolpath, g76Part().tools, stock);
    benchmark::DoNotOptimize(stock.volumeMm3());
  }
}

// A CAM-posted thread: the same bar and tool, twelve passes each written as 300 chained G32
// blocks of 0.1 mm (3,600 thread moves), from Z0 to Z-30 at depths 0.1 … 1.2.
const Part& shortPassesPart() {
  static const Part part = [] {
    std::ostringstream program;
    program << "G99 M03 S500\nT0101\n";
    for (int level = 1; level <= 12; ++level) {
      program << "G00 X32 Z0\nX" << 30 - 0.2 * level << "\n";
      for (int step = 1; step <= 300; ++step) program << "G32 Z" << -0.1 * step << " F2\n";
      program << "G00 X32\n";
    }
    program << "M30\n";
    return loadPart("g76-m30x2", program.str());
  }();
  return part;
}

void BM_ShortPassesFloor(benchmark::State& state) {
  for (auto _ : state) {
    sim::Stock stock(shortPassesPart().setup.stock, state.range(0) / 1000.0);
    benchmark::DoNotOptimize(stock.activeVoxelCount());
  }
}

void BM_ShortPasses(benchmark::State& state) {
  for (auto _ : state) {
    sim::Stock stock(shortPassesPart().setup.stock, state.range(0) / 1000.0);
    sim::simulate(shortPassesPart().toolpath, shortPassesPart().tools, stock);
    benchmark::DoNotOptimize(stock.volumeMm3());
  }
}

// Wall time decides; the CPU column is the whole process's (all threads), which is steadier
// than wall time when other work shares the machine.
BENCHMARK(BM_Floor)->Arg(200)->Arg(100)->Unit(benchmark::kSecond)->UseRealTime()->MeasureProcessCPUTime()->Iterations(3);
BENCHMARK(BM_Simulate)->Arg(200)->Arg(100)->Unit(benchmark::kSecond)->UseRealTime()->MeasureProcessCPUTime()->Iterations(3);
BENCHMARK(BM_G76Floor)->Arg(100)->Unit(benchmark::kSecond)->UseRealTime()->MeasureProcessCPUTime()->Iterations(3);
BENCHMARK(BM_G76Relief)->Arg(100)->Unit(benchmark::kSecond)->UseRealTime()->MeasureProcessCPUTime()->Iterations(3);
BENCHMARK(BM_G76Simulate)->Arg(100)->Unit(benchmark::kSecond)->UseRealTime()->MeasureProcessCPUTime()->Iterations(3);
BENCHMARK(BM_ShortPassesFloor)->Arg(100)->Unit(benchmark::kSecond)->UseRealTime()->MeasureProcessCPUTime()->Iterations(1);
BENCHMARK(BM_ShortPasses)->Arg(100)->Unit(benchmark::kSecond)->UseRealTime()->MeasureProcessCPUTime()->Iterations(1);

}  // namespace

BENCHMARK_MAIN();
