#include "measure/thread_moves.hpp"

namespace lathesim::measure {
namespace {

bool cuts(const interp::Move& move) {
  return move.kind != interp::MoveKind::Rapid && move.kind != interp::MoveKind::Dwell;
}

}  // namespace

void ThreadMoveCollector::take(interp::Move move) {
  if (move.kind == interp::MoveKind::Thread) {
    moves_.push_back(std::move(move));
    standsIn_ = false;
  } else if (!standsIn_) {
    moves_.push_back(std::move(move));
    standsIn_ = true;
  } else if (cuts(move) && !cuts(moves_.back())) {
    moves_.back() = std::move(move);
  }
}

}  // namespace lathesim::measure
