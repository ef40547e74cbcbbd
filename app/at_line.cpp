#include "app/at_line.hpp"

#include <algorithm>
#include <iostream>

namespace lathesim::app {

ToolpathAtLine toolpathAtLine(const interp::Toolpath& toolpath, int line, int sourceLineCount) {
  if (line < 1 || line > sourceLineCount) {
    return {std::nullopt, "--at-line " + std::to_string(line) + ": the program has no line " + std::to_string(line) +
                              " (it has lines 1 to " + std::to_string(sourceLineCount) + ")"};
  }
  const auto& moves = toolpath.moves;
  // A move of a subprogram's file runs under the program's line whose call led there.
  const auto isOnLine = [&toolpath, line](const interp::Move& m) {
    int programLine = m.line;
    for (int source = m.source; source != 0; source = toolpath.sources[static_cast<std::size_t>(source - 1)].caller)
      programLine = toolpath.sources[static_cast<std::size_t>(source - 1)].callLine;
    return programLine == line;
  };
  const auto first = std::find_if(moves.begin(), moves.end(), isOnLine);
  if (first == moves.end()) {
    return {std::nullopt, "--at-line " + std::to_string(line) + ": line " + std::to_string(line) +
                              " makes no move; give a line that moves the tool"};
  }
  const auto end = std::find_if_not(first, moves.end(), isOnLine);

  interp::Toolpath cut = toolpath;
  cut.moves.assign(moves.begin(), end);
  // Block ordinals repeat when a subprogram runs again, so they bound nothing in order. The
  // cycle starts (in program order) kept are those whose block's moves have begun.
  cut.blockCount = 0;
  std::size_t cyclesBegun = 0;
  for (std::size_t m = 0; m < cut.moves.size(); ++m) {
    const int block = cut.moves[m].block;
    cut.blockCount = std::max(cut.blockCount, block + 1);
    const bool blockBegins = m == 0 || cut.moves[m - 1].block != block;
    if (blockBegins && cyclesBegun < cut.cycleStarts.size() && cut.cycleStarts[cyclesBegun].block == block)
      ++cyclesBegun;
  }
  cut.cycleStarts.resize(cyclesBegun);
  return {std::move(cut), ""};
}

bool cutAtLine(std::optional<int> atLine, setup::Job& job) {
  if (!atLine) return true;
  const std::string_view text = job.programText.text().view();
  const auto lineCount = static_cast<int>(std::count(text.begin(), text.end(), '\n') +
                                          (text.empty() || text.back() == '\n' ? 0 : 1));
  ToolpathAtLine cut = toolpathAtLine(job.toolpath, *atLine, lineCount);
  if (!cut.toolpath) {
    std::cerr << "lathesim: error: " << cut.problem << '\n';
    return false;
  }
  job.toolpath = std::move(*cut.toolpath);
  return true;
}

}  // namespace lathesim::app
