#pragma once
// The simulation: a toolpath run through the stock. Every move sweeps its tool's outline from
// start to end and removes what it covers — revolved about the spindle axis while the spindle
// turns, along the helix for a thread move (geometry/helical_sweep.hpp), and as a straight
// slot the insert's thickness wide when the spindle stands (geometry/straight_slot.hpp).
//
// One entry, in two forms: simulate() cuts a whole toolpath; a Simulation is fed one move at a
// time (a MoveSink), so that the moves can come straight from the interpreter and a long
// program's toolpath is never held. simulate() is a Simulation fed every move. What either
// found is a SimulationResult (simulation_result.hpp).

#include <cstddef>
#include <deque>
#include <functional>
#include <map>
#include <optional>
#include <unordered_map>
#include <vector>

#include "geometry/convex_polygon.hpp"
#include "interp/base/move.hpp"
#include "interp/base/move_sink.hpp"
#include "sim/cut_history.hpp"
#include "sim/holder_check.hpp"
#include "sim/part_off.hpp"
#include "sim/simulation_result.hpp"
#include "sim/stock.hpp"
#include "sim/thread_history.hpp"

namespace lathesim::sim {

using ToolOutlines = std::map<int, ConvexPolygon>;  // tool number → outline (radial, axial) mm
/// tool number → the insert's thickness across the tool's plane (mm): what a cut with the
/// spindle stopped removes across that plane. A tool not listed is kDefaultInsertThicknessMm.
using ToolThicknesses = std::map<int, double>;
inline constexpr double kDefaultInsertThicknessMm = 4.0;
using BlockProgress = std::function<void(int blocksDone, int blocksTotal)>;

/// Called before the moves [firstMove, endMove) are cut, with the stock as it stands then and
/// the collisions found so far: what a picture taken while those moves run shows (the
/// animation's frames, the crashes marked from the frame after each).
using CutObserver = std::function<void(std::size_t firstMove, std::size_t endMove, const Stock& stock,
                                       const std::vector<Collision>& collisions)>;

/// What a simulation may be given besides the toolpath, the tools and the stock.
struct SimulationOptions {
  BlockProgress progress;                   // told as blocks are finished
  const CollisionChecks* checks = nullptr;  // holder and chuck collisions (holder_check.hpp), when given
  ToolThicknesses thicknesses;              // the inserts' thicknesses, for cuts with the spindle stopped
  CutObserver observer;                     // told of each group of moves before it is cut
};

/// Removes every move's swept region from `stock` in program order. Consecutive feeds and
/// arcs of one block made with the spindle turning are united, revolved, and written once (a
/// cycle's cut and retract overlap heavily); each rapid is written on its own so that a rapid
/// into material is caught and located; each thread move on its own along its helix (from
/// its start angle, one turn per lead); each feed, arc or thread move made with the spindle
/// stopped (before M03/M04, after M05, at S0) as a straight slot at the angle the spindle
/// stands at (Move::spindleAngleDeg; arcs by their chords); dwells remove nothing. After each
/// write that removed material, what came loose is taken out of `stock` (part_off.hpp): the
/// stock is then the stub left in the chuck, and the first piece is the result's `part`.
SimulationResult simulate(const interp::Toolpath& toolpath, const ToolOutlines& tools, Stock& stock,
                          const SimulationOptions& options = {});

/// The same, fed one move at a time.
class Simulation final : public interp::MoveSink {
 public:
  /// Cuts `stock`. `recorded` is the toolpath the moves belong to, whose cycle starts, parts
  /// catcher commands and block count are read as the moves come (its own moves are not): a
  /// whole toolpath, or the one the interpreter fills as it runs (recordingIn rebinds it).
  Simulation(const interp::Toolpath& recorded, ToolOutlines tools, Stock& stock, SimulationOptions options = {});

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
  SimulationOptions options_;

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
