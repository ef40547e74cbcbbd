#pragma once
// The NC words of a macro block with their values as the block runs (the variables may have
// changed since it last ran). A word an expression gives is written as the control reads it
// (Fanuc: "the value of a variable is rounded to the least input increment of the address"):
//   M N O P Q L S T H D     a whole number, rounded half away from zero (M#1 with #1 = 3.5 is
//                           M04; S[1000.5] is S1001), written without a decimal point: P and
//                           Q of G74/G75 are then counts of least increments, as written
//   G                       not rounded ("except G codes"): G#1 with 1.5 is no code
//   F                       the value as it is (not rounded; not checked in a manual)
//   other letters (X Z U W I K R …)  a length in mm (inch under G20): rounded to the least
//                           input increment (0.001 mm at IS-B, 0.0001 mm at IS-C; a tenth of
//                           that in inches) and written with a decimal point, so a control that
//                           reads "X20" as 0.020 mm (least-increment input, Fanuc DPI = 0)
//                           still reads X#1 with #1 = 20 as 20 mm (Fanuc: "#1 = 123" holds
//                           123.000; X#1 with 12.3456 at 0.001 mm is X12.346)
// In G65's arguments a value an expression gives is kept unrounded; an argument written
// without a decimal point is counted in the least input increment of its address (Fanuc
// 16i/18i custom macro manual: "The units used for argument data passed without a decimal
// point correspond to the least input increment of each address"): under least-increment
// input, X20 passes 0.020 mm in X Y Z U V W I J K R; the other letters pass the number as
// written (whether A B C count 0.001° on a lathe with those axes is not checked: ⚠).
// An address given a <vacant> value is left out, as if the word were not written (Fanuc:
// G00 X#1 with #1 vacant is G00 alone).

#include <string>
#include <vector>

#include "interp/text/statement.hpp"
#include "interp/macro/variables.hpp"
#include "interp/base/result.hpp"
#include "interp/text/lexer.hpp"
#include "interp/text/word_units.hpp"

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

/// The words of `block` (which holds no statement), read as the control reads them: `reading`
/// holds the unit in force (G20, or G20/G21 in the block itself) and the input parameters.
Result<BlockWords> evaluateWords(const MacroBlock& block, const VariableStore& variables, int line,
                                 NumberReading reading);

/// Whether a G65 argument of `letter` is a length (X Y Z U V W I J K R), as above.
bool isLengthArgument(char letter);

/// A word for `letter` with a value a macro expression gave, rounded and written as above.
Word evaluatedWord(char letter, int column, double value, const NumberReading& reading);

/// `error` of a block whose words `leftOut` were left out, with a note naming them ("X#1 at
/// column 5 was left out: #1 is vacant"): the word left out is often why the block fails (G90
/// without its X).
Error withLeftOutNote(Error error, const std::vector<VacantWord>& leftOut);

}  // namespace lathesim::interp::macro
