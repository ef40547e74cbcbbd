// Thread passes written only where they can change anything (sim/thread_history.hpp): the
// stock must come out voxel for voxel as when every pass is written whole, and a pass that
// repeats the one before (a spring pass) must be bounded to its ends.

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <vector>

#include "sim/simulate.hpp"
#include "sim/thread_history.hpp"
#include "tests/sim/thread_test_support.hpp"

namespace lathesim::sim {
namespace {

using test::kTan30;
using test::threadMove;

ConvexPolygon vee() { return test::sharpVee(1.8); }  // 1.8 mm tall

// A G76's passes on a Φ20 bar (Z −12…0) cut from Z3 to Z−8: depths 0.3, 0.45, 0.6, 0.6 (the
// last a spring pass), each started `infeedTan`·depth further along −Z (flank infeed when
// tan 30°, radial when 0) at `startDeg`, with a run-out of `runoutMm` (along and across).
std::vector<interp::Move> passes(double leadMm, double taperMm, double infeedTan, double runoutMm, double startDeg,
                                 interp::SpindleDirection direction) {
  std::vector<interp::Move> moves;
  for (const double depth : {0.3, 0.45, 0.6, 0.6}) {
    const RZ from(10.0 - depth + taperMm, 3.0 - infeedTan * depth);
    const RZ end(10.0 - depth, -8.0);
    moves.push_back(threadMove(from, end, leadMm, startDeg, direction));
    if (runoutMm > 0) moves.push_back(threadMove(end, end + RZ(runoutMm, -runoutMm), leadMm, startDeg, direction));
  }
  return moves;
}

struct ThreadCase {
  const char* name;
  double lead, taper, infeedTan, runout, startDeg;
  interp::SpindleDirection direction;
  double voxel;
};

// Every kind of pass sequence a bound could get wrong: flank and radial infeed, a taper, a
// run-out (a second helix per pass), the other hand, a start angle, two voxel sizes.
TEST(ThreadHistory, BoundedPassesLeaveWhatWholePassesLeave) {
  using D = interp::SpindleDirection;
  for (const ThreadCase c : {ThreadCase{"flank infeed", 2.0, 0, kTan30, 0, 0, D::Clockwise, 0.1},
                       ThreadCase{"radial infeed", 1.5, 0, 0, 0, 0, D::Clockwise, 0.1},
                       ThreadCase{"taper and run-out", 2.0, 0.4, kTan30, 1.0, 0, D::Clockwise, 0.1},
                       ThreadCase{"left hand, start angle", 2.5, 0, kTan30, 0.8, 137, D::CounterClockwise, 0.1},
                       ThreadCase{"finer voxel", 1.75, -0.3, kTan30, 0.5, 45, D::Clockwise, 0.07}}) {
    SCOPED_TRACE(c.name);
    const StockSpec bar{20, 12, 0};
    interp::Toolpath path;
    path.blockCount = 1;
    path.moves = passes(c.lead, c.taper, c.infeedTan, c.runout, c.startDeg, c.direction);
    Stock bounded(bar, c.voxel);
    simulate(path, {{1, vee()}}, bounded);

    Stock whole(bar, c.voxel);
    for (const interp::Move& m : path.moves) {
      const int sense = m.spindleDirection == D::Clockwise ? 1 : -1;
      whole.remove(HelicalSweep(vee(), m.from, m.to, m.thread.revolutions(m.from, m.to), sense * m.thread.startAngleDeg,
                                sense));
    }
    EXPECT_EQ(bounded.volumeMm3(), whole.volumeMm3());
    EXPECT_EQ(bounded.activeVoxelCount(), whole.activeVoxelCount());
    // φ at every voxel centre of a slab through the thread, all round.
    std::vector<Eigen::Vector3d> points;
    for (double x = -10.5; x <= 10.5; x += c.voxel)
      for (double y = -10.5; y <= 10.5; y += c.voxel)
        if (std::hypot(x, y) > 8.5 && std::hypot(x, y) < 10.5)
          for (const double z : {-1.0, -4.3, -7.9}) points.emplace_back(x, y, z);
    std::vector<double> a(points.size()), b(points.size());
    bounded.signedDistancesAt(points, a);
    whole.signedDistancesAt(points, b);
    int differing = 0;
    for (std::size_t i = 0; i < points.size(); ++i) differing += a[i] != b[i];
    EXPECT_EQ(differing, 0) << "of " << points.size() << " points";
  }
}

ThreadPass straightPass(double depth, double startDeg, int sense, double leadMm = 2.0) {
  const RZ from(10.0 - depth, 3.0), to(10.0 - depth, -8.0);
  return {vee(), from, to, (from.y() - to.y()) / leadMm, startDeg, sense};
}

// A spring pass (the same pass again) removes nothing: it is bounded to its ends, Z3 and Z−8.
// A point on the groove's flank halfway along, where the whole pass would be written, is left
// out; the ends are kept. A pass of the other hand, or another lead, shares no helix.
TEST(ThreadHistory, SpringPassIsBoundedToItsEnds) {
  ThreadHistory history;
  EXPECT_FALSE(history.changesOf(straightPass(0.6, 0, 1)));
  const auto spring = history.changesOf(straightPass(0.6, 0, 1));
  ASSERT_TRUE(spring);
  // At azimuth 0 the spindle is at 0° when the pass starts: the apex stands at Z3 − k·2, radius
  // 9.4; the flank at radius 9.7 lies 0.3·tan 30° to either side of it.
  const double flankZ = 3.0 - 2 * 2.0 + 0.3 * kTan30;
  EXPECT_FALSE(spring->mayChange(9.7, 0, flankZ, 0.2, 0.3));
  EXPECT_TRUE(spring->mayChange(9.7, 0, 3.0 + 0.3 * kTan30, 0.2, 0.3));
  EXPECT_TRUE(spring->mayChange(9.7, 0, -8.0 + 0.3 * kTan30, 0.2, 0.3));
  EXPECT_FALSE(history.changesOf(straightPass(0.6, 0, -1)));       // the other hand
  EXPECT_FALSE(history.changesOf(straightPass(0.6, 0, 1, 2.5)));   // another lead
}

// A deeper pass at the same start: only near its new tip and flanks. 0.3 mm deeper, radially:
// the old groove's flank 1 mm out from the apex (radius 10.5, outside the band of the new
// apex region) is still in the band of the new flank, but a point in the middle of the old
// groove's air, 0.9 mm beyond both new flanks' band, is left out.
TEST(ThreadHistory, DeeperPassIsBoundedToItsSliver) {
  ThreadHistory history;
  history.changesOf(straightPass(0.3, 0, 1));
  const auto deeper = history.changesOf(straightPass(0.6, 0, 1));
  ASSERT_TRUE(deeper);
  const double apexZ = 3.0 - 2 * 2.0;  // at azimuth 0, three turns in
  EXPECT_TRUE(deeper->mayChange(9.4, 0, apexZ, 0.0, 0.1));  // the new apex
  // Radius 10.6, in the middle of the groove: the sliver (a band 0.3 · sin 60° thick inside each
  // flank) lies 1.2·tan 30° − 0.26 ≈ 0.43 mm away, beyond 0.1 + 0.1 but not beyond 0.1 + 0.4.
  EXPECT_FALSE(deeper->mayChange(10.6, 0, apexZ, 0.1, 0.1));
  EXPECT_TRUE(deeper->mayChange(10.6, 0, apexZ, 0.1, 0.4));
}

}  // namespace
}  // namespace lathesim::sim
