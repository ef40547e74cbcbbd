// A toolpath longer than the move limit is refused with the figure, at the line of the move
// that passes it — however the moves come: blocks, nested subprogram repeats, dog-leg legs.

#include <gtest/gtest.h>

#include "interp/interpreter.hpp"
#include "test_support.hpp"

namespace lathesim::interp {
namespace {

// Exactly the limit passes; one more move is refused at the block that makes it.
TEST(MoveLimit, OneMoveMoreThanTheLimitIsRefusedAtItsLine) {
  for (const std::size_t limit : {1u, 2u, 5u}) {
    SCOPED_TRACE(limit);
    std::string program = "G98 F500\n";
    for (std::size_t n = 0; n < limit; ++n) program += n % 2 ? "G01 U2\n" : "G01 U-2\n";
    InterpreterOptions options = test::defaultOptions();
    options.maxMoves = limit;
    const InterpretResult exact = test::run(program + "M30\n", options);
    ASSERT_TRUE(exact.ok()) << exact.diagnostics.front().message;
    EXPECT_EQ(exact.toolpath.moves.size(), limit);
    const InterpretResult over = test::run(program + "G01 W-1\nM30\n", options);
    test::expectError(over, static_cast<int>(limit) + 2, 1,
                      "the program makes more than " + std::to_string(limit) + " moves (the limit) by this block");
  }
}

// Four subprograms nested, each repeated 9999 times, would ask for 10^16 moves: refused at
// the limit, at once, instead of filling the memory.
TEST(MoveLimit, NestedRepeatsStopAtTheLimit) {
  const std::string program =
      "G98 F500\nM98 P1001 L9999\nM30\n"
      "O1001\nM98 P1002 L9999\nM99\n"
      "O1002\nM98 P1003 L9999\nM99\n"
      "O1003\nM98 P1004 L9999\nM99\n"
      "O1004\nG01 U-1\nG01 U1\nM99\n";
  InterpreterOptions options = test::defaultOptions();
  options.maxMoves = 1000;
  test::expectError(test::run(program, options), 14, 1, "more than 1000 moves");  // G01 U-1 of O1004
}

// Under non-linear positioning a diagonal rapid is two moves, and both count.
TEST(MoveLimit, DogLegLegsCount) {
  InterpreterOptions options = test::defaultOptions();
  options.control.rapidPath = RapidPath::NonLinear;
  options.maxMoves = 1;
  test::expectError(test::run("G00 X50 Z50\nM30\n", options), 1, 1, "more than 1 moves");
  options.maxMoves = 2;
  EXPECT_TRUE(test::run("G00 X50 Z50\nM30\n", options).ok());
}

// A pecking cycle is refused at its block as soon as its pecks pass the limit, before they are
// all made: the fuzzer's G74 pecking 0.07 mm over 5.7·10^22 mm (W5666…6.1) filled 1.9 GB, and
// pecks far below a coordinate's precision (1 µm at Z-10^12) never arrive.
TEST(MoveLimit, PeckingCyclesStopAtTheLimit) {
  InterpreterOptions options = test::defaultOptions();
  options.maxMoves = 1000;
  test::expectError(test::run("G00 X0 Z2\nG74 R1\nG74 Z-1000000 Q1000 F0.1\n", options), 3, 1,
                    "more than 1000 moves");  // 10^6 pecks of 1 mm
  test::expectError(test::run("G00 X0 Z2\nG74 R1\nG74 Z-1000000000000 Q1 F0.1\n", options), 3, 1,
                    "more than 1000 moves");
  test::expectError(test::run("G00 X40 Z-5\nG75 R1\nG75 X0 Z-1000000 P1000 Q1000 F0.1\n", options), 3, 1,
                    "more than 1000 moves");  // 10^6 plunges
  test::expectError(test::run("G00 X0 Z5\nG83 Z-1000000 R-3 Q1000 F0.1\n", options), 2, 1, "more than 1000 moves");
  test::expectError(test::run("G00 X0 Z5\nG83 Z-1000000000000 R-3 Q1 F0.1\n", options), 2, 1,
                    "more than 1000 moves");
  // Within the limit the same cycles run: 100 pecks of 1 mm.
  EXPECT_TRUE(test::run("G00 X0 Z2\nG74 R1\nG74 Z-98 Q1000 F0.1\n", options).ok());
  EXPECT_TRUE(test::run("G00 X0 Z5\nG83 Z-97 R-3 Q1000 F0.1\n", options).ok());
}

}  // namespace
}  // namespace lathesim::interp
