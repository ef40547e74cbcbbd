// G54–G59, G53 and G10 as a Fanuc/GSK lathe reads them. Positions are (radius, Z) in the
// setup's frame; the tool starts at X200 Z200 = (100, 200), which is also the reference point
// and so machine zero unless a test sets one. Every expected point is worked by hand from
// the offsets the test gives.

#include <gtest/gtest.h>

#include "../test_support.hpp"

namespace lathesim::interp {
namespace {

using test::expectError;
using test::expectMoves;
using test::kFeed;
using test::kRapid;
using test::run;

InterpreterOptions withWorkOffsets(RZ g55, RZ g56 = RZ(0, 0)) {
  InterpreterOptions options = test::defaultOptions();
  options.workOffsets[2] = g55;
  options.workOffsets[3] = g56;
  return options;
}

TEST(WorkCoordinates, G54IsTheDefaultWithZeroShift) {
  const auto plain = run("G00 X40 Z10\nG01 Z-20 F0.2\nM30\n");
  const auto g54 = run("G54\nG00 X40 Z10\nG01 Z-20 F0.2\nM30\n");
  ASSERT_TRUE(plain.ok() && g54.ok());
  expectMoves(g54.toolpath.moves, {{kRapid, 100, 200, 20, 10, 0, 0}, {kFeed, 20, 10, 20, -20, 0.2, 0}});
  ASSERT_EQ(plain.toolpath.moves.size(), g54.toolpath.moves.size());
}

TEST(WorkCoordinates, AnotherSystemShiftsTheNextMovesNotTheTool) {
  // G55's zero lies 30 mm towards the chuck: Z10 under G55 is Z-20 of the setup. The G55 block
  // moves nothing; the tool stays at (20, 10), which G55 calls Z40; W-5 goes to setup Z5.
  const auto result = run("G00 X40 Z10\nG55\nG00 Z10\nG00 W-5\nG54 G00 Z10\nM30\n", withWorkOffsets(RZ(0, -30)));
  ASSERT_TRUE(result.ok()) << result.diagnostics[0].message;
  expectMoves(result.toolpath.moves, {{kRapid, 100, 200, 20, 10, 0, 0},
                                      {kRapid, 20, 10, 20, -20, 0, 0},
                                      {kRapid, 20, -20, 20, -25, 0, 0},
                                      {kRapid, 20, -25, 20, 10, 0, 0}});
}

TEST(WorkCoordinates, XOffsetIsADiameterAndArcCentresMoveToo) {
  // G56: X shift Φ2 (radius 1), Z shift −5. The arc from X30 Z0 to X40 Z-5 by R5 (G02,
  // clockwise with Z right and X up: centre X40 Z0) lies at radius +1 and Z −5 in the setup.
  const auto result = run("G56 G00 X30 Z0\nG02 X40 Z-5 R5 F0.1\nM30\n", withWorkOffsets(RZ(0, 0), RZ(1, -5)));
  ASSERT_TRUE(result.ok()) << result.diagnostics[0].message;
  const auto& arc = result.toolpath.moves.at(1);
  EXPECT_NEAR(arc.from.x(), 16, 1e-12);
  EXPECT_NEAR(arc.from.y(), -5, 1e-12);
  EXPECT_NEAR(arc.to.x(), 21, 1e-12);
  EXPECT_NEAR(arc.to.y(), -10, 1e-12);
  EXPECT_NEAR(arc.center.x(), 21, 1e-12);
  EXPECT_NEAR(arc.center.y(), -5, 1e-12);
}

TEST(WorkCoordinates, CycleStartsAndG28ReferenceAreInTheSetupFrame) {
  // G90 from X50 Z2 under G55 (Z −30): A is setup (25, −28). G28 U0 W0 goes to the reference
  // point (100, 200) of the setup whatever the work system.
  const auto result = run("G55 G00 X50 Z2\nG90 X40 Z-10 F0.2\nG00 X60\nG28 U0 W0\nM30\n", withWorkOffsets(RZ(0, -30)));
  ASSERT_TRUE(result.ok()) << result.diagnostics[0].message;
  ASSERT_EQ(result.toolpath.cycleStarts.size(), 1u);
  EXPECT_NEAR(result.toolpath.cycleStarts[0].point.y(), -28, 1e-12);
  const Move& last = result.toolpath.moves.back();
  EXPECT_NEAR(last.to.x(), 100, 1e-12);
  EXPECT_NEAR(last.to.y(), 200, 1e-12);
}

TEST(WorkCoordinates, SweepOfShiftsKeepsThePartTheSameShapeMovedByTheShift) {
  const std::string program = "G55 G00 X50 Z2\nG01 X30 F0.2\nG01 Z-20\nG02 X40 Z-25 R5\nG00 X60 Z5\nM30\n";
  const auto base = run(program, withWorkOffsets(RZ(0, 0)));
  ASSERT_TRUE(base.ok());
  for (double dz : {-75.5, -12.0, -0.001, 3.25, 40.0}) {
    for (double dx : {0.0, 0.5}) {
      SCOPED_TRACE(testing::Message() << "shift " << dx << ", " << dz);
      const auto moved = run(program, withWorkOffsets(RZ(dx, dz)));
      ASSERT_TRUE(moved.ok());
      ASSERT_EQ(moved.toolpath.moves.size(), base.toolpath.moves.size());
      // The first move starts at the start point; every later point is the base's plus the shift.
      for (std::size_t i = 0; i < base.toolpath.moves.size(); ++i) {
        const Move& a = base.toolpath.moves[i];
        const Move& b = moved.toolpath.moves[i];
        EXPECT_NEAR(b.to.x(), a.to.x() + dx, 1e-9);
        EXPECT_NEAR(b.to.y(), a.to.y() + dz, 1e-9);
        if (i > 0) {
          EXPECT_NEAR(b.from.y(), a.from.y() + dz, 1e-9);
        }
      }
    }
  }
}

TEST(MachineCoordinates, G53GoesToMachineZeroPlusTheWordsWhateverTheWorkSystem) {
  // Machine zero defaults to the reference point (100, 200). G53 Z-50 → setup Z150, X kept.
  const auto result = run("G55 G00 X40 Z10\nG53 Z-50\nG00 G53 X0\nM30\n", withWorkOffsets(RZ(0, -30)));
  ASSERT_TRUE(result.ok()) << result.diagnostics[0].message;
  expectMoves(result.toolpath.moves, {{kRapid, 100, 200, 20, -20, 0, 0},
                                      {kRapid, 20, -20, 20, 150, 0, 0},
                                      {kRapid, 20, 150, 100, 150, 0, 0}});
}

TEST(MachineCoordinates, TheSetupPlacesMachineZero) {
  InterpreterOptions options = test::defaultOptions();
  options.machineZero = RZ(150, 300);
  // X-100 is a diameter: radius 150 − 50 = 100; Z 300 − 100 = 200; then back to G54 Z0.
  const auto result = run("G00 X40 Z10\nG53 X-100 Z-100\nG00 Z0\nM30\n", options);
  ASSERT_TRUE(result.ok()) << result.diagnostics[0].message;
  expectMoves(result.toolpath.moves, {{kRapid, 100, 200, 20, 10, 0, 0},
                                      {kRapid, 20, 10, 100, 200, 0, 0},
                                      {kRapid, 100, 200, 100, 0, 0, 0}});
}

TEST(MachineCoordinates, Errors) {
  expectError(run("G00 X40 Z10\nG53 U0\n"), 2, 5, "G53 goes to machine coordinates");
  expectError(run("G00 X40 Z10\nG53\n"), 2, 1, "G53 needs X and/or Z");
}

TEST(MachineCoordinates, AMotionCodeBesideG53OnlyBecomesModal) {
  // G53 takes the axis words and moves at rapid (machine zero X200 = r 100 here); G01 is the
  // motion of the blocks after it (issue 11: a one-shot code beside a motion code).
  const auto result = run("G00 X40 Z10\nG01 G53 X0 F0.2\nZ5\n");
  ASSERT_TRUE(result.ok()) << result.diagnostics[0].message;
  expectMoves(result.toolpath.moves, {{kRapid, 100, 200, 20, 10, 0, 0},
                                      {kRapid, 20, 10, 100, 10, 0, 0},
                                      {test::kFeed, 100, 10, 100, 5, 0.2, 0}});
}

TEST(DataSetting, G10GeometryOffsetTakesEffectAtTheNextTWord) {
  InterpreterOptions options = test::defaultOptions();
  options.offsets[1] = ToolOffset{0.4, 0, 0, 3, 0, 0};
  // T0101: shift (0.2, 0). G10 P10001 X1.0 Z-0.5 rewrites the geometry: shift (0.5, −0.5), in
  // force only after the second T0101.
  const auto result = run("T0101\nG00 X40 Z10\nG10 P10001 X1.0 Z-0.5\nG00 X30\nT0101\nG00 X20\nM30\n", options);
  ASSERT_TRUE(result.ok()) << result.diagnostics[0].message;
  expectMoves(result.toolpath.moves, {{kRapid, 100, 200, 20.2, 10, 0, 0},
                                      {kRapid, 20.2, 10, 15.2, 10, 0, 0},
                                      {kRapid, 15.2, 10, 10.5, 9.5, 0, 0}});
}

TEST(DataSetting, G10WearAddsWithUAndSetsWithX) {
  InterpreterOptions options = test::defaultOptions();
  options.offsets[2] = ToolOffset{0, 0, 0, 3, 0.1, 0};
  // Wear X 0.1 + U0.2 = 0.3 (radius 0.15); wear Z set to 0.05.
  const auto result = run("G10 P2 U0.2 Z0.05\nT0102\nG00 X40 Z10\nM30\n", options);
  ASSERT_TRUE(result.ok()) << result.diagnostics[0].message;
  expectMoves(result.toolpath.moves, {{kRapid, 100, 200, 20.15, 10.05, 0, 0}});
}

TEST(DataSetting, G10SetsNoseRadiusAndTipForCompensation) {
  // Offset 3 starts empty; G10 P10003 R0.8 Q3 gives it R0.8 tip 3, so G42 offsets the cut.
  const auto result = run("G10 P10003 R0.8 Q3\nT0103\nG00 X40 Z2\nG42 G01 Z-10 F0.2\nG40 G00 X60\nM30\n");
  ASSERT_TRUE(result.ok()) << result.diagnostics[0].message;
  ASSERT_EQ(result.toolpath.moves.size(), 3u);
  EXPECT_EQ(result.toolpath.moves[1].noseComp, (NoseComp{NoseSide::Right, 0.8, 3}));
}

TEST(DataSetting, G10L2ChangesAWorkOffsetAtOnce) {
  // G54's Z offset becomes −10 while G54 is in force: the tool stays at setup Z10 (now G54 Z20);
  // the next Z10 goes to setup Z0. G10 L2 P2 W-30 shifts G55 by −30 for the G55 move.
  const auto result = run("G00 X40 Z10\nG10 L2 P1 Z-10\nG00 Z10\nG10 L2 P2 W-30\nG55 G00 Z10\nM30\n");
  ASSERT_TRUE(result.ok()) << result.diagnostics[0].message;
  expectMoves(result.toolpath.moves, {{kRapid, 100, 200, 20, 10, 0, 0},
                                      {kRapid, 20, 10, 20, 0, 0, 0},
                                      {kRapid, 20, 0, 20, -20, 0, 0}});
}

TEST(DataSetting, Errors) {
  expectError(run("G10 X1\n"), 1, 1, "G10 needs P");
  expectError(run("G10 P0 X1\n"), 1, 5, "G10 P0 sets the work coordinate system shift");
  expectError(run("G10 P100 X1\n"), 1, 5, "P100 is not a tool offset");
  expectError(run("G10 L2 P7 Z1\n"), 1, 8, "P7 is not a work offset");
  expectError(run("G10 L3 P1 Z1\n"), 1, 5, "G10 L3: lathesim reads G10 L2");
  expectError(run("G10 P1 X1 U1\n"), 1, 11, "X1 and U1 both give the same value");
  expectError(run("G10 P10001 Q12\n"), 1, 12, "Q12 is not an imaginary tip number");
  expectError(run("G10 P10001 R-1\n"), 1, 12, "negative nose radius");
}

TEST(DrillingCycleCancel, G80DoesNotEndAnAxialCycleAndSaysSoWhenItRepeats) {
  const auto result = run("G00 X50 Z2\nG90 X40 Z-10 F0.2\nG80\nX30\nG00 X60\nM30\n");
  ASSERT_TRUE(result.ok());
  // The G00 to A, two G90 runs of four legs, then the G00 X60.
  EXPECT_EQ(result.toolpath.moves.size(), 10u);
  ASSERT_EQ(result.diagnostics.size(), 1u);
  EXPECT_EQ(result.diagnostics[0].severity, Severity::Warning);
  EXPECT_EQ(result.diagnostics[0].line, 4);
  EXPECT_NE(result.diagnostics[0].message.find("G80 on line 3 cancels drilling cycles only"), std::string::npos);
}

TEST(DrillingCycleCancel, G80InASafetyLineChangesNothing) {
  const auto with = run("G40 G80 G99\nG00 X40 Z10\nG01 Z-20 F0.2\nM30\n");
  ASSERT_TRUE(with.ok());
  EXPECT_TRUE(with.diagnostics.empty());
  expectMoves(with.toolpath.moves, {{kRapid, 100, 200, 20, 10, 0, 0}, {kFeed, 20, 10, 20, -20, 0.2, 0}});
}

}  // namespace
}  // namespace lathesim::interp
