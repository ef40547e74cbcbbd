#include "interp/text/typing_slips.hpp"

#include <cctype>

#include <fmt/format.h>

namespace lathesim::interp {
namespace {

bool isLetterO(const SourceChar& c) { return c.text == "O" || c.text == "o"; }
bool isDigitChar(const SourceChar& c) { return c.text.size() == 1 && std::isdigit(static_cast<unsigned char>(c.text[0])); }
bool isPoint(const SourceChar& c) { return c.text == "."; }
bool isAsciiLetterChar(const SourceChar& c) {
  return c.text.size() == 1 && std::isalpha(static_cast<unsigned char>(c.text[0]));
}

}  // namespace

std::optional<Error> letterOForZero(const RawBlock& block, std::size_t at, char letter, const std::string& number) {
  const auto& chars = block.chars;
  if (at == 0 || at >= chars.size() || !isLetterO(chars[at]) || chars[at].column != chars[at - 1].column + 1)
    return std::nullopt;
  // The O's, and the digits among and after them, written with no space: Q2OO, X1O.5, O1OOO.
  std::string meant = std::string(1, letter) + number;
  std::size_t end = at;
  for (; end < chars.size() && chars[end].column == chars[end - 1].column + 1; ++end) {
    if (isLetterO(chars[end])) meant += '0';
    else if (isDigitChar(chars[end]) || isPoint(chars[end])) meant += chars[end].text;
    else break;
  }
  // Followed at once by another letter, it is prose ("co" in "coolant"), not a zero.
  if (end < chars.size() && chars[end].column == chars[end - 1].column + 1 && isAsciiLetterChar(chars[end]))
    return std::nullopt;
  // O with no digits before it is a word of its own (O1000 after G00 in "G00O1000" is not "G000").
  if (letter == 'O' && number.empty()) return std::nullopt;
  return Error{block.line, chars[at].column,
               fmt::format("the letter '{}' {}; did you mean the digit 0 ({})?", chars[at].text,
                           number.empty() ? fmt::format("right after {}, where a number belongs", letter)
                                          : fmt::format("inside the number {}{}", letter, number),
                           meant)};
}

std::optional<Error> pastedCitation(const RawBlock& block) {
  const auto& chars = block.chars;  // spaces are gone: "[cite: 133]" is "[cite:133]"
  for (std::size_t i = 0; i + 4 < chars.size(); ++i) {
    if (chars[i].text != "[") continue;
    std::string word;
    for (std::size_t k = i + 1; k < chars.size() && k <= i + 4; ++k)
      word += static_cast<char>(std::tolower(static_cast<unsigned char>(chars[k].text[0])));
    if (word != "cite") continue;
    std::string written;
    std::size_t k = i;
    for (; k < chars.size() && chars[k].text != "]"; ++k) written += chars[k].text;
    if (k < chars.size()) written += "]";
    return Error{block.line, chars[i].column,
                 fmt::format("'{}' is a citation pasted with the program (from a chat or a document), not G-code; "
                             "did you mean to leave it out? delete it",
                             written)};
  }
  return std::nullopt;
}

std::optional<Error> zeroForLetterO(int line, const std::string& number, int column) {
  if (number.size() < 2 || number[0] != '0') return std::nullopt;
  for (char c : number)
    if (!std::isdigit(static_cast<unsigned char>(c))) return std::nullopt;
  return Error{line, column,
               fmt::format("a block opens with the number {}: a program number is the letter O, not the digit "
                           "zero (did you mean O{}?)",
                           number, number.substr(1))};
}

Error strayBracket(int line, const std::string& bracket, int column) {
  return Error{line, column,
               fmt::format("stray '{}': a bracket holds a Macro B expression (X[#1+2]), and none is open here; "
                           "delete it (did you mean a comment in ( )?)",
                           bracket)};
}

}  // namespace lathesim::interp
