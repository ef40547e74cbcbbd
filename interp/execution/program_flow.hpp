#pragma once
// What a block asks of the program counter besides "go on to the next block": M98 calls a
// subprogram, M99 returns from one, and G71–G73 resume after their contour's last block.

#include <cstddef>
#include <optional>

namespace lathesim::interp {

/// M98 P… [L…]: run program O`programNumber` `repeats` times, then come back.
struct SubprogramCall {
  int programNumber = 0;
  int repeats = 1;
  int column = 0;  // of the P word, for diagnostics
};

struct ProgramFlow {
  std::optional<SubprogramCall> call;        // M98
  std::optional<int> returnColumn;           // M99: the column of the code
  std::optional<std::size_t> continueAfter;  // index of a block: go on with the one after it
};

}  // namespace lathesim::interp
