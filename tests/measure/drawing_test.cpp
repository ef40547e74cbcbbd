// The drawing's profile file: points as diameters, arcs by radius or centre, and every
// mistake reported on its line.

#include "measure/drawing.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace lathesim::measure {
namespace {

std::string firstMessage(const DrawingResult& result) {
  return result.diagnostics.empty() ? std::string("(none)") : result.diagnostics.front().message;
}

TEST(Drawing, PointsAreDiametersAndZ) {
  const DrawingResult r = parseDrawing("[[profile]]\nx = 30\nz = 0\n[[profile]]\nx = 50\nz = -20\n", "d.toml");
  ASSERT_TRUE(r.outline) << firstMessage(r);
  ASSERT_EQ(r.outline->size(), 2u);
  EXPECT_EQ((*r.outline)[0], RZ(15, 0));
  EXPECT_EQ((*r.outline)[1], RZ(25, -20));
}

// From (r 15, Z0) to (r 25, Z-10), radius 10. In the drawing view (Z right, r up) the chord
// runs left and up; its midpoint is (r 20, Z-5), and the centre lies √(10² − 50) = √50 off the
// chord's middle: counter-clockwise (the shorter arc) on its left, at (r 15, Z-10); the arc
// then bulges up and right through (r 15 + 10/√2, Z-10 + 10/√2) = (22.07, -2.93).
TEST(Drawing, CounterClockwiseArcByRadiusBulgesOutwards) {
  const DrawingResult r = parseDrawing(
      "profile = [{x = 30, z = 0}, {x = 50, z = -10, arc = \"ccw\", radius = 10}]\n", "d.toml");
  ASSERT_TRUE(r.outline) << firstMessage(r);
  ASSERT_GT(r.outline->size(), 10u);  // chords within 0.1 µm
  EXPECT_EQ(r.outline->back(), RZ(25, -10));
  double farthestFromAxisSide = 0;
  for (const RZ& p : *r.outline) {
    EXPECT_NEAR((p - RZ(15, -10)).norm(), 10.0, 1e-9);
    farthestFromAxisSide = std::max(farthestFromAxisSide, p.x() + p.y());
  }
  // The point at 45°: r + z = 15 + 10/√2 − 10 + 10/√2 = 5 + 10√2.
  EXPECT_NEAR(farthestFromAxisSide, 5 + 10 * std::sqrt(2.0), 1e-4);
}

// Clockwise, the centre is on the chord's right, (r 25, Z0); the arc passes (r 25 − 10/√2, Z −10/√2).
TEST(Drawing, ClockwiseArcByCentreIsTheCove) {
  const DrawingResult r = parseDrawing(
      "profile = [{x = 30, z = 0}, {x = 50, z = -10, arc = \"cw\", center = [50, 0]}]\n", "d.toml");
  ASSERT_TRUE(r.outline) << firstMessage(r);
  double nearestToAxisSide = 1e9;
  for (const RZ& p : *r.outline) {
    EXPECT_NEAR((p - RZ(25, 0)).norm(), 10.0, 1e-9);
    nearestToAxisSide = std::min(nearestToAxisSide, p.x() + p.y());
  }
  EXPECT_NEAR(nearestToAxisSide, 25 - 10 * std::sqrt(2.0), 1e-4);
}

// A negative radius takes the longer arc: three quarters of the circle, 15π/2 · 10 mm long.
TEST(Drawing, NegativeRadiusIsTheLongerArc) {
  const DrawingResult r = parseDrawing(
      "profile = [{x = 30, z = 0}, {x = 50, z = -10, arc = \"ccw\", radius = -10}]\n", "d.toml");
  ASSERT_TRUE(r.outline) << firstMessage(r);
  double length = 0;
  for (std::size_t i = 1; i < r.outline->size(); ++i) length += ((*r.outline)[i] - (*r.outline)[i - 1]).norm();
  EXPECT_NEAR(length, 1.5 * M_PI * 10, 1e-3);
}

TEST(Drawing, LastRowRepeatingTheFirstClosesTheOutline) {
  const DrawingResult r = parseDrawing(
      "profile = [{x = 20, z = 0}, {x = 50, z = 0}, {x = 50, z = -30}, {x = 20, z = -30}, {x = 20, z = 0}]\n", "d.toml");
  ASSERT_TRUE(r.outline) << firstMessage(r);
  ASSERT_EQ(r.outline->size(), 5u);
  EXPECT_EQ(r.outline->front(), r.outline->back());
}

struct BadDrawing {
  std::string text;
  int line;
  std::string message;
};

void PrintTo(const BadDrawing& bad, std::ostream* out) { *out << "'" << bad.message << "'"; }

class DrawingErrors : public testing::TestWithParam<BadDrawing> {};

TEST_P(DrawingErrors, SayWhatIsWrongOnItsLine) {
  const DrawingResult r = parseDrawing(GetParam().text, "d.toml");
  EXPECT_FALSE(r.outline);
  ASSERT_FALSE(r.diagnostics.empty());
  EXPECT_EQ(r.diagnostics.front().line, GetParam().line);
  EXPECT_NE(r.diagnostics.front().message.find(GetParam().message), std::string::npos) << r.diagnostics.front().message;
}

INSTANTIATE_TEST_SUITE_P(
    Drawing, DrawingErrors,
    testing::Values(
        BadDrawing{"[[profile]]\nx = 30\nz = 0\n", 1, "at least two [[profile]] rows"},
        BadDrawing{"[[profile]]\nx = 30\nz = 0\n[[profile]]\nx = 50\n", 4, "profile row needs z"},
        BadDrawing{"[[profile]]\nx = 30\nz = 0\n[[profile]]\nx = 50\nz = \"a\"\n", 6, "z must be a number"},
        BadDrawing{"[[profile]]\nx = -30\nz = 0\n[[profile]]\nx = 50\nz = 1\n", 1, "diameter and cannot be negative"},
        BadDrawing{"profile = [{x = 30, z = 0}, {x = 50, z = -10, arc = \"left\", radius = 10}]\n", 1,
                   "arc must be \"cw\" or \"ccw\""},
        BadDrawing{"profile = [{x = 30, z = 0}, {x = 50, z = -10, arc = \"cw\", radius = 5}]\n", 1,
                   "radius is shorter than half the distance"},
        BadDrawing{"profile = [{x = 30, z = 0}, {x = 50, z = -10, arc = \"cw\"}]\n", 1, "an arc needs radius or center"},
        BadDrawing{"profile = [{x = 30, z = 0}, {x = 50, z = -10, arc = \"cw\", center = [30, 0]}]\n", 1,
                   "not the same distance from its center"},
        BadDrawing{"profile = [{x = 30, z = 0}, {x = 50, z = -10, radius = 10}]\n", 1, "need arc"},
        BadDrawing{"[part]\n[[profile]]\nx = 30\nz = 0\n[[profile]]\nx = 50\nz = 1\n", 1, "unknown key 'part'"},
        BadDrawing{"[[profile]]\nx = 30\nz = = 0\n", 3, ""},
        // Beside the fuzz harness (whose million runs missed them): the long way round a
        // radius no part has needs billions of chords (and a step that 1 − e/r rounded to 0
        // gave an infinite count, cast to int); a centre at infinity made every distance NaN.
        BadDrawing{"profile = [{x = 0, z = 0}, {x = 2, z = 0},\n"
                   "  {x = 2, z = -2, arc = \"ccw\", center = [2e13, -1]}]\n",
                   2, "is too large for a turned part"},
        BadDrawing{"profile = [{x = 30, z = 0}, {x = 50, z = -10, arc = \"cw\", radius = -1e9}]\n", 1,
                   "is too large for a turned part"},
        BadDrawing{"profile = [{x = 30, z = 0}, {x = 50, z = -10, arc = \"cw\", center = [inf, 0]}]\n", 1,
                   "center must be [x diameter, z]"},
        BadDrawing{"profile = [{x = 30, z = 0}, {x = 30, z = -9}]\n[[thread]]\npitch = 2\n", 2, "needs z_range"},
        BadDrawing{"profile = [{x = 30, z = 0}, {x = 30, z = -9}]\n[[thread]]\nz_range = [0, -9]\npitch = 2\n", 3,
                   "z_range must be [least, greatest]"},
        BadDrawing{"profile = [{x = 30, z = 0}, {x = 30, z = -9}]\n[[thread]]\nz_range = [-9, 0]\npitch = 0\n", 4,
                   "pitch must be a number > 0"},
        BadDrawing{"profile = [{x = 30, z = 0}, {x = 30, z = -9}]\n[[thread]]\nz_range = [-9, 0]\npitch = 2\nhand = \"up\"\n",
                   5, "hand must be \"right\" or \"left\""},
        BadDrawing{"profile = [{x = 30, z = 0}, {x = 30, z = -9}]\n[[thread]]\nz_range = [-9, 0]\npitch = 2\nmajor = 30\n", 5,
                   "major must be [least, greatest]"},
        BadDrawing{"profile = [{x = 30, z = 0}, {x = 30, z = -9}]\n[[thread]]\nz_range = [-9, 0]\npitch = 2\nlead = 2\n", 5,
                   "unknown thread key 'lead'"},
        // Tolerances: a fit only on a diameter, of the diameter's kind, as the standard writes it.
        BadDrawing{"[[profile]]\nx = 0\nz = 0\n[[profile]]\nx = 30\nz = 0\ntolerance = \"h7\"\n", 7,
                   "applies to a diameter"},
        BadDrawing{"[[profile]]\nx = 30\nz = 0\n[[profile]]\nx = 30\nz = -9\ntolerance = \"H7\"\n", 7,
                   "this diameter is a shaft's"},
        BadDrawing{"profile = [{x = 30, z = 0}, {x = 50, z = 0}, {x = 50, z = -9},\n {x = 30, z = -9}, "
                   "{x = 30, z = 0, tolerance = \"h7\"}]\n",
                   2, "this diameter is a bore's"},
        BadDrawing{"[[profile]]\nx = 30\nz = 0\n[[profile]]\nx = 30\nz = -9\ntolerance = \"h13\"\n", 7,
                   "not an ISO 286 fit covered here"},
        BadDrawing{"[[profile]]\nx = 30\nz = 0\ntolerance = 0.1\n[[profile]]\nx = 30\nz = -9\n", 4, "no line to tolerance"},
        BadDrawing{"[[profile]]\nx = 30\nz = 0\n[[profile]]\nx = 30\nz = -9\ntolerance = [-0.1, 0]\n", 7, "upper ≥ lower"},
        BadDrawing{"[[profile]]\nx = 30\nz = 0\n[[profile]]\nx = 30\nz = -9\ntolerance = -0.1\n", 7, "± a number ≥ 0"},
        BadDrawing{"general_tolerance = \"k\"\n[[profile]]\nx = 30\nz = 0\n[[profile]]\nx = 30\nz = -9\n", 1,
                   "ISO 2768-1 class"},
        BadDrawing{"corner_radius = -1\n[[profile]]\nx = 30\nz = 0\n[[profile]]\nx = 30\nz = -9\n", 1,
                   "corner_radius must be a number ≥ 0"}));

// Each line between rows takes the tolerance its second row states; fits become limits.
TEST(Drawing, TolerancesOfTheLinesReachingEachRow) {
  const DrawingResult r = parseDrawing(
      "general_tolerance = \"f\"\ncorner_radius = 0.8\n"
      "profile = [{x = 0, z = 0}, {x = 20, z = 0}, {x = 20, z = -30, tolerance = \"g6\"},\n"
      "  {x = 30, z = -30, tolerance = 0.05}, {x = 30, z = -50, tolerance = [0, -0.1]}, {x = 40, z = -60}]\n",
      "d.toml");
  ASSERT_TRUE(r.outline) << firstMessage(r);
  EXPECT_EQ(r.generalTolerance, 'f');
  EXPECT_DOUBLE_EQ(r.cornerRadiusMm, 0.8);
  ASSERT_EQ(r.lines.size(), 5u);
  EXPECT_TRUE(r.lines[0].face());
  EXPECT_FALSE(r.lines[0].tolerance);
  ASSERT_TRUE(r.lines[1].diameter());
  ASSERT_TRUE(r.lines[1].tolerance);
  EXPECT_NEAR(r.lines[1].tolerance->upperMm, -0.007, 1e-12);  // g6 on Φ20 (ISO 286-2)
  EXPECT_NEAR(r.lines[1].tolerance->lowerMm, -0.020, 1e-12);
  EXPECT_EQ(r.lines[1].tolerance->source, "g6");
  EXPECT_TRUE(r.lines[2].face());
  EXPECT_EQ(r.lines[2].tolerance->source, "±0.05");
  EXPECT_DOUBLE_EQ(r.lines[3].tolerance->lowerMm, -0.1);
  EXPECT_EQ(r.lines[3].tolerance->source, "0/−0.1");
  EXPECT_FALSE(r.lines[4].diameter() || r.lines[4].face());  // a taper
  EXPECT_EQ(r.lines[4].line, 4);
}

// A bore's fit in upper case: H7 on Φ30 is +0.021/0.
TEST(Drawing, BoreTakesAHoleFit) {
  const DrawingResult r = parseDrawing(
      "profile = [{x = 30, z = 0}, {x = 50, z = 0}, {x = 50, z = -9},\n {x = 30, z = -9}, {x = 30, z = 0, tolerance = \"H7\"}]\n",
      "d.toml");
  ASSERT_TRUE(r.outline) << firstMessage(r);
  ASSERT_TRUE(r.lines.back().tolerance);
  EXPECT_NEAR(r.lines.back().tolerance->upperMm, 0.021, 1e-12);
  EXPECT_NEAR(r.lines.back().tolerance->lowerMm, 0, 1e-12);
}

// A nearly straight arc (a CAD export's radius of ten kilometres) is drawn, as one chord.
TEST(Drawing, ArcOfAHugeRadiusOverAShortSpanIsOneChord) {
  const DrawingResult r =
      parseDrawing("profile = [{x = 30, z = 0}, {x = 30, z = -10, arc = \"cw\", radius = 1e7}]\n", "d.toml");
  ASSERT_TRUE(r.outline) << firstMessage(r);
  EXPECT_EQ(r.outline->size(), 2u);
}

// A thread callout: its zone, pitch, starts, hand and diameter limits.
TEST(Drawing, ThreadCallout) {
  const DrawingResult r = parseDrawing(
      "profile = [{x = 30, z = 0}, {x = 30, z = -40}]\n[[thread]]\nz_range = [-30, 0]\npitch = 2\nstarts = 2\n"
      "hand = \"left\"\nmajor = [29.7, 30]\nminor = [27.4, 27.7]\n",
      "d.toml");
  ASSERT_TRUE(r.outline) << firstMessage(r);
  ASSERT_EQ(r.threads.size(), 1u);
  const ThreadCallout& t = r.threads[0];
  EXPECT_EQ(t.line, 2);
  EXPECT_EQ(t.zLowMm, -30);
  EXPECT_EQ(t.zHighMm, 0);
  EXPECT_EQ(t.pitchMm, 2);
  EXPECT_EQ(t.starts, 2);
  ASSERT_TRUE(t.rightHand);
  EXPECT_FALSE(*t.rightHand);
  ASSERT_TRUE(t.major && t.minor);
  EXPECT_EQ(t.major->least, 29.7);
  EXPECT_EQ(t.minor->greatest, 27.7);
  EXPECT_FALSE(t.pitchDiameter);
}

}  // namespace
}  // namespace lathesim::measure
