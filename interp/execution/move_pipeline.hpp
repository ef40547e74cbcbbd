#pragma once
// The stages a move goes through after its block made it, on its way to the MoveSink: the
// corner a move asks for (motion/corners.hpp), the setup's frame, nose radius compensation
// (compensation/nose_compensation.hpp), the tool offsets' shifts, a rapid's dog-leg
// (motion/rapid_path.hpp), the move limit and the machine's travel. Each stage looks at most
// at its neighbours, so the moves pass in pieces: the pipeline holds the moves made since the
// last piece and lets them go once it holds `window` of them and the last can be cut after —
// no corner asked of the next move, no G41/G42 chain open (its cancel move is in), not a
// dwell (it stands where the next chain may still move it) — and at the end of the program.
// A piece of moves is the same moves whether it passes in one or in many: what the stages
// carry over from one piece to the next (the shift in force) goes with the pipeline.
// What it holds is bounded by `window` plus one block's moves, except inside a G41/G42 chain,
// which is held until it is cancelled.

#include <cstddef>
#include <optional>
#include <utility>
#include <vector>

#include "interp/compensation/uncompensated_nose.hpp"
#include "interp/state/interpreter_options.hpp"
#include "interp/motion/travel_limits.hpp"
#include "interp/base/move_sink.hpp"
#include "interp/base/result.hpp"

namespace lathesim::interp {

class MovePipeline {
 public:
  /// Warnings of the stages (a corner that does nothing) go to `warnings`.
  MovePipeline(const InterpreterOptions& options, MoveSink& sink, std::vector<Error>& warnings);

  /// The moves of one block, as it made them, in order; `pass`: the block was a G70–G73 that
  /// finished or roughed a contour; `legsCompensated`: a G90/G94 that offset its own legs.
  void add(const std::vector<Move>& moves, const std::optional<ContourPass>& pass = std::nullopt,
           bool legsCompensated = false);
  /// Lets the moves held go if there are `window` of them and they can be cut after;
  /// `anyCount`: however few there are (a parts catcher command counts the moves before it).
  Status release(bool anyCount = false);
  /// Lets every move go: the program has ended.
  Status finish();
  /// After an error of a block: the moves held, as their blocks made them (not compensated,
  /// offset nor split), for a look at what ran before the error; none goes to the sink.
  std::vector<Move> abandon() { return std::exchange(held_, {}); }

  /// Moves handed to the sink so far, and held: made but not yet handed on.
  std::size_t passed() const { return passed_; }
  std::size_t held() const { return held_.size(); }

 private:
  bool cutAfterLast() const;
  Status pass();

  const InterpreterOptions& options_;
  MoveSink& sink_;
  std::vector<Error>& warnings_;
  std::vector<Move> held_;
  RZ shiftInForce_{0, 0};  // the tool offset's shift the last move passed left in force
  std::size_t passed_ = 0;
  UncompensatedNoseCheck uncompensated_;  // contours cut under G40 with a nose radius
  DerivedTravelWarned travelWarned_;  // a derived travel's warning is given once per axis
};

}  // namespace lathesim::interp
