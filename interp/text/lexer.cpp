#include "interp/text/lexer.hpp"

#include <cctype>
#include <charconv>
#include <string_view>

#include <fmt/format.h>

#include "interp/text/utf8.hpp"

namespace lathesim::interp {
namespace {

bool isBlank(char c) { return c == ' ' || c == '\t' || c == '\r'; }

// The address letters of lathe G-code (system A). Others are unknown letters.
constexpr std::string_view kKnownLetters = "CEFGIJKLMNOPQRSTUWXZ";

bool isNumberChar(const std::string& text) {
  return text.size() == 1 && (std::isdigit(static_cast<unsigned char>(text[0])) ||
                              text[0] == '.' || text[0] == '+' || text[0] == '-');
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

Result<std::vector<Word>> tokenize(const RawBlock& block) {
  std::vector<Word> words;
  const auto& chars = block.chars;
  std::size_t i = 0;
  while (i < chars.size()) {
    const SourceChar& head = chars[i];
    const unsigned char byte = static_cast<unsigned char>(head.text[0]);
    if (head.text.size() != 1 || !std::isalpha(byte)) {
      return Error{block.line, head.column,
                   fmt::format("unexpected character '{}': expected a word, a letter followed by "
                               "a number such as X20",
                               head.text)};
    }
    const char letter = static_cast<char>(std::toupper(byte));
    if (letter == 'Y') {
      return Error{block.line, head.column,
                   "Y: this machine has no Y axis; a lathe moves in X (diameter) and Z only"};
    }
    if (kKnownLetters.find(letter) == std::string_view::npos) {
      return Error{block.line, head.column,
                   fmt::format("unknown letter '{}': lathe G-code words start with one of {}",
                               head.text, kKnownLetters)};
    }
    std::string number;
    std::size_t end = i + 1;
    while (end < chars.size() && isNumberChar(chars[end].text)) number += chars[end++].text;
    if (number.empty()) {
      return Error{block.line, head.column,
                   fmt::format("{} has no number: expected a value after it, such as {}20",
                               letter, letter)};
    }
    if (!isWellFormedNumber(number)) {
      return Error{block.line, head.column,
                   fmt::format("malformed number in {}{}: expected an optional sign, then digits "
                               "with at most one decimal point",
                               letter, number)};
    }
    words.push_back({letter, number, readNumber(number), head.column});
    i = end;
  }
  return words;
}

}  // namespace lathesim::interp
