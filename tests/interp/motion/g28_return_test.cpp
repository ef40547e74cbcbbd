// G28 X(U) Z(W): rapid to the intermediate point, then to the reference point, each named
// axis only. The tool starts at X200 Z200 = (100, 200); the reference here is X100 Z150 =
// (50, 150) unless a test says otherwise.

#include "interp/motion/g28_return.hpp"

#include <gtest/gtest.h>

#include "../test_support.hpp"

namespace lathesim::interp {
namespace {

using test::expectError;
using test::expectMoves;
using test::kRapid;

InterpretResult runWithReference(std::string_view program) {
  InterpreterOptions options = test::defaultOptions();
  options.referencePosition = RZ(50, 150);
  return interpret(program, "test.nc", options);
}

TEST(ReferenceReturn, AbsoluteIntermediatePoint) {
  // From X40 Z10 = (20, 10): X80 Z50 → (40, 50), then the reference (50, 150).
  const auto result = runWithReference("G00 X40 Z10\nG28 X80 Z50\n");
  ASSERT_TRUE(result.ok()) << result.diagnostics[0].message;
  expectMoves(result.toolpath.moves, {{kRapid, 100, 200, 20, 10, 0, 0},
                                      {kRapid, 20, 10, 40, 50, 0, 1},
                                      {kRapid, 40, 50, 50, 150, 0, 2}});
}

TEST(ReferenceReturn, IncrementalIntermediatePoint) {
  // U20 W5 from (20, 10): (20 + 10, 10 + 5) = (30, 15), then (50, 150).
  const auto result = runWithReference("G00 X40 Z10\nG28 U20 W5\n");
  ASSERT_TRUE(result.ok()) << result.diagnostics[0].message;
  expectMoves(result.toolpath.moves, {{kRapid, 100, 200, 20, 10, 0, 0},
                                      {kRapid, 20, 10, 30, 15, 0, 1},
                                      {kRapid, 30, 15, 50, 150, 0, 2}});
}

TEST(ReferenceReturn, U0W0GoesStraightToTheReference) {
  const auto result = runWithReference("G00 X40 Z10\nG28 U0 W0\nG00 W-10\n");
  ASSERT_TRUE(result.ok()) << result.diagnostics[0].message;
  // The zero-length first leg is left out; the position is the reference afterwards.
  expectMoves(result.toolpath.moves, {{kRapid, 100, 200, 20, 10, 0, 0},
                                      {kRapid, 20, 10, 50, 150, 0, 2},
                                      {kRapid, 50, 150, 50, 140, 0, 0}});
}

TEST(ReferenceReturn, AnAxisNotNamedDoesNotMove) {
  // G28 U0: only X returns; Z stays at 10.
  const auto onlyX = runWithReference("G00 X40 Z10\nG28 U0\n");
  ASSERT_TRUE(onlyX.ok());
  expectMoves(onlyX.toolpath.moves, {{kRapid, 100, 200, 20, 10, 0, 0}, {kRapid, 20, 10, 50, 10, 0, 2}});
  // G28 W5: Z goes to 15, then to the reference Z 150; X stays at 20.
  const auto onlyZ = runWithReference("G00 X40 Z10\nG28 W5\n");
  ASSERT_TRUE(onlyZ.ok());
  expectMoves(onlyZ.toolpath.moves, {{kRapid, 100, 200, 20, 10, 0, 0},
                                     {kRapid, 20, 10, 20, 15, 0, 1},
                                     {kRapid, 20, 15, 20, 150, 0, 2}});
}

TEST(ReferenceReturn, WithoutAReferenceTheStartPositionIsIt) {
  const auto result = test::run("G00 X40 Z10\nG28 U0 W0\n");
  ASSERT_TRUE(result.ok());
  expectMoves(result.toolpath.moves, {{kRapid, 100, 200, 20, 10, 0, 0}, {kRapid, 20, 10, 100, 200, 0, 2}});
}

TEST(ReferenceReturn, EndsACyclesRetainedValues) {
  expectError(runWithReference("G00 X60 Z2\nG94 X50 Z-5 F0.2\nG28 U0\nZ-10\n"), 4, 1,
              "G94 needs X(U) and Z(W)");
}

TEST(ReferenceReturn, NeedsAnAxis) {
  expectError(runWithReference("G28\n"), 1, 1, "G28 needs X(U) and/or Z(W)");
}

TEST(ReferenceReturnLegs, TheTwoLegsByHand) {
  const auto legs = referenceReturnLegs(RZ(20, 10), 30.0, std::nullopt, RZ(50, 150));
  test::expectLegs(legs, {{kRapid, 20, 10, 30, 10, 0, 1}, {kRapid, 30, 10, 50, 10, 0, 2}});
}

}  // namespace
}  // namespace lathesim::interp
