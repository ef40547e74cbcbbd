#include "interp/text/lexer.hpp"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <string_view>

#include <fmt/format.h>

#include "interp/text/lookalikes.hpp"
#include "interp/text/utf8.hpp"

namespace lathesim::interp {
namespace {

bool isBlank(char c) { return c == ' ' || c == '\t' || c == '\r'; }

// C0 control codes but tab and the line ends, and DEL: tape and DNC leftovers.
bool isControl(char c) {
  const auto byte = static_cast<unsigned char>(c);
  return (byte < 0x20 && c != '\t' && c != '\n' && c != '\r') || byte == 0x7F;
}

std::string controlName(char c) {
  static constexpr std::string_view kNames[] = {
      "NUL", "SOH", "STX", "ETX", "EOT", "ENQ", "ACK", "BEL", "BS",  "HT",  "LF",
      "VT",  "FF",  "CR",  "SO",  "SI",  "DLE", "DC1", "DC2", "DC3", "DC4", "NAK",
      "SYN", "ETB", "CAN", "EM",  "SUB", "ESC", "FS",  "GS",  "RS",  "US"};
  const auto byte = static_cast<unsigned char>(c);
  return byte < 0x20 ? std::string(kNames[byte]) : std::string("DEL");
}

bool isAsciiLetter(char c) { return (c >= 'A' && c <= 'Z') || (c >= 'a' && c <= 'z'); }
bool isAsciiDigit(char c) { return c >= '0' && c <= '9'; }

// The rule in lexer.hpp: does the rest of a line after ';' read as prose?
bool readsAsProse(std::string_view tail) {
  std::size_t i = 0;
  const auto skipBlanks = [&](std::size_t at) {
    while (at < tail.size() && isBlank(tail[at])) ++at;
    return at;
  };
  i = skipBlanks(i);
  if (i == tail.size()) return false;
  if (!isAsciiLetter(tail[i])) return std::string_view("#/:%[(").find(tail[i]) == std::string_view::npos;
  std::size_t run = i;
  while (run < tail.size() && isAsciiLetter(tail[run])) ++run;
  const std::size_t after = skipBlanks(run);
  const char next = after < tail.size() ? tail[after] : '\0';
  if (run - i == 1) return isAsciiLetter(next);
  std::string word(tail.substr(i, run - i));
  for (char& c : word) c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
  if ((word == "IF" || word == "WHILE") && next == '[') return false;
  if ((word == "GOTO" || word == "END" || word == "DO") && (isAsciiDigit(next) || next == '#' || next == '['))
    return false;
  return true;
}

// The address letters of lathe G-code (system A). Others are unknown letters.
// B and C are read as words so that a code taking them (G10's C) can; left over, they are
// refused as the axes this lathe lacks (block_executor.cpp). A is a direct drawing
// dimension's angle, D the GSK's corner radius.
constexpr std::string_view kKnownLetters = "ABCDFGIJKLMNOPQRSTUWXZ";
// The letters Fanuc writes after a comma (",A" angle, ",C" chamfer, ",R" corner radius).
constexpr std::string_view kCommaLetters = "ACR";

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
  while (probe < text_.size() && (isBlank(text_[probe]) || (!inProgram_ && isControl(text_[probe])))) ++probe;
  if (probe >= text_.size() || text_[probe] != '%') return false;
  if (readBlock_) {
    closeAt(probe);
    return true;
  }
  for (std::size_t i = at_; i < probe; ++i)
    if (isControl(text_[i])) noteLeaderControl(text_[i], column_ + static_cast<int>(i - at_));
  at_ = probe;
  inProgram_ = true;
  endLine();
  return true;
}

void BlockReader::closeAt(std::size_t percent) {
  closingPercent_ = std::pair{line_, column_ + static_cast<int>(percent - at_)};
  // The first character after the '%' that is not blank or a line end.
  int line = line_;
  int column = closingPercent_->second + 1;
  for (std::size_t i = percent + 1; i < text_.size(); i += codePointLength(text_, i)) {
    const char c = text_[i];
    if (c == '\n') {
      ++line;
      column = 1;
      continue;
    }
    if (!isBlank(c)) {
      textAfterClosing_ = std::pair{line, column};
      break;
    }
    ++column;
  }
  at_ = text_.size();
}

void BlockReader::noteLeaderControl(char c, int column) {
  const std::string name = controlName(c);
  if (std::find(leaderSkipped_.begin(), leaderSkipped_.end(), name) == leaderSkipped_.end())
    leaderSkipped_.push_back(name);
  if (!leaderAt_) leaderAt_ = ReadNote{line_, column, {}};
}

bool BlockReader::skipLeaderLine() {
  std::size_t probe = at_;
  while (probe < text_.size() && (isBlank(text_[probe]) || isControl(text_[probe]))) ++probe;
  if (probe >= text_.size() || text_[probe] != '&') return false;
  for (std::size_t i = at_; i < probe; ++i)
    if (isControl(text_[i])) noteLeaderControl(text_[i], column_ + static_cast<int>(i - at_));
  std::size_t end = text_.find('\n', probe);
  if (end == std::string_view::npos) end = text_.size();
  std::string header(text_.substr(probe, end - probe));
  while (!header.empty() && isBlank(header.back())) header.pop_back();
  leaderSkipped_.push_back(fmt::format("the header line '{}'", header));
  if (!leaderAt_) leaderAt_ = ReadNote{line_, 1, {}};
  at_ = end;
  endLine();
  return true;
}

bool BlockReader::skipDirectiveLine() {
  std::size_t probe = at_;
  while (probe < text_.size() && isBlank(text_[probe])) ++probe;
  if (probe >= text_.size() || text_[probe] != '[') return false;
  std::size_t end = text_.find('\n', probe);
  if (end == std::string_view::npos) end = text_.size();
  std::string directive(text_.substr(probe, end - probe));
  while (!directive.empty() && isBlank(directive.back())) directive.pop_back();
  directives_.push_back({line_, column_ + static_cast<int>(probe - at_), directive});
  at_ = end;
  endLine();
  return true;
}

void BlockReader::advance(std::size_t bytes) {
  column_ += codePointCount(text_.substr(at_, bytes));
  at_ += bytes;
}

void BlockReader::endLine() {
  const std::size_t newline = text_.find('\n', at_);
  at_ = newline == std::string_view::npos ? text_.size() : newline + 1;
  ++line_;
  column_ = 1;
  atLineStart_ = true;
}

// Just past a ';': the rest of the line, if it reads as prose, becomes a comment of `block`
// (or of the next block, when `block` is empty).
void BlockReader::takeProseTail(RawBlock& block) {
  std::size_t end = text_.find('\n', at_);
  if (end == std::string_view::npos) end = text_.size();
  const std::string_view tail = text_.substr(at_, end - at_);
  if (!readsAsProse(tail)) return;
  const std::size_t first = tail.find_first_not_of(" \t");
  std::string comment(tail.substr(first));
  while (!comment.empty() && (isBlank(comment.back()))) comment.pop_back();
  prose_.push_back({line_, column_ + codePointCount(tail.substr(0, first)), comment});
  (block.chars.empty() ? pendingAbove_ : block.comments).push_back(std::move(comment));
  advance(end - at_);
}

Result<std::optional<RawBlock>> BlockReader::next() {
  // A UTF-8 byte order mark at the very start is not part of the program.
  if (at_ == 0 && text_.substr(0, 3) == "\xEF\xBB\xBF") at_ = 3;

  while (at_ < text_.size()) {
    const bool lineStart = atLineStart_;
    if (atLineStart_ && !inProgram_ && skipLeaderLine()) continue;
    if (atLineStart_ && skipPercentLine()) continue;
    if (atLineStart_ && skipDirectiveLine()) continue;
    atLineStart_ = false;

    RawBlock block;
    block.line = line_;
    bool started = false;
    std::vector<std::string> comments;
    while (at_ < text_.size() && text_[at_] != '\n' && text_[at_] != ';') {
      const char c = text_[at_];
      if (isBlank(c)) {
        advance(1);
        continue;
      }
      if (!inProgram_ && isControl(c)) {  // tape and DNC leftovers before the program
        noteLeaderControl(c, column_);
        advance(1);
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
        const std::string_view body = text_.substr(at_ + 1, end - at_ - 1);
        if (const std::size_t inner = body.find('('); inner != std::string_view::npos && !block.parenInComment)
          block.parenInComment = RawBlock::ParenInComment{column_, column_ + 1 + codePointCount(body.substr(0, inner)),
                                                          column_ + 1 + codePointCount(body)};
        comments.emplace_back(body);
        advance(end + 1 - at_);
        continue;
      }
      const std::size_t length = codePointLength(text_, at_);
      if (!started && c == '/') {
        block.deleted = true;
      } else if (c == '/' && !block.skipFrom) {
        block.skipFrom = block.chars.size();
      } else {
        block.chars.push_back({std::string(text_.substr(at_, length)), column_});
      }
      if (!started) block.column = column_;
      started = true;
      inProgram_ = true;
      at_ += length;
      ++column_;
    }
    block.comments = std::move(comments);
    const bool semicolon = at_ < text_.size() && text_[at_] == ';';
    if (semicolon) {
      ++at_;
      ++column_;
      takeProseTail(block);
    } else if (at_ < text_.size()) {
      endLine();
    }
    if (started) {
      readBlock_ = true;
      block.commentsAbove = std::move(pendingAbove_);
      pendingAbove_.clear();
      return std::optional<RawBlock>(std::move(block));
    }
    // No block: its comments stand above the next one; an empty line parts them.
    if (!block.comments.empty()) {
      pendingAbove_.insert(pendingAbove_.end(), block.comments.begin(), block.comments.end());
    } else if (lineStart && !semicolon && block.chars.empty()) {
      pendingAbove_.clear();
    }
  }
  return std::optional<RawBlock>();
}

std::vector<ReadNote> BlockReader::notes() const {
  std::vector<ReadNote> notes;
  if (leaderAt_) {
    std::string what;
    for (std::size_t i = 0; i < leaderSkipped_.size(); ++i)
      what += (i == 0 ? "" : i + 1 == leaderSkipped_.size() ? " and " : ", ") + leaderSkipped_[i];
    notes.push_back({leaderAt_->line, leaderAt_->column,
                     fmt::format("skipped the tape/DNC leader before the program: {}", what)});
  }
  if (!directives_.empty()) {
    const ReadNote& first = directives_.front();
    notes.push_back({first.line, first.column,
                     fmt::format("a line opening with '[' is a trainer's directive, not a block: skipped "
                                 "'{}'{}",
                                 first.message,
                                 directives_.size() > 1 ? fmt::format(" (and {} more)", directives_.size() - 1)
                                                        : std::string())});
  }
  if (!prose_.empty()) {
    const ReadNote& first = prose_.front();
    notes.push_back({first.line, first.column,
                     fmt::format("the text after ';' reads as prose, so it is a comment, not a block: "
                                 "'{}'{}",
                                 first.message,
                                 prose_.size() > 1 ? fmt::format(" (and {} more like it)", prose_.size() - 1)
                                                   : std::string())});
  }
  return notes;
}

namespace {

// A control character or a typographic look-alike among the block's characters.
std::optional<Error> strangeCharacter(const RawBlock& block) {
  for (const SourceChar& c : block.chars) {
    if (c.text.size() == 1 && isControl(c.text[0])) {
      return Error{block.line, c.column,
                   fmt::format("control character {} (0x{:02X}) inside the program: a tape or DNC "
                               "leftover; delete it",
                               controlName(c.text[0]), static_cast<unsigned char>(c.text[0]))};
    }
    if (c.text.size() == 1) continue;
    if (const auto alike = lookAlikeOf(c.text)) {
      const bool space = alike->meant == " ";
      return Error{block.line, c.column,
                   fmt::format("'{}' ({} {}) looks like {} but is not: controls read ASCII only; "
                               "retype it as {}",
                               c.text, codePointLabel(c.text), alike->name,
                               space ? "a space" : fmt::format("'{}'", alike->meant),
                               space ? "a plain space" : fmt::format("'{}'", alike->meant))};
    }
  }
  return std::nullopt;
}

// A ')' outside a comment: most often the end of a comment that was meant to hold another.
std::optional<Error> strayClosingParenthesis(const RawBlock& block) {
  const auto stray = std::find_if(block.chars.begin(), block.chars.end(), [](const SourceChar& c) { return c.text == ")"; });
  if (stray == block.chars.end()) return std::nullopt;
  const auto& nested = block.parenInComment;
  if (nested && nested->closeColumn < stray->column) {
    return Error{block.line, stray->column,
                 fmt::format("')' closes no comment: comments do not nest, so the '(' at column {} is text of the "
                             "comment opened at column {}, which the ')' at column {} closed; write the inner "
                             "parentheses another way or close the first comment before opening another",
                             nested->innerColumn, nested->openColumn, nested->closeColumn)};
  }
  return Error{block.line, stray->column, "')' closes no comment: a comment opens with '(' on the same line"};
}

bool isLetterO(const SourceChar& c) { return c.text == "O" || c.text == "o"; }

// The letter O typed for a zero: right after an address letter (`GO`) or inside a number
// (`X1O.5`), with no space between.
std::optional<Error> letterOForZero(const RawBlock& block, std::size_t at, char letter, const std::string& number) {
  const auto& chars = block.chars;
  if (at >= chars.size() || !isLetterO(chars[at]) || chars[at].column != chars[at - 1].column + 1) return std::nullopt;
  // Followed at once by another letter, it is prose ("co" in "coolant"), not a zero.
  const bool letterFollows = at + 1 < chars.size() && chars[at + 1].column == chars[at].column + 1 &&
                             chars[at + 1].text.size() == 1 && isAsciiLetter(chars[at + 1].text[0]);
  if (letterFollows) return std::nullopt;
  std::string meant = std::string(1, letter) + number + "0";
  for (std::size_t k = at + 1; k < chars.size() && isNumberChar(chars[k].text); ++k) meant += chars[k].text;
  return Error{block.line, chars[at].column,
               fmt::format("the letter '{}' {}; did you mean the digit 0 ({})?", chars[at].text,
                           number.empty() ? fmt::format("right after {}, where a number belongs", letter)
                                          : fmt::format("inside the number {}{}", letter, number),
                           meant)};
}

}  // namespace

Result<std::vector<Word>> tokenize(const RawBlock& block) {
  if (auto strange = strangeCharacter(block)) return *strange;
  if (auto paren = strayClosingParenthesis(block)) return *paren;
  std::vector<Word> words;
  const auto& chars = block.chars;
  std::size_t i = 0;
  while (i < chars.size()) {
    // ",A" and its kin: the comma and the letter make one address.
    const bool comma = chars[i].text == "," && i + 1 < chars.size() && chars[i + 1].text.size() == 1 &&
                       std::isalpha(static_cast<unsigned char>(chars[i + 1].text[0]));
    const int commaColumn = chars[i].column;
    if (comma) {
      const char after = static_cast<char>(std::toupper(static_cast<unsigned char>(chars[i + 1].text[0])));
      if (kCommaLetters.find(after) == std::string_view::npos) {
        return Error{block.line, commaColumn,
                     fmt::format("unknown address ',{}': a comma is followed by A (angle), C (chamfer) or R "
                                 "(corner radius)",
                                 after)};
      }
      ++i;
    }
    const SourceChar& head = chars[i];
    const unsigned char byte = static_cast<unsigned char>(head.text[0]);
    // ':' is the ISO tape's program number address, the same as O (`:0100` is O0100).
    const bool colon = head.text == ":";
    if (!colon && (head.text.size() != 1 || !std::isalpha(byte))) {
      return Error{block.line, head.column,
                   fmt::format("unexpected character '{}': expected a word, a letter followed by "
                               "a number such as X20",
                               head.text)};
    }
    const char letter = colon ? 'O' : static_cast<char>(std::toupper(byte));
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
    if (letter != 'O') {
      if (auto zero = letterOForZero(block, end, letter, number)) return *zero;
    }
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
    if (comma) words.push_back({static_cast<char>(std::tolower(static_cast<unsigned char>(letter))), number,
                                readNumber(number), commaColumn});
    else words.push_back({letter, number, readNumber(number), head.column});
    i = end;
  }
  return words;
}

}  // namespace lathesim::interp
