#include "interp/macro/block_words.hpp"

#include <cmath>
#include <optional>
#include <string_view>

#include <fmt/format.h>

#include "interp/macro/evaluator.hpp"
#include "interp/macro/functions.hpp"

namespace lathesim::interp::macro {
namespace {

constexpr std::string_view kWholeNumberLetters = "MNOPQLSTHD";
// The G65 arguments whose address is a length: counted in least increments when written
// without a decimal point under least-increment input.
constexpr std::string_view kLengthArgumentLetters = "XYZUVWIJKR";
constexpr int kMacroCallCode = 65;

bool isWholeNumberLetter(char letter) { return kWholeNumberLetters.find(letter) != std::string_view::npos; }

// The least input increment an expression's value is rounded to in `letter`; none for F and
// for G, whose codes are not rounded (G#1 with 1.5 is no code, not G02).
std::optional<double> incrementOf(char letter, const NumberReading& reading) {
  if (isWholeNumberLetter(letter)) return 1.0;
  if (letter == 'F' || letter == 'G') return std::nullopt;
  return reading.leastIncrement();
}

// "20." "12.346" "-0.5": the fewest digits that give the value back, and always a decimal point.
std::string withDecimalPoint(double value) {
  std::string text = fmt::format("{}", value == 0.0 ? 0.0 : value);
  if (text.find_first_of(".e") == std::string::npos) text += '.';
  return text;
}

// How an address's value is shown when it was vacant: X#1, Z-#26, X#[…].
std::string writtenVacant(char letter, const Expression& expression) {
  const Expression* variable = &expression;
  std::string sign;
  if (variable->kind == Expression::Kind::Negate) {
    sign = "-";
    variable = &variable->operands.front();
  }
  if (variable->kind == Expression::Kind::Variable && variable->operands.front().kind == Expression::Kind::Number) {
    return fmt::format("{}{}#{}", letter, sign, variable->operands.front().text);
  }
  return fmt::format("{}{}#[…]", letter, sign);
}

// A G65 argument written as a number, as the called macro's variable receives it.
Word argumentAsPassed(const Word& word, const NumberReading& reading) {
  const bool counted =
      reading.decimalPointInput == DecimalPointInput::LeastIncrements && !hasDecimalPoint(word) && isLengthArgument(word.letter);
  if (!counted) return word;
  Word passed = word;
  passed.value = word.value * reading.leastIncrement();
  return passed;
}

}  // namespace

bool isLengthArgument(char letter) { return kLengthArgumentLetters.find(letter) != std::string_view::npos; }

Word evaluatedWord(char letter, int column, double value, const NumberReading& reading) {
  Word word;
  word.letter = letter;
  word.column = column;
  word.evaluated = true;
  const auto increment = incrementOf(letter, reading);
  word.value = increment ? roundToIncrement(value, *increment) : value;
  if (word.value == 0.0) word.value = 0.0;  // no "-0."
  constexpr double kLargestWholeText = 1e15;  // beyond, no address takes it anyway
  const bool whole = isWholeNumberLetter(letter) || (letter == 'G' && std::floor(word.value) == word.value);
  word.number = whole && std::abs(word.value) < kLargestWholeText ? fmt::format("{}", static_cast<long long>(word.value))
                                                                  : withDecimalPoint(word.value);
  return word;
}

Result<BlockWords> evaluateWords(const MacroBlock& block, const VariableStore& variables, int line,
                                 NumberReading reading) {
  BlockWords out;
  for (const MacroWord& word : block.words) {
    if (word.word.letter == 'G' && !word.expression && word.word.value == kMacroCallCode) out.macroCall = true;
    // G20/G21 in the block itself set the unit its lengths are rounded in.
    if (word.word.letter == 'G' && !word.expression && (word.word.value == 20 || word.word.value == 21)) {
      reading.inch = word.word.value == 20;
    }
  }
  for (const MacroWord& word : block.words) {
    if (!word.expression) {
      out.words.push_back(out.macroCall ? argumentAsPassed(word.word, reading) : word.word);
      continue;
    }
    const char letter = word.word.letter;
    const EvaluationContext context{variables, line, out.macroCall ? std::nullopt : incrementOf(letter, reading)};
    auto value = evaluate(*word.expression, context);
    if (!value.ok()) return value.error();
    if (!value.value()) {
      out.leftOut.push_back({letter, word.word.column, writtenVacant(letter, *word.expression)});
      continue;
    }
    if (out.macroCall) {
      Word argument{letter, withDecimalPoint(*value.value()), *value.value(), word.word.column, true};
      out.words.push_back(argument);
    } else {
      out.words.push_back(evaluatedWord(letter, word.word.column, *value.value(), reading));
    }
  }
  return out;
}

Error withLeftOutNote(Error error, const std::vector<VacantWord>& leftOut) {
  std::string note;
  for (const VacantWord& word : leftOut) {
    const std::string variable = word.written.substr(word.written.find('#'));
    note += fmt::format("{}{} at column {} was left out: {} is vacant", note.empty() ? "" : "; ", word.written,
                        word.column, variable);
  }
  if (!note.empty()) error.message += " (" + note + ")";
  return error;
}

}  // namespace lathesim::interp::macro
