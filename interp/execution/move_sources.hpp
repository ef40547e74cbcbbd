#pragma once
// Which text a block's moves come from (Move::source, Toolpath::sources): the program's own,
// or a subprogram's file reached by a chain of calls. Each file entered from a different
// calling line is a source of its own, so that a move found wrong in O2000.nc names its line
// there and the M98 that called it ("called from main.nc:14").

#include <cstddef>
#include <cstdint>
#include <map>
#include <span>
#include <tuple>
#include <vector>

#include "interp/base/move.hpp"
#include "interp/text/program.hpp"

namespace lathesim::interp {

class MoveSources {
 public:
  /// `program` and `toolpath` must outlive it; the sources found are added to toolpath.sources.
  MoveSources(const Program& program, Toolpath& toolpath) : program_(program), toolpath_(toolpath) {}

  /// The source of a block in text `text` (ProgramBlock::source) run under the calls
  /// `calls` (their M98/G65 blocks, outermost first).
  std::uint16_t of(int text, std::span<const std::size_t> calls);

 private:
  std::uint16_t entered(int text, int caller, int callLine, int callColumn);

  const Program& program_;
  Toolpath& toolpath_;
  std::map<std::tuple<int, int, int, int>, std::uint16_t> found_;  // (text, caller, line, column) → source
  // The last block's answer: the blocks of a subprogram run one after another.
  int lastText_ = 0;
  std::vector<std::size_t> lastCalls_;
  std::uint16_t last_ = 0;
};

}  // namespace lathesim::interp
