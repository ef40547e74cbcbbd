#pragma once
// The NC words of a macro block with their values as the block runs (the variables may have
// changed since it last ran). A word an expression gives is written as the control reads it
// (Fanuc: "the value of a variable is rounded to the least input increment of the address"):
//   M N O P Q L S T H D     a whole number, rounded half away from zero (M#1 with #1 = 3.5 is
//                           M04; S[1000.5] is S1001), written without a decimal point: P and
//                           Q of G74/G75 are then counts of least increments, as written
//   G                       not rounded ("except G codes"): G#1 with 1.5 is no code
//   F                       the value as it is (not rounded; not checked in a manual)
//   other letters (X Z U W I K R …)  a length: rounded to 0.001 mm (0.0001 inch under G20)
//                           and written with a decimal point, so a control that reads
//                           "X20" as 0.020 mm still reads X#1 with #1 = 20 as 20 mm
// In G65's arguments the value is kept unrounded. An address given a <vacant> value is left
// out, as if the word were not written (Fanuc: G00 X#1 with #1 vacant is G00 alone).

#include <string>
#include <vector>

#include "interp/macro/statement.hpp"
#include "interp/macro/variables.hpp"
#include "interp/result.hpp"
#include "interp/text/lexer.hpp"

namespace lathesim::interp::macro {

/// An address left out because its value was <vacant>.
struct VacantWord {
  char letter = 0;
  int column = 0;
  std::string written;  // e.g. "X#1", "Z-#26"
};

struct BlockWords {
  std::vector<Word> words;
  std::vector<VacantWord> leftOut;
  bool macroCall = false;  // the block holds G65: its words are a call's, arguments unrounded
};

/// The words of `block` (which holds no statement). `inch`: G20 in force for the block.
Result<BlockWords> evaluateWords(const MacroBlock& block, const VariableStore& variables, int line, bool inch);

/// A word for `letter` with a value a macro expression gave, rounded and written as above.
Word evaluatedWord(char letter, int column, double value, bool inch);

/// `error` of a block whose words `leftOut` were left out, with a note naming them ("X#1 at
/// column 5 was left out: #1 is vacant"): the word left out is often why the block fails (G90
/// without its X).
Error withLeftOutNote(Error error, const std::vector<VacantWord>& leftOut);

}  // namespace lathesim::interp::macro
