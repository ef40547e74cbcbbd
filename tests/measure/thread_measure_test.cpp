// Threads measured on the simulated level set (measure/thread_measure.hpp) against what was
// programmed: the lead at every angle within a tenth of a voxel, the minor diameter within a
// voxel of the programmed root, the hand (M03/M04, toward the chuck or away), a start shifted
// by Q measured at its angle, two starts, an internal thread. Leads, voxels and tools are
// swept so that the groove pattern does not repeat on the voxel grid.

#include "measure/thread_measure.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <sstream>
#include <string>

#include "geometry/tool_shape.hpp"
#include "interp/interpreter.hpp"
#include "sim/simulate.hpp"

namespace lathesim::measure {
namespace {

struct Cut {
  std::vector<MeasuredThread> threads;
  double voxel;
};

// A Φ20 × 14 bar (face Z0) cut by `program` with thread tool 1 (`tool`) and a 3 mm grooving
// blade 2 for bores.
Cut cut(const std::string& program, const ConvexPolygon& tool, double voxel, double diameter = 20) {
  interp::InterpreterOptions options;
  options.startPosition = RZ(30, 20);
  options.toolNumbers = {1, 2};
  const auto result = interp::interpret(program, "thread.nc", options);
  EXPECT_TRUE(result.ok()) << (result.diagnostics.empty() ? "" : result.diagnostics[0].message);
  sim::Stock stock({diameter, 14.0, 0.0}, voxel);
  const std::vector<RZ> blade{{0, 0}, {-12, 0}, {-12, 3}, {0, 3}};  // a boring blade, its top the programmed point
  const std::map<int, ConvexPolygon> tools{{1, tool}, {2, *ConvexPolygon::fromOutline(blade).polygon}};
  sim::simulate(result.toolpath, tools, stock);
  return {measureThreads(stock, result.toolpath, tools, interp::Dialect::FanucA), voxel};
}

ConvexPolygon threadOutline(double pitch, double noseRadius, bool internal = false) {
  return threadTool(60, pitch, noseRadius, std::nullopt, internal).tool->cutter;
}

// One G32 pass at root X from Z4 to Z-17, through the whole bar (its far end at Z-14 is in
// air), so that every groove on the bar is complete but the end ones.
std::string onePass(double rootDiameter, double lead, const std::string& extra = "") {
  std::ostringstream program;
  program << "M03 S500\nG00 X24 Z4\nX" << rootDiameter << "\nG32 Z-17 F" << lead << ' ' << extra << "\nG00 X24\nZ4\n";
  return program.str();
}

struct Case {
  double lead, voxel, noseRadius;
};

TEST(ThreadMeasure, LeadAtEveryAngleAndMinorDiameterAgainstTheProgram) {
  for (const Case c : {Case{1.5, 0.1, 0.0}, Case{1.75, 0.07, 0.22}, Case{2.5, 0.1, 0.3125}, Case{1.25, 0.06, 0.15}}) {
    SCOPED_TRACE(testing::Message() << "lead " << c.lead << " voxel " << c.voxel << " nose " << c.noseRadius);
    const double depth = 0.6134 * c.lead;  // an ISO external thread's height
    const double root = 20 - 2 * depth;
    const Cut result = cut(onePass(root, c.lead), threadOutline(c.lead, c.noseRadius), c.voxel);
    ASSERT_EQ(result.threads.size(), 1u);
    const ThreadMeasurement& m = result.threads[0].measured;
    ASSERT_FALSE(m.problem) << *m.problem;
    EXPECT_EQ(m.anglesDeg.size(), 12u);
    EXPECT_GE(m.grooves, 4);  // 14 mm of bar: at least four whole grooves at leads to 2.5
    EXPECT_NEAR(m.leadMm.min, c.lead, 0.1 * c.voxel);
    EXPECT_NEAR(m.leadMm.max, c.lead, 0.1 * c.voxel);
    EXPECT_NEAR(m.leadPerTurnMm, c.lead, 0.1 * c.voxel);
    EXPECT_EQ(m.starts, 1);
    EXPECT_TRUE(m.rightHand);
    // The root: the tool's lowest point runs at the programmed X.
    EXPECT_NEAR(m.minorDiameterMm.min / 2, root / 2, c.voxel);
    EXPECT_NEAR(m.minorDiameterMm.max / 2, root / 2, c.voxel);
    EXPECT_NEAR(m.majorDiameterMm.mean, 20, 2 * c.voxel);
    EXPECT_NEAR(m.leftFlankDeg.mean, 30, 1.0);
    EXPECT_NEAR(m.rightFlankDeg.mean, 30, 1.0);
    // Where the groove is half a pitch wide: for the tool's straight flanks, the point of its V
    // (sharp: at the root; rounded: r/sin 30° − r below the nose) plus a quarter pitch / tan 30°.
    const double apex = root / 2 - c.noseRadius * (1 / std::sin(M_PI / 6) - 1);
    EXPECT_NEAR(m.pitchDiameterMm.mean / 2, apex + c.lead / 4 / std::tan(M_PI / 6), c.voxel / 4);
  }
}

// M03 toward the chuck is right-hand; M04, or M03 toward the tailstock, left-hand. A test that
// fails if the hand is flipped anywhere between the program and the measurement.
TEST(ThreadMeasure, HandFollowsTheSpindleAndTheDirectionOfTravel) {
  const ConvexPolygon tool = threadOutline(1.5, 0.19);
  const auto handOf = [&](const std::string& program) {
    const Cut result = cut(program, tool, 0.1);
    EXPECT_EQ(result.threads.size(), 1u);
    EXPECT_FALSE(result.threads[0].measured.problem);
    EXPECT_EQ(result.threads[0].programmed.rightHand, result.threads[0].measured.rightHand);
    return result.threads[0].measured.rightHand;
  };
  EXPECT_TRUE(handOf(onePass(18.16, 1.5)));
  EXPECT_FALSE(handOf("M04 S500\nG00 X24 Z4\nX18.16\nG32 Z-17 F1.5\nG00 X24\n"));
  EXPECT_FALSE(handOf("M03 S500\nG00 X24 Z-17\nX18.16\nG32 Z4 F1.5\nG00 X24\n"));
  EXPECT_TRUE(handOf("M04 S500\nG00 X24 Z-17\nX18.16\nG32 Z4 F1.5\nG00 X24\n"));
}

// Q90000 starts the pass a quarter turn later: measured at 90° (to a tenth of a voxel along
// the lead, 360°·0.1·h/L), and 0° without it; 270° is −90°, a start half a turn away 180°.
TEST(ThreadMeasure, StartAngleIsMeasuredAtItsAngle) {
  const ConvexPolygon tool = threadOutline(2.0, 0.25);
  constexpr double kVoxel = 0.1;
  const double tolerance = 360 * 0.1 * kVoxel / 2.0;
  for (const double q : {0.0, 90.0, 270.0, 180.0, 33.0}) {
    SCOPED_TRACE(testing::Message() << "Q " << q << "°");
    std::ostringstream word;
    word << 'Q' << std::lround(q * 1000);
    const Cut result = cut(onePass(17.6, 2.0, word.str()), tool, kVoxel);
    ASSERT_EQ(result.threads.size(), 1u);
    const ThreadMeasurement& m = result.threads[0].measured;
    ASSERT_FALSE(m.problem) << *m.problem;
    // Angles are reported in (−180°, 180°]: compare around the circle.
    const auto offBy = [](double a, double b) { return std::abs(std::remainder(a - b, 360.0)); };
    EXPECT_LT(offBy(m.startAngleDeg, q), tolerance) << m.startAngleDeg;
    EXPECT_LT(offBy(result.threads[0].programmed.startAngleDeg, q), 1e-9);
  }
}

// Two starts by G32 and Q (lead 4, pitch 2): two grooves half a turn apart; each pass cut
// twice as deep.
TEST(ThreadMeasure, TwoStartsByQ) {
  const std::string program =
      "M03 S500\nG00 X24 Z4\nX18.5\nG32 Z-17 F4\nG00 X24\nZ4\nX18.5\nG32 Z-17 Q180000\nG00 X24\nZ4\n"
      "X17.6\nG32 Z-17\nG00 X24\nZ4\nX17.6\nG32 Z-17 Q180000\nG00 X24\nZ4\n";
  const Cut result = cut(program, threadOutline(2.0, 0.25), 0.1);
  ASSERT_EQ(result.threads.size(), 1u);
  EXPECT_EQ(result.threads[0].programmed.starts, 2);
  EXPECT_EQ(result.threads[0].programmed.passes.size(), 4u);
  const ThreadMeasurement& m = result.threads[0].measured;
  ASSERT_FALSE(m.problem) << *m.problem;
  EXPECT_EQ(m.starts, 2);
  EXPECT_NEAR(m.pitchMm.mean, 2.0, 0.01);
  EXPECT_NEAR(m.leadMm.mean, 4.0, 0.01);
  EXPECT_NEAR(m.minorDiameterMm.mean, 17.6, 0.2);
}

// An internal M24×1.5 thread in a Φ40 bar bored to Φ22.376 (the nut's minor diameter): the
// groove goes outward; its root is the major diameter, programmed at X24.
TEST(ThreadMeasure, InternalThread) {
  const std::string program =
      "M03 S500\nT0202\nG00 X22.376 Z4\nG01 Z-17 F0.2\nG00 X20\nZ4\nT0101\n"
      "G00 X20 Z4\nX24\nG32 Z-17 F1.5\nG00 X20\nZ4\n";
  const Cut result = cut(program, threadOutline(1.5, 0.094, true), 0.1, 40);
  ASSERT_EQ(result.threads.size(), 1u);
  EXPECT_TRUE(result.threads[0].programmed.internal);
  const ThreadMeasurement& m = result.threads[0].measured;
  ASSERT_FALSE(m.problem) << *m.problem;
  EXPECT_NEAR(m.leadMm.mean, 1.5, 0.01);
  EXPECT_NEAR(m.majorDiameterMm.mean / 2, 12.0, 0.1);   // the root, outward
  EXPECT_NEAR(m.minorDiameterMm.mean / 2, 11.188, 0.1);  // the bore
  EXPECT_TRUE(m.rightHand);
}

// A tool for pitch 3 (its V 2·(h + 0.375·(1/sin 30° − 1))·tan 30° wide h above its point,
// nose 0.375) cutting a pitch-1 thread 0.613 deep: 1.14 mm wide at the crest, more than the
// pitch and a voxel; a pitch-2 thread 1.227 deep: 1.85 mm at the crest, fine.
TEST(ThreadMeasure, ToolTooWideForThePitch) {
  const ConvexPolygon tool = threadOutline(3.0, 0.375);
  MeasuredThread thread;
  thread.programmed.leadMm = 1.0;
  thread.programmed.rootRadiusMm = 10 - 0.613;
  thread.measured.majorDiameterMm = {20, 20, 20};
  const auto tooWide = threadToolTooWide(thread, tool, 0.1);
  ASSERT_TRUE(tooWide);
  EXPECT_NE(tooWide->find("1.141 mm wide at the thread's crest, more than its pitch of 1.000 mm"), std::string::npos)
      << *tooWide;
  thread.programmed.leadMm = 2.0;
  thread.programmed.rootRadiusMm = 10 - 1.227;
  EXPECT_FALSE(threadToolTooWide(thread, tool, 0.1));
  // Grooves that ran together could not be measured: the tool's full width decides.
  thread.programmed.leadMm = 1.0;
  thread.measured.problem = "fewer than two complete grooves at 0°";
  EXPECT_TRUE(threadToolTooWide(thread, tool, 0.1));
}

}  // namespace
}  // namespace lathesim::measure
