// Simulation speed against its floor, measured in one run so that both see the same
// machine load: the floor is building the bar's level set once from its analytic distance
// (no sweep can beat it); "simulate" is the whole simulation of seed 000's program —
// building the bar, every cut, and measuring the final volume.
//
// Voxel sizes are given in micrometres (Google Benchmark arguments are integers).

#include <benchmark/benchmark.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <fstream>
#include <map>
#include <memory>
#include <sstream>

#include "setup/job.hpp"
#include "setup/setup.hpp"
#include "interp/interpreter.hpp"
#include "sim/move_sweep.hpp"
#include "sim/simulate.hpp"
#include "sim/stock_grid.hpp"
#include "sim/table_grid.hpp"

namespace {

using namespace lathesim;

const std::string kPart = std::string(LATHESIM_PARTS_DIR) + "/seed000-face-taper/";

struct Seed000 {
  setup::Setup setup;
  interp::Toolpath toolpath;
  sim::ToolOutlines tools;
};

const Seed000& seed000() {
  static const Seed000 loaded = [] {
    Seed000 s{*setup::loadSetup(kPart + "setup.toml").setup, {}, {}};
    std::ifstream in(kPart + "program.nc");
    std::ostringstream text;
    text << in.rdbuf();
    for (const auto& tool : s.setup.tools) s.tools.emplace(tool.number, tool.outline);
    s.toolpath = interp::interpret(text.str(), "program.nc", setup::interpreterOptionsOf(s.setup)).toolpath;
    return s;
  }();
  return loaded;
}

// The floor: the bar's level set, built voxel by voxel (a stock in the revolved table would
// build its level set only when read).
void buildFloor(benchmark::State& state, const sim::StockSpec& bar) {
  const double voxel = state.range(0) / 1000.0;
  for (auto _ : state) {
    sim::Stock stock(bar, voxel, sim::RevolvedWrites::Voxels);
    benchmark::DoNotOptimize(stock.activeVoxelCount());
  }
}

void BM_Floor(benchmark::State& state) { buildFloor(state, seed000().setup.stock); }
// bench.sh's large bar: Φ300×600, its face at Z2.
void BM_LargeBarFloor(benchmark::State& state) { buildFloor(state, sim::StockSpec{300.0, 600.0, 2.0}); }

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
  setup::Setup setup;
  interp::Toolpath toolpath;
  sim::ToolOutlines tools;
};

Part loadPart(const std::string& name, const std::string& programText = "") {
  const std::string dir = std::string(LATHESIM_PARTS_DIR) + "/" + name + "/";
  Part p{*setup::loadSetup(dir + "setup.toml").setup, {}, {}};
  std::string text = programText;
  if (text.empty()) {
    std::ifstream in(dir + "program.nc");
    std::ostringstream read;
    read << in.rdbuf();
    text = read.str();
  }
  for (const auto& tool : p.setup.tools) p.tools.emplace(tool.number, tool.outline);
  p.toolpath = interp::interpret(text, "program.nc", setup::interpreterOptionsOf(p.setup)).toolpath;
  return p;
}

const Part& g76Part() {
  static const Part part = loadPart("g76-m30x2");
  return part;
}

void BM_G76Floor(benchmark::State& state) { buildFloor(state, g76Part().setup.stock); }

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

void BM_ShortPassesFloor(benchmark::State& state) { buildFloor(state, shortPassesPart().setup.stock); }

void BM_ShortPasses(benchmark::State& state) {
  for (auto _ : state) {
    sim::Stock stock(shortPassesPart().setup.stock, state.range(0) / 1000.0);
    sim::simulate(shortPassesPart().toolpath, shortPassesPart().tools, stock);
    benchmark::DoNotOptimize(stock.volumeMm3());
  }
}

// Long programs on a Φ50 × 80 bar (the default tool): what a move costs against what it
// changes. The floor is building that bar once.
Part programPart(const std::string& program) {
  Part p{*setup::parseSetup("[stock]\ndiameter = 50\nlength = 80\nface_z = 0\n", "bench.toml").setup, {}, {}};
  for (const auto& tool : p.setup.tools) p.tools.emplace(tool.number, tool.outline);
  p.toolpath = interp::interpret(program, "bench.nc", setup::interpreterOptionsOf(p.setup)).toolpath;
  return p;
}

// The profile of the long programs: a wavy diameter (mm) at Z (0 ≥ z ≥ −60).
double wavyDiameter(double baseMm, double slope, double amplitudeMm, double z) {
  return baseMm + slope * -z + amplitudeMm * std::sin(2.0 * M_PI * z / 7.5);
}

