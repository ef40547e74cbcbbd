#include "interp/macro/loop_pairs.hpp"

#include <vector>

#include <fmt/format.h>

namespace lathesim::interp::macro {
namespace {

struct OpenLoop {
  std::size_t index;  // the DO block
  int number;
};

class Pairing {
 public:
  explicit Pairing(const Program& program) : program_(program) {}

  LoopPairs run() {
    if (program_.loopBlocks == 0) return {};  // no block to pair: the text need not be read again
    int segment = program_.blockCount() == 0 ? -1 : program_.block(0).program;
    for (std::size_t i = 0; i < program_.blockCount(); ++i) {
      const ProgramBlock block = program_.block(i);
      if (block.program != segment) {  // a new O program: the last one's loops end here
        closeSegment();
        segment = block.program;
      }
      const MacroBlock* macro = block.skipped ? nullptr : block.macroBlock();
      if (macro == nullptr || !macro->statement) continue;
      if (const auto* start = std::get_if<LoopStart>(&*macro->statement)) open(i, *start);
      if (const auto* end = std::get_if<LoopEnd>(&*macro->statement)) close(i, *end);
    }
    closeSegment();
    return std::move(pairs_);
  }

 private:
  int lineOf(std::size_t index) const { return program_.block(index).line; }

  void fail(std::size_t index, const Error& error) { pairs_.partner.insert_or_assign(index, error); }

  void open(std::size_t index, const LoopStart& start) {
    const int line = lineOf(index);
    for (const OpenLoop& loop : open_) {
      if (loop.number == start.loopNumber) {
        fail(index, Error{line, start.numberColumn,
                          fmt::format("DO {} inside the loop DO {} of line {}, which is still open: nested loops "
                                      "need different numbers (1, 2, 3)",
                                      start.loopNumber, loop.number, lineOf(loop.index))});
        return;
      }
    }
    open_.push_back({index, start.loopNumber});
  }

  void close(std::size_t index, const LoopEnd& end) {
    const int line = lineOf(index);
    std::size_t match = open_.size();
    for (std::size_t k = open_.size(); k-- > 0;) {
      if (open_[k].number == end.loopNumber) {
        match = k;
        break;
      }
    }
    if (match == open_.size()) {
      fail(index, Error{line, end.column,
                        fmt::format("END {} has no DO {} open before it in this program", end.loopNumber,
                                    end.loopNumber)});
      return;
    }
    if (match + 1 != open_.size()) {  // loops opened inside DO m are still open: they cross
      const OpenLoop& inner = open_.back();
      const Error crossing{line, end.column,
                           fmt::format("END {} closes DO {} of line {} while DO {} of line {} inside it is still "
                                       "open: loops may nest but not cross (alarm 124)",
                                       end.loopNumber, end.loopNumber, lineOf(open_[match].index), inner.number,
                                       lineOf(inner.index))};
      fail(index, crossing);
      for (std::size_t k = match; k < open_.size(); ++k) fail(open_[k].index, crossing);
      open_.resize(match);
      return;
    }
    pairs_.partner.insert_or_assign(open_.back().index, Result<std::size_t>(index));
    pairs_.partner.insert_or_assign(index, Result<std::size_t>(open_.back().index));
    open_.pop_back();
  }

  void closeSegment() {
    for (const OpenLoop& loop : open_) {
      const ProgramBlock block = program_.block(loop.index);
      const auto& start = std::get<LoopStart>(*block.macroBlock()->statement);
      fail(loop.index, Error{block.line, start.column,
                             fmt::format("DO {} has no END {} before the end of its program (alarm 124)",
                                         loop.number, loop.number)});
    }
    open_.clear();
  }

  const Program& program_;
  std::vector<OpenLoop> open_;
  LoopPairs pairs_;
};

}  // namespace

LoopPairs pairLoops(const Program& program) { return Pairing(program).run(); }

}  // namespace lathesim::interp::macro
