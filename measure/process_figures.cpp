#include "measure/process_figures.hpp"

#include <cmath>
#include <map>

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

ProcessFigures processFigures(const interp::Toolpath& toolpath, const sim::SimulationResult& simulation,
                              double voxelMm) {
  ProcessFigures figures;
  const double airMm3 = voxelMm * voxelMm * voxelMm;
  std::map<int, double> removedByBlock;
  for (const auto& b : simulation.blocks) removedByBlock[b.block] += b.removedMm3;
  std::map<int, int> toolOfBlock;
  for (const interp::Move& move : toolpath.moves) {
    toolOfBlock.try_emplace(move.block, move.tool);
    const double length = pathLengthMm(move);
    if (move.kind == interp::MoveKind::Rapid) {
      figures.rapidPathMm += length;
      figures.rapidTimeS += move.timeS;
    } else if (interp::isCutting(move.kind)) {
      figures.feedPathMm += length;
      figures.feedTimeS += move.timeS;
      if (removedByBlock[move.block] < airMm3) {
        ++figures.airFeedMoves;
        figures.airFeedPathMm += length;
        figures.airFeedTimeS += move.timeS;
      }
    }
  }
  std::map<int, double> byTool;
  for (const auto& [block, removed] : removedByBlock) byTool[toolOfBlock[block]] += removed;
  for (const auto& [tool, removed] : byTool) figures.removedPerTool.push_back({tool, removed});
  return figures;
}

}  // namespace lathesim::measure
