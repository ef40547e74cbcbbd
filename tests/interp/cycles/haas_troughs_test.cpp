// Haas G71/G72 contours with troughs (the Haas operator's manual, "Troughs": all the material
// above the troughs is roughed first, then the troughs in the direction of Z; at most ten a
// cycle; type 1 and type 2 differ in their retraction, "Type 2 details": type 2 follows the
// path after each pass and retracts by Setting 73). The expected legs are worked by hand from
// that rule as lathesim reads it (stock_removal.cpp): levels k·D deep from A′; each stretch of
// a level that lies in the material is one cut; the stretch reached from Z_A′ at every level
// first, then each trough level by level, troughs in Z order; a trough is entered over X_A′,
// down to e above the top of its entry wall (no deeper than the level above), at feed onto the
// wall and down it; a type I stretch ends by the 45° retract e, a type II one by following the
// contour up to the level above and backing off e in X.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "../test_support.hpp"
#include "interp/contour/contour_geometry.hpp"
#include "interp/cycles/roughing_cycle.hpp"
#include "roughing_test_support.hpp"

namespace lathesim::interp {
namespace {

using test::expectLegsNear;
using test::HandLeg;
using test::segment;

using test::kRapid;
using test::kFeed;

/// One hand-worked leg given by where it ends; it starts where the one before it ended.
struct To {
  MoveKind kind;
  double r, z;
  int step;
};

std::vector<HandLeg> chain(double r, double z, const std::vector<To>& legs) {
  std::vector<HandLeg> out;
  for (const To& to : legs) {
    out.push_back({to.kind, r, z, to.r, to.z, to.step});
    r = to.r;
    z = to.z;
  }
  return out;
}

/// G72 is G71 with the axes exchanged: the G71 cases below, moved to a facing contour by
/// (r, z) → (z + 40, r − 30), expand to the G71 legs moved the same way.
RZ facingPoint(const RZ& p) { return RZ(p.y() + 40, p.x() - 30); }
Contour facingContour(Contour contour) {
  for (ContourSegment& s : contour) {
    s.from = facingPoint(s.from);
    s.to = facingPoint(s.to);
  }
  return contour;
}
std::vector<HandLeg> facingLegs(std::vector<HandLeg> legs) {
  for (HandLeg& leg : legs) {
    const RZ from = facingPoint(RZ(leg.r0, leg.z0));
    const RZ to = facingPoint(RZ(leg.r1, leg.z1));
    leg = {leg.kind, from.x(), from.y(), to.x(), to.y(), leg.step};
  }
  return legs;
}

RoughingParams haasParams(double depthMm, double retractMm, bool typeII) {
  RoughingParams p = test::params(depthMm, retractMm, 0, 0);
  p.retractAtFeed = false;
  p.typeII = typeII;
  p.haasTroughs = true;
  return p;
}

// One trough, type I. A = (26, 2); N1 G00 to B = (10, 2); then (10, −10), up to the crest
// (20, −15), down to (13, −22), the floor to (13, −25), up to (23, −30), (25, −32). Depth =
// 26 − r; D = 2 → levels 2 … 14 (16 is B's depth). The crest is 6 deep: levels 2, 4 and 6 run
// over the trough (6 touches the crest) to the last wall, at Z −31, −29.5, −28.5; levels 8–14
// stop on the first wall at Z −14, −13, −12, −11. Then the trough: levels 8, 10, 12 from its
// entry wall (Z −17, −19, −21) to its exit wall (Z −27.5, −26.5, −25.5), each entered over
// X_A′ = r 26, down to 0.5 above the wall's top (the crest for level 8, then the level above).
// Each stretch ends with the 45° retract (+0.5, +0.5). Then back over r 26 to Z 2, rapid to B,
// the contour, rapid to A.
Contour oneTrough() {
  return {segment(kRapid, 26, 2, 10, 2, 1),     segment(kFeed, 10, 2, 10, -10, 2),
          segment(kFeed, 10, -10, 20, -15, 3),  segment(kFeed, 20, -15, 13, -22, 4),
          segment(kFeed, 13, -22, 13, -25, 5),  segment(kFeed, 13, -25, 23, -30, 6),
          segment(kFeed, 23, -30, 25, -32, 7)};
}

std::vector<HandLeg> oneTroughLegs() {
  return chain(26, 2, {
      // above the trough
      {kRapid, 24, 2, 2},    {kFeed, 24, -31, 3},    {kRapid, 24.5, -30.5, 4},
      {kRapid, 24.5, 2, 5},  {kRapid, 22, 2, 6},     {kFeed, 22, -29.5, 3},  {kRapid, 22.5, -29, 4},
      {kRapid, 22.5, 2, 5},  {kRapid, 20, 2, 6},     {kFeed, 20, -28.5, 3},  {kRapid, 20.5, -28, 4},
      {kRapid, 20.5, 2, 5},  {kRapid, 18, 2, 6},     {kFeed, 18, -14, 3},    {kRapid, 18.5, -13.5, 4},
      {kRapid, 18.5, 2, 5},  {kRapid, 16, 2, 6},     {kFeed, 16, -13, 3},    {kRapid, 16.5, -12.5, 4},
      {kRapid, 16.5, 2, 5},  {kRapid, 14, 2, 6},     {kFeed, 14, -12, 3},    {kRapid, 14.5, -11.5, 4},
      {kRapid, 14.5, 2, 5},  {kRapid, 12, 2, 6},     {kFeed, 12, -11, 3},    {kRapid, 12.5, -10.5, 4},
      // the trough, level 8
      {kRapid, 26, -10.5, 5}, {kRapid, 26, -15, 5},  {kRapid, 20.5, -15, 5},
      {kFeed, 20, -15, 6},   {kFeed, 18, -17, 6},    {kFeed, 18, -27.5, 3},  {kRapid, 18.5, -27, 4},
      // level 10
      {kRapid, 26, -27, 5},  {kRapid, 26, -17, 5},   {kRapid, 18.5, -17, 5},
      {kFeed, 18, -17, 6},   {kFeed, 16, -19, 6},    {kFeed, 16, -26.5, 3},  {kRapid, 16.5, -26, 4},
      // level 12
      {kRapid, 26, -26, 5},  {kRapid, 26, -19, 5},   {kRapid, 16.5, -19, 5},
      {kFeed, 16, -19, 6},   {kFeed, 14, -21, 6},    {kFeed, 14, -25.5, 3},  {kRapid, 14.5, -25, 4},
      // back to Z_A′, the closing pass, back to A
      {kRapid, 26, -25, 5},  {kRapid, 26, 2, 5},     {kRapid, 10, 2, 6},
      {kFeed, 10, -10, 7},   {kFeed, 20, -15, 7},    {kFeed, 13, -22, 7},    {kFeed, 13, -25, 7},
      {kFeed, 23, -30, 7},   {kFeed, 25, -32, 7},    {kRapid, 26, 2, 8}});
}

TEST(HaasTroughs, OneTroughTypeIG71) {
  auto legs = turningRoughingLegs(RZ(26, 2), oneTrough(), haasParams(2, 0.5, false));
  ASSERT_TRUE(legs.ok()) << legs.error().message;
  expectLegsNear(legs.value(), oneTroughLegs());
}

TEST(HaasTroughs, OneTroughTypeIG72) {
  auto legs = facingRoughingLegs(facingPoint(RZ(26, 2)), facingContour(oneTrough()), haasParams(2, 0.5, false));
  ASSERT_TRUE(legs.ok()) << legs.error().message;
  expectLegsNear(legs.value(), facingLegs(oneTroughLegs()));
}

// Two troughs, type II (the P block moves X and Z). A = (30, 2); N1 G00 to B = (10, 0); then
// (10, −5), a wall up to the crest (24, −5)–(24, −8), down to the floor (16, −8)–(16, −12), up
// to the crest (25, −12)–(25, −15), down to the floor (20, −15)–(20, −18), up to (28, −18),
// (28, −20). Depth = 30 − r; D = 4 → levels at r 26, 22, 18, 14 (20 is B's depth); e = 1.
// Level 26 runs over both troughs to the last wall (Z −18); level 22 has three stretches (to
// the first wall, in trough 1, in trough 2), 18 two (to the first wall, in trough 1), 14 one.
// Order: 26, then the stretches from Z_A′ at 22, 18, 14, then trough 1 at 22 and 18, then
// trough 2 at 22. Each stretch ends by following the contour up to the level above (or over a
// crest's flat to where it turns down) and backing off 1 in X. A trough's stretch is entered
// over r 30, down to e above the wall's top but no deeper than the level above (r 26 for the
// crests, 23 inside trough 1), at feed onto the top and down the wall.
Contour twoTroughs() {
  return {segment(kRapid, 30, 2, 10, 0, 1),     segment(kFeed, 10, 0, 10, -5, 2),
          segment(kFeed, 10, -5, 24, -5, 3),    segment(kFeed, 24, -5, 24, -8, 4),
          segment(kFeed, 24, -8, 16, -8, 5),    segment(kFeed, 16, -8, 16, -12, 6),
          segment(kFeed, 16, -12, 25, -12, 7),  segment(kFeed, 25, -12, 25, -15, 8),
          segment(kFeed, 25, -15, 20, -15, 9),  segment(kFeed, 20, -15, 20, -18, 10),
          segment(kFeed, 20, -18, 28, -18, 11), segment(kFeed, 28, -18, 28, -20, 12)};
}

std::vector<HandLeg> twoTroughLegs() {
  return chain(30, 2, {
      // above the troughs: level 26, then the stretches from Z_A′ at 22, 18, 14
      {kRapid, 26, 2, 2},   {kFeed, 26, -18, 3},  {kFeed, 28, -18, 4},  {kFeed, 28, -20, 4}, {kRapid, 29, -20, 4},
      {kRapid, 29, 2, 5},   {kRapid, 22, 2, 6},   {kFeed, 22, -5, 3},   {kFeed, 24, -5, 4},
      {kFeed, 24, -8, 4},   {kRapid, 25, -8, 4},
      {kRapid, 25, 2, 5},   {kRapid, 18, 2, 6},   {kFeed, 18, -5, 3},   {kFeed, 22, -5, 4},  {kRapid, 23, -5, 4},
      {kRapid, 23, 2, 5},   {kRapid, 14, 2, 6},   {kFeed, 14, -5, 3},   {kFeed, 18, -5, 4},  {kRapid, 19, -5, 4},
      // trough 1, level 22 then 18
      {kRapid, 30, -5, 5},  {kRapid, 30, -8, 5},  {kRapid, 26, -8, 5},  {kFeed, 24, -8, 6},  {kFeed, 22, -8, 6},
      {kFeed, 22, -12, 3},  {kFeed, 25, -12, 4},  {kFeed, 25, -15, 4},  {kRapid, 26, -15, 4},
      {kRapid, 30, -15, 5}, {kRapid, 30, -8, 5},  {kRapid, 23, -8, 5},  {kFeed, 22, -8, 6},  {kFeed, 18, -8, 6},
      {kFeed, 18, -12, 3},  {kFeed, 22, -12, 4},  {kRapid, 23, -12, 4},
      // trough 2, level 22
      {kRapid, 30, -12, 5}, {kRapid, 30, -15, 5}, {kRapid, 26, -15, 5}, {kFeed, 25, -15, 6}, {kFeed, 22, -15, 6},
      {kFeed, 22, -18, 3},  {kFeed, 26, -18, 4},  {kRapid, 27, -18, 4},
      // back to Z_A′, the closing pass, back to A
      {kRapid, 30, -18, 5}, {kRapid, 30, 2, 5},   {kRapid, 10, 0, 6},
      {kFeed, 10, -5, 7},   {kFeed, 24, -5, 7},   {kFeed, 24, -8, 7},   {kFeed, 16, -8, 7},  {kFeed, 16, -12, 7},
      {kFeed, 25, -12, 7},  {kFeed, 25, -15, 7},  {kFeed, 20, -15, 7},  {kFeed, 20, -18, 7}, {kFeed, 28, -18, 7},
      {kFeed, 28, -20, 7},  {kRapid, 30, 2, 8}});
}

TEST(HaasTroughs, TwoTroughsTypeIIG71) {
  auto legs = turningRoughingLegs(RZ(30, 2), twoTroughs(), haasParams(4, 1, true));
  ASSERT_TRUE(legs.ok()) << legs.error().message;
  expectLegsNear(legs.value(), twoTroughLegs());
}

TEST(HaasTroughs, TwoTroughsTypeIIG72) {
  auto legs = facingRoughingLegs(facingPoint(RZ(30, 2)), facingContour(twoTroughs()), haasParams(4, 1, true));
  ASSERT_TRUE(legs.ok()) << legs.error().message;
  expectLegsNear(legs.value(), facingLegs(twoTroughLegs()));
}

// The move limit holds in the trough order too: one leg fewer than the two-trough contour's
// is refused at its P block.
TEST(HaasTroughs, StopsAtTheMoveLimit) {
  RoughingParams params = haasParams(4, 1, true);
  params.maxLegs = twoTroughLegs().size() - 1;
  test::expectRoughingError(turningRoughingLegs(RZ(30, 2), twoTroughs(), params), 1, 1, "would make more than");
  params.maxLegs = twoTroughLegs().size();
  EXPECT_TRUE(turningRoughingLegs(RZ(30, 2), twoTroughs(), params).ok());
}

// At most ten troughs a cycle ("Troughs"): eleven V troughs on a G72 face are refused at the
// block that reaches the eleventh's bottom; ten are roughed.
Contour vTroughs(int count) {
  Contour contour = {segment(kRapid, 26, 2, 10, 2, 1), segment(kFeed, 10, 2, 10, -2, 2)};
  double z = -2;
  int line = 3;
  for (int i = 0; i < count; ++i) {
    contour.push_back(segment(kFeed, i == 0 ? 10 : 15, z, 20, z - 1, line++));  // up to a crest
    contour.push_back(segment(kFeed, 20, z - 1, 15, z - 2, line++));            // down to a bottom
    z -= 2;
  }
  contour.push_back(segment(kFeed, 15, z, 25, z - 1, line));
  return contour;
}

TEST(HaasTroughs, AtMostTenTroughsACycle) {
  const RoughingParams params = haasParams(2, 0.5, false);
  test::expectRoughingError(facingRoughingLegs(facingPoint(RZ(26, 2)), facingContour(vTroughs(11)), params), 24, 1,
                            "G72 contour has 11 troughs (this block reaches the bottom of trough 11)");
  EXPECT_TRUE(facingRoughingLegs(facingPoint(RZ(26, 2)), facingContour(vTroughs(10)), params).ok());
}

// The Fanuc/GSK engine is unchanged: without haasTroughs the two-trough type II contour is
// roughed level by level (every level's stretches before the next level's), as before.
TEST(HaasTroughs, FanucStillRoughsLevelByLevel) {
  RoughingParams params = haasParams(4, 1, true);
  params.haasTroughs = false;
  auto legs = turningRoughingLegs(RZ(30, 2), twoTroughs(), params);
  ASSERT_TRUE(legs.ok()) << legs.error().message;
  std::vector<double> levels;
  for (const CycleLeg& leg : legs.value()) {
    if (leg.step == 3) levels.push_back(leg.from.x());
  }
  EXPECT_EQ(levels, (std::vector<double>{26, 22, 22, 22, 18, 18, 14}));
}


// A sweep over contours with one to three troughs of random crests, floors and widths, depths
// of cut D and allowances, type I and II, G71 and G72 (the G72 case is the G71 one moved onto a
// face as above and its legs moved back), where a level could be lost or a trough cut from
// above before the material over it. Every case, in G71's axes, A′ = A + (u, w):
//   - no cut, infeed, retract or rapid crosses the rough contour;
//   - every level cut (step 3) lies a whole number of D below A′, and, below the first level,
//     under a level cut D above it made earlier that spans its Z (no cut deeper than D, no
//     trough entered before the material over it is gone);
//   - every point of the material lies at most D above a level cut through it, or within D of
//     the rough contour (what the closing pass along it takes): no level lost, every trough
//     bottom reached.
struct SweepCase {
  Contour contour;
  RZ start;
  RoughingParams params;
};

class Lcg {
 public:
  explicit Lcg(unsigned seed) : state_(seed) {}
  double uniform(double lo, double hi) {
    state_ = state_ * 1103515245u + 12345u;
    return lo + (hi - lo) * ((state_ >> 8) % 100000) / 100000.0;
  }

