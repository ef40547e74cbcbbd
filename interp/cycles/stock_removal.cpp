// G71/G72 stock removal (lathe-cycles.md §3–4, GSK980TDi 3.23.1–3.23.2), written in G71's axes:
// "X" is the step axis (levels of constant X), "Z" the cutting axis (passes parallel to Z).
// G72 runs the same code with the axes exchanged.
//
// Rough contour: the finishing contour translated by the allowance (Δu/2, Δw), arcs keep
// their radius (translatedContour). A′ = A + allowance, B′ = where its ns block ends, C′ =
// where its last block ends. The step direction is the sign of X_B′ − X_A′ (toward the axis
// for OD work, away from it for boring); the cutting direction is the way the contour after
// the ns block moves in Z. Level k lies at X_k = X_A′ + k·Δd in the step direction, for every
// k with k·Δd short of the depth to cut (type I: to B′; type II: to the deepest contour
// point): the last partial depth is left to the semi-finishing pass.
//
// Steps (CycleLeg::step), type I:
//   1 rapid  A → A′
//   2 infeed A′ → (X_1, Z_A′)                 rapid if the ns block is G00, else feed
//   3 feed   along Z to where level k meets the rough contour (its last meeting point
//            along the contour; C′'s Z if the level never meets it)
//   4 45° retract by e in both axes, back toward A′      feed if retractAtFeed, else rapid
//   5 rapid  in Z back to Z_A′
//   6 infeed Δd + e to the next level (as step 2); after the last level, to B′
//   7 feed   the semi-finishing pass along the rough contour B′ → C′, arcs as arcs (a G00
//            block inside the contour is cut at feed too)
//   8 rapid  C′ → A
// Type II (pockets: Z monotonic, X free) [GSK: "at the end of each level the tool follows the
// contour, then backs off by e; no 45° escape"; "when it moves on to the next pocket, the last
// e of the approach is made at G1"; "all roughing first, then the semi-finishing pass"].
// The levels run down to the deepest point of the contour. Each level is cut in intervals:
// the stretches of the line X = X_k, from Z_A′ to Z_C′, where the level lies in the material,
// i.e. on A′'s side of the contour (before B′'s Z, on A′'s side of B′'s X). Levels are taken
// in order, and each level's intervals in cutting order. For each interval:
//   2/6 an interval starting at Z_A′: from where the tool is (back at Z_A′) infeed to the
//       level as in type I
//   an interval starting further on, at a pocket's entry wall:
//   5   rapid up to X_A′ (unless already above the wall's top, see below), rapid in Z to the
//       top W of the entry wall (walking the contour back from the level while it climbs:
//       up to the previous level or to a crest — it stops at a flat), rapid to e short of W
//       but no deeper than the previous level (beside a flat the band between the previous
//       level and the flat is still there)
//   6   feed the rest onto W (the last e), then down the wall along the contour to the level
//   3   feed along Z to the interval's end
//   4   feed along the contour from there while it climbs back toward A′ (flats included),
//       up to the previous level, a crest, or C′; then back off e in X (feed if
//       retractAtFeed, else rapid)
//   5   before the next level's interval at Z_A′: rapid along Z to Z_A′ at that height if this
//       interval began at Z_A′ (everything above it is cut), else up to X_A′ first
// After the last level: 5 back to Z_A′ as above, then 6 infeed to B′ (G00/G01 as the ns
// block), 7 the semi-finishing pass, 8 rapid C′ → A, as in type I. A wall's descent and the
// climb out take away the band between two levels next to the walls, so each band is cut
// whole and every move stays on A′'s side of the rough contour.
// The legs of zero length are left out.
// Haas's one-block G71/G72 may add a rough allowance I (X, a radius) and K (Z): the levels then
// rough against the contour translated by (Δu/2 + I, Δw + K) (A′ moves with it), and steps 6–7
// go to and follow the contour translated by (Δu/2, Δw) alone. Without them both are the same.
// Haas troughs (RoughingParams::haasTroughs; the Haas operator's manual, "Troughs"): a contour
// that turns back deeper after the ns block (contour_troughs.hpp), type I or II, is cut by the
// type II steps above with its stretches in another order: "all material above the troughs is
// roughed first, followed by the troughs in the direction of Z". Each stretch of level k lies
// under one stretch of level k − 1; taken depth first, the stretches from Z_A′ come first, then
// each trough level by level, troughs in Z order (regionOrder). Type I ends each stretch by step
// 4 of type I (the 45° retract e, no further back in Z than the stretch began) instead of the
// climb: "Type 1 and Type 2 differ in their retraction". Type I is then checked by the type II
// rules (Z monotonic, X free). More than kHaasMaxTroughs troughs: an error at the block that
// ends the first one too many.
//
// Errors, each at the contour block to blame (the ns block for Δd and e; line 0 for an
// empty contour): empty contour; Δd ≤ 0; e < 0; ns block an arc; ns block not moving in X;
// type I: a block moving X back toward B, or an arc turning in X inside its span; both
// types: a block moving Z against the earlier blocks, or an arc turning in Z inside its span;
// more legs than `maxLegs` (the move limit), found before they fill memory.
// "Monotonic in X" for type I means: after the ns block, X moves only away from B, toward
// A's side; the ns block itself (the approach A → B) is exempt.

