#include "interp/motion/corners.hpp"

#include <algorithm>
#include <cmath>

#include <fmt/format.h>

#include "interp/base/tolerance.hpp"
#include "interp/output/toolpath_csv.hpp"

namespace lathesim::interp {
namespace {

constexpr double kInLine = 1e-9;  // |sin φ| below this: the two lines are in line

// > 0 when `b` turns counter-clockwise from `a` (Z to the right, X up).
double crossOf(const RZ& a, const RZ& b) { return a.y() * b.x() - a.x() * b.y(); }

Error errorAt(const Move& move, std::string message) {
  return Error{move.line, move.cornerAfter->column, std::move(message)};
}

}  // namespace

Status insertCorners(std::vector<Move>& moves, std::vector<Error>& warnings) {
  // Most programs ask for none: their moves are not copied (a copy of a million moves is 272 MB).
  if (std::none_of(moves.begin(), moves.end(), [](const Move& m) { return m.cornerAfter != nullptr; }))
    return success();
  std::vector<Move> out;
  out.reserve(moves.size());
  for (std::size_t i = 0; i < moves.size(); ++i) {
    Move move = moves[i];
    if (!move.cornerAfter) {
      out.push_back(move);
      continue;
    }
    const CornerRequest corner = *move.cornerAfter;
    move.cornerAfter.reset();
    if (i + 1 >= moves.size()) {
      return errorAt(moves[i], fmt::format("{} asks for a {} to the next move, but no move follows (the last "
                                           "block of a contour may not end in one)",
                                           corner.word, corner.round ? "corner radius" : "chamfer"));
    }
    Move& next = moves[i + 1];
    if (next.kind != MoveKind::Feed || move.kind != MoveKind::Feed) {
      return errorAt(moves[i], fmt::format("{}: the {} is made between two G01 cuts; next to a rapid, a dwell or an "
                                           "arc lathesim does not simulate it yet",
                                           corner.word, corner.round ? "corner radius" : "chamfer"));
    }
    const RZ corner0 = move.to;
    const double firstMm = (move.from - corner0).norm();
    const double secondMm = (next.to - corner0).norm();
    const RZ u1 = (move.from - corner0) / firstMm;
    const RZ u2 = (next.to - corner0) / secondMm;
    const double sine = std::abs(crossOf(u1, u2));
    if (sine < kInLine && u1.dot(u2) < 0) {
      warnings.push_back({moves[i].line, corner.column,
                          fmt::format("{} does nothing: the two lines are in line (GSK980TDi §3.11.3)", corner.word)});
      out.push_back(move);
      continue;
    }
    // φ, the angle at the corner between the two lines: cos φ = u1·u2.
    const double halfAngle = std::acos(std::clamp(u1.dot(u2), -1.0, 1.0)) / 2.0;
    double distanceMm = corner.sizeMm;
    if (corner.round) distanceMm = corner.sizeMm / std::tan(halfAngle);
    else if (corner.chamferLength) distanceMm = corner.sizeMm / (u1 - u2).norm();
    if (distanceMm > firstMm + kTolMm || distanceMm > secondMm + kTolMm) {
      return errorAt(moves[i], fmt::format("{} does not fit: it needs {} mm of each line from the corner, and the "
                                           "lines are {} and {} mm long (GSK980TDi §3.11.3)",
                                           corner.word, csvNumber(distanceMm), csvNumber(firstMm),
                                           csvNumber(secondMm)));
    }
    const RZ a = corner0 + distanceMm * u1;
    const RZ b = corner0 + distanceMm * u2;
    move.to = a;
    next.from = b;
    Move joint = move;
    joint.from = a;
    joint.to = b;
    if (corner.round) {
      const RZ bisector = (u1 + u2).normalized();
      joint.center = corner0 + (corner.sizeMm / std::sin(halfAngle)) * bisector;
      joint.kind = crossOf(-u1, u2) > 0 ? MoveKind::ArcCCW : MoveKind::ArcCW;
    }
    out.push_back(move);
    out.push_back(joint);
  }
  moves = std::move(out);
  return success();
}

}  // namespace lathesim::interp
