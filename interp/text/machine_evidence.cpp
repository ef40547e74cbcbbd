#include "interp/text/machine_evidence.hpp"

#include <algorithm>
#include <array>
#include <bitset>
#include <charconv>
#include <cstdint>
#include <cmath>
#include <system_error>
#include <string_view>
#include <utility>

#include <fmt/format.h>

#include "interp/base/utf8.hpp"

namespace lathesim::interp {
namespace {

// A word of a block as written: a letter and the number after it (no number: an expression,
// a keyword, or a lone letter). ',C' and ',R' are kept as the letters 'c' and 'r'.
struct ScannedWord {
  char letter = 0;
  std::size_t at = 0;  // its byte in the line (its column is counted only when it is named)
  bool hasNumber = false;
  bool hasPoint = false;
  double value = 0;
  std::string_view text;  // "G95", "Z-23", ",C1."
};

char upper(char c) { return c >= 'a' && c <= 'z' ? static_cast<char>(c - 'a' + 'A') : c; }

// A number as written from line[i] ("-23", "+.5", "12."): where it ends, whether it has a
// digit and a point, and its value. A number of hundreds of digits is no length: it is read
// as 0, never as an error. Up to 15 digits the digits as an integer, divided by the power of
// ten the point gives, are exact doubles, so the one division rounds as from_chars would
// (Clinger's fast path): most words of a program take it, in the one pass over their digits.
struct ScannedNumber {
  std::size_t end = 0;
  bool hasDigits = false;
  bool hasPoint = false;
  double value = 0;
};

ScannedNumber scanNumber(std::string_view line, std::size_t i) {
  ScannedNumber number;
  const bool negative = i < line.size() && line[i] == '-';
  if (i < line.size() && (line[i] == '-' || line[i] == '+')) ++i;
  const std::size_t first = i;  // from_chars takes no '+', and the sign is put back below
  std::int64_t digits = 0;
  int count = 0;
  int decimals = 0;  // digits after the point
  for (; i < line.size(); ++i) {
    const char c = line[i];
    if (c == '.' && !number.hasPoint) {
      number.hasPoint = true;
      continue;
    }
    if (!isAsciiDigit(c)) break;
    if (count < 15) digits = digits * 10 + (c - '0');  // longer: from_chars reads it (no overflow)
    ++count;
    if (number.hasPoint) ++decimals;
  }
  number.end = i;
  number.hasDigits = count > 0;
  if (!number.hasDigits) return number;
  if (count <= 15) {
    static constexpr std::array<double, 16> kPowers{1e0, 1e1, 1e2,  1e3,  1e4,  1e5,  1e6,  1e7,
                                                    1e8, 1e9, 1e10, 1e11, 1e12, 1e13, 1e14, 1e15};
    number.value = static_cast<double>(digits) / kPowers[static_cast<std::size_t>(decimals)];
  } else {
    double value = 0;
    const auto [end, error] = std::from_chars(line.data() + first, line.data() + i, value);
    if (error != std::errc() || !std::isfinite(value)) return number;  // read as 0
    number.value = value;
  }
  if (negative) number.value = -number.value;
  return number;
}

// Which letters a block holds (bit letter & 63: 'A'–'Z' and the corner words' 'c'/'r' apart)
// and which whole G and M codes under 256: most of the rules ask for a code the block does
// not have, and are answered without a look at its words.
struct BlockIndex {
  std::uint64_t letters = 0;
  std::bitset<256> gCodes;
  std::bitset<256> mCodes;
  static std::uint64_t bitOf(char letter) { return std::uint64_t{1} << (static_cast<unsigned char>(letter) & 63U); }
};

// The words of a comment-free line, into `words` (its storage kept from line to line), and
// their index. A ';' ends the block (Fanuc's end of block).
void scanWords(std::string_view line, std::vector<ScannedWord>& words, BlockIndex& index) {
  words.clear();
  index = BlockIndex{};
  std::size_t i = 0;
  while (i < line.size()) {
    const char c = line[i];
    if (c == ';') break;
    const bool corner = c == ',' && i + 1 < line.size() && isAsciiLetter(line[i + 1]);
    if (!isAsciiLetter(c) && !corner) {
      ++i;
      continue;
    }
    const std::size_t start = i;
    ScannedWord word;
    word.letter = upper(line[corner ? i + 1 : i]);
    if (corner) word.letter = static_cast<char>(word.letter - 'A' + 'a');
    word.at = start;
    i += corner ? 2 : 1;
    word.text = line.substr(start, i - start);  // a lone letter, unless a number follows
    while (i < line.size() && (line[i] == ' ' || line[i] == '\t')) ++i;
    const ScannedNumber number = scanNumber(line, i);
    if (number.hasDigits) {
      word.hasNumber = true;
      word.hasPoint = number.hasPoint;
      word.value = number.value;
      i = number.end;
      word.text = line.substr(start, i - start);
    }
    index.letters |= BlockIndex::bitOf(word.letter);
    if (word.hasNumber && !word.hasPoint && word.value >= 0 && word.value < 256) {
      if (word.letter == 'G') index.gCodes.set(static_cast<std::size_t>(word.value));
      if (word.letter == 'M') index.mCodes.set(static_cast<std::size_t>(word.value));
    }
    words.push_back(word);
  }
}

// A block's words, and what the rules ask of them.
class ScannedBlock {
 public:
  ScannedBlock(const std::vector<ScannedWord>& words, const BlockIndex& index) : words_(words), index_(index) {}