#include "interp/cycles/stock_removal.hpp"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <iterator>
#include <numbers>
#include <optional>
#include <string>
#include <utility>

#include <fmt/format.h>

#include "interp/base/tolerance.hpp"
#include "interp/contour/contour_geometry.hpp"
#include "interp/contour/contour_troughs.hpp"

namespace lathesim::interp {
namespace {

constexpr double kHalfPi = std::numbers::pi / 2;

Error errorAt(const ContourSegment& segment, std::string message) {
  return Error{segment.line, segment.column, std::move(message)};
}

/// +1 or −1, the way the contour after the ns block moves in Z (−1 if it never does).
double cuttingDirection(const Contour& contour) {
  for (std::size_t i = 1; i < contour.size(); ++i) {
    const double dz = contour[i].to.y() - contour[i].from.y();
    if (std::abs(dz) > kTolMm) return dz > 0 ? 1.0 : -1.0;
  }
  const double dz = contour.front().to.y() - contour.front().from.y();
  return dz > kTolMm ? 1.0 : -1.0;
}

/// Why the contour cannot be roughed, or nullopt. `stepDir` is the sign of X_B − X_A.
std::optional<Error> contourProblem(const Contour& contour, const RoughingParams& params,
                                    double stepDir, double cutDir,
                                    const StockRemovalNames& names) {
  const char* cycle = names.cycle;
  for (std::size_t i = 1; i < contour.size(); ++i) {
    const ContourSegment& segment = contour[i];
    const RZ along = segment.to - segment.from;
    const bool arc = isArc(segment.kind);
    if (!params.typeII) {
      if (along.x() * stepDir > kTolMm) {
        return errorAt(segment, fmt::format(
            "{} type I contour must be monotonic in {}: this block moves {} back toward B "
            "(expected {} to keep moving from B toward the start point's side; type II, with "
            "both axes in the ns block, allows pockets)",
            cycle, names.stepAxis, names.stepAxis, names.stepAxis));
      }
      if (arc && (arcPassesAngleInside(segment, kHalfPi) ||
                  arcPassesAngleInside(segment, -kHalfPi))) {
        return errorAt(segment, fmt::format(
            "{} type I contour must be monotonic in {}: this arc reverses {} inside its span "
            "(expected its {} to keep moving one way between its ends)",
            cycle, names.stepAxis, names.stepAxis, names.stepAxis));
      }
    }
    if (along.y() * cutDir < -kTolMm) {
      return errorAt(segment, fmt::format(
          "{} contour must be monotonic in {}: this block moves {} against the blocks before "
          "it (expected every block to move {} the same way, or not at all)",
          cycle, names.cutAxis, names.cutAxis, names.cutAxis));
    }
    if (arc && (arcPassesAngleInside(segment, 0) ||
                arcPassesAngleInside(segment, std::numbers::pi))) {
      return errorAt(segment, fmt::format(
          "{} contour must be monotonic in {}: this arc reverses {} inside its span "
          "(expected its {} to keep moving one way between its ends)",
          cycle, names.cutAxis, names.cutAxis, names.cutAxis));
    }
  }
  return std::nullopt;
}

/// Builds the leg list, leaving out straight legs of no length. Past `maxLegs` legs it keeps
/// no more and is `full()`: the cycle is refused, and an absurd contour or depth (levels of
/// 4 mm over 10²¹ mm) must not fill memory first.
class LegList {
 public:
  LegList(const RZ& at, std::size_t maxLegs) : at_(at), maxLegs_(maxLegs) {}

