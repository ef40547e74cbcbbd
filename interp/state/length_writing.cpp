#include "interp/state/length_writing.hpp"

#include <fmt/format.h>

namespace lathesim::interp {

void LengthWriting::note(const Word& word, int line, int block) {
  // Zero reads the same under both: X0 is no evidence either way; nor is a value a macro
  // expression gave (X#1), which is a length under both.
  if (word.value == 0 || word.evaluated) return;
  if (block != block_) {
    block_ = block;
    blockBare_.reset();
    blockPointed_.reset();
  }
  const Written written{line, word.column, word.text(), word.value};
  std::optional<Written>& first = hasDecimalPoint(word) ? firstPointed_ : firstBare_;
  std::optional<Written>& inBlock = hasDecimalPoint(word) ? blockPointed_ : blockBare_;
  if (!first) first = written;
  if (!inBlock) inBlock = written;
  if (!mixedBare_ && blockBare_ && blockPointed_) {
    mixedBare_ = blockBare_;
    mixedPointed_ = blockPointed_;
  }
}

std::optional<Error> LengthWriting::mixedWarning(const NumberReading& reading) const {
  if (!firstBare_ || !firstPointed_) return std::nullopt;
  const Written& bare = mixedBare_ ? *mixedBare_ : *firstBare_;
  const Written& pointed = mixedBare_ ? *mixedPointed_ : *firstPointed_;
  const char* unit = reading.inch ? "inch" : "mm";
  const bool counted = reading.decimalPointInput == DecimalPointInput::LeastIncrements;
  const std::string asUnits = fmt::format("{:g} {}", bare.value, unit);
  const std::string asIncrements = fmt::format("{:g} {}", bare.value * reading.leastIncrement(), unit);
  const std::string where = mixedBare_ ? "in the same block" : fmt::format("on line {}", pointed.line);
  return Error{bare.line, bare.column,
               fmt::format("{} has no decimal point while {} {} has one: this control reads {} as {} "
                           "(decimal_point_input = \"{}\"), a control that {} reads it as {}; a program "
                           "that mixes the two forms crashes on one of them: write every length with a "
                           "decimal point",
                           bare.text, pointed.text, where, bare.text, counted ? asIncrements : asUnits,
                           counted ? "increments" : "calculator",
                           counted ? "takes it in mm (calculator input)" : "counts least increments (Fanuc DPI = 0)",
                           counted ? asUnits : asIncrements)};
}

}  // namespace lathesim::interp
