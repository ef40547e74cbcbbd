#include "interp/state/move_limit.hpp"

#include <fmt/format.h>

namespace lathesim::interp {

std::optional<Error> moveLimitError(std::size_t moves, std::size_t maxMoves, int line, int column) {
  if (moves <= maxMoves) return std::nullopt;
  return Error{line, column,
               fmt::format("the program makes more than {} moves (the limit) by this block: a toolpath that long takes "
                           "hours to simulate, and nested repeats can ask for billions; if it is meant, raise the "
                           "limit with --max-moves or [sim] max_moves",
                           maxMoves)};
}

}  // namespace lathesim::interp