  const RZ& at() const { return at_; }
  bool full() const { return overflowed_ || legs_.size() > maxLegs_; }
  std::size_t maxLegs() const { return maxLegs_; }
  /// More levels are coming than legs allowed: full whatever was kept.
  void overflow() { overflowed_ = true; }

  /// `drawnBy`: the contour segment the leg makes (its block's line goes with it), if any.
  void straight(MoveKind kind, const RZ& to, int step, const ContourSegment* drawnBy = nullptr) {
    if (!full() && (to - at_).norm() > kTolMm)
      legs_.push_back({kind, at_, to, step, RZ(0, 0), {}, drawnBy ? drawnBy->line : 0, drawnBy ? drawnBy->column : 0});
    at_ = to;
  }

  /// Along a contour segment from the current point to `to` (a straight segment at feed,
  /// an arc as an arc about its centre), on the segment's block's line.
  void follow(const ContourSegment& segment, const RZ& to, int step) {
    const MoveKind kind = isArc(segment.kind) ? segment.kind : MoveKind::Feed;
    const RZ center = isArc(segment.kind) ? segment.center : RZ(0, 0);
    if (!full() && (to - at_).norm() > kTolMm)
      legs_.push_back({kind, at_, to, step, center, {}, segment.line, segment.column});
    at_ = to;
  }

  /// The legs, or nullopt when there were more than `maxLegs`.
  std::optional<std::vector<CycleLeg>> take() && {
    if (full()) return std::nullopt;
    return std::move(legs_);
  }

