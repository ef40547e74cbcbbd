#include "sim/simulate.hpp"

#include <stdexcept>

#include "sim/cut_history.hpp"
#include "sim/move_sweep.hpp"
#include "sim/part_off.hpp"
#include "sim/simulation_warnings.hpp"

namespace lathesim::sim {
namespace {

const ConvexPolygon& toolOf(const interp::Move& move, const ToolOutlines& tools) {
  const auto tool = tools.find(move.tool);
  if (tool == tools.end())  // interp checks T words against the setup; this is a broken invariant
    throw std::logic_error("move on line " + std::to_string(move.line) + " uses undefined tool " +
                           std::to_string(move.tool));
  return tool->second;
}

double thicknessOf(const interp::Move& move, const ToolThicknesses& thicknesses) {
  const auto found = thicknesses.find(move.tool);
  return found == thicknesses.end() ? kDefaultInsertThicknessMm : found->second;
}

// Adds `area` to where a write changed the stock.
void widen(std::optional<ChangedArea>& changed, const ChangedArea& area) {
  if (changed) changed->add(area);
  else changed = area;
}

// What a move made with the spindle stopped removes: a straight slot along each segment.
double removeSlots(const interp::Move& move, const ConvexPolygon& tool, double thicknessMm, Stock& stock,
                   std::optional<ChangedArea>& changed) {
  double removed = 0.0;
  for (const auto& [from, to] : sweptSegments(move, stock.voxelMm())) {
    const StraightSlot slot(tool, from, to, thicknessMm, move.spindleAngleDeg);
    removed += stock.remove(slot);
    widen(changed, ChangedArea::of(slot.hull()));
  }
  return removed;
}

// What a thread move removes: the outline along its helix, from its start angle (measured in
// the direction the spindle turns) one turn per lead.
double removeThread(const interp::Move& move, const ConvexPolygon& tool, Stock& stock,
                    std::optional<ChangedArea>& changed) {
  const int sense = move.spindleDirection == interp::SpindleDirection::Clockwise ? 1 : -1;
  const HelicalSweep sweep(tool, move.from, move.to, move.thread.revolutions(move.from, move.to),
                           sense * move.thread.startAngleDeg, sense);
  widen(changed, ChangedArea::of(sweep.hull()));
  return stock.remove(sweep);
}

}  // namespace

bool spindleTurns(const interp::Move& move) { return move.spindleOn && move.spindleS > 0.0; }

void recordCollision(std::vector<Collision>& collisions, const interp::Move& move, const char* kind, double volumeMm3) {
  // The block's collisions are the last ones, of one or more kinds.
  for (auto c = collisions.rbegin(); c != collisions.rend() && c->line == move.line && c->column == move.column; ++c) {
    if (c->kind != kind) continue;
    c->volumeMm3 += volumeMm3;
    return;
  }
  collisions.push_back({move.line, move.column, kind, volumeMm3});
}

SimulationResult simulate(const interp::Toolpath& toolpath, const ToolOutlines& tools, Stock& stock,
                          const BlockProgress& progress, const CollisionChecks* checks) {
  return simulate(toolpath, tools, stock, progress, checks, {});
}

SimulationResult simulate(const interp::Toolpath& toolpath, const ToolOutlines& tools, Stock& stock,
                          const BlockProgress& progress, const CollisionChecks* checks,
                          const ToolThicknesses& thicknesses, const CutObserver& observer) {
  SimulationResult result;
  const auto& moves = toolpath.moves;
  const double voxelVolume = stock.voxelMm() * stock.voxelMm() * stock.voxelMm();
  const int totalBlocks = toolpath.blockCount;
  auto cycleStart = toolpath.cycleStarts.begin();
  int spindleWarnedBlock = -1;  // one spindle warning per block
  int threadWarnedBlock = -1;   // one thread-start warning per block
  RZ frame(0, 0);               // the G50 frame of the moves so far
  PartOffWatch partOffs;
  bool checkShift = false;      // after G50 moved it: until the first cut, or a warning
  CutHistory history;           // what turning writes removed: bounds where the next can change anything

  for (std::size_t first = 0; first < moves.size();) {
    const interp::Move& head = moves[first];
    if (result.blocks.empty() || result.blocks.back().block != head.block) {
      result.blocks.push_back({head.block, head.line, head.column, 0.0, 0.0});
      for (; cycleStart != toolpath.cycleStarts.end() && cycleStart->block <= head.block; ++cycleStart)
        if (auto warning = cycleStartInStock(*cycleStart, stock)) result.warnings.push_back(*warning);
    }
    BlockRemoval& block = result.blocks.back();
    if (head.kind != interp::MoveKind::Dwell && head.workShift != frame) {
      frame = head.workShift;
      checkShift = true;
    }
    if (checkShift && head.kind != interp::MoveKind::Dwell) {
      const auto warning = shiftedMoveInStock(head, stock);
      if (warning) result.warnings.push_back(*warning);
      checkShift = !warning && !interp::isCutting(head.kind);
    }

    // Turning: the feeds and arcs that follow in this block with the spindle turning too.
    const auto turning = [](const interp::Move& m) {
      return (m.kind == interp::MoveKind::Feed || interp::isArc(m.kind)) && spindleTurns(m);
    };
    std::size_t end = first + 1;
    if (turning(head))
      while (end < moves.size() && moves[end].block == head.block && turning(moves[end])) ++end;

    if (observer) observer(first, end, stock);
    double removed = 0.0;
    RevolvedRegion revolved;             // what a turning write swept (none for a thread or a slot)
    std::optional<ChangedArea> changed;  // where the write can have changed the stock
    const ConvexPolygon& tool = toolOf(head, tools);
    // With the spindle stopped nothing turns the part: a feed or a rapid alike drags the tool's
    // outline through it as a straight slot (a rapid swept as a ring would part the bar).
    if ((interp::isCutting(head.kind) || head.kind == interp::MoveKind::Rapid) && !spindleTurns(head)) {
      removed = removeSlots(head, tool, thicknessOf(head, thicknesses), stock, changed);
    } else if (head.kind == interp::MoveKind::Thread) {
      if (auto warning = threadPassStartsInStock(head, moves, first, stock); warning && threadWarnedBlock != head.block) {
        result.warnings.push_back(*warning);
        threadWarnedBlock = head.block;
      }
      removed = removeThread(head, tool, stock, changed);
    } else {
      std::vector<ConvexPolygon> pieces;
      for (std::size_t m = first; m < end; ++m) {
        const auto swept = sweptPieces(moves[m], toolOf(moves[m], tools), stock.voxelMm());
        pieces.insert(pieces.end(), swept.begin(), swept.end());
      }
      revolved = RevolvedRegion(pieces);
      if (!pieces.empty()) {
        const auto changes = history.changesOf(pieces);
        removed = changes ? stock.remove(revolved, *changes) : stock.remove(revolved);
        changed = ChangedArea::of(revolved);
      }
    }
    for (std::size_t m = first; m < end; ++m) block.timeS += moves[m].timeS;
    block.removedMm3 += removed;
    partOffs.afterCut(toolpath, first, end, revolved, changed, removed, stock, result);
    if (auto warning = cutWithSpindleStopped(head, removed, stock.voxelMm()); warning && spindleWarnedBlock != head.block) {
      result.warnings.push_back(*warning);
      spindleWarnedBlock = head.block;
    }
    if (head.kind == interp::MoveKind::Rapid && removed > kCollisionVoxels * voxelVolume)
      recordCollision(result.collisions, head, "rapid_into_stock", removed);
    if (checks) checkMoves(*checks, std::span(moves).subspan(first, end - first), stock, result.collisions);

    first = end;
    if (progress && (first == moves.size() || moves[first].block != head.block)) progress(head.block + 1, totalBlocks);
  }
  return result;
}

SimulationResult simulate(const interp::Toolpath& toolpath, const ToolOutlines& tools, Stock& stock,
                          const BlockProgress& progress) {
  return simulate(toolpath, tools, stock, progress, nullptr, {});
}

}  // namespace lathesim::sim
