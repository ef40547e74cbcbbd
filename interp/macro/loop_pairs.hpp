#pragma once
// Which DO pairs with which END, found once for the whole program (its text read through
// again, unless it has no DO or END at all) (Fanuc 0i/16i "Repetition
// (WHILE statement)"): within one program (between O blocks), an END m closes the innermost
// open DO m; loops may not cross (DO 1 … DO 2 … END 1 … END 2); a DO inside a loop of the
// same number, an END with no open DO of its number and a DO with no END before the program
// ends are errors. With three loop numbers and no number reused inside its own loop, loops
// nest at most three deep, as Fanuc allows. Each error is located at the block at
// fault and raised when execution reaches any block of the broken pair (the controls alarm
// when they run into it, too: 124 missing END, 126 bad loop number or nesting).

#include <cstddef>
#include <map>

#include "interp/base/result.hpp"
#include "interp/text/program.hpp"

namespace lathesim::interp::macro {

struct LoopPairs {
  /// For the block of every DO and END: the block of its partner, or why it has none.
  std::map<std::size_t, Result<std::size_t>> partner;
};

LoopPairs pairLoops(const Program& program);

}  // namespace lathesim::interp::macro
