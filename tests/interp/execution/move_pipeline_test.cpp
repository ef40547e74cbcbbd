// The moves stream from the interpreter in pieces (interp/execution/move_pipeline.hpp): the
// toolpath is the same whether it passes whole or cut after every move it may be cut after,
// and a long program's moves reach the sink while it runs, never more than a window held.

#include <gtest/gtest.h>

#include <limits>
#include <sstream>
#include <string>

#include <fmt/format.h>

#include "../test_support.hpp"
#include "interp/motion/cycle_time.hpp"
#include "interp/output/toolpath_csv.hpp"

namespace lathesim::interp {
namespace {

InterpreterOptions pipelineOptions() {
  InterpreterOptions options = test::under("fanuc-0i-t");
  options.control.rapidPath = RapidPath::NonLinear;  // rapids in two legs: the pieces grow
  options.offsets[1] = ToolOffset{0, 0, 0.8, 3, 0, 0};
  options.offsets[2] = ToolOffset{0.4, -0.2, 0.4, 2, 0.1, 0.05};  // a shift carried between pieces
  return options;
}

// A program with everything that looks at a neighbouring move: dog-leg rapids, a chamfer and a
// corner radius, dwells before, inside and at the end of a G42 chain with an arc, an offset change,
// a G71/G70 cycle, a subprogram repeated, parts catcher commands. `k` moves its numbers.
std::string programWithNeighbours(int k) {
  return fmt::format(
      "G99 T0101 M03 S1000\n"
      "G00 X{0}. Z2.\n"
      "G01 Z-5. F0.2\n"
      "G01 X{1}. ,C1.\n"
      "G01 Z-15. ,R2.\n"
      "G01 X{2}.\n"
      "G04 X0.5\n"
      "G42 G01 X{3}. Z-16.\n"
      "G01 Z-24.\n"
      "G04 X0.2\n"
      "G02 X{4}. Z-29. R5.\n"
      "G01 Z-33.\n"
      "G40\n"
      "G04 X0.1\n"  // a dwell between the chain and its cancel move
      "G01 X{5}. Z-34.\n"
      "G04 X0.1\n"
      "T0202\n"
      "G00 X{6}. Z3.\n"
      "G71 U1.5 R0.5\n"
      "G71 P10 Q20 U0.4 W0.1 F0.25\n"
      "N10 G00 X{7}.\n"
      "G01 Z-10. F0.1\n"
      "X{8}. Z-20.\n"
      "N20 X{6}.\n"
      "G70 P10 Q20\n"
      "G00 X{6}. Z-25.\n"
      "M36\n"
      "M98 P{9}1000\n"
      "G00 X{6}.\n"
      "M37\n"
      "G00 X{6}. Z50.\n"
      "M30\n"
      "O1000\n"
      "G01 U-4. F0.1\n"
      "G00 U4. W-1.\n"
      "M99\n",
      40 + k, 50 + k, 56 + k, 30 + k, 40 + k, 60 + k, 66 + k, 20 + k, 30 + k, 2 + k);
}

struct Streamed {
  InterpretResult result;
  std::string csv;
};

Streamed interpretInWindow(const std::string& program, std::size_t window) {
  InterpreterOptions options = pipelineOptions();
  options.moveWindow = window;
  Streamed streamed{interpret(program, "t.nc", options), {}};
  (void)assignMoveTimes(streamed.result.toolpath, options.machine);
  std::ostringstream csv;
  writeToolpathCsv(streamed.result.toolpath, csv);
  streamed.csv = csv.str();
  return streamed;
}

TEST(MovePipeline, TheToolpathIsTheSameInPiecesOfAnySize) {
  for (int k = 0; k < 6; ++k) {
    const std::string program = programWithNeighbours(k);
    const Streamed whole = interpretInWindow(program, std::numeric_limits<std::size_t>::max());
    ASSERT_TRUE(whole.result.ok()) << whole.result.diagnostics[0].message;
    ASSERT_GT(whole.result.toolpath.moves.size(), 60u);
    for (const std::size_t window : {1, 2, 3, 5, 13}) {
      SCOPED_TRACE(testing::Message() << "k " << k << ", window " << window);
      const Streamed pieces = interpretInWindow(program, window);
      ASSERT_TRUE(pieces.result.ok()) << pieces.result.diagnostics[0].message;
      EXPECT_EQ(pieces.csv, whole.csv);
      ASSERT_EQ(pieces.result.toolpath.partsCatcher.size(), 2u);
      for (std::size_t i = 0; i < 2; ++i)
        EXPECT_EQ(pieces.result.toolpath.partsCatcher[i].movesBefore, whole.result.toolpath.partsCatcher[i].movesBefore);
      EXPECT_EQ(pieces.result.toolpath.cycleStarts.size(), whole.result.toolpath.cycleStarts.size());
      EXPECT_EQ(pieces.result.diagnostics.size(), whole.result.diagnostics.size());
    }
  }
}

TEST(MovePipeline, APartsCatcherCommandCountsTheMovesAsTheyEndUp) {
  // From (100, 200) the rapid to X50 Z2 = (25, 2) moves both axes: two legs (rapid_path.hpp).
  // M36 acts after both; the G01 X20 beside M37 is one move, so M37 comes after three.
  InterpreterOptions options = test::defaultOptions();
  options.control.rapidPath = RapidPath::NonLinear;
  const auto result = interpret("G00 X50 Z2\nM36\nG01 X20 F0.1\nM37\nM30\n", "t.nc", options);
  ASSERT_TRUE(result.ok()) << result.diagnostics[0].message;
  ASSERT_EQ(result.toolpath.moves.size(), 3u);
  ASSERT_EQ(result.toolpath.partsCatcher.size(), 2u);
  EXPECT_EQ(result.toolpath.partsCatcher[0].movesBefore, 2u);
  EXPECT_EQ(result.toolpath.partsCatcher[1].movesBefore, 3u);
}

class CountingSink final : public MoveSink {
 public:
  void take(Move) override { ++count; }
  std::size_t count = 0;
};

// `blocks` one-move G01 blocks, and after them `tail`.
std::string straightBlocks(int blocks, const std::string& tail) {
  std::string program = "G99 M03 S800\nG00 X40 Z2\n";
  for (int i = 0; i < blocks; ++i) program += fmt::format("G01 X{} Z{:.3f} F0.1\n", i % 2 ? 40 : 42, -0.01 * i);
  return program + tail;
}

TEST(MovePipeline, MovesReachTheSinkWhileTheProgramRuns) {
  // An error after the moves: they have reached the sink already, all but fewer than a
  // window's; held until the end, none would have.
  constexpr int kBlocks = 20000;
  for (const std::size_t window : {std::size_t{1}, std::size_t{100}, kDefaultMoveWindow}) {
    SCOPED_TRACE(testing::Message() << "window " << window);
    InterpreterOptions options = test::defaultOptions();
    options.moveWindow = window;
    CountingSink sink;
    const auto result = interpret(straightBlocks(kBlocks, "G999\n"), "t.nc", options, sink);
    ASSERT_FALSE(result.ok());
    EXPECT_EQ(result.diagnostics[0].line, kBlocks + 3);
    EXPECT_LE(sink.count, kBlocks + 1u);
    EXPECT_GE(sink.count + window, kBlocks + 1u);  // the rapid and the cuts
  }
}

TEST(MovePipeline, ACycleAndRepeatedSubprogramsStreamToo) {
  // A G71 cycle, then a subprogram repeated 3000 times (two moves each, the rapid in two legs),
  // then an error: every piece but the last has gone to the sink.
  const std::string body =
      "G99 M03 S800\nG00 X44 Z2\nG71 U1.5 R0.5\nG71 P10 Q20 U0.4 W0.1 F0.25\nN10 G00 X20\nG01 Z-10 F0.1\n"
      "X30 Z-20\nN20 X44\nM98 P30001000\n";
  const std::string subprogram = "O1000\nG01 U-2. F0.1\nG00 U2. W-0.01\nM99\n";
  InterpreterOptions options = test::defaultOptions();
  options.control.rapidPath = RapidPath::NonLinear;
  const auto whole = interpret(body + "M30\n" + subprogram, "t.nc", options);
  ASSERT_TRUE(whole.ok()) << whole.diagnostics[0].message;
  ASSERT_GT(whole.toolpath.moves.size(), 9000u);
  CountingSink sink;
  const auto failed = interpret(body + "G999\nM30\n" + subprogram, "t.nc", options, sink);
  ASSERT_FALSE(failed.ok());
  EXPECT_LE(sink.count, whole.toolpath.moves.size());
  EXPECT_GE(sink.count + 2 * kDefaultMoveWindow, whole.toolpath.moves.size());
}

}  // namespace
}  // namespace lathesim::interp
