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
//   7 feed   the semi-finishing pass along the rough contour B′ → C′, arcs as arcs
//   8 rapid  C′ → A
// Type II (pockets: Z monotonic, X free). Each level is cut in intervals: the stretches of
// the line X = X_k, from Z_A′ to Z_C′, where the contour lies at or beyond the level (before
// B′'s Z there is no contour and everything is cut). Per interval:
//   2/6 first interval of a level, starting at Z_A′: infeed as in type I
//   5   an interval starting further on (a pocket): rapid up to X_A′, rapid in Z to the
//       pocket's entry point, rapid down to e short of the previous level (never past X_A′);
//   6   then feed the rest (Δd + e) down to the level
//   3   feed along Z to the interval's end
//   4   feed along the contour from there while it climbs back toward A′, up to the
//       previous level (or the contour's top, or its end), then back off e in X (feed if
//       retractAtFeed, else rapid) — no 45° escape
//   5   rapid back: along Z to Z_A′ at that height after an interval that began at Z_A′,
//       otherwise up to X_A′ first
// After the last level: 6 infeed to B′, 7 the semi-finishing pass, 8 rapid C′ → A, as in
// type I. GSK makes all roughing first and then the semi-finishing pass; so do we.
// The legs of zero length are left out.

#include "interp/stock_removal.hpp"

#include <cmath>
#include <numbers>
#include <optional>
#include <string>
#include <utility>

#include <fmt/format.h>

#include "interp/contour_geometry.hpp"

namespace lathesim::interp {
namespace {

constexpr double kTolMm = 1e-9;
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

/// Builds the leg list, leaving out straight legs of no length.
class LegList {
 public:
  explicit LegList(const RZ& at) : at_(at) {}

  const RZ& at() const { return at_; }

  void straight(MoveKind kind, const RZ& to, int step) {
    if ((to - at_).norm() > kTolMm) legs_.push_back({kind, at_, to, step});
    at_ = to;
  }

  /// Along a contour segment from the current point to `to` (a straight segment at feed,
  /// an arc as an arc about its centre).
  void follow(const ContourSegment& segment, const RZ& to, int step) {
    if (!isArc(segment.kind)) {
      straight(MoveKind::Feed, to, step);
      return;
    }
    if ((to - at_).norm() > kTolMm) legs_.push_back({segment.kind, at_, to, step, segment.center});
    at_ = to;
  }

  std::vector<CycleLeg> take() && { return std::move(legs_); }

 private:
  RZ at_;
  std::vector<CycleLeg> legs_;
};

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
  double stepDir;  // +1/−1: the way the levels advance in X
  double cutDir;   // +1/−1: the way the passes run in Z
  MoveKind infeedKind;
  MoveKind retractKind;
  const RoughingParams* params;
};

void semiFinishAndReturn(const Plan& plan, LegList& legs, int infeedStep) {
  legs.straight(plan.infeedKind, plan.rough.front().to, infeedStep);
  for (std::size_t i = 1; i < plan.rough.size(); ++i) {
    legs.follow(plan.rough[i], plan.rough[i].to, 7);
  }
  legs.straight(MoveKind::Rapid, plan.start, 8);
}

std::vector<CycleLeg> typeOneLegs(const Plan& plan) {
  const RZ& shiftedStart = plan.rough.front().from;
  const RZ& b = plan.rough.front().to;
  const double depthMm = plan.params->depthMm;
  const double retractMm = plan.params->retractMm;
  const double depthToCutMm = plan.stepDir * (b.x() - shiftedStart.x());
  LegList legs(plan.start);
  legs.straight(MoveKind::Rapid, shiftedStart, 1);
  int infeedStep = 2;
  for (int k = 1; k * depthMm < depthToCutMm - kTolMm; ++k) {
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
  if (auto problem = contourProblem(contour, params, stepDir, cutDir, names)) return *problem;
  if (params.typeII) {
    return errorAt(ns, fmt::format("{} type II (pockets) is not supported yet", cycle));
  }
  const Plan plan{start,
                  translatedContour(contour, RZ(params.allowanceXMm, params.allowanceZMm)),
                  stepDir,
                  cutDir,
                  ns.kind == MoveKind::Rapid ? MoveKind::Rapid : MoveKind::Feed,
                  params.retractAtFeed ? MoveKind::Feed : MoveKind::Rapid,
                  &params};
  return typeOneLegs(plan);
}

}  // namespace lathesim::interp
