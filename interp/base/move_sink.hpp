#pragma once
// Where the interpreter hands its moves, one by one in program order, each once nothing can
// change it any more (interp/execution/move_pipeline.hpp): a long program's moves flow to
// their consumer (a CSV, a simulation) instead of piling up in a Toolpath.

#include <vector>

#include "interp/base/move.hpp"

namespace lathesim::interp {

class MoveSink {
 public:
  virtual ~MoveSink() = default;
  /// The next move of the toolpath, final (in the setup's frame, compensated, offset).
  virtual void take(Move move) = 0;
  /// The toolpath the interpreter records into as it runs (its cycle starts, stops, parts
  /// catcher commands and block count; not its moves), for a sink that reads them beside the
  /// moves: told before the first move; each is recorded before its block's moves come. Valid
  /// until the interpreter returns.
  virtual void recordingIn(const Toolpath& /*toolpath*/) {}
};

/// The sink that keeps every move, for the callers that need the whole toolpath at once.
class MoveCollector final : public MoveSink {
 public:
  explicit MoveCollector(std::vector<Move>& moves) : moves_(moves) {}
  void take(Move move) override { moves_.push_back(std::move(move)); }

 private:
  std::vector<Move>& moves_;
};

}  // namespace lathesim::interp
