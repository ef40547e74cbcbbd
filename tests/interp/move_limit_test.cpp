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


// G71/G72 roughing levels and G73 passes are counted as they are made: a contour coordinate
// of 10^21 mm (the fuzzer's G72 W4. over Z-2111…1.: 5·10^20 levels) or a Δd of 1 µm is refused
// at the contour's P block before the levels fill memory.
TEST(MoveLimit, RoughingCyclesStopAtTheLimit) {
  InterpreterOptions options = test::defaultOptions();
  options.maxMoves = 1000;
  const std::string g71 = "G00 X62. Z2.\nG71 U1. R0.5\nG71 P10 Q30 U0.4 W0.2 F0.25\n";
  const std::string g72 = "G00 X62. Z2.\nG72 W4. R0.5\nG72 P10 Q30 U0.4 W0.2 F0.25\n";
  for (const std::string far : {"1000000.", "1000000000000.", "2111111111111111111111."}) {
    SCOPED_TRACE(far);
    // Type I: the levels step to the P block's far X (G71) or Z (G72).
    test::expectError(test::run(g71 + "N10 G00 X-" + far + "\nN20 G01 Z-10.\nN30 X62.\nM30\n", options), 4, 1,
                      "G71 would make more than 1000 moves (the limit)");
    test::expectError(test::run(g72 + "N10 G00 Z-" + far + "\nN20 G01 X40.\nN30 Z-10.\nM30\n", options), 4, 1,
                      "G72 would make more than 1000 moves (the limit)");
    // Type II: down to a pocket's far bottom.
    test::expectError(
        test::run(g71 + "N10 G00 X40. Z2.\nN20 G01 Z-10.\nN25 X-" + far + " Z-11.\nN30 X62. Z-12.\nM30\n", options),
        4, 1, "G71 would make more than 1000 moves (the limit)");
  }
  // A depth of cut of 1 µm over 11 mm: 10,800 levels, in either dialect's form.
  test::expectError(test::run("G00 X62. Z2.\nG71 U0.001 R0.5\nG71 P10 Q30 U0.4 W0.2 F0.25\n"
                              "N10 G00 X40.\nN20 G01 Z-10.\nN30 X62.\nM30\n",
                              options),
                    4, 1, "G71 would make more than 1000 moves");
  InterpreterOptions haas = test::haas();
  haas.maxMoves = 1000;
  test::expectError(test::run("G00 X62. Z2.\nG71 P10 Q30 D0.001 U0.4 W0.2 F0.25\n"
                              "N10 G00 X40.\nN20 G01 Z-10.\nN30 X62.\nM30\n",
                              haas),
                    3, 1, "G71 would make more than 1000 moves");
}

// At the limit, by hand. G71 U1. R0.5 from A = (31, 2) (radii) to B = (20, 2) with Δu/2 0.2:
// A′ = (31.2, 2.2), B′ = (20.2, 2.2), 11 mm to cut, levels k = 1 … 10 of four legs (infeed,
// cut, 45° retract, back in Z) = 40, plus A → A′, the infeed to B′, the semi-finishing pass's
// two blocks and C′ → A = 45; with the G00 before, 46 moves. G73 U3. W0. R3 over the same
// three blocks: three passes of four legs (to A_k, then the shifted ns, N20, N30) and the
// rapid back to A = 13; 14 moves.
TEST(MoveLimit, RoughingCyclesAtTheLimitByHand) {
  const std::string contour = "N10 G00 X40.\nN20 G01 Z-10.\nN30 X62.\nM30\n";
  const std::string g71 = "G00 X62. Z2.\nG71 U1. R0.5\nG71 P10 Q30 U0.4 W0.2 F0.25\n" + contour;
  const std::string g73 = "G00 X62. Z2.\nG73 U3. W0. R3\nG73 P10 Q30 U0.4 W0.2 F0.25\n" + contour;
  InterpreterOptions options = test::defaultOptions();
  options.maxMoves = 46;
  const InterpretResult exact = test::run(g71, options);
  ASSERT_TRUE(exact.ok()) << test::messageOf(exact);
  EXPECT_EQ(exact.toolpath.moves.size(), 46u);
  options.maxMoves = 45;  // the cycle's 45 legs pass, the program's 46th move is refused
  test::expectError(test::run(g71, options), 3, 1, "the program makes more than 45 moves");
  options.maxMoves = 44;  // the cycle alone is over the limit: refused before it is all built
  test::expectError(test::run(g71, options), 4, 1, "G71 would make more than 44 moves");

  options.maxMoves = 14;
  const InterpretResult pattern = test::run(g73, options);
  ASSERT_TRUE(pattern.ok()) << test::messageOf(pattern);
  EXPECT_EQ(pattern.toolpath.moves.size(), 14u);
  for (const std::size_t limit : {13u, 12u, 5u}) {
    options.maxMoves = limit;
    test::expectError(test::run(g73, options), 3, 1, "more than " + std::to_string(limit) + " moves");
  }
  // More passes than the limit are refused at the count itself, however large (an int holds
  // no 3·10^12).
  for (const std::string passes : {"R1001", "R2000000000", "R3000000000000"}) {
    options.maxMoves = 1000;
    test::expectError(test::run("G00 X62. Z2.\nG73 U3. W0. " + passes + "\nG73 P10 Q30 U0.4 W0.2 F0.25\n" + contour,
                                options),
                      2, 13, "more than 1000 moves");
  }
}

}  // namespace
}  // namespace lathesim::interp
