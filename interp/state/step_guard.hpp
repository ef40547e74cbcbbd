#pragma once
// The step limit: a program may run its blocks again at most so many times (a block's first
// run is free, so a long program without loops is never stopped; every later run counts), so
// that an endless WHILE or GOTO loop, or calls repeated beyond reason, end in an error rather
// than a hang or a toolpath that fills the memory. The error names the loop the program is
// stuck in: of the loops running when
// the limit is reached, the one in the outermost program (main program, then the
// subprograms and macros it called) that spans the most blocks, so an endless outer loop is
// blamed rather than a finite inner one it keeps restarting.
// A loop is running from its first jump back (END to WHILE, a GOTO to an earlier block, M99
// repeating a called program) until execution leaves the blocks it spans in its program.

#include <cstddef>
#include <map>
#include <optional>
#include <vector>

#include "interp/base/result.hpp"

namespace lathesim::interp {

/// The default limit: a million blocks run again. An endless loop of moves stops after about
/// a second and 150 MB of moves; the Macro B programs of shops repeat a few thousand blocks.
constexpr long long kDefaultMaxSteps = 1'000'000;

/// Where a loop is written: the block that starts it (WHILE, DO), jumps back (GOTO) or calls
/// the program repeated.
struct LoopSite {
  std::size_t block = 0;
  int column = 0;
};

class StepGuard {
 public:
  explicit StepGuard(long long maxSteps) : maxSteps_(maxSteps), frames_(1) {}

  /// Counts a run of block `index` of the innermost running program. True when the limit is
  /// passed: then stuckLoop() says where.
  bool step(std::size_t index);
  /// A jump back from block `from` to block `to` (≤ from) of the innermost running program.
  void jumpedBack(std::size_t from, std::size_t to, LoopSite site);
  /// A subprogram or macro starts (it has loops of its own) or ends.
  void enterProgram() { frames_.emplace_back(); }
  void leaveProgram() { frames_.pop_back(); }

  /// The loop to blame when the limit is passed, if any loop is running.
  std::optional<LoopSite> stuckLoop() const;
  long long maxSteps() const { return maxSteps_; }

 private:
  struct RunningLoop {
    std::size_t first = 0;  // the blocks it spans
    std::size_t last = 0;
    LoopSite site;
  };
  using Frame = std::vector<RunningLoop>;

  bool noteRun(std::size_t index);  // whether block `index` had run before; notes that it has

  long long maxSteps_;
  long long steps_ = 0;     // runs of blocks that had run before
  // The blocks that have run, as runs of consecutive blocks: first → one past the last. A
  // program run straight through is one run, however long.
  std::map<std::size_t, std::size_t> ran_;
  std::vector<Frame> frames_;  // the main program first
};

}  // namespace lathesim::interp
