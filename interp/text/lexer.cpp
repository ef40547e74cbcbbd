#include "interp/text/lexer.hpp"

#include <algorithm>
#include <array>
#include <cctype>
#include <charconv>
#include <optional>
#include <string_view>

#include <fmt/format.h>

#include "interp/text/lookalikes.hpp"
#include "interp/text/typing_slips.hpp"
#include "interp/base/utf8.hpp"

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

// The address letters of lathe G-code (system A). Others are unknown letters, except in a
// G65 block, where every letter but G L N O P passes an argument.
// B and C are read as words so that a code taking them (G10's C, HNC G82's C) can; left
// over, they are refused as the axes this lathe lacks (block_executor.cpp). A is a direct
// drawing dimension's angle, D the GSK's corner radius, E HNC G82's run-out. V is known only in
// a G76 block (HNC G76's Δdmin).
constexpr std::string_view kKnownLetters = "ABCDEFGIJKLMNOPQRSTUWXZ";
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

// The words of Fanuc Custom Macro B. A run of letters that is one of these is a name, never
// address letters: GOTO is not G with no number (the controls read them the same way, and
// spaces inside a block are insignificant there too).
constexpr std::array<std::string_view, 33> kMacroNames{
    "IF",  "GOTO", "THEN", "WHILE", "DO",  "END",                                // statements
    "SIN", "COS",  "TAN",  "ASIN",  "ACOS", "ATAN", "SQRT", "ABS", "ROUND", "FIX",  // functions
    "FUP", "LN",   "EXP",  "POW",   "BIN", "BCD",  "ADP",
    "EQ",  "NE",   "GT",   "GE",    "LT",  "LE",                                 // comparisons
    "AND", "OR",   "XOR",  "MOD"};                                               // operators

bool isLetter(const SourceChar& c) { return c.text.size() == 1 && isAsciiLetter(c.text[0]); }
bool isDigit(const SourceChar& c) { return c.text.size() == 1 && isAsciiDigit(c.text[0]); }
bool is(const SourceChar& c, char expected) { return c.text.size() == 1 && c.text[0] == expected; }

std::string upperCase(std::string text) {
  for (char& c : text) c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
  return text;
}

// The characters of a letter's number: from `from` while they are digits, '.', '+' or '-'.
std::string numberAt(const std::vector<SourceChar>& chars, std::size_t from, std::size_t& end) {
  std::string number;
  end = from;
  while (end < chars.size() && isNumberChar(chars[end].text)) number += chars[end++].text;
  return number;
}

// Whether the block holds the word G`code` written as a plain number (G65, g065).
bool holdsGCode(const std::vector<SourceChar>& chars, double code) {
  for (std::size_t i = 0; i < chars.size(); ++i) {
    if (!isLetter(chars[i]) || std::toupper(static_cast<unsigned char>(chars[i].text[0])) != 'G') continue;
    std::size_t end = 0;
    const std::string number = numberAt(chars, i + 1, end);
    if (isWellFormedNumber(number) && readNumber(number) == code) return true;
  }
  return false;
}