  const ScannedWord* find(char letter) const {
    if (!has(letter)) return nullptr;
    for (const ScannedWord& w : words_)
      if (w.letter == letter) return &w;
    return nullptr;
  }
  bool has(char letter) const { return (index_.letters & BlockIndex::bitOf(letter)) != 0; }
  /// The word `letter``number` (a whole number: G95, not G95.), or nullptr.
  const ScannedWord* code(char letter, int number) const {
    const std::bitset<256>* known = letter == 'G' ? &index_.gCodes : letter == 'M' ? &index_.mCodes : nullptr;
    if (known && number >= 0 && number < 256 && !known->test(static_cast<std::size_t>(number))) return nullptr;
    for (const ScannedWord& w : words_)
      if (w.letter == letter && w.hasNumber && !w.hasPoint && w.value == number) return &w;
    return nullptr;
  }
  bool hasAnyG() const { return has('G'); }
  bool hasX() const { return has('X') || has('U'); }
  bool hasZ() const { return has('Z') || has('W'); }
  bool hasXZ() const { return hasX() || hasZ(); }
  bool movesByCode() const { return code('G', 0) || code('G', 1) || code('G', 2) || code('G', 3); }
  const std::vector<ScannedWord>& words() const { return words_; }

 private:
  const std::vector<ScannedWord>& words_;
  const BlockIndex& index_;
};

class EvidenceReader {
 public:
  explicit EvidenceReader(MachineEvidence& evidence) : evidence_(evidence) {}

  void read(int line, std::string_view text) {
    line_ = line;
    text_ = text;
    if (directive(text)) return;
    scanWords(text, words_, index_);
    const ScannedBlock block(words_, index_);
    systemA(block);
    systemB(block);
    hnc(block);
    haas(block);
    for (const ScannedWord& w : block.words())
      if (w.letter == 'c' || w.letter == 'r') mark(EvidenceKind::FanucCorner, w, "{}", w.text);
    if (const auto* g = block.code('G', 20)) mark(EvidenceKind::Inch, *g, "G20");
    if (block.code('G', 21)) evidence_.metricStated = true;
    if (const auto* m = block.code('M', 6); m && block.find('T') && block.find('T')->hasNumber)
      mark(EvidenceKind::Trainer, *m, "M06 beside {}", block.find('T')->text);
    lengths(block);
  }

 private:
  // The mark's text is made, and its column counted, only for the first few kept.
  template <class... Args>
  void mark(EvidenceKind kind, const ScannedWord& at, fmt::format_string<Args...> text, Args&&... args) {
    const auto k = static_cast<std::size_t>(kind);
    ++evidence_.counts[k];
    if (evidence_.marks[k].size() < MachineEvidence::kMarksKept)
      evidence_.marks[k].push_back({kind, line_, columnOf(at), fmt::format(text, std::forward<Args>(args)...)});
  }

  int columnOf(const ScannedWord& word) const { return codePointCount(text_.substr(0, word.at)) + 1; }

  // A line opening with '[' is a trainer's directive (the lexer skips it, and so does this),
  // unless it is a pasted citation, read as a block. `[BILLET` is Denford's stock line.
  bool directive(std::string_view text) {
    const std::size_t at = text.find_first_not_of(" \t");
    if (at == std::string_view::npos || text[at] != '[') return false;
    const std::string_view name = text.substr(at + 1);
    const auto opens = [&](std::string_view word) {  // in any case
      return name.size() >= word.size() &&
             std::equal(word.begin(), word.end(), name.begin(), [](char a, char b) { return a == upper(b); });
    };
    if (opens("CITE")) return false;  // as the lexer tells a citation
    if (opens("BILLET") && (name.size() == 6 || !isAsciiLetter(name[6]))) {
      const ScannedWord where{0, at, false, false, 0, {}};
      mark(EvidenceKind::Trainer, where, "[BILLET");
    }
    return true;
  }

  void systemA(const ScannedBlock& b) {
    for (const int n : {98, 99, 50, 32})
      if (const auto* g = b.code('G', n)) mark(EvidenceKind::SystemA, *g, "G{}", n);
    // U/W beside a move: a block that moves (G00–G03, or no G code: the modal motion). A
    // block with a cycle's P/Q or a dwell's code is not a move.
    if ((b.movesByCode() || !b.hasAnyG()) && !b.has('P') && !b.has('Q')) {
      for (const char axis : {'U', 'W'})
        if (const auto* w = b.find(axis); w && w->hasNumber) {
          mark(EvidenceKind::SystemA, *w, "{} beside a move", w->text);
          break;
        }
    }
  }