 private:
  RZ at_;
  std::size_t maxLegs_;
  bool overflowed_ = false;
  std::vector<CycleLeg> legs_;
};

/// Whether level `k` may be cut: it is short of the depth to cut, and the list can take it.
/// Each level adds at least one leg, so level maxLegs + 1 overflows the list without being
/// built (a Δd below a far coordinate's precision would never reach the depth).
bool nextLevel(long long k, double depthMm, double depthToCutMm, LegList& legs) {
  if (!(k * depthMm < depthToCutMm - kTolMm) || legs.full()) return false;
  if (static_cast<double>(k) > static_cast<double>(legs.maxLegs())) {
    legs.overflow();
    return false;
  }
  return true;
}

/// Where the level X = `levelMm` last meets the rough contour after the ns block, or C′ moved
/// onto the level when it never does.
RZ typeOneLevelEnd(const Contour& rough, double levelMm) {
  std::optional<RZ> last;
  for (std::size_t i = 1; i < rough.size(); ++i) {
    const std::vector<RZ> crossings = levelCrossings(rough[i], levelMm);
    if (!crossings.empty()) last = crossings.back();
  }
  return last.value_or(RZ(levelMm, rough.back().to.y()));
}

struct Plan {
  RZ start;        // A
  Contour rough;   // the rough contour: front().from is A′, front().to is B′
  Contour finish;  // the contour the closing pass follows: `rough`, or with Haas's I/K the
                   // contour shifted by the finishing allowance alone
  double stepDir;  // +1/−1: the way the levels advance in X
  double cutDir;   // +1/−1: the way the passes run in Z
  MoveKind infeedKind;
  MoveKind retractKind;
  const RoughingParams* params;
};

void semiFinishAndReturn(const Plan& plan, LegList& legs, int infeedStep) {
  legs.straight(plan.infeedKind, plan.finish.front().to, infeedStep, &plan.finish.front());  // the ns block's move
  for (std::size_t i = 1; i < plan.finish.size(); ++i) {
    legs.follow(plan.finish[i], plan.finish[i].to, 7);
  }
  legs.straight(MoveKind::Rapid, plan.start, 8);
}

std::optional<std::vector<CycleLeg>> typeOneLegs(const Plan& plan) {
  const RZ& shiftedStart = plan.rough.front().from;
  const RZ& b = plan.rough.front().to;
  const double depthMm = plan.params->depthMm;
  const double retractMm = plan.params->retractMm;
  const double depthToCutMm = plan.stepDir * (b.x() - shiftedStart.x());
  LegList legs(plan.start, plan.params->maxLegs);
  legs.straight(MoveKind::Rapid, shiftedStart, 1);
  int infeedStep = 2;
  for (long long k = 1; nextLevel(k, depthMm, depthToCutMm, legs); ++k) {
    const double levelMm = shiftedStart.x() + plan.stepDir * k * depthMm;
    legs.straight(plan.infeedKind, RZ(levelMm, shiftedStart.y()), infeedStep);
    const RZ end = typeOneLevelEnd(plan.rough, levelMm);
    legs.straight(MoveKind::Feed, end, 3);
    const RZ retracted = end - RZ(plan.stepDir * retractMm, plan.cutDir * retractMm);
    legs.straight(plan.retractKind, retracted, 4);
    legs.straight(MoveKind::Rapid, RZ(retracted.x(), shiftedStart.y()), 5);
    infeedStep = 6;
  }
  semiFinishAndReturn(plan, legs, infeedStep);
  return std::move(legs).take();
}

// ---- Type II -------------------------------------------------------------------------

/// A run of contour pieces the tool follows, in order.
using Path = std::vector<ContourSegment>;

/// From `at` on `tail[index]`, the contour while it climbs back toward A′ (its X moves
/// against the step direction): up to the level X = `targetXMm`, its first top, or its end.
/// Flat stretches (constant X) are followed when `acrossFlats`, else they end the climb.
Path climb(const Contour& tail, std::size_t index, const RZ& at, double targetXMm,
           double stepDir, bool acrossFlats) {
  Path path;
  for (std::size_t j = index; j < tail.size(); ++j) {
    ContourSegment piece = tail[j];
    if (j == index) piece.from = at;
    if ((piece.to - piece.from).norm() <= kTolMm) continue;
    RZ top = piece.to;
    bool turns = false;
    if (isArc(piece.kind)) {
      double nearest = arcSweepRad(piece);
      for (const double angle : {kHalfPi, -kHalfPi}) {
        if (!arcPassesAngleInside(piece, angle)) continue;
        const RZ extreme = arcPointAt(piece, angle);
        if (arcTravelRad(piece, extreme) < nearest) {
          nearest = arcTravelRad(piece, extreme);
          top = extreme;
          turns = true;
        }
      }
    }
    const double climbMm = stepDir * (piece.from.x() - top.x());
    if (climbMm < -kTolMm || (!acrossFlats && climbMm <= kTolMm)) break;  // heads deeper/flat
    if (stepDir * top.x() <= stepDir * targetXMm + kTolMm) {
      const std::vector<RZ> hits = levelCrossings(piece, targetXMm);
      piece.to = hits.empty() ? top : hits.front();
      if ((piece.to - piece.from).norm() > kTolMm) path.push_back(piece);
      break;
    }
    piece.to = top;
    path.push_back(piece);
    if (turns) break;
  }
  return path;
}

/// The path run backwards.
Path reversedPath(const Path& path) {
  Path back;
  for (auto it = path.rbegin(); it != path.rend(); ++it) back.push_back(reversed(*it));
  return back;
}

struct Crossing {
  double s;           // distance along the cutting direction from Z_A′
  std::size_t index;  // in the contour's tail (the blocks after ns)
  RZ point;
};

struct Interval {
  double s0, s1;
};

/// One stretch of one level to cut.
struct LevelCut {
  long long level;  // k: the level lies k·Δd deep
  Interval interval;
};

/// How the pocket engine orders and ends its cuts.
struct PocketStyle {
  bool byRegion = false;    // Haas: region by region (the cut above each stretch first, then the
                            // stretches below it in Z order), else level by level (Fanuc/GSK)
  bool escapeAt45 = false;  // Haas type I: leave each stretch by the 45° retract of e, else
                            // follow the contour up and back off e in X (type II)
};

/// The cuts in region order: each stretch (its level's k) lies under exactly one stretch of
/// level k − 1 (the material is connected upward); visiting that tree depth first, children in
/// Z order, cuts the region reached from Z_A′ (the material above every trough) down to its
/// bottom first, then each trough, in the order of Z, level by level down to its own bottom
/// (a trough holding troughs of its own: its common part first, then those in Z order).
std::vector<LevelCut> regionOrder(const std::vector<LevelCut>& byLevel) {
  constexpr double kSpanTolMm = 1e-6;
  std::vector<std::vector<std::size_t>> children(byLevel.size());
  std::vector<std::size_t> roots;
  std::size_t aboveBegin = 0, aboveEnd = 0;  // the stretches of the level above, in Z order
  for (std::size_t i = 0; i < byLevel.size(); ++i) {
    if (i > 0 && byLevel[i].level != byLevel[i - 1].level) {
      aboveBegin = aboveEnd;
      aboveEnd = i;
      while (aboveBegin < aboveEnd && byLevel[aboveBegin].level != byLevel[i].level - 1) ++aboveBegin;
    }
    const Interval& below = byLevel[i].interval;
    // The last stretch above that begins no later than this one; it holds it, or none does.
    const auto first = byLevel.begin() + static_cast<std::ptrdiff_t>(aboveBegin);
    const auto last = byLevel.begin() + static_cast<std::ptrdiff_t>(aboveEnd);
    const auto after = std::upper_bound(first, last, below.s0 + kSpanTolMm,
                                        [](double s, const LevelCut& cut) { return s < cut.interval.s0; });
    if (after != first && below.s1 <= std::prev(after)->interval.s1 + kSpanTolMm) {
      children[static_cast<std::size_t>(std::prev(after) - byLevel.begin())].push_back(i);
    } else {
      roots.push_back(i);
    }
  }
  std::vector<LevelCut> ordered;
  std::vector<std::size_t> stack(roots.rbegin(), roots.rend());
  while (!stack.empty()) {
    const std::size_t i = stack.back();
    stack.pop_back();
    ordered.push_back(byLevel[i]);
    stack.insert(stack.end(), children[i].rbegin(), children[i].rend());
  }
  return ordered;
}

class TypeTwo {
 public:
  TypeTwo(const Plan& plan, PocketStyle style)
      : plan_(plan),
        style_(style),
        shiftedStart_(plan.rough.front().from),
        b_(plan.rough.front().to),
        tail_(plan.rough.begin() + 1, plan.rough.end()),
        swappedTail_(swappedAxes(tail_)),
        legs_(plan.start, plan.params->maxLegs) {
    for (auto it = tail_.rbegin(); it != tail_.rend(); ++it) backwards_.push_back(reversed(*it));
  }

