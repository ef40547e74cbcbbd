#pragma once
// Lengths written with a decimal point and without one, noted as the program's words are read.
// A control reads `X20` as 20 mm (calculator input) or as 20 least increments, 0.020 mm (a
// Fanuc with DPI = 0); `Z-10.` is -10 mm either way. A program that writes lengths both ways
// is right under one reading only: the classic crash when it meets the other control.

#include <optional>
#include <string>

#include "interp/base/result.hpp"
#include "interp/text/lexer.hpp"
#include "interp/text/word_units.hpp"

namespace lathesim::interp {

class LengthWriting {
 public:
  /// Notes a length word of the block with ordinal `block` at `line` (zero, the same either way,
  /// and a value a macro expression gave are not noted).
  void note(const Word& word, int line, int block);

  /// One warning for a program that mixes the two forms, at a length written without a point
  /// (in the first block that mixes them, else the first such word), naming both readings.
  std::optional<Error> mixedWarning(const NumberReading& reading) const;

 private:
  struct Written {
    int line = 0;
    int column = 0;
    std::string text;
    double value = 0;
  };
  std::optional<Written> firstBare_, firstPointed_;
  std::optional<Written> mixedBare_, mixedPointed_;  // of the first block with both
  int block_ = -1;                                  // the block being noted, and its words
  std::optional<Written> blockBare_, blockPointed_;
};

}  // namespace lathesim::interp
