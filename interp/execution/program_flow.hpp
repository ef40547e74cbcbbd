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
  bool local = false;  // Haas M97 P… L…: `programNumber` is the N of a block of this program
};

/// M99 [P…]: return from a subprogram, to the block after the call, or to N`sequence` of the
/// calling program (Fanuc, GSK). In the main program it starts the program over.
struct SubprogramReturn {
  int column = 0;                 // of the M99
  std::optional<int> sequence;    // P
  int sequenceColumn = 0;         // of the P word
};

struct ProgramFlow {
  std::optional<SubprogramCall> call;        // M98
  std::optional<SubprogramReturn> giveBack;  // M99
  std::optional<std::size_t> continueAfter;  // index of a block: go on with the one after it
};

}  // namespace lathesim::interp