  std::optional<std::vector<CycleLeg>> legs() && {
    const double depthMm = plan_.params->depthMm;
    legs_.straight(MoveKind::Rapid, shiftedStart_, 1);
    int infeedStep = 2;
    for (const LevelCut& cut : cuts()) {
      if (legs_.full()) break;
      const Interval& interval = cut.interval;
      const double levelMm = xAtDepth(cut.level * depthMm);
      const double previousMm = xAtDepth((cut.level - 1) * depthMm);
      if (interval.s0 <= kTolMm) {
        returnToStartZ();
        legs_.straight(plan_.infeedKind, RZ(levelMm, shiftedStart_.y()), infeedStep);
      } else {
        enterPocket(levelMm, previousMm, interval.s0);
      }
      infeedStep = 6;
      cutAndEscape(levelMm, previousMm, interval);
      inFirstRegion_ = interval.s0 <= kTolMm;
    }
    returnToStartZ();
    semiFinishAndReturn(plan_, legs_, infeedStep);
    return std::move(legs_).take();
  }

 private:
  double sOf(double zMm) const { return plan_.cutDir * (zMm - shiftedStart_.y()); }
  double zOf(double s) const { return shiftedStart_.y() + plan_.cutDir * s; }
  double depthOf(double xMm) const { return plan_.stepDir * (xMm - shiftedStart_.x()); }
  double xAtDepth(double depthMm) const { return shiftedStart_.x() + plan_.stepDir * depthMm; }

