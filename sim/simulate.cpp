#include "sim/simulate.hpp"

#include <span>
#include <stdexcept>

#include "sim/cut_rules.hpp"
#include "sim/move_sweep.hpp"
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
// Only near what the thread passes before it left (thread_history.hpp).
double removeThread(const interp::Move& move, const ConvexPolygon& tool, Stock& stock, ThreadHistory& history,
                    std::optional<ChangedArea>& changed) {
  const int sense = move.spindleDirection == interp::SpindleDirection::Clockwise ? 1 : -1;
  const ThreadPass pass{tool, move.from, move.to, move.thread.revolutions(move.from, move.to),
                        sense * move.thread.startAngleDeg, sense};
  const HelicalSweep sweep = pass.sweep();
  widen(changed, ChangedArea::of(sweep.hull()));
  const auto changes = history.changesOf(pass);
  return changes ? stock.remove(sweep, *changes) : stock.remove(sweep);
}

// A feed or arc made with the spindle turning: consecutive ones of a block are written together.
bool turning(const interp::Move& m) {
  return (m.kind == interp::MoveKind::Feed || interp::isArc(m.kind)) && spindleTurns(m);
}

}  // namespace

SimulationResult simulate(const interp::Toolpath& toolpath, const ToolOutlines& tools, Stock& stock,
                          const SimulationOptions& options) {
  Simulation simulation(toolpath, tools, stock, options);
  for (const interp::Move& move : toolpath.moves) simulation.take(move);
  return simulation.finish(toolpath);
}

Simulation::Simulation(const interp::Toolpath& recorded, ToolOutlines tools, Stock& stock, SimulationOptions options)
    : recorded_(&recorded), tools_(std::move(tools)), stock_(stock), options_(std::move(options)) {}

void Simulation::take(interp::Move move) {
  if (!group_.empty()) {
    const interp::Move& head = group_.front();
    if (turning(head) && move.block == head.block && turning(move)) {
      group_.push_back(std::move(move));
      return;
    }
    const int block = head.block;
    cutGroup();
    if (options_.progress && move.block != block) options_.progress(block + 1, recorded_->blockCount);
  }
  group_.push_back(std::move(move));
}

SimulationResult Simulation::finish(const interp::Toolpath& recorded) {
  recorded_ = &recorded;
  if (!group_.empty()) {
    const int block = group_.front().block;
    cutGroup();
    if (options_.progress) options_.progress(block + 1, recorded_->blockCount);
  }
  if (block_) finishBlock();
  return std::move(result_);
}

void Simulation::finishBlock() {
  if (blockSink_) blockSink_(*block_);
  else result_.blocks.push_back(*block_);
}

// Matched by block and in the order made, not by block number alone: blocks run out of their
// order (a subprogram written after M30 runs before the main program's later blocks) and again
// (a loop), and a whole toolpath's starts are all recorded before its first move comes.
void Simulation::checkCycleStart(int block) {
  const auto& starts = recorded_->cycleStarts;
  for (; startsSeen_ < starts.size(); ++startsSeen_) pendingStarts_[starts[startsSeen_].block].push_back(startsSeen_);
  const auto pending = pendingStarts_.find(block);
  if (pending == pendingStarts_.end()) return;
  if (auto warning = cycleStartInStock(starts[pending->second.front()], stock_)) result_.warnings.push_back(*warning);
  pending->second.pop_front();
  if (pending->second.empty()) pendingStarts_.erase(pending);
}

void Simulation::cutGroup() {
  const interp::Move& head = group_.front();
  Stock& stock = stock_;
  SimulationResult& result = result_;
  if (!block_ || block_->block != head.block) {
    if (block_) finishBlock();
    block_ = BlockRemoval{head.block, head.line, head.column, 0.0, 0.0, head.source};
    checkCycleStart(head.block);
  }
  BlockRemoval& block = *block_;
  if (head.kind != interp::MoveKind::Dwell && head.workShift != frame_) {
    frame_ = head.workShift;
    checkShift_ = true;
  }
  if (checkShift_ && head.kind != interp::MoveKind::Dwell) {
    const auto warning = shiftedMoveInStock(head, stock);
    if (warning) result.warnings.push_back(*warning);
    checkShift_ = !warning && !interp::isCutting(head.kind);
  }

  const std::size_t end = groupFirst_ + group_.size();
  if (options_.observer) options_.observer(groupFirst_, end, stock, result.collisions);
  double removed = 0.0;
  RevolvedRegion revolved;             // what a turning write swept (none for a thread or a slot)
  std::optional<ChangedArea> changed;  // where the write can have changed the stock
  const ConvexPolygon& tool = toolOf(head, tools_);
  // With the spindle stopped nothing turns the part: a feed or a rapid alike drags the tool's
  // outline through it as a straight slot (a rapid swept as a ring would part the bar).
  if ((interp::isCutting(head.kind) || head.kind == interp::MoveKind::Rapid) && !spindleTurns(head)) {
    removed = removeSlots(head, tool, thicknessOf(head, options_.thicknesses), stock, changed);
  } else if (head.kind == interp::MoveKind::Thread) {
    const interp::Move* before = previous_ ? &*previous_ : nullptr;
    if (auto warning = threadPassStartsInStock(head, before, stock); warning && threadWarnedBlock_ != head.block) {
      result.warnings.push_back(*warning);
      threadWarnedBlock_ = head.block;
    }
    removed = removeThread(head, tool, stock, threads_, changed);
  } else {
    std::vector<ConvexPolygon> pieces;
    for (const interp::Move& move : group_) {
      const auto swept = sweptPieces(move, toolOf(move, tools_), stock.voxelMm());
      pieces.insert(pieces.end(), swept.begin(), swept.end());
    }
    revolved = RevolvedRegion(pieces);
    if (!pieces.empty()) {
      const auto changes = history_.changesOf(pieces);
      removed = changes ? stock.remove(revolved, *changes) : stock.remove(revolved);
      changed = ChangedArea::of(revolved);
    }
  }
  for (const interp::Move& move : group_) block.timeS += move.timeS;
  block.removedMm3 += removed;
  partOffs_.afterCut(group_, groupFirst_, recorded_->partsCatcher, revolved, changed, removed, stock, result);
  if (auto warning = cutWithSpindleStopped(head, removed, stock.voxelMm()); warning && spindleWarnedBlock_ != head.block) {
    result.warnings.push_back(*warning);
    spindleWarnedBlock_ = head.block;
  }
  const double voxelVolume = stock.voxelMm() * stock.voxelMm() * stock.voxelMm();
  if (head.kind == interp::MoveKind::Rapid && removed > kCollisionVoxels * voxelVolume)
    recordCollision(result.collisions, head, "rapid_into_stock", removed);
  if (options_.checks) checkMoves(*options_.checks, group_, stock, result.collisions);

  groupFirst_ = end;
  previous_ = std::move(group_.back());
  group_.clear();
}

}  // namespace lathesim::sim
