#pragma once
// `lathesim run --at-line N`: the program as far as line N, so the part can be shown as it
// was then. The cut-off is made here, before simulation; sim sees an ordinary toolpath.
//
// Precisely: the moves from the program's start up to and including the last move of the
// first execution of line N — the unbroken run of moves, in program order, that begins with
// the first move line N makes. A line run several times (a subprogram called twice, a
// repeated loop) is cut after its first execution; a canned cycle's block is cut after all
// the moves it expands to.

#include <optional>
#include <string>

#include "setup/job.hpp"
#include "interp/base/move.hpp"

namespace lathesim::app {

struct ToolpathAtLine {
  std::optional<interp::Toolpath> toolpath;  // the moves up to line N; blockCount and cycleStarts cut to match
  std::string problem;                       // empty when toolpath is set
};

/// The toolpath cut after line `line`'s first execution. A line that does not exist in the
/// `sourceLineCount`-line program, or makes no move, is a problem naming it.
ToolpathAtLine toolpathAtLine(const interp::Toolpath& toolpath, int line, int sourceLineCount);

/// With `atLine` given, cuts the job's toolpath there; false (the problem printed) if it
/// cannot. Without it, leaves the job alone.
bool cutAtLine(std::optional<int> atLine, setup::Job& job);

}  // namespace lathesim::app
