#pragma once
// What programmedThreads (thread_programs.hpp) reads of a toolpath whose moves stream past:
// every thread move, and for each run of other moves between them one move that stands for
// the run — a cut if the run has one (a cut ends a thread), else its first move (a rapid or a
// dwell, which keeps a pass from joining the one before). programmedThreads finds the same
// threads in these as in the whole toolpath; a program without threads keeps one move.

#include <vector>

#include "interp/base/move.hpp"
#include "interp/base/move_sink.hpp"

namespace lathesim::measure {

class ThreadMoveCollector final : public interp::MoveSink {
 public:
  explicit ThreadMoveCollector(std::vector<interp::Move>& moves) : moves_(moves) {}
  void take(interp::Move move) override;

 private:
  std::vector<interp::Move>& moves_;
  bool standsIn_ = false;  // the last move kept stands for a run of other moves
};

}  // namespace lathesim::measure
