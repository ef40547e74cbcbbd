#pragma once
// The run block by block, for report.html's stepping: the stock's section (its meridian
// profile at C0) after every block that changed it, and each block's figures (line, moves,
// machine time, feed, S and rpm, tool, where the tool stands at its end; the removed volume
// comes from the simulation's block rows when the page is written).
//
// It takes every move as the interpreter makes it (a MoveSink beside the simulation) and a
// section as the simulation goes (sim::CutObserver, before each group of moves it cuts: the
// stock then holds every move before the group) when the group starts a block, kept only when
// it differs from the last one.
// Sections are written in whole micrometres, each as its change from the one before (the
// points a cut left unchanged at either end of a polyline are not repeated), so a 2,000-block
// program's page stays small. A long program is thinned, and the page says so: sections take
// at most kTimeShare of the run's time beside them (past a first kFreeSeconds), skipping
// blocks when they would take more; past kMaxSections every other section is dropped and
// sections are taken half as often. Past kMaxSteps steps neighbouring steps are merged in
// pairs (each then covers 2, 4, 8 … blocks: its time and removed volume their sums, its lines
// the range they span), and past kMaxMoves moves the toolpath is let go and no longer kept, so
// what a run holds for the page is bounded whatever the program's length (the streamed run's
// promise): at most kMaxSteps + 1 steps (about 100 bytes each) and kMaxMoves moves of path
// (at most 40 bytes each), about 2.5 MB at the most with the vectors' spare room and a merge's
// copy, and kMaxSections + 1 sections, each the size of the stock's profile.

#include <array>
#include <chrono>
#include <nlohmann/json.hpp>
#include <vector>

#include "interp/base/move_sink.hpp"
#include "setup/setup.hpp"
#include "sim/block_rows.hpp"
#include "sim/simulate.hpp"

namespace lathesim::app {

class StepRecording final : public interp::MoveSink {
 public:
  static constexpr std::size_t kMaxSections = 1500;
  static constexpr std::size_t kMaxSteps = 5000;
  static constexpr std::size_t kMaxMoves = 20000;
  static constexpr double kTimeShare = 0.1;
  static constexpr double kFreeSeconds = 0.2;  // under a tenth of a run that draws its pictures (≥ 2.5 s)

  explicit StepRecording(double voxelMm) : toleranceMm_(voxelMm / 4) {}

  void take(interp::Move move) override;
  /// What the simulation calls before each group of moves it cuts.
  sim::CutObserver observer();
  /// The section as the program leaves the stock.
  void finish(const sim::Stock& stock);

  /// Wall time spent taking sections so far (s).
  double secondsSpent() const { return secondsSpent_; }

  /// report.html's "steps" data (see writeReportHtml).
  nlohmann::ordered_json json(const sim::BlockRows& rows, const setup::Setup& setup, const RZ& start) const;

 private:
  using Polylines = std::vector<std::vector<std::array<long, 2>>>;  // (r, z) in µm
  struct Section {
    std::size_t afterMove = 0;  // the stock after moves [0, afterMove)
    Polylines polylines;
  };
  struct Step {
    int firstBlock = 0, block = 0;  // the ordinals of its first and its last block
    int line = 0, lastLine = 0, tool = 0;
    std::size_t blocks = 1;  // how many blocks it covers
    std::size_t firstMove = 0, endMove = 0;
    double timeS = 0, feed = 0, spindleS = 0, rpm = 0;
    std::array<long, 2> end{0, 0};
  };
  void take(const sim::Stock& stock, std::size_t afterMove, bool always);
  void mergeStepsInPairs();

  double toleranceMm_;
  std::size_t everyMoves_ = 1;  // a section at most every so many moves
  std::vector<Section> sections_;
  std::vector<Step> steps_;
  std::vector<long> path_;  // per move: its kind, where it ends (r, z); an arc its centre too
  std::size_t moves_ = 0;
  std::size_t nextStep_ = 0;  // the observer's place in steps_
  std::size_t blocksPerStep_ = 1;
  bool pathLeftOut_ = false;  // past kMaxMoves
  double secondsSpent_ = 0;
  std::chrono::steady_clock::time_point started_ = std::chrono::steady_clock::now();
};

}  // namespace lathesim::app
