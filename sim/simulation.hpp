#pragma once
// A simulation fed one move at a time (simulate.hpp says what it does to the stock): the moves
// can come straight from the interpreter, so that a long program's toolpath is never held.
// It holds only the group of moves it writes next (a turning block's run of feeds and arcs, or
// one move) and the move before it.

#include <cstddef>
#include <deque>
#include <functional>
#include <optional>
#include <unordered_map>
#include <vector>

#include "interp/base/move.hpp"
#include "interp/base/move_sink.hpp"
#include "sim/cut_history.hpp"
#include "sim/part_off.hpp"
#include "sim/simulate.hpp"
#include "sim/thread_history.hpp"

namespace lathesim::sim {

class Simulation final : public interp::MoveSink {
 public:
  /// Cuts `stock`. `recorded` is the toolpath the moves belong to, whose cycle starts, parts
  /// catcher commands and block count are read as the moves come (its own moves are not): a
  /// whole toolpath, or the one the interpreter fills as it runs (recordingIn rebinds it).
  Simulation(const interp::Toolpath& recorded, ToolOutlines tools, Stock& stock, BlockProgress progress = {},
             const CollisionChecks* checks = nullptr, ToolThicknesses thicknesses = {}, CutObserver observer = {});

  /// Each block's row to `sink` once the block is finished, instead of into the result's
  /// blocks (which finish then leaves empty). Before the first move.
  void sendBlocksTo(std::function<void(const BlockRemoval&)> sink) { blockSink_ = std::move(sink); }

  void recordingIn(const interp::Toolpath& toolpath) override { recorded_ = &toolpath; }
  /// The next move of the toolpath: the group before it is cut once the move cannot join it.
  void take(interp::Move move) override;
  /// Cuts the last group; what the whole toolpath did. `recorded` is the toolpath as the
  /// interpreter left it (the one recorded into may be gone). Once, after the last move.
  SimulationResult finish(const interp::Toolpath& recorded);

 private:
  /// Writes group_ into the stock and clears it.
  void cutGroup();
  /// block_ to the sink or the result.
  void finishBlock();
  /// Checks the cycle start made by this run of `block`, if it made one.
  void checkCycleStart(int block);

  const interp::Toolpath* recorded_;
  ToolOutlines tools_;
  Stock& stock_;
  BlockProgress progress_;
  const CollisionChecks* checks_;
  ToolThicknesses thicknesses_;
  CutObserver observer_;

  SimulationResult result_;
  std::function<void(const BlockRemoval&)> blockSink_;
  std::optional<BlockRemoval> block_;    // the row of the block being cut
  std::vector<interp::Move> group_;      // the moves written together next
  std::size_t groupFirst_ = 0;           // the toolpath's index of group_'s first move
  std::optional<interp::Move> previous_;  // the last move cut (a thread pass may continue it)
  // Cycle starts not yet checked, by block ordinal, each block's in the order they were made;
  // the first startsSeen_ of recorded_->cycleStarts are in here or checked.
  std::unordered_map<int, std::deque<std::size_t>> pendingStarts_;
  std::size_t startsSeen_ = 0;
  int spindleWarnedBlock_ = -1;  // one spindle warning per block
  int threadWarnedBlock_ = -1;   // one thread-start warning per block
  RZ frame_{0, 0};               // the G50 frame of the moves so far
  bool checkShift_ = false;      // after G50 moved it: until the first cut, or a warning
  PartOffWatch partOffs_;
  CutHistory history_;           // what turning writes removed: bounds where the next can change anything
  ThreadHistory threads_;        // the same for thread passes
};

}  // namespace lathesim::sim