// A finishing contour as CAM posts it: `moves` G01 segments of `stepMm` each, a wavy Φ44 from
// Z0 leftwards, cut from the Φ50 bar.
std::string contourProgram(int moves, double stepMm) {
  std::ostringstream program;
  program << "G99 M03 S1000\nG00 X44.2 Z1.\nG01 Z0 F0.1\n";
  program.setf(std::ios::fixed);
  program.precision(4);
  for (int k = 1; k <= moves; ++k) {
    const double z = -stepMm * k;
    program << "G01 X" << wavyDiameter(44.0, 0.0, 0.2, z) << " Z" << z << "\n";
  }
  program << "G00 X52.\nZ1.\nM30\n";
  return program.str();
}

const Part& contourPart() {
  static const Part part = programPart(contourProgram(2000, 0.03));
  return part;
}

// A CAM-style program of about 5,000 moves: G71 roughing with a 0.2 mm depth of cut to a
// 150-block profile of short lines and arcs (Φ30 at Z0 rising to Φ48 at Z-60), then a
// semi-finishing and a finishing pass as CAM posts them, 2,300 short lines and arcs each.
const Part& camPart() {
  static const Part part = [] {
    std::ostringstream program;
    program.setf(std::ios::fixed);
    program.precision(4);
    program << "G99 M03 S1200\nG00 X52. Z2.\nG71 U0.2 R0.1\nG71 P100 Q200 U0.2 W0.05 F0.25\nN100 G00 X30.\nG01 Z0\n";
    for (int k = 1; k <= 150; ++k) {
      const double z = -0.4 * k;
      program << (k % 2 ? "G01 X" : "G02 X") << wavyDiameter(30.0, 0.3, 0.0, z) << " Z" << z << (k % 2 ? "\n" : " R3.\n");
    }
    program << "N200 G01 X52.\n";
    for (const double allowance : {0.2, 0.0}) {
      program << "G00 X" << 30.0 + allowance << " Z1.\nG01 Z0 F0.1\n";
      for (int k = 1; k <= 2300; ++k) {
        const double z = -0.026 * k;
        program << (k % 4 ? "G01 X" : "G03 X") << wavyDiameter(30.0 + allowance, 0.3, 0.1, z) << " Z" << z
                << (k % 4 ? "\n" : " R2.\n");
      }
      program << "G01 X52.\nG00 Z2.\n";
    }
    program << "G00 X60. Z10.\nM30\n";
    return programPart(program.str());
  }();
  return part;
}

void BM_LongFloor(benchmark::State& state) {
  buildFloor(state, contourPart().setup.stock);
  state.counters["moves"] = 0;  // the same columns as the programs' (CSV has one header)
}

void simulatePart(benchmark::State& state, const Part& part) {
  for (auto _ : state) {
    sim::Stock stock(part.setup.stock, state.range(0) / 1000.0);
    sim::simulate(part.toolpath, part.tools, stock);
    benchmark::DoNotOptimize(stock.volumeMm3());
  }
  state.counters["moves"] = static_cast<double>(part.toolpath.moves.size());
}

void BM_Contour2000(benchmark::State& state) { simulatePart(state, contourPart()); }
void BM_CamProgram(benchmark::State& state) { simulatePart(state, camPart()); }

// What a move costs against the region it sweeps: the same 3 mm deep cut over 12 mm of Z
// (Φ50 to a wavy Φ44) at 0.1 mm, posted as moves of the given length (µm). Per move, it should
// follow the move's length, not the tool's outline or the bar.
void BM_MoveLength(benchmark::State& state) {
  const double stepMm = state.range(0) / 1000.0;
  const int moves = static_cast<int>(std::lround(12.0 / stepMm));
  const Part part = programPart(contourProgram(moves, stepMm));
  double cutsS = 0.0;
  for (auto _ : state) {
    sim::Stock stock(part.setup.stock, 0.1);
    const auto start = std::chrono::steady_clock::now();
    sim::simulate(part.toolpath, part.tools, stock);
    cutsS += std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  }
  const double perMoveS = cutsS / static_cast<double>(state.iterations()) / moves;
  state.counters["moves"] = moves;
  state.counters["ms_per_move"] = 1e3 * perMoveS;
  state.counters["ms_per_mm"] = 1e3 * perMoveS / stepMm;
}

// The whole level set built from the revolved table (sim/table_grid.hpp) against the route it
// replaces, the bar's level set built and the table's changes settled into it: on seed 000's
// bar after seed 000's cuts, written into its table move by move (its air voxels with it: both
// routes read the table alone). Both start from a copy of that table
// (not timed), and neither's grid is freed within the timing.
struct CutBar {
  RevolvedRegion bar;  // as Stock's constructor writes it: the section mirrored across the axis
  std::unique_ptr<sim::RevolvedTable> table;
};