 private:
  unsigned state_;
};

// A = (30, 2); B at radius 6–10 (type I: at Z 2; type II: at Z 0); then 1–3 troughs, each a
// slanted wall up to a crest 2–8 deep, a flat, a slanted wall down to a floor between 1 deeper
// and r 1 (deeper than B at times), a flat; then up to a last flat 1–2 deep. Every block moves
// Z.
SweepCase sweepCase(Lcg& random, int troughs, bool typeII) {
  SweepCase c;
  c.start = RZ(30, 2);
  const double rB = random.uniform(6, 10);
  RZ at(rB, typeII ? 0.0 : 2.0);
  int line = 1;
  c.contour.push_back(segment(kRapid, 30, 2, at.x(), at.y(), line++));
  auto to = [&](double r, double dz) {
    c.contour.push_back(segment(kFeed, at.x(), at.y(), r, at.y() - dz, line++));
    at = RZ(r, at.y() - dz);
  };
  to(rB, random.uniform(0.5, 3));
  for (int i = 0; i < troughs; ++i) {
    const double crest = 30 - random.uniform(2, 8);
    to(crest, random.uniform(0.3, 3));
    to(crest, random.uniform(0.2, 2));
    to(crest - random.uniform(1, crest - 1), random.uniform(0.3, 3));  // down to r 1, deeper than B at times
    to(at.x(), random.uniform(0.2, 2));
  }
  to(30 - random.uniform(1, 2), random.uniform(0.3, 3));
  to(at.x(), 1);
  return c;
}

void expectRoughedByLevels(const std::vector<CycleLeg>& legs, const SweepCase& c, Lcg& random) {
  const RoughingParams& p = c.params;
  const RZ offset(p.allowanceXMm + p.roughAllowanceXMm, p.allowanceZMm + p.roughAllowanceZMm);
  const Contour rough = translatedContour(c.contour, offset);
  const RZ shiftedStart = c.start + offset;
  test::expectNoGouge(legs, rough, -1.0);
  auto roughR = [&](double z) {  // the rough contour's radius at z (B′'s before its Z)
    const std::vector<double> xs = test::contourXsAt(rough, z);
    return xs.empty() ? rough.front().to.x() : *std::max_element(xs.begin(), xs.end());
  };
  // The rapids of the roughing too (up to the infeed onto the closing pass's contour, which
  // with a rough allowance lies inside the rough one).
  const auto closing = std::find_if(legs.begin(), legs.end(), [](const CycleLeg& leg) { return leg.step == 7; });
  for (auto it = legs.begin(); it + 1 < closing; ++it) {
    const CycleLeg& leg = *it;
    if (leg.kind != kRapid) continue;
    for (int i = 0; i <= 20; ++i) {
      const RZ q = test::legPoint(leg, i / 20.0);
      if (q.y() > rough.front().to.y() || q.y() < rough.back().to.y()) continue;
      EXPECT_GE(q.x(), roughR(q.y()) - 1e-9) << "rapid step " << leg.step << " at " << q.x() << ", " << q.y();
    }
  }
  std::vector<const CycleLeg*> cuts;
  for (const CycleLeg& leg : legs) {
    if (leg.step != 3) continue;
    const double depth = shiftedStart.x() - leg.from.x();
    const double k = std::round(depth / p.depthMm);
    EXPECT_NEAR(depth, k * p.depthMm, 1e-9);
    EXPECT_NEAR(leg.from.x(), leg.to.x(), 1e-12);
    const double zHi = std::max(leg.from.y(), leg.to.y()), zLo = std::min(leg.from.y(), leg.to.y());
    if (k > 1) {
      const bool under = std::any_of(cuts.begin(), cuts.end(), [&](const CycleLeg* above) {
        return std::abs(above->from.x() - (leg.from.x() + p.depthMm)) < 1e-9 &&
               std::max(above->from.y(), above->to.y()) >= zHi - 1e-9 &&
               std::min(above->from.y(), above->to.y()) <= zLo + 1e-9;
      });
      EXPECT_TRUE(under) << "level cut at r " << leg.from.x() << " Z " << zHi << " to " << zLo
                         << " before the material above it is cut";
    }
    cuts.push_back(&leg);
  }
  // The Haas order: the cuts from Z_A′ (the material above the troughs) first; then, of two
  // trough cuts, the later lies under the earlier (the same trough, deeper) or wholly beyond it
  // along Z (a later trough), never back toward A.
  auto zHiOf = [](const CycleLeg* leg) { return std::max(leg->from.y(), leg->to.y()); };
  auto zLoOf = [](const CycleLeg* leg) { return std::min(leg->from.y(), leg->to.y()); };
  const auto fromStart = [&](const CycleLeg* leg) { return std::abs(leg->from.y() - shiftedStart.y()) < 1e-9; };
  const auto firstTrough = std::find_if_not(cuts.begin(), cuts.end(), fromStart);
  EXPECT_TRUE(std::none_of(firstTrough, cuts.end(), fromStart)) << "a cut from Z_A′ after a trough's";
  for (auto i = firstTrough; i != cuts.end(); ++i) {
    for (auto j = i + 1; j != cuts.end(); ++j) {
      const bool under = zHiOf(*j) <= zHiOf(*i) + 1e-9 && zLoOf(*j) >= zLoOf(*i) - 1e-9;
      const bool beyond = zHiOf(*j) <= zLoOf(*i) + 1e-9;
      EXPECT_TRUE(under || beyond) << "trough cut at r " << (*j)->from.x() << " Z " << zHiOf(*j)
                                   << " after the one at r " << (*i)->from.x() << " Z " << zHiOf(*i);
    }
  }
  const double zEnd = rough.back().to.y();
  for (int i = 0; i < 400; ++i) {
    const double z = random.uniform(zEnd, shiftedStart.y());
    const double floorR = roughR(z);
    if (floorR >= shiftedStart.x()) continue;
    const double r = random.uniform(floorR, shiftedStart.x());
    const double levelR = shiftedStart.x() - std::ceil((shiftedStart.x() - r) / p.depthMm - 1e-9) * p.depthMm;
    if (levelR <= floorR + 1e-6) continue;  // within D of the contour: the closing pass's
    const bool cut = std::any_of(cuts.begin(), cuts.end(), [&](const CycleLeg* leg) {
      return std::abs(leg->from.x() - levelR) < 1e-9 && std::max(leg->from.y(), leg->to.y()) >= z - 1e-9 &&
             std::min(leg->from.y(), leg->to.y()) <= z + 1e-9;
    });
    EXPECT_TRUE(cut) << "no level cut at r " << levelR << " over Z " << z << " (material at r " << r << ")";
  }
}

TEST(HaasTroughs, SweepEveryLevelWithinDAndEveryTroughReached) {
  Lcg random(12);
  for (int n = 0; n < 240; ++n) {
    const bool typeII = n % 2 == 1;
    const bool facing = n % 4 >= 2;
    SweepCase c = sweepCase(random, 1 + n % 3, typeII);
    c.params = haasParams(std::vector<double>{0.7, 1.3, 2.0, 2.5, 3.1}[n % 5], random.uniform(0, 0.6), typeII);
    if (n % 3 == 0) {
      c.params.allowanceXMm = random.uniform(0, 0.4);
      c.params.allowanceZMm = random.uniform(0, 0.15);  // narrower than the narrowest trough floor
      c.params.roughAllowanceXMm = random.uniform(0, 0.2);
    }
    SCOPED_TRACE(testing::Message() << "case " << n << (facing ? " G72" : " G71") << (typeII ? " type II" : " type I")
                                    << " D " << c.params.depthMm);
    Result<std::vector<CycleLeg>> legs = Error{0, 0, ""};
    if (!facing) {
      legs = turningRoughingLegs(c.start, c.contour, c.params);
    } else {
      RoughingParams mirrored = c.params;
      mirrored.allowanceXMm = c.params.allowanceZMm;
      mirrored.allowanceZMm = c.params.allowanceXMm;
      mirrored.roughAllowanceXMm = c.params.roughAllowanceZMm;
      mirrored.roughAllowanceZMm = c.params.roughAllowanceXMm;
      legs = facingRoughingLegs(facingPoint(c.start), facingContour(c.contour), mirrored);
      if (legs.ok()) {
        for (CycleLeg& leg : legs.value()) {
          leg.from = RZ(leg.from.y() + 30, leg.from.x() - 40);
          leg.to = RZ(leg.to.y() + 30, leg.to.x() - 40);
        }
      }
    }
    ASSERT_TRUE(legs.ok()) << legs.error().message;
    expectRoughedByLevels(legs.value(), c, random);
  }
}

}  // namespace
}  // namespace lathesim::interp
