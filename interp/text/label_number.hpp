#pragma once
// The numbers that label blocks and programs: N sequence numbers (and the P/Q of G70–G73 and
// M99 P that name them) have at most five digits (N1–N99999), O program numbers at most eight.
// A longer number is an error quoting it as written, never an integer that wrapped round.

#include <string>
#include <string_view>

#include "interp/base/result.hpp"
#include "interp/text/lexer.hpp"

namespace lathesim::interp {

inline constexpr int kMaxSequenceDigits = 5;
inline constexpr int kMaxProgramDigits = 8;

/// What to say of a word that must be a whole number (a label, a count) but was written with
/// a decimal point — "a decimal point where a whole number is meant; write P1000" (for P1000.
/// or P1000.0) or "…; a count has no fraction" (L2.5) — or empty for any other word.
std::string decimalPointSlip(const Word& word);

/// The value of `word` as a label of at most `maxDigits` digits, or the error at it; `what`
/// names the number in the message ("a sequence number").
Result<int> labelNumberOf(const Word& word, int line, int maxDigits, std::string_view what);

}  // namespace lathesim::interp
