#pragma once
// The run block by block, for report.html's stepping: the stock's section (its meridian
// profile at C0) after every block that changed it, and each block's figures (line, moves,
// machine time, feed, S and rpm, tool, where the tool stands at its end; the removed volume
// comes from the simulation's block rows when the page is written).
//
// It takes every move as the interpreter makes it (a MoveSink beside the simulation) and a
// section as the simulation goes (sim::CutObserver, before each group of moves it cuts: the
// stock then holds every move before the group), kept only when it differs from the last one.
// Sections are written in whole micrometres, each as its change from the one before (the
// points a cut left unchanged at either end of a polyline are not repeated), so a 2,000-block
// program's page stays small. A long program is thinned, and the page says so: past
// kMaxSections every other section is dropped and sections are taken half as often; past
// kMaxSteps blocks the stepping is left out.

#include <array>
#include <nlohmann/json.hpp>
#include <vector>

#include "interp/base/move_sink.hpp"
#include "job/setup.hpp"
#include "sim/block_rows.hpp"
#include "sim/simulate.hpp"

namespace lathesim::app {

class StepRecording final : public interp::MoveSink {
 public:
  static constexpr std::size_t kMaxSections = 1500;
  static constexpr std::size_t kMaxSteps = 100000;

  explicit StepRecording(double voxelMm) : toleranceMm_(voxelMm / 4) {}

  void take(interp::Move move) override;
  /// What the simulation calls before each group of moves it cuts.
  sim::CutObserver observer();
  /// The section as the program leaves the stock.
  void finish(const sim::Stock& stock);

  /// report.html's "steps" data (see writeReportHtml), or null when the program has too many blocks.
  nlohmann::ordered_json json(const sim::BlockRows& rows, const job::Setup& setup, const RZ& start) const;

 private:
  using Polylines = std::vector<std::vector<std::array<long, 2>>>;  // (r, z) in µm
  struct Section {
    std::size_t afterMove = 0;  // the stock after moves [0, afterMove)
    Polylines polylines;
  };
  struct Step {
    int block = 0, line = 0, tool = 0;
    std::size_t firstMove = 0, endMove = 0;
    double timeS = 0, feed = 0, spindleS = 0, rpm = 0;
    std::array<long, 2> end{0, 0};
  };
  void take(const sim::Stock& stock, std::size_t afterMove, bool always);

  double toleranceMm_;
  std::size_t everyMoves_ = 1;  // a section at most every so many moves
  std::vector<Section> sections_;
  std::vector<Step> steps_;
  std::vector<long> path_;  // per move: its kind, where it ends (r, z); an arc its centre too
  std::size_t moves_ = 0;
};

}  // namespace lathesim::app
