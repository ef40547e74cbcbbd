#include "interp/text/control_family.hpp"

#include <algorithm>
#include <array>
#include <cstdint>
#include <regex>
#include <string>
#include <vector>

#include "interp/text/regex_text.hpp"
#include "interp/base/utf8.hpp"

namespace lathesim::interp {
namespace {

// Blanks out the ( ) comments of `line`, so that columns stay where they were.
void blankComments(std::string& line) {
  bool inComment = false;
  for (char& c : line) {
    if (c == '(') inComment = true;
    const bool close = c == ')';
    if (inComment) c = ' ';
    if (close) inComment = false;
  }
}

// A control family's sign: a pattern, words one of which a line must hold (in any case) for
// the pattern to match there, and a word it must hold besides (empty: none). std::regex is
// slow (each of a million lines tried six times took most of a long program's reading): a
// line that holds none of the words is not searched.
struct Sign {
  std::regex pattern;
  std::string_view family;
  std::vector<std::string_view> needles;  // upper case
  std::string_view alsoNeeded = {};       // upper case
};

char asciiUpper(char c) { return c >= 'a' && c <= 'z' ? static_cast<char>(c - 'a' + 'A') : c; }

// Which characters a text holds, coarsely: one bit of 64 per byte value (several share a bit).
// A word whose bits are not all in a line's is not in it, so most lines need no search at all.
using CharacterBits = std::uint64_t;
CharacterBits bitOf(char c) { return CharacterBits{1} << (static_cast<unsigned char>(c) & 63U); }
CharacterBits bitsOf(std::string_view text) {
  CharacterBits bits = 0;
  for (const char c : text) bits |= bitOf(c);
  return bits;
}

// A line in upper case and its characters' bits, in a buffer kept from line to line (the walk
// asks for every line).
struct UpperLine {
  std::string text;
  CharacterBits bits = 0;
  bool holds(std::string_view word) const {
    return (bitsOf(word) & ~bits) == 0 && text.find(word) != std::string::npos;
  }
};

const UpperLine& upperCase(const std::string& line) {
  thread_local UpperLine upper;
  upper.text.resize(line.size());
  upper.bits = 0;
  for (std::size_t i = 0; i < line.size(); ++i) {
    upper.text[i] = asciiUpper(line[i]);
    upper.bits |= bitOf(upper.text[i]);
  }
  return upper;
}

bool mayMatch(const Sign& sign, const UpperLine& line) {
  if (!sign.alsoNeeded.empty() && !line.holds(sign.alsoNeeded)) return false;
  return std::any_of(sign.needles.begin(), sign.needles.end(), [&](std::string_view needle) { return line.holds(needle); });
}

const std::array<Sign, 9>& signs() {
  using std::regex_constants::icase;
  static const std::array<Sign, 9> table{
      Sign{std::regex(R"(^\s*%PM\b)"), "Philips 432/532", {"%PM"}},
      Sign{std::regex(R"(\bo(\d+|<[^>]*>)\s*(sub|endsub|call|if|elseif|else|endif|while|endwhile|do|repeat|endrepeat|return|break|continue)\b)", icase),
           "LinuxCNC (O-word subroutines)",
           {"SUB", "CALL", "IF", "ELSE", "WHILE", "DO", "REPEAT", "RETURN", "BREAK", "CONTINUE"},
           "O"},
      Sign{std::regex(R"(#<[A-Za-z_])"), "LinuxCNC (named parameters)", {"#<"}},
      Sign{std::regex(R"(\bG0*64\s*P)", icase), "LinuxCNC (G64 path blending with a P tolerance)", {"64"}, "P"},
      // LinuxCNC's lathe diameter / radius modes. Fanuc's G07.1 (cylindrical interpolation)
      // has a point and its G08 (look-ahead) a P: neither is taken.
      Sign{std::regex(R"(\bG0*[78](?![.\d])(?!\s*P))", icase), "LinuxCNC (G7/G8 diameter and radius modes)",
           {"G7", "G07", "G8", "G08"}},
      Sign{std::regex(R"(\bBEGIN\s+PGM\b)", icase), "Heidenhain", {"BEGIN"}},
      Sign{std::regex(R"(\b(DIAMON|DIAMOF|DIAM90|CYCLE9[0-9]|LIMS\s*=)\b)", icase), "Siemens Sinumerik",
           {"DIAM", "CYCLE9", "LIMS"}},
      // Fagor 8055/8070 program header `%name,MX,` (the attribute field between commas).
      Sign{std::regex(R"(^\s*%[^,]*,M[A-Z]*,)", icase), "Fagor 8055/8070", {","}, "%"},
      // The tool call of Fagor and Siemens alike: T the tool, D its offset (Fanuc, GSK and
      // Haas give both in one T word).
      Sign{std::regex(R"(\bT\s*\d+\s*D\s*\d+\b)", icase), "Fagor 8055/8070 or Siemens Sinumerik (T with its offset in D)",
           {"D"}, "T"},
  };
  return table;
}

}  // namespace

namespace detail {
void codeLineInto(std::string& line, std::string_view text, std::size_t begin, std::size_t end) {
  line.assign(text.substr(begin, end - begin));
  blankComments(line);
  line.resize(regexTextLength(line));
}

std::string codeLineAt(std::string_view text, std::size_t begin, std::size_t end) {
  std::string line;
  codeLineInto(line, text, begin, end);
  return line;
}
}  // namespace detail

std::optional<ForeignProgram> foreignSignOf(const std::string& line, int lineNumber, bool first) {
  const std::size_t start = line.find_first_not_of(" \t\r");
  if (start == std::string::npos) return std::nullopt;
  if (first && line[start] == '$') {
    return ForeignProgram{lineNumber, codePointCount(std::string_view(line).substr(0, start)) + 1, "Okuma OSP",
                          line.substr(start, line.find_last_not_of(" \t\r") + 1 - start)};
  }
  const UpperLine& upperLine = upperCase(line);
  for (const Sign& sign : signs()) {
    if (!mayMatch(sign, upperLine)) continue;
    std::smatch match;
    if (std::regex_search(line, match, sign.pattern)) {
      const auto at = static_cast<std::size_t>(match.position(0));
      const std::size_t from = line.find_first_not_of(" \t", at);
      return ForeignProgram{lineNumber, codePointCount(std::string_view(line).substr(0, from)) + 1,
                            std::string(sign.family), match.str(0).substr(from - at)};
    }
  }
  return std::nullopt;
}

std::optional<ForeignProgram> recogniseForeignProgram(PagedText paged) {
  std::optional<ForeignProgram> found;
  bool first = true;
  forEachCodeLine(paged, [&](int lineNumber, const std::string& line, std::string_view) {
    if (line.find_first_not_of(" \t\r") == std::string::npos) return true;
    found = foreignSignOf(line, lineNumber, first);
    first = false;
    return !found;
  });
  return found;
}

}  // namespace lathesim::interp
