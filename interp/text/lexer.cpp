#include "interp/text/lexer.hpp"

#include <algorithm>
#include <array>
#include <cctype>
#include <charconv>
#include <optional>
#include <string_view>

#include <fmt/format.h>

#include "interp/text/utf8.hpp"

namespace lathesim::interp {
namespace {

bool isBlank(char c) { return c == ' ' || c == '\t' || c == '\r'; }

// The address letters of lathe G-code (system A). Others are unknown letters, except in a
// G65 block, where every letter but G L N O P passes an argument.
constexpr std::string_view kKnownLetters = "FGIJKLMNOPQRSTUWXZ";

// The words of Fanuc Custom Macro B. A run of letters that is one of these is a name, never
// address letters: GOTO is not G with no number (the controls read them the same way, and
// spaces inside a block are insignificant there too).
constexpr std::array<std::string_view, 33> kMacroNames{
    "IF",  "GOTO", "THEN", "WHILE", "DO",  "END",                                // statements
    "SIN", "COS",  "TAN",  "ASIN",  "ACOS", "ATAN", "SQRT", "ABS", "ROUND", "FIX",  // functions
    "FUP", "LN",   "EXP",  "POW",   "BIN", "BCD",  "ADP",
    "EQ",  "NE",   "GT",   "GE",    "LT",  "LE",                                 // comparisons
    "AND", "OR",   "XOR",  "MOD"};                                               // operators

bool isAsciiLetter(const SourceChar& c) {
  return c.text.size() == 1 && std::isalpha(static_cast<unsigned char>(c.text[0]));
}

bool isDigit(const SourceChar& c) {
  return c.text.size() == 1 && std::isdigit(static_cast<unsigned char>(c.text[0]));
}

bool is(const SourceChar& c, char expected) { return c.text.size() == 1 && c.text[0] == expected; }

bool isNumberChar(const SourceChar& c) {
  return isDigit(c) || is(c, '.') || is(c, '+') || is(c, '-');
}

// Accepts an optional sign, then digits with at most one decimal point, at least one digit.
bool isWellFormedNumber(std::string_view number) {
  if (!number.empty() && (number[0] == '+' || number[0] == '-')) number.remove_prefix(1);
  int digits = 0;
  int points = 0;
  for (char c : number) {
    if (c == '.') {
      ++points;
    } else if (std::isdigit(static_cast<unsigned char>(c))) {
      ++digits;
    } else {
      return false;
    }
  }
  return digits > 0 && points <= 1;
}

double readNumber(std::string_view number) {
  if (!number.empty() && number[0] == '+') number.remove_prefix(1);
  double value = 0.0;
  std::from_chars(number.data(), number.data() + number.size(), value);
  return value;
}

std::string upperCase(std::string text) {
  for (char& c : text) c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
  return text;
}

// The characters of a letter's number: from `from` while they are digits, '.', '+' or '-'.
std::string numberAt(const std::vector<SourceChar>& chars, std::size_t from, std::size_t& end) {
  std::string number;
  end = from;
  while (end < chars.size() && isNumberChar(chars[end])) number += chars[end++].text;
  return number;
}

// Whether the block holds the word G65 written as a plain number (G65, g065).
bool holdsMacroCall(const std::vector<SourceChar>& chars) {
  for (std::size_t i = 0; i < chars.size(); ++i) {
    if (!isAsciiLetter(chars[i]) || std::toupper(static_cast<unsigned char>(chars[i].text[0])) != 'G') continue;
    std::size_t end = 0;
    const std::string number = numberAt(chars, i + 1, end);
    if (isWellFormedNumber(number) && readNumber(number) == 65.0) return true;
  }
  return false;
}

// Why `letter` (upper case) cannot start a word here, if it cannot.
std::optional<std::string> letterProblem(char letter, const std::string& written, bool macroCall) {
  if (macroCall) return std::nullopt;  // G65's arguments: A–Z (G L N O P are its own words)
  if (letter == 'Y') return std::string("Y: this machine has no Y axis; a lathe moves in X (diameter) and Z only");
  if (kKnownLetters.find(letter) == std::string_view::npos) {
    return fmt::format("unknown letter '{}': lathe G-code words start with one of {}", written, kKnownLetters);
  }
  return std::nullopt;
}

Token makeToken(TokenKind kind, int column, std::string text, double value = 0.0, Word word = {}) {
  Token token;
  token.kind = kind;
  token.column = column;
  token.word = std::move(word);
  token.text = std::move(text);
  token.value = value;
  return token;
}

std::optional<TokenKind> punctuation(const SourceChar& c) {
  if (c.text.size() != 1) return std::nullopt;
  switch (c.text[0]) {
    case '#': return TokenKind::Hash;
    case '[': return TokenKind::Open;
    case ']': return TokenKind::Close;
    case '=': return TokenKind::Equals;
    case '+': return TokenKind::Plus;
    case '-': return TokenKind::Minus;
    case '*': return TokenKind::Times;
    case '/': return TokenKind::Divide;
    case ',': return TokenKind::Comma;
    default: return std::nullopt;
  }
}

}  // namespace

bool BlockReader::skipPercentLine() {
  std::size_t probe = at_;
  while (probe < text_.size() && isBlank(text_[probe])) ++probe;
  if (probe >= text_.size() || text_[probe] != '%') return false;
  const std::size_t newline = text_.find('\n', probe);
  at_ = newline == std::string_view::npos ? text_.size() : newline + 1;
  ++line_;
  column_ = 1;
  return true;
}

Result<std::optional<RawBlock>> BlockReader::next() {
  // A UTF-8 byte order mark at the very start is not part of the program.
  if (at_ == 0 && text_.substr(0, 3) == "\xEF\xBB\xBF") at_ = 3;

  while (at_ < text_.size()) {
    if (atLineStart_ && skipPercentLine()) continue;
    atLineStart_ = false;

    RawBlock block;
    block.line = line_;
    bool started = false;
    while (at_ < text_.size() && text_[at_] != '\n' && text_[at_] != ';') {
      const char c = text_[at_];
      if (isBlank(c)) {
        ++at_;
        ++column_;
        continue;
      }
      if (c == '(') {
        std::size_t end = at_ + 1;
        while (end < text_.size() && text_[end] != ')' && text_[end] != '\n') ++end;
        if (end >= text_.size() || text_[end] != ')') {
          return Error{line_, column_,
                       "comment opened here is not closed: expected ')' before the end of the "
                       "line"};
        }
        block.comments.push_back({std::string(text_.substr(at_ + 1, end - at_ - 1)), column_});
        column_ += codePointCount(text_.substr(at_, end + 1 - at_));
        at_ = end + 1;
        continue;
      }
      const std::size_t length = codePointLength(text_, at_);
      if (!started && c == '/') {
        block.deleted = true;
      } else {
        block.chars.push_back({std::string(text_.substr(at_, length)), column_});
      }
      if (!started) block.column = column_;
      started = true;
      at_ += length;
      ++column_;
    }
    if (at_ < text_.size()) {  // consume the end of block
      if (text_[at_] == '\n') {
        ++line_;
        column_ = 1;
        atLineStart_ = true;
      } else {
        ++column_;
      }
      ++at_;
    }
    if (started) return std::optional<RawBlock>(std::move(block));
  }
  return std::optional<RawBlock>();
}

Result<std::vector<Token>> lexBlock(const RawBlock& block) {
  std::vector<Token> tokens;
  const auto& chars = block.chars;
  const bool macroCall = holdsMacroCall(chars);
  std::size_t i = 0;
  while (i < chars.size()) {
    const SourceChar& head = chars[i];
    if (isAsciiLetter(head)) {
      std::size_t runEnd = i;
      std::string run;
      while (runEnd < chars.size() && isAsciiLetter(chars[runEnd])) run += chars[runEnd++].text;
      run = upperCase(run);
      if (run.size() > 1 && std::find(kMacroNames.begin(), kMacroNames.end(), run) != kMacroNames.end()) {
        tokens.push_back(makeToken(TokenKind::Name, head.column, run));
        i = runEnd;
        continue;
      }
      const char letter = run[0];
      if (auto problem = letterProblem(letter, head.text, macroCall)) return Error{block.line, head.column, *problem};
      Word word;
      word.letter = letter;
      word.column = head.column;
      // X#1, X[#1+2], X-#1, X-[…]: the value is an expression that follows.
      const std::size_t next = i + 1;
      const bool signed_ = next < chars.size() && (is(chars[next], '-') || is(chars[next], '+'));
      const std::size_t valueAt = signed_ ? next + 1 : next;
      if (valueAt < chars.size() && (is(chars[valueAt], '#') || is(chars[valueAt], '['))) {
        tokens.push_back(makeToken(TokenKind::Address, head.column, std::string(1, letter), 0.0, word));
        i = next;
        continue;
      }
      std::size_t end = 0;
      word.number = numberAt(chars, next, end);
      if (word.number.empty()) {
        return Error{block.line, head.column,
                     fmt::format("{} has no number: expected a value after it, such as {}20", letter, letter)};
      }
      if (!isWellFormedNumber(word.number)) {
        return Error{block.line, head.column,
                     fmt::format("malformed number in {}{}: expected an optional sign, then digits "
                                 "with at most one decimal point",
                                 letter, word.number)};
      }
      word.value = readNumber(word.number);
      tokens.push_back(makeToken(TokenKind::Word, head.column, word.text(), word.value, word));
      i = end;
      continue;
    }
    if (isDigit(head) || is(head, '.')) {  // a number of a macro expression: no sign of its own
      std::string number;
      std::size_t end = i;
      while (end < chars.size() && (isDigit(chars[end]) || is(chars[end], '.'))) number += chars[end++].text;
      if (!isWellFormedNumber(number)) {
        return Error{block.line, head.column,
                     fmt::format("malformed number {}: expected digits with at most one decimal point", number)};
      }
      tokens.push_back(makeToken(TokenKind::Number, head.column, number, readNumber(number)));
      i = end;
      continue;
    }
    if (const auto kind = punctuation(head)) {
      tokens.push_back(makeToken(*kind, head.column, head.text));
      ++i;
      continue;
    }
    return Error{block.line, head.column,
                 fmt::format("unexpected character '{}': expected a word, a letter followed by a number such as X20",
                             head.text)};
  }
  return tokens;
}

Result<std::vector<Word>> tokenize(const RawBlock& block) {
  auto tokens = lexBlock(block);
  if (!tokens.ok()) return tokens.error();
  std::vector<Word> words;
  for (const Token& token : tokens.value()) {
    if (token.kind != TokenKind::Word) {
      return Error{block.line, token.column,
                   fmt::format("unexpected '{}': expected a word, a letter followed by a number such as X20", token.text)};
    }
    words.push_back(token.word);
  }
  return words;
}

}  // namespace lathesim::interp
