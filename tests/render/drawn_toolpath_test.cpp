// The drawn toolpath against the true one: its size stays bounded, and every point of either
// lies within the drawing's error bound of the other (points of the same drawing class: rapid,
// feed, thread), on long straight runs, arcs of short segments, zig-zags, rapids between
// feeds, and a random walk that forces the bound to coarsen it.

#include "render/drawn_toolpath.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <random>
#include <vector>

#include "render/move_points.hpp"

namespace lathesim::render {
namespace {

using interp::MoveKind;

enum class Drawn { Rapid, Feed, Thread };
Drawn drawnAs(const interp::Move& m) {
  if (m.kind == MoveKind::Thread) return Drawn::Thread;
  return interp::isCutting(m.kind) ? Drawn::Feed : Drawn::Rapid;
}

interp::Move straight(MoveKind kind, const RZ& from, const RZ& to, int tool = 1) {
  interp::Move m;
  m.kind = kind;
  m.from = from;
  m.to = to;
  m.tool = tool;
  return m;
}

struct Segment {
  RZ a, b;
  Drawn as;
};

std::vector<Segment> segmentsOf(const std::vector<interp::Move>& moves) {
  std::vector<Segment> segments;
  for (const interp::Move& m : moves) {
    if (m.kind == MoveKind::Dwell) continue;
    const std::vector<RZ> points = movePoints(m);
    for (std::size_t k = 1; k < points.size(); ++k) segments.push_back({points[k - 1], points[k], drawnAs(m)});
  }
  return segments;
}

double distanceToSegment(const RZ& p, const Segment& s) {
  const RZ ab = s.b - s.a;
  const double t = ab.squaredNorm() > 0 ? std::clamp((p - s.a).dot(ab) / ab.squaredNorm(), 0.0, 1.0) : 0.0;
  return (p - (s.a + t * ab)).norm();
}

// The largest distance from a point of `from` (each segment's ends and eight points between)
// to the nearest segment of `to` drawn the same way.
double farthest(const std::vector<Segment>& from, const std::vector<Segment>& to) {
  double worst = 0;
  for (const Segment& s : from)
    for (int k = 0; k <= 9; ++k) {
      const RZ p = s.a + (k / 9.0) * (s.b - s.a);
      double nearest = std::numeric_limits<double>::infinity();
      for (const Segment& t : to)
        if (t.as == s.as) nearest = std::min(nearest, distanceToSegment(p, t));
      worst = std::max(worst, nearest);
    }
  return worst;
}

struct Drawing {
  std::vector<interp::Move> moves;
  double boundMm;
};

Drawing draw(const std::vector<interp::Move>& path, double toleranceMm, std::size_t maxMoves = kDrawnMovesAtMost) {
  DrawnToolpath drawn(toleranceMm, maxMoves);
  for (const interp::Move& m : path) drawn.take(m);
  return {drawn.toolpath(interp::Toolpath{}).moves, drawn.errorBoundMm()};
}

// Both ways within the bound, and the tool left where the last move ended.
void expectWithinBound(const std::vector<interp::Move>& path, const Drawing& drawing) {
  const std::vector<Segment> truth = segmentsOf(path), drawn = segmentsOf(drawing.moves);
  EXPECT_LE(farthest(truth, drawn), drawing.boundMm + 1e-9);
  EXPECT_LE(farthest(drawn, truth), drawing.boundMm + 1e-9);
  ASSERT_FALSE(drawing.moves.empty());
  EXPECT_EQ(drawing.moves.back().to, path.back().to);
}

// 20 000 feeds of 0.005 mm along Z: one line, drawn as runs of at most 128 points (127 moves).
TEST(DrawnToolpath, LongStraightRunIsMergedIntoFewMoves) {
  std::vector<interp::Move> path;
  for (int i = 0; i < 20000; ++i) path.push_back(straight(MoveKind::Feed, RZ(10, -0.005 * i), RZ(10, -0.005 * (i + 1))));
  const Drawing drawing = draw(path, 0.01);
  EXPECT_LE(drawing.moves.size(), 20000u / 127 + 2);
  EXPECT_DOUBLE_EQ(drawing.boundMm, 0.01);
  expectWithinBound(path, drawing);
}

// A circle of radius 10 in 2 000 chords, drawn within 0.01 mm: a chord within 0.01 of the arc
// sweeps at most 2·acos(1 − 0.01/10) = 0.0894 rad, so a turn needs at least 70; merging is
// greedy, so allow twice that.
TEST(DrawnToolpath, ArcOfShortSegmentsKeepsAFewChordsWithinTolerance) {
  std::vector<interp::Move> path;
  const auto at = [](int k) { const double a = 2 * M_PI * k / 2000; return RZ(20 + 10 * std::cos(a), 10 * std::sin(a)); };
  for (int k = 0; k < 2000; ++k) path.push_back(straight(MoveKind::Feed, at(k), at(k + 1)));
  const Drawing drawing = draw(path, 0.01);
  EXPECT_GE(drawing.moves.size(), 70u);
  EXPECT_LE(drawing.moves.size(), 140u);
  expectWithinBound(path, drawing);
}

// What scripts/long_program_memory.sh runs: feeds between X40/X42 and Z0…Z-49, 30 000 of them
// going round the same 50 segments after the first: the drawing keeps those 51, whatever the
// length, and the last move taken once more, last.
TEST(DrawnToolpath, ZigZagOverTheSamePathsKeepsEachOnce) {
  std::vector<interp::Move> path;
  RZ at(20, 0);
  for (int i = 0; i < 30000; ++i) {
    const RZ next(i % 2 ? 20 : 21, -(i % 50));
    path.push_back(straight(MoveKind::Feed, at, next));
    at = next;
  }
  const Drawing drawing = draw(path, 0.01);
  EXPECT_LE(drawing.moves.size(), 52u);
  expectWithinBound(path, drawing);
}

// Turning passes: rapid in, 400 feeds of 0.1 mm along Z, rapid out and back, 30 passes 0.5 mm
// apart, then a thread pass and a dwell at its end. Rapids stay rapids, the thread stays a
// thread, and the dwell (standing still) is not drawn but leaves the tool where it stands.
TEST(DrawnToolpath, RapidsBetweenFeedsKeepTheirKinds) {
  std::vector<interp::Move> path;
  for (int pass = 0; pass < 30; ++pass) {
    const double r = 24.5 - 0.5 * pass;
    path.push_back(straight(MoveKind::Rapid, RZ(26, 2), RZ(r, 2)));
    for (int i = 0; i < 400; ++i) path.push_back(straight(MoveKind::Feed, RZ(r, 2 - 0.1 * i), RZ(r, 2 - 0.1 * (i + 1))));
    path.push_back(straight(MoveKind::Rapid, RZ(r, -38), RZ(26, -38)));
    path.push_back(straight(MoveKind::Rapid, RZ(26, -38), RZ(26, 2)));
  }
  path.push_back(straight(MoveKind::Thread, RZ(9, 2), RZ(9, -20)));
  interp::Move dwell = straight(MoveKind::Dwell, RZ(9, -20), RZ(9, -20), 2);
  path.push_back(dwell);
  const Drawing drawing = draw(path, 0.01);
  // Per pass three rapids and 400 feeds in runs of 127; the last rapid back repeats.
  EXPECT_LE(drawing.moves.size(), 30u * (3 + 4) + 3);
  const auto count = [&](Drawn as) {
    return std::count_if(drawing.moves.begin(), drawing.moves.end(), [&](const interp::Move& m) { return drawnAs(m) == as; });
  };
  EXPECT_GE(count(Drawn::Rapid), 30 * 2 + 1);
  EXPECT_EQ(count(Drawn::Thread), 1);
  EXPECT_EQ(drawing.moves.back().tool, 2);  // the dwell's: the tool picture's
  expectWithinBound(path, drawing);
}

// 1 500 random steps and arcs inside a 50 mm square, held to 100 moves: the tolerance doubles
// until they fit, and the drawing stays within the bound it reports.
TEST(DrawnToolpath, SizeBoundCoarsensTheToleranceAndStaysWithinItsBound) {
  std::mt19937 random(7);
  std::uniform_real_distribution<double> step(-3, 3);
  std::vector<interp::Move> path;
  RZ at(25, -25);
  for (int i = 0; i < 1500; ++i) {
    RZ next = at + RZ(step(random), step(random));
    next = next.cwiseMax(RZ(0, -50)).cwiseMin(RZ(50, 0));
    interp::Move m = straight(i % 7 == 0 ? MoveKind::Rapid : MoveKind::Feed, at, next);
    if (i % 5 == 0 && (next - at).norm() > 0.1) {  // a half circle on the step as diameter
      m.kind = i % 2 ? MoveKind::ArcCW : MoveKind::ArcCCW;
      m.center = 0.5 * (at + next);
    }
    path.push_back(m);
    at = next;
  }
  const Drawing drawing = draw(path, 0.01, 100);
  EXPECT_LE(drawing.moves.size(), 101u);  // and the last move taken
  EXPECT_GT(drawing.boundMm, 0.01);
  expectWithinBound(path, drawing);
}

}  // namespace
}  // namespace lathesim::render
