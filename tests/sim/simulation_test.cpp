// A simulation fed straight from the interpreter (sim/simulate.hpp), its block rows spooled
// (sim/block_rows.hpp), finds what simulate() finds in the whole toolpath: the cycle starts
// and thread passes it reads beside the moves are the ones the interpreter records as it goes.

#include "sim/simulate.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "interp/interpreter.hpp"
#include "sim/block_rows.hpp"
#include "test_moves.hpp"

namespace lathesim::sim {
namespace {

// Cycles, a rapid into the bar (a collision), a subprogram after M30, a thread pass, and
// blocks that make several moves.
constexpr const char* kProgram =
    "G99 M03 S500\nG00 X44 Z2\nG90 X36 Z-20 F0.2\nX32\nG00 X30 Z-5\nG90 X28 Z-10 F0.2\nG00 X44 Z2\n"
    "M98 P1000\nG00 X44 Z2\nG92 X30 Z-15 F1.5\nG00 X60 Z10\nM30\nO1000\nG01 X34 Z-25 F0.1\nG00 X44\nM99\n";

interp::InterpreterOptions options() {
  interp::InterpreterOptions options;
  options.startPosition = {30, 10};
  options.toolNumbers = {1};
  return options;
}

TEST(Simulation, FedFromTheInterpreterFindsWhatTheWholeToolpathGives) {
  const interp::InterpretResult whole = interp::interpret(kProgram, "streamed.nc", options());
  ASSERT_TRUE(whole.ok());
  Stock wholeStock({40.0, 30.0, 0.0}, 0.5);
  const SimulationResult expected = simulate(whole.toolpath, test::squareTool(2.0), wholeStock);

  Stock stock({40.0, 30.0, 0.0}, 0.5);
  const interp::Toolpath none;
  Simulation simulation(none, test::squareTool(2.0), stock);
  SpooledBlockRows rows;
  simulation.sendBlocksTo([&](const BlockRemoval& row) { rows.add(row); });
  const interp::InterpretResult streamed = interp::interpret(kProgram, "streamed.nc", options(), simulation);
  ASSERT_TRUE(streamed.ok());
  const SimulationResult result = simulation.finish(streamed.toolpath);

  EXPECT_TRUE(result.blocks.empty());  // they went to the spool
  std::vector<BlockRemoval> spooled;
  rows.forEach([&](const BlockRemoval& row) { spooled.push_back(row); });
  ASSERT_EQ(spooled.size(), expected.blocks.size());
  for (std::size_t b = 0; b < spooled.size(); ++b) {
    EXPECT_EQ(spooled[b].block, expected.blocks[b].block);
    EXPECT_EQ(spooled[b].line, expected.blocks[b].line);
    // A thread's removal is summed in parallel: the last digit may differ.
    EXPECT_NEAR(spooled[b].removedMm3, expected.blocks[b].removedMm3, 1e-9 * (1 + expected.blocks[b].removedMm3));
    EXPECT_EQ(spooled[b].timeS, expected.blocks[b].timeS);
  }
  ASSERT_EQ(result.warnings.size(), expected.warnings.size());
  for (std::size_t w = 0; w < result.warnings.size(); ++w) EXPECT_EQ(result.warnings[w].message, expected.warnings[w].message);
  ASSERT_EQ(result.collisions.size(), expected.collisions.size());
  EXPECT_FALSE(expected.collisions.empty());  // G00 X30 Z-5 into the bar
  EXPECT_EQ(result.collisions[0].line, expected.collisions[0].line);
  EXPECT_NEAR(stock.volumeMm3(), wholeStock.volumeMm3(), 1e-6);
  EXPECT_TRUE(std::any_of(whole.toolpath.moves.begin(), whole.toolpath.moves.end(),
                          [](const interp::Move& m) { return m.kind == interp::MoveKind::Thread; }));
}

// The subprogram, written after M30, faces the bar to Z-2 (down to X4: not parting it off)
// before the main program's G90 starts at X20 Z-1: in air then, though inside the bar as it
// was. Its blocks come after the G90's in the text; both routes check the start when the G90
// runs, and find no fault.
TEST(Simulation, ChecksACycleStartAfterASubprogramWhenTheCycleRuns) {
  const std::string program = "G99 M03 S500\nG00 X44 Z2\nM98 P1000\nG00 X20 Z-1\nG90 X18 Z-10 F0.2\n"
                              "G00 X60 Z10\nM30\nO1000\nG00 X44 Z-2\nG01 X4 F0.1\nG00 X44\nZ2\nM99\n";
  const Stock bar({40.0, 30.0, 0.0}, 0.5);
  ASSERT_LT(bar.signedDistanceAt(RZ(10, -1)), -0.9);  // 1 mm in the bar before the facing

  const interp::InterpretResult whole = interp::interpret(program, "subprogram.nc", options());
  ASSERT_TRUE(whole.ok());
  ASSERT_EQ(whole.toolpath.cycleStarts.size(), 1u);
  Stock wholeStock({40.0, 30.0, 0.0}, 0.5);
  EXPECT_TRUE(simulate(whole.toolpath, test::squareTool(2.0), wholeStock).warnings.empty());

  Stock stock({40.0, 30.0, 0.0}, 0.5);
  const interp::Toolpath none;
  Simulation simulation(none, test::squareTool(2.0), stock);
  const interp::InterpretResult streamed = interp::interpret(program, "subprogram.nc", options(), simulation);
  ASSERT_TRUE(streamed.ok());
  EXPECT_TRUE(simulation.finish(streamed.toolpath).warnings.empty());
}

}  // namespace
}  // namespace lathesim::sim
