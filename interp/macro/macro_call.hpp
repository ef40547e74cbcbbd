#pragma once
// G65 P<program> [L<repeats>] <arguments>: a macro call's words, their values known (literal,
// or evaluated by macro/block_words.hpp). The arguments become the called macro's local
// variables (Fanuc 16i/18i custom macro manual, argument specification I and II):
//   I:  A #1  B #2  C #3  I #4  J #5  K #6  D #7  E #8  F #9  H #11  M #13  Q #17  R #18
//       S #19  T #20  U #21  V #22  W #23  X #24  Y #25  Z #26   (G L N O P are not arguments)
//   II: A B C, then up to ten sets of I J K: I1 #4 J1 #5 K1 #6, I2 #7 J2 #8 K2 #9 … K10 #33
// The control tells them apart by the order of I, J and K: an I, J or K that does not come
// after the previous one in the order I J K starts the next set. Set 1 is argument
// specification I's I J K, so both read alike; where both name one variable (D and I2 are
// both #7) the later word wins (the manual's example G65 A1.0 B2.0 I-3.0 I4.0 D5.0 P1000).
// Argument values are the words' values as the control reads them; a value an expression
// gives is passed unrounded (not checked in a manual).

#include <vector>

#include "interp/macro/variables.hpp"
#include "interp/base/result.hpp"
#include "interp/text/lexer.hpp"

namespace lathesim::interp::macro {

constexpr int kMaxMacroRepeats = 9999;

struct MacroCall {
  int programNumber = 0;
  int repeats = 1;
  int column = 0;  // of the P word, for diagnostics
  LocalVariables arguments{};  // <vacant> where no argument is given
};

/// Reads a G65 block's words (G65 among them). Fails without P, on a P or L that is no
/// whole number, on another G code, O, an argument given twice (but I J K), or more than ten
/// I J K sets.
Result<MacroCall> readMacroCall(const std::vector<Word>& words, int line);

}  // namespace lathesim::interp::macro