  /// Every stretch of every level, level by level (each level's in cutting order), or in region
  /// order. Each stretch makes at least one leg: past the move limit the list overflows.
  std::vector<LevelCut> cuts() {
    const double depthMm = plan_.params->depthMm;
    const double deepestMm = deepestDepthMm();
    std::vector<LevelCut> byLevel;
    for (long long k = 1; nextLevel(k, depthMm, deepestMm, legs_); ++k) {
      for (const Interval& interval : intervals(xAtDepth(k * depthMm))) byLevel.push_back({k, interval});
      if (byLevel.size() > legs_.maxLegs()) {
        legs_.overflow();
        return {};
      }
    }
    return style_.byRegion ? regionOrder(byLevel) : byLevel;
  }

  double deepestDepthMm() const {
    double deepest = depthOf(b_.x());
    for (const ContourSegment& segment : tail_) {
      deepest = std::max(deepest, depthOf(segment.to.x()));
      const double deepAngle = plan_.stepDir * kHalfPi;
      if (isArc(segment.kind) && arcPassesAngleInside(segment, deepAngle)) {
        deepest = std::max(deepest, depthOf(arcPointAt(segment, deepAngle).x()));
      }
    }
    return deepest;
  }

  std::vector<Crossing> crossings(double levelMm) const {
    std::vector<Crossing> found;
    for (std::size_t i = 0; i < tail_.size(); ++i) {
      for (const RZ& point : levelCrossings(tail_[i], levelMm)) {
        found.push_back({sOf(point.y()), i, point});
      }
    }
    return found;
  }

  /// Whether the level lies in the material at `s`: on A′'s side of the contour (before B′'s
  /// Z, of B′ itself, as if the contour began with a cylinder at B′'s X).
  bool inMaterial(double levelMm, double s) const {
    if (s < sOf(b_.y())) return plan_.stepDir * (b_.x() - levelMm) >= -kTolMm;
    for (const ContourSegment& segment : swappedTail_) {
      const std::vector<RZ> hits = levelCrossings(segment, zOf(s));
      if (!hits.empty()) return plan_.stepDir * (hits.front().y() - levelMm) >= -kTolMm;
    }
    return false;
  }

  /// The stretches of the level, from Z_A′ to Z_C′, that lie in the material.
  std::vector<Interval> intervals(double levelMm) const {
    const double sEnd = sOf((tail_.empty() ? b_ : tail_.back().to).y());  // a contour of the ns block alone ends at B′
    std::vector<double> bounds = {0.0, sEnd};
    const double sB = sOf(b_.y());
    if (sB > kTolMm && sB < sEnd - kTolMm) bounds.push_back(sB);
    for (const Crossing& crossing : crossings(levelMm)) {
      if (crossing.s > kTolMm && crossing.s < sEnd - kTolMm) bounds.push_back(crossing.s);
    }
    std::sort(bounds.begin(), bounds.end());
    std::vector<Interval> found;
    for (std::size_t i = 0; i + 1 < bounds.size(); ++i) {
      if (bounds[i + 1] - bounds[i] <= kTolMm) continue;
      if (!inMaterial(levelMm, (bounds[i] + bounds[i + 1]) / 2)) continue;
      if (!found.empty() && bounds[i] - found.back().s1 <= kTolMm) {
        found.back().s1 = bounds[i + 1];
      } else {
        found.push_back({bounds[i], bounds[i + 1]});
      }
    }
    return found;
  }

