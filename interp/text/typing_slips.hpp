#pragma once
// Typing slips that read as other G-code, each refused at its column with what was meant:
//   GO1, X1O.5, Q2OO, O1OOO   the letter O (or o) typed for the digit zero, right after an
//                             address letter or inside its number  → G01, X10.5, Q200, O1000
//   01000                     a block opening with a number that starts with the digit zero:
//                             a program number typed with a zero for the letter O → O1000
//   [cite: 133]               a citation pasted with the program from a chat or a document
//   ] or [ outside a macro    a stray bracket (a bracket holds a Macro B expression, X[#1+2])
// A lower-case o is the letter O (o1000 is O1000, as the lexer reads every letter).

#include <cstddef>
#include <optional>
#include <string>

#include "interp/base/result.hpp"
#include "interp/text/lexer.hpp"

namespace lathesim::interp {

/// The letter O typed for a zero at `chars[at]`, right after the `letter` word's `number`
/// (which ends there), with the word meant; nullopt when no O stands there, or when the O's are
/// followed at once by another letter (prose: "co" in "coolant").
std::optional<Error> letterOForZero(const RawBlock& block, std::size_t at, char letter, const std::string& number);

/// A citation pasted into the block (`[cite: 133]`, `[cite_start]`), at its '['.
std::optional<Error> pastedCitation(const RawBlock& block);

/// For a block on `line` whose first token is the number `number` at `column`: the slip of a
/// zero for the letter O in a program number (01000 → "did you mean O1000?"), or nullopt.
std::optional<Error> zeroForLetterO(int line, const std::string& number, int column);

/// A bracket outside a Macro B expression at `line`:`column`: what it is and what to do.
Error strayBracket(int line, const std::string& bracket, int column);

}  // namespace lathesim::interp