// Why `letter` (upper case) cannot start a word here, if it cannot.
std::optional<std::string> letterProblem(char letter, const std::string& written, bool macroCall, bool threading) {
  if (macroCall) return std::nullopt;  // G65's arguments: A–Z (G L N O P are its own words)
  if (letter == 'V' && threading) return std::nullopt;  // HNC G76's V(Δdmin); left over elsewhere
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
  // A pasted citation ("[cite: 133]") is no trainer's directive: read as a block, it is refused
  // as what it is (typing_slips.hpp).
  if (upperCase(std::string(text_.substr(probe + 1, 4))) == "CITE") return false;
  std::size_t end = text_.find('\n', probe);
  if (end == std::string_view::npos) end = text_.size();
  std::string directive(text_.substr(probe, end - probe));
  while (!directive.empty() && isBlank(directive.back())) directive.pop_back();
  if (directives_++ == 0) firstDirective_ = ReadNote{line_, column_ + static_cast<int>(probe - at_), directive};
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
  if (prose_++ == 0) firstProse_ = ReadNote{line_, column_ + codePointCount(tail.substr(0, first)), comment};
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

    blockStart_ = ReadPosition{at_, line_, column_, inProgram_};
    RawBlock block;
    block.line = line_;
    bool started = false;
    int bracketDepth = 0;    // inside a Macro B expression's [ ]
    bool assigning = false;  // past the '=' of a Macro B assignment
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
      } else if (c == '/' && bracketDepth == 0 && !assigning && !block.skipFrom) {
        block.skipFrom = block.chars.size();
      } else {
        block.chars.push_back({std::string(text_.substr(at_, length)), column_});
        bracketDepth += c == '[' ? 1 : c == ']' && bracketDepth > 0 ? -1 : 0;
        assigning = assigning || c == '=';
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
  if (firstDirective_) {
    const ReadNote& first = *firstDirective_;
    notes.push_back({first.line, first.column,
                     fmt::format("a line opening with '[' is a trainer's directive, not a block: skipped "
                                 "'{}'{}",
                                 first.message,
                                 directives_ > 1 ? fmt::format(" (and {} more)", directives_ - 1)
                                                        : std::string())});
  }
  if (firstProse_) {
    const ReadNote& first = *firstProse_;
    notes.push_back({first.line, first.column,
                     fmt::format("the text after ';' reads as prose, so it is a comment, not a block: "
                                 "'{}'{}",
                                 first.message,
                                 prose_ > 1 ? fmt::format(" (and {} more like it)", prose_ - 1)
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

}  // namespace

Result<std::vector<Token>> lexBlock(const RawBlock& block) {
  if (auto strange = strangeCharacter(block)) return *strange;
  if (auto citation = pastedCitation(block)) return *citation;
  if (auto paren = strayClosingParenthesis(block)) return *paren;
  std::vector<Token> tokens;
  const auto& chars = block.chars;
  const bool macroCall = holdsGCode(chars, 65);
  const bool threading = holdsGCode(chars, 76);
  std::size_t i = 0;
  int bracketDepth = 0;
  while (i < chars.size()) {
    // ",A" and its kin: the comma and the letter make one address. Inside a macro expression's
    // [ ] a comma parts a function's arguments (ATAN[#1,SIN[#2]]).
    const bool comma = bracketDepth == 0 && chars[i].text == "," && i + 1 < chars.size() &&
                       chars[i + 1].text.size() == 1 && std::isalpha(static_cast<unsigned char>(chars[i + 1].text[0]));
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
    // ':' is the ISO tape's program number address, the same as O (`:0100` is O0100).
    const bool colon = head.text == ":";
    if (isLetter(head) || colon) {
      std::size_t runEnd = i;
      std::string run;
      while (!colon && runEnd < chars.size() && isLetter(chars[runEnd])) run += chars[runEnd++].text;
      run = upperCase(run);
      if (run.size() > 1 && std::find(kMacroNames.begin(), kMacroNames.end(), run) != kMacroNames.end()) {
        tokens.push_back(makeToken(TokenKind::Name, head.column, run));
        i = runEnd;
        continue;
      }
      const char letter = colon ? 'O' : run[0];
      if (auto problem = letterProblem(letter, head.text, macroCall || colon, threading)) {
        return Error{block.line, head.column, *problem};
      }
      Word word;
      word.letter = comma ? static_cast<char>(std::tolower(static_cast<unsigned char>(letter))) : letter;
      word.column = comma ? commaColumn : head.column;
      // X#1, X[#1+2], X-#1, X-[…]: the value is an expression that follows.
      const std::size_t next = i + 1;
      const bool sign = next < chars.size() && (is(chars[next], '-') || is(chars[next], '+'));
      const std::size_t valueAt = sign ? next + 1 : next;
      if (valueAt < chars.size() && (is(chars[valueAt], '#') || is(chars[valueAt], '['))) {
        tokens.push_back(makeToken(TokenKind::Address, word.column, word.text(), 0.0, word));
        i = next;
        continue;
      }
      std::size_t end = 0;
      word.number = numberAt(chars, next, end);
      if (auto zero = letterOForZero(block, end, letter, word.number)) return *zero;
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
      tokens.push_back(makeToken(TokenKind::Word, word.column, word.text(), word.value, word));
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
      bracketDepth += *kind == TokenKind::Open ? 1 : *kind == TokenKind::Close ? -1 : 0;
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
    if (token.kind == TokenKind::Number && words.empty())
      if (auto slip = zeroForLetterO(block.line, token.text, token.column)) return *slip;
    if (token.kind == TokenKind::Open || token.kind == TokenKind::Close)
      return strayBracket(block.line, token.text, token.column);
    if (token.kind != TokenKind::Word) {
      return Error{block.line, token.column,
                   fmt::format("unexpected '{}': expected a word, a letter followed by a number such as X20", token.text)};
    }
    words.push_back(token.word);
  }
  return words;
}

}  // namespace lathesim::interp