  /// Back to Z_A′: along Z at this height from the first region, else over X_A′.
  void returnToStartZ() {
    if (std::abs(legs_.at().y() - shiftedStart_.y()) <= kTolMm) return;
    if (!inFirstRegion_) legs_.straight(MoveKind::Rapid, RZ(shiftedStart_.x(), legs_.at().y()), 5);
    legs_.straight(MoveKind::Rapid, RZ(legs_.at().x(), shiftedStart_.y()), 5);
  }

  /// Into a pocket whose stretch of the level begins at `s0`: over X_A′ to the top W of the
  /// pocket's entry wall (where it leaves the previous level), rapid to e short of W (but not
  /// below the previous level), feed onto W, then feed down the wall to the level.
  void enterPocket(double levelMm, double previousMm, double s0) {
    Path wall;
    RZ entry(levelMm, zOf(s0));
    for (const Crossing& crossing : crossings(levelMm)) {
      if (std::abs(crossing.s - s0) > kTolMm) continue;
      entry = crossing.point;
      const std::size_t backIndex = backwards_.size() - 1 - crossing.index;
      wall = reversedPath(climb(backwards_, backIndex, entry, previousMm, plan_.stepDir, false));
      break;
    }
    const RZ top = wall.empty() ? entry : wall.front().from;
    // Rapid no deeper than the previous level (below it, beside a flat, stock may be left)
    // and no higher than A′, and stop e short of W.
    const double topDepthMm = depthOf(top.x());
    const double clearDepthMm =
        std::max(0.0, std::min(topDepthMm - plan_.params->retractMm, depthOf(previousMm)));
    const RZ aboveTop(xAtDepth(std::min(clearDepthMm, topDepthMm)), top.y());
    if (std::abs(legs_.at().y() - top.y()) > kTolMm) {
      legs_.straight(MoveKind::Rapid, RZ(shiftedStart_.x(), legs_.at().y()), 5);
      legs_.straight(MoveKind::Rapid, RZ(shiftedStart_.x(), top.y()), 5);
    }
    legs_.straight(MoveKind::Rapid, aboveTop, 5);
    legs_.straight(MoveKind::Feed, top, 6);
    for (const ContourSegment& piece : wall) legs_.follow(piece, piece.to, 6);
    legs_.straight(MoveKind::Feed, entry, 6);
  }

  /// Along the level to the stretch's end, then up the contour to the previous level and back
  /// off e in X; or (escapeAt45) back off e in X and in Z at once, no further back in Z than
  /// where the stretch began (a trough narrower than e).
  void cutAndEscape(double levelMm, double previousMm, const Interval& interval) {
    const double s1 = interval.s1;
    const double retractMm = plan_.params->retractMm;
    std::optional<Crossing> exit;
    for (const Crossing& crossing : crossings(levelMm)) {
      if (std::abs(crossing.s - s1) <= kTolMm) exit = crossing;
    }
    legs_.straight(MoveKind::Feed, exit ? exit->point : RZ(levelMm, zOf(s1)), 3);
    if (style_.escapeAt45) {
      const RZ& at = legs_.at();
      const double backMm = std::min(retractMm, interval.s1 - interval.s0);
      legs_.straight(plan_.retractKind,
                     RZ(at.x() - plan_.stepDir * retractMm, at.y() - plan_.cutDir * backMm), 4);
      return;
    }
    if (exit) {
      for (const ContourSegment& piece :
           climb(tail_, exit->index, exit->point, previousMm, plan_.stepDir, true)) {
        legs_.follow(piece, piece.to, 4);
      }
    }
    const RZ& at = legs_.at();
    legs_.straight(plan_.retractKind, RZ(at.x() - plan_.stepDir * retractMm, at.y()), 4);
  }

