#include "interp/text/machine_evidence.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <string_view>

#include <fmt/format.h>

#include "interp/base/utf8.hpp"

namespace lathesim::interp {
namespace {

// A word of a block as written: a letter and the number after it (no number: an expression,
// a keyword, or a lone letter). ',C' and ',R' are kept as the letters 'c' and 'r'.
struct ScannedWord {
  char letter = 0;
  int column = 0;  // 1-based, in code points
  bool hasNumber = false;
  bool hasPoint = false;
  double value = 0;
  std::string_view text;  // "G95", "Z-23", ",C1."
};

bool isDigit(char c) { return c >= '0' && c <= '9'; }

// The words of a comment-free line. A ';' ends the block (Fanuc's end of block).
std::vector<ScannedWord> scanWords(std::string_view line) {
  std::vector<ScannedWord> words;
  std::size_t i = 0;
  while (i < line.size()) {
    const char c = line[i];
    if (c == ';') break;
    const bool corner = c == ',' && i + 1 < line.size() && std::isalpha(static_cast<unsigned char>(line[i + 1]));
    if (!std::isalpha(static_cast<unsigned char>(c)) && !corner) {
      ++i;
      continue;
    }
    const std::size_t start = i;
    ScannedWord word;
    word.letter = static_cast<char>(std::toupper(static_cast<unsigned char>(line[corner ? i + 1 : i])));
    if (corner) word.letter = static_cast<char>(std::tolower(static_cast<unsigned char>(word.letter)));
    word.column = codePointCount(line.substr(0, start)) + 1;
    i += corner ? 2 : 1;
    while (i < line.size() && (line[i] == ' ' || line[i] == '\t')) ++i;
    std::size_t number = i;
    if (number < line.size() && (line[number] == '-' || line[number] == '+')) ++number;
    std::size_t end = number;
    while (end < line.size() && isDigit(line[end])) ++end;
    if (end < line.size() && line[end] == '.') {
      word.hasPoint = true;
      ++end;
      while (end < line.size() && isDigit(line[end])) ++end;
    }
    const bool digits = std::any_of(line.begin() + static_cast<std::ptrdiff_t>(number),
                                    line.begin() + static_cast<std::ptrdiff_t>(end), isDigit);
    if (digits) {
      word.hasNumber = true;
      // A number of hundreds of digits is no length; it is read as large, never as an error.
      word.value = std::strtod(std::string(line.substr(i, end - i)).c_str(), nullptr);
      if (!std::isfinite(word.value)) word.value = 0;
      i = end;
    }
    word.text = line.substr(start, i - start);
    while (!word.text.empty() && (word.text.back() == ' ' || word.text.back() == '\t')) word.text.remove_suffix(1);
    words.push_back(word);
  }
  return words;
}

// A block's words, and what the rules ask of them.
class ScannedBlock {
 public:
  explicit ScannedBlock(std::vector<ScannedWord> words) : words_(std::move(words)) {}

  const ScannedWord* find(char letter) const {
    for (const ScannedWord& w : words_)
      if (w.letter == letter) return &w;
    return nullptr;
  }
  bool has(char letter) const { return find(letter) != nullptr; }
  /// The G word G`number`, or nullptr.
  const ScannedWord* code(char letter, int number) const {
    for (const ScannedWord& w : words_)
      if (w.letter == letter && w.hasNumber && !w.hasPoint && w.value == number) return &w;
    return nullptr;
  }
  bool hasAnyG() const { return has('G'); }
  bool hasX() const { return has('X') || has('U'); }
  bool hasZ() const { return has('Z') || has('W'); }
  bool hasXZ() const { return has('X') || has('Z') || has('U') || has('W'); }
  bool movesByCode() const { return code('G', 0) || code('G', 1) || code('G', 2) || code('G', 3); }
  const std::vector<ScannedWord>& words() const { return words_; }

 private:
  std::vector<ScannedWord> words_;
};

class EvidenceReader {
 public:
  explicit EvidenceReader(MachineEvidence& evidence) : evidence_(evidence) {}

  void read(int line, std::string_view text) {
    const ScannedBlock block(scanWords(text));
    line_ = line;
    systemA(block);
    systemB(block);
    hnc(block);
    haas(block);
    for (const ScannedWord& w : block.words())
      if (w.letter == 'c' || w.letter == 'r') mark(EvidenceKind::FanucCorner, w, std::string(w.text));
    if (const auto* g = block.code('G', 20)) mark(EvidenceKind::Inch, *g, "G20");
    if (block.code('G', 21)) evidence_.metricStated = true;
    lengths(block);
  }

