#pragma once
// The limit on the moves a run may make (InterpreterOptions::maxMoves), kept by the program
// runner, the move pipeline and the cycles that make many legs.

#include <cstddef>
#include <optional>

#include "interp/base/result.hpp"

namespace lathesim::interp {

/// When `moves` passes `maxMoves` (InterpreterOptions::maxMoves), the error at `line`,
/// `column` (the block that made the move past the limit) that names the limit.
std::optional<Error> moveLimitError(std::size_t moves, std::size_t maxMoves, int line, int column);

}  // namespace lathesim::interp