  const Plan& plan_;
  PocketStyle style_;
  RZ shiftedStart_;
  RZ b_;
  Contour tail_;
  Contour swappedTail_;
  Contour backwards_;  // the tail run backwards: backwards_[i] is tail_[size − 1 − i] reversed
  LegList legs_;
  bool inFirstRegion_ = true;
};

std::optional<std::vector<CycleLeg>> typeTwoLegs(const Plan& plan, PocketStyle style) {
  return TypeTwo(plan, style).legs();
}

}  // namespace

Result<std::vector<CycleLeg>> stockRemovalLegs(const RZ& start, const Contour& contour,
                                               const RoughingParams& params,
                                               const StockRemovalNames& names) {
  const char* cycle = names.cycle;
  if (contour.empty()) {
    return Error{0, 0, fmt::format("{} contour is empty: the blocks P(ns) to Q(nf) make no "
                                   "move (expected at least the ns block's G00/G01)", cycle)};
  }
  const ContourSegment& ns = contour.front();
  if (!(params.depthMm > 0)) {
    return errorAt(ns, fmt::format("{} depth of cut Δd is {}; expected a depth greater than 0",
                                   cycle, params.depthMm));
  }
  if (!(params.retractMm >= 0)) {
    return errorAt(ns, fmt::format("{} retract e is {}; expected 0 or more", cycle,
                                   params.retractMm));
  }
  if (isArc(ns.kind)) {
    return errorAt(ns, fmt::format("{} ns block is an arc; expected G00 or G01 (arcs are "
                                   "allowed only after the ns block)", cycle));
  }
  const double stepMm = ns.to.x() - ns.from.x();
  if (std::abs(stepMm) <= kTolMm) {
    return errorAt(ns, fmt::format("{} ns block does not move {}; expected it to move {} from "
                                   "the start point to the contour's first point",
                                   cycle, names.stepAxis, names.stepAxis));
  }
  const double stepDir = stepMm > 0 ? 1.0 : -1.0;
  const double cutDir = cuttingDirection(contour);
  // Haas: a contour with troughs, type I as well as type II, is roughed region by region.
  bool haasTroughs = false;
  if (params.haasTroughs) {
    const std::vector<std::size_t> bottoms = troughBottoms(contour, stepDir);
    if (bottoms.size() > kHaasMaxTroughs) {
      return errorAt(contour[bottoms[kHaasMaxTroughs]],
                     fmt::format("{} contour has {} troughs (this block reaches the bottom of trough {}): a Haas roughs at most {} in "
                                 "one cycle (its operator's manual, \"Troughs\"); split the contour into two cycles",
                                 cycle, bottoms.size(), kHaasMaxTroughs + 1, kHaasMaxTroughs));
    }
    haasTroughs = !bottoms.empty();
  }
  RoughingParams checked = params;
  checked.typeII = params.typeII || haasTroughs;
  if (auto problem = contourProblem(contour, checked, stepDir, cutDir, names)) return *problem;
  const RZ finishing(params.allowanceXMm, params.allowanceZMm);
  const Plan plan{start,
                  translatedContour(contour, finishing + RZ(params.roughAllowanceXMm, params.roughAllowanceZMm)),
                  translatedContour(contour, finishing),
                  stepDir,
                  cutDir,
                  ns.kind == MoveKind::Rapid ? MoveKind::Rapid : MoveKind::Feed,
                  params.retractAtFeed ? MoveKind::Feed : MoveKind::Rapid,
                  &params};
  auto legs = haasTroughs    ? typeTwoLegs(plan, {.byRegion = true, .escapeAt45 = !params.typeII})
              : params.typeII ? typeTwoLegs(plan, {})
                              : typeOneLegs(plan);
  if (!legs) {
    return errorAt(ns, fmt::format("{} would make more than {} moves (the limit) roughing this contour {:g} mm a "
                                   "level: check the contour's {} coordinates and the depth of cut Δd; if it is "
                                   "meant, raise the limit with --max-moves or [sim] max_moves",
                                   cycle, params.maxLegs, params.depthMm, names.stepAxis));
  }
  return std::move(*legs);
}

}  // namespace lathesim::interp