 private:
  void mark(EvidenceKind kind, const ScannedWord& at, std::string text) {
    const auto k = static_cast<std::size_t>(kind);
    ++evidence_.counts[k];
    if (evidence_.marks[k].size() < MachineEvidence::kMarksKept)
      evidence_.marks[k].push_back({kind, line_, at.column, std::move(text)});
  }

  void systemA(const ScannedBlock& b) {
    for (const int n : {98, 99, 50, 32})
      if (const auto* g = b.code('G', n)) mark(EvidenceKind::SystemA, *g, fmt::format("G{}", n));
    // U/W beside a move: a block that moves (G00–G03, or no G code: the modal motion). A
    // block with a cycle's P/Q or a dwell's code is not a move.
    if ((b.movesByCode() || !b.hasAnyG()) && !b.has('P') && !b.has('Q')) {
      for (const char axis : {'U', 'W'})
        if (const auto* w = b.find(axis); w && w->hasNumber) {
          mark(EvidenceKind::SystemA, *w, fmt::format("{} beside a move", w->text));
          break;
        }
    }
  }

  void systemB(const ScannedBlock& b) {
    if (const auto* g = b.code('G', 95); g && !b.hasXZ()) mark(EvidenceKind::SystemB, *g, "G95");
    if (const auto* g = b.code('G', 94); g && !b.hasXZ() && b.has('F'))
      mark(EvidenceKind::SystemB, *g, fmt::format("G94 {}", b.find('F')->text));
    if (const auto* g = b.code('G', 92); g && b.has('S') && !b.hasXZ())
      mark(EvidenceKind::SystemB, *g, fmt::format("G92 {}", b.find('S')->text));
    for (const int n : {77, 78, 79, 91, 33})
      if (const auto* g = b.code('G', n)) mark(EvidenceKind::SystemB, *g, fmt::format("G{}", n));
    if (const auto* g = b.code('G', 90); g && !b.hasXZ()) mark(EvidenceKind::SystemB, *g, "G90");
    for (const int n : {90, 92, 94})
      if (const auto* g = b.code('G', n); g && b.hasXZ() && evidence_.ambiguous.size() < MachineEvidence::kMarksKept)
        evidence_.ambiguous.push_back({EvidenceKind::SystemA, line_, g->column, fmt::format("G{} with X/Z", n)});
  }

  // HNC's single cycles take X(U) and Z(W); Fanuc's drilling codes of the same numbers take
  // an R point or a Q peck (and G80 cancels, with no axes).
  void hnc(const ScannedBlock& b) {
    if (!b.hasX() || !b.hasZ()) return;
    if (const auto* g = b.code('G', 80)) mark(EvidenceKind::Hnc, *g, "G80 with X and Z");
    if (b.has('R') || b.has('Q')) return;
    for (const int n : {81, 82})
      if (const auto* g = b.code('G', n)) mark(EvidenceKind::Hnc, *g, fmt::format("G{} with X and Z", n));
  }

  void haas(const ScannedBlock& b) {
    for (const int n : {71, 72})
      if (const auto* g = b.code('G', n); g && b.has('D') && b.has('P') && b.has('Q'))
        mark(EvidenceKind::Haas, *g, fmt::format("one-block G{} with {}", n, b.find('D')->text));
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
          evidence_.largestPointLengthWord = LengthWord{line_, w.column, std::string(w.text), w.value};
        }
      } else if (size != 0) {
        ++evidence_.bareLengths;
        evidence_.largestBareLength = std::max(evidence_.largestBareLength, size);
        if (!evidence_.firstBareLength) evidence_.firstBareLength = LengthWord{line_, w.column, std::string(w.text), w.value};
      }
    }
  }

  MachineEvidence& evidence_;
  int line_ = 0;
};

}  // namespace

MachineEvidence readMachineEvidence(PagedText text) {
  MachineEvidence evidence;
  EvidenceReader reader(evidence);
  bool first = true;
  forEachCodeLine(text, [&](int line, const std::string& code) {
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
  for (const ScannedWord& w : scanWords(code))
    if (w.hasNumber && !w.hasPoint && w.value != 0 &&
        (w.letter == 'X' || w.letter == 'Z' || w.letter == 'U' || w.letter == 'W'))
      bare.push_back({lineNumber, w.column, std::string(w.text), w.value});
  return bare;
}

}  // namespace lathesim::interp
