#include "sim/simulation_warnings.hpp"

#include <cstdio>
#include <string>

#include "sim/cut_rules.hpp"

namespace lathesim::sim {
namespace {

std::string number(const char* format, double value) {
  char text[64];
  std::snprintf(text, sizeof text, format, value);
  return text;
}

}  // namespace

std::optional<SimulationWarning> cycleStartInStock(const interp::CycleStart& start, const Stock& stock) {
  if (stock.signedDistanceAt(start.point) >= -kInsideStockVoxels * stock.voxelMm()) return std::nullopt;
  return SimulationWarning{start.line, start.column,
                           start.code + " starts at X" + number("%g", diameterOf(start.point)) + " Z" +
                               number("%g", start.point.y()) +
                               " (the cycle start point), which is inside the stock: the cycle's "
                               "rapid legs start in material; start the cycle clear of the blank", start.source};
}

std::optional<SimulationWarning> shiftedMoveInStock(const interp::Move& move, const Stock& stock) {
  const bool cut = interp::isCutting(move.kind);
  const RZ& point = cut ? move.from : move.to;
  if (stock.signedDistanceAt(point) >= -kInsideStockVoxels * stock.voxelMm()) return std::nullopt;
  const RZ& shift = move.workShift;
  return SimulationWarning{
      move.line, move.column,
      std::string(cut ? "the first cut after G50 starts" : "this rapid after G50 ends") + " inside the bar, at X" +
          number("%g", diameterOf(point)) + " Z" + number("%g", point.y()) +
          " of the setup: G50 declared a position the tool is not at, which moved the program's zero to X" +
          number("%g", diameterOf(shift)) + " Z" + number("%g", shift.y()) +
          " of the setup; check the G50 against [machine] start", move.source};
}

std::optional<SimulationWarning> cutWithSpindleStopped(const interp::Move& head, double removedMm3,
                                                       double voxelMm) {
  if (!interp::isCutting(head.kind) || spindleTurns(head)) return std::nullopt;
  if (removedMm3 <= kCollisionVoxels * voxelMm * voxelMm * voxelMm) return std::nullopt;
  const char* why = head.spindleOn ? "at S0" : "with no M03/M04 in force (or after M05)";
  return SimulationWarning{head.line, head.column,
                           "cutting with the spindle stopped: this block cuts a straight slot of " +
                               number("%.1f", removedMm3) + " mm³ (the tool's outline, as thick as the insert, at "
                               "spindle angle " + number("%.0f", head.spindleAngleDeg) + "°) " + why +
                               "; start the spindle before cutting", head.source};
}

std::optional<SimulationWarning> threadPassStartsInStock(const interp::Move& move, const interp::Move* before,
                                                         const Stock& stock) {
  const bool continues = before && before->kind == interp::MoveKind::Thread && before->to == move.from;
  if (continues || stock.signedDistanceAt(move.from) >= -kInsideStockVoxels * stock.voxelMm()) return std::nullopt;
  return SimulationWarning{move.line, move.column,
                           "this thread pass starts at X" + number("%g", diameterOf(move.from)) + " Z" +
                               number("%g", move.from.y()) +
                               ", inside the stock: the cut would be synchronised with the spindle with the tool "
                               "already in the material; start the pass clear of the part", move.source};
}

}  // namespace lathesim::sim
