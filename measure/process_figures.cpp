#include "measure/process_figures.hpp"

#include <cmath>
#include <map>
#include <optional>
#include <stdexcept>
#include <vector>

namespace lathesim::measure {

double pathLengthMm(const interp::Move& move) {
  if (move.kind == interp::MoveKind::Dwell) return 0;
  if (!interp::isArc(move.kind)) return (move.to - move.from).norm();
  const auto angle = [&](const RZ& p) { return std::atan2(p.x() - move.center.x(), p.y() - move.center.y()); };
  double sweep = angle(move.to) - angle(move.from);  // drawing view: clockwise decreases it
  if (move.kind == interp::MoveKind::ArcCW)
    while (sweep >= 0) sweep -= 2 * M_PI;
  else
    while (sweep <= 0) sweep += 2 * M_PI;
  return std::abs(sweep) * (move.from - move.center).norm();
}

namespace {

// A block run more than once: what all its runs removed, and the tool of its first move.
struct RepeatedBlock {
  double removedMm3 = 0;
  std::optional<int> tool;
};

}  // namespace

ProcessFigures processFigures(const interp::MoveSpool& moves, const sim::BlockRows& rows, double voxelMm) {
  ProcessFigures figures;
  const double airMm3 = voxelMm * voxelMm * voxelMm;
  sim::MetTwice repeats;
  rows.forEach([&](const sim::BlockRemoval& row) { repeats.note(row.block); });
  std::map<int, RepeatedBlock> repeated;
  rows.forEach([&](const sim::BlockRemoval& row) {
    if (repeats.has(row.block)) repeated[row.block].removedMm3 += row.removedMm3;
  });

  std::map<int, double> byTool;
  interp::MoveSpool::Reader reader(moves);
  std::optional<interp::Move> move = reader.next();
  rows.forEach([&](const sim::BlockRemoval& row) {
    if (!move || move->block != row.block) throw std::logic_error("the simulation's rows are not the moves' blocks");
    RepeatedBlock* again = repeats.has(row.block) ? &repeated[row.block] : nullptr;
    if (!again) byTool[move->tool] += row.removedMm3;
    else if (!again->tool) again->tool = move->tool;
    const double blockRemovedMm3 = again ? again->removedMm3 : row.removedMm3;
    for (; move && move->block == row.block; move = reader.next()) {
      const double length = pathLengthMm(*move);
      if (move->kind == interp::MoveKind::Rapid) {
        figures.rapidPathMm += length;
        figures.rapidTimeS += move->timeS;
      } else if (interp::isCutting(move->kind)) {
        figures.feedPathMm += length;
        figures.feedTimeS += move->timeS;
        if (blockRemovedMm3 < airMm3) {
          ++figures.airFeedMoves;
          figures.airFeedPathMm += length;
          figures.airFeedTimeS += move->timeS;
        }
      }
    }
  });
  if (move) throw std::logic_error("moves left over after the simulation's last row");
  for (const auto& [block, again] : repeated) byTool[*again.tool] += again.removedMm3;
  for (const auto& [tool, removed] : byTool) figures.removedPerTool.push_back({tool, removed});
  return figures;
}

}  // namespace lathesim::measure
