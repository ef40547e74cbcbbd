#pragma once
// Where a programmed number becomes millimetres: the one place for G20 (inch) and for words
// counted in least input increments.

#include <string>

#include "interp/text/lexer.hpp"

namespace lathesim::interp {

constexpr double kMmPerInch = 25.4;
// IS-B, the usual increment system: the least input increment is 0.001 mm (0.0001 inch).
constexpr double kLeastIncrementMm = 0.001;
constexpr double kLeastIncrementInch = 0.0001;

/// A length as written: mm, or inches under G20.
inline double lengthMm(const Word& word, bool inch) {
  return inch ? word.value * kMmPerInch : word.value;
}

/// A length word of the kind lathe-cycles.md marks [LII] (G74/G75 P, Q and R(Δd)): written
/// without a decimal point it counts least input increments (P1500 = 1.5 mm); with one it is
/// a length as written (P1.5 = 1.5 mm).
inline double leastIncrementLengthMm(const Word& word, bool inch) {
  if (word.number.find('.') != std::string::npos) return lengthMm(word, inch);
  return inch ? word.value * kLeastIncrementInch * kMmPerInch : word.value * kLeastIncrementMm;
}

}  // namespace lathesim::interp