  void systemB(const ScannedBlock& b) {
    if (const auto* g = b.code('G', 95); g && !b.hasXZ()) mark(EvidenceKind::SystemB, *g, "G95");
    if (const auto* g = b.code('G', 94); g && !b.hasXZ() && b.has('F'))
      mark(EvidenceKind::SystemB, *g, "G94 {}", b.find('F')->text);
    if (const auto* g = b.code('G', 92); g && b.has('S') && !b.hasXZ())
      mark(EvidenceKind::SystemB, *g, "G92 {}", b.find('S')->text);
    for (const int n : {77, 78, 79, 91, 33})
      if (const auto* g = b.code('G', n)) mark(EvidenceKind::SystemB, *g, "G{}", n);
    if (const auto* g = b.code('G', 90); g && !b.hasXZ()) mark(EvidenceKind::SystemB, *g, "G90");
    for (const int n : {90, 92, 94})
      if (const auto* g = b.code('G', n); g && b.hasXZ() && evidence_.ambiguous.size() < MachineEvidence::kMarksKept)
        evidence_.ambiguous.push_back({EvidenceKind::SystemA, line_, columnOf(*g), fmt::format("G{} with X/Z", n)});
  }

  // HNC's single cycles take X(U) and Z(W); Fanuc's drilling codes of the same numbers take
  // an R point or a Q peck (and G80 cancels, with no axes).
  void hnc(const ScannedBlock& b) {
    if (!b.hasX() || !b.hasZ()) return;
    if (const auto* g = b.code('G', 80)) mark(EvidenceKind::Hnc, *g, "G80 with X and Z");
    if (b.has('R') || b.has('Q')) return;
    for (const int n : {81, 82})
      if (const auto* g = b.code('G', n)) mark(EvidenceKind::Hnc, *g, "G{} with X and Z", n);
  }

  void haas(const ScannedBlock& b) {
    for (const int n : {71, 72})
      if (const auto* g = b.code('G', n); g && b.has('D') && b.has('P') && b.has('Q'))
        mark(EvidenceKind::Haas, *g, "one-block G{} with {}", n, b.find('D')->text);
    if (const auto* m = b.code('M', 97)) mark(EvidenceKind::Haas, *m, "M97");
    if (const auto* g = b.code('G', 187)) mark(EvidenceKind::Haas, *g, "G187");
  }

  void lengths(const ScannedBlock& b) {
    for (const ScannedWord& w : b.words()) {
      if (!w.hasNumber || (w.letter != 'X' && w.letter != 'Z' && w.letter != 'U' && w.letter != 'W')) continue;
      const double size = std::abs(w.value);
      if (w.hasPoint) {
        ++evidence_.pointLengths;
        if (size > evidence_.largestPointLength || !evidence_.largestPointLengthWord) {
          evidence_.largestPointLength = std::max(evidence_.largestPointLength, size);
          evidence_.largestPointLengthWord = LengthWord{line_, columnOf(w), std::string(w.text), w.value};
        }
      } else if (size != 0) {
        ++evidence_.bareLengths;
        evidence_.largestBareLength = std::max(evidence_.largestBareLength, size);
        if (!evidence_.firstBareLength) evidence_.firstBareLength = LengthWord{line_, columnOf(w), std::string(w.text), w.value};
      }
    }
  }

  MachineEvidence& evidence_;
  int line_ = 0;
  std::string_view text_;           // the line's code
  std::vector<ScannedWord> words_;  // the line's, kept from line to line
  BlockIndex index_;
};

}  // namespace

MachineEvidence readMachineEvidence(PagedText text) {
  MachineEvidence evidence;
  EvidenceReader reader(evidence);
  bool first = true;
  forEachCodeLine(text, [&](int line, const std::string& code, std::string_view written) {
    if (!evidence.stock) evidence.stock = stockStatedOn(written, line);  // a comment line may state it
    if (code.find_first_not_of(" \t\r") == std::string::npos) return true;
    if (!evidence.foreign) evidence.foreign = foreignSignOf(code, line, first);
    first = false;
    reader.read(line, code);
    return true;
  });
  return evidence;
}

std::vector<LengthWord> bareLengthsIn(std::string_view line, int lineNumber) {
  std::vector<LengthWord> bare;
  const std::string code = detail::codeLineAt(line, 0, line.size());
  std::vector<ScannedWord> words;
  BlockIndex index;
  scanWords(code, words, index);
  for (const ScannedWord& w : words)
    if (w.hasNumber && !w.hasPoint && w.value != 0 &&
        (w.letter == 'X' || w.letter == 'Z' || w.letter == 'U' || w.letter == 'W'))
      bare.push_back({lineNumber, codePointCount(std::string_view(code).substr(0, w.at)) + 1, std::string(w.text), w.value});
  return bare;
}

}  // namespace lathesim::interp