const CutBar& seed000CutBar(double voxel) {
  static std::map<double, CutBar> cut;
  CutBar& c = cut[voxel];
  if (c.table) return c;
  const sim::StockSpec& spec = seed000().setup.stock;
  const double r = spec.diameterMm / 2.0, back = spec.faceZMm - spec.lengthMm;
  const std::vector<RZ> section{{-r, back}, {r, back}, {r, spec.faceZMm}, {-r, spec.faceZMm}};
  c.bar = RevolvedRegion({ConvexPolygon::hullOf(section)});
  sim::StockGrid stock(spec, voxel);
  stock.startTable(c.bar);
  for (const interp::Move& move : seed000().toolpath.moves) {
    const std::vector<ConvexPolygon> pieces = sim::sweptPieces(move, seed000().tools.at(move.tool), voxel);
    if (!pieces.empty()) stock.table->write(RevolvedRegion(pieces), false);
  }
  c.table = std::move(stock.table);
  return c;
}

// Runs `build` on a fresh stock holding a copy of the cut table, an empty grid beside it.
template <class Build>
void buildFromCutTable(benchmark::State& state, Build build) {
  const double voxel = state.range(0) / 1000.0;
  const CutBar& cut = seed000CutBar(voxel);
  std::unique_ptr<sim::StockGrid> stock;
  for (auto _ : state) {
    state.PauseTiming();
    stock.reset();
    stock = std::make_unique<sim::StockGrid>(seed000().setup.stock, voxel);
    stock->table = std::make_unique<sim::RevolvedTable>(*cut.table);
    state.ResumeTiming();
    build(*stock, cut.bar);
    benchmark::DoNotOptimize(stock->grid.get());
    benchmark::ClobberMemory();
  }
  state.counters["leaves"] = static_cast<double>(stock->grid->tree().leafCount());
  state.counters["grid_mb"] = static_cast<double>(stock->grid->tree().memUsage()) / 1e6;
}

void BM_GridBarThenSettle(benchmark::State& state) {
  buildFromCutTable(state, [](sim::StockGrid& stock, const RevolvedRegion& bar) {
    sim::writeRegion(stock, bar, sim::RegionWrite::Add);
    stock.settle();
  });
}

void BM_GridFromTable(benchmark::State& state) {
  buildFromCutTable(state, [](sim::StockGrid& stock, const RevolvedRegion&) { sim::writeGridFromTable(stock); });
}

// Wall time decides; the CPU column is the whole process's (all threads), which is steadier
// than wall time when other work shares the machine.
BENCHMARK(BM_Floor)->Arg(200)->Arg(100)->Arg(50)->Unit(benchmark::kSecond)->UseRealTime()->MeasureProcessCPUTime()->Iterations(3);
BENCHMARK(BM_LargeBarFloor)->Arg(200)->Unit(benchmark::kSecond)->UseRealTime()->MeasureProcessCPUTime()->Iterations(3);
BENCHMARK(BM_Simulate)->Arg(200)->Arg(100)->Unit(benchmark::kSecond)->UseRealTime()->MeasureProcessCPUTime()->Iterations(3);
BENCHMARK(BM_G76Floor)->Arg(100)->Unit(benchmark::kSecond)->UseRealTime()->MeasureProcessCPUTime()->Iterations(3);
BENCHMARK(BM_G76Relief)->Arg(100)->Unit(benchmark::kSecond)->UseRealTime()->MeasureProcessCPUTime()->Iterations(3);
BENCHMARK(BM_G76Simulate)->Arg(100)->Unit(benchmark::kSecond)->UseRealTime()->MeasureProcessCPUTime()->Iterations(3);
BENCHMARK(BM_ShortPassesFloor)->Arg(100)->Unit(benchmark::kSecond)->UseRealTime()->MeasureProcessCPUTime()->Iterations(1);
BENCHMARK(BM_ShortPasses)->Arg(100)->Unit(benchmark::kSecond)->UseRealTime()->MeasureProcessCPUTime()->Iterations(1);
BENCHMARK(BM_LongFloor)->Arg(100)->Unit(benchmark::kSecond)->UseRealTime()->MeasureProcessCPUTime()->Iterations(3);
BENCHMARK(BM_Contour2000)->Arg(100)->Unit(benchmark::kSecond)->UseRealTime()->MeasureProcessCPUTime()->Iterations(1);
BENCHMARK(BM_CamProgram)->Arg(100)->Unit(benchmark::kSecond)->UseRealTime()->MeasureProcessCPUTime()->Iterations(1);
BENCHMARK(BM_GridBarThenSettle)->Arg(100)->Arg(50)->Unit(benchmark::kSecond)->UseRealTime()->MeasureProcessCPUTime()->Iterations(3);
BENCHMARK(BM_GridFromTable)->Arg(100)->Arg(50)->Unit(benchmark::kSecond)->UseRealTime()->MeasureProcessCPUTime()->Iterations(3);
BENCHMARK(BM_MoveLength)->Arg(10)->Arg(30)->Arg(100)->Arg(300)->Arg(1000)->Arg(3000)->Unit(benchmark::kSecond)->UseRealTime()->Iterations(1);

}  // namespace

BENCHMARK_MAIN();
