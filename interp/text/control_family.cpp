#include "interp/text/control_family.hpp"

#include <algorithm>
#include <array>
#include <cstdint>
#include <mutex>
#include <optional>
#include <regex>
#include <string>
#include <vector>

#include "interp/text/regex_text.hpp"
#include "interp/base/utf8.hpp"

namespace lathesim::interp {
namespace {

// Blanks out the ( ) comments of `line`, so that columns stay where they were.
void blankComments(std::string& line) {
  const std::size_t open = line.find('(');  // most lines have none: one memchr
  if (open == std::string::npos) return;
  bool inComment = false;
  for (std::size_t i = open; i < line.size(); ++i) {
    char& c = line[i];
    if (c == '(') inComment = true;
    const bool close = c == ')';
    if (inComment) c = ' ';
    if (close) inComment = false;
  }
}

// Which characters a text holds, coarsely: one bit of 64 per byte value (several share a bit).
// A word whose bits are not all in a line's is not in it, so most lines need no search at all.
using CharacterBits = std::uint64_t;
CharacterBits bitOf(char c) { return CharacterBits{1} << (static_cast<unsigned char>(c) & 63U); }
CharacterBits bitsOf(std::string_view text) {
  CharacterBits bits = 0;
  for (const char c : text) bits |= bitOf(c);
  return bits;
}

// A word a line must hold (upper case), with its characters' bits worked out once.
struct Needle {
  std::string_view word;
  CharacterBits bits = 0;
  Needle(const char* w) : word(w), bits(bitsOf(word)) {}  // NOLINT(google-explicit-constructor): the table lists words
  explicit Needle(std::string_view w) : word(w), bits(bitsOf(w)) {}
};

// A control family's sign: a pattern, words one of which a line must hold (in any case) for
// the pattern to match there, and a word it must hold besides (empty: none). std::regex is
// slow (each of a million lines tried six times took most of a long program's reading): a
// line that holds none of the words is not searched, and a pattern is compiled only when a
// line first holds its words (most programs never need one).
class Sign {
 public:
  Sign(std::string_view pattern, std::regex_constants::syntax_option_type flags, std::string_view family,
       std::vector<Needle> needles, std::string_view alsoNeeded = {})
      : family(family), needles(std::move(needles)), source_(pattern), flags_(flags) {
    if (!alsoNeeded.empty()) this->alsoNeeded.emplace(alsoNeeded);
  }

  std::string_view family;
  std::vector<Needle> needles;       // upper case
  std::optional<Needle> alsoNeeded;  // upper case

  const std::regex& pattern() const {
    std::call_once(compiled_, [&] { pattern_ = std::regex(source_.begin(), source_.end(), flags_); });
    return pattern_;
  }

 private:
  std::string_view source_;
  std::regex_constants::syntax_option_type flags_;
  mutable std::once_flag compiled_;
  mutable std::regex pattern_;
};

char asciiUpper(char c) { return c >= 'a' && c <= 'z' ? static_cast<char>(c - 'a' + 'A') : c; }

// A line in upper case and its characters' bits, in a buffer kept from line to line (the walk
// asks for every line).
struct UpperLine {
  std::string text;
  CharacterBits bits = 0;
  bool holds(const Needle& needle) const {
    return (needle.bits & ~bits) == 0 && text.find(needle.word) != std::string::npos;
  }
};

const UpperLine& upperCase(const std::string& line) {
  thread_local UpperLine upper;
  upper.text.resize(line.size());
  // Locals, not the members: a store through a char pointer could alias them, and each
  // character would reload them.
  char* out = upper.text.data();
  CharacterBits bits = 0;
  for (const char c : line) {
    const char u = asciiUpper(c);
    *out++ = u;
    bits |= bitOf(u);
  }
  upper.bits = bits;
  return upper;
}

bool mayMatch(const Sign& sign, const UpperLine& line) {
  if (sign.alsoNeeded && !line.holds(*sign.alsoNeeded)) return false;
  return std::any_of(sign.needles.begin(), sign.needles.end(), [&](const Needle& needle) { return line.holds(needle); });
}

const std::array<Sign, 10>& signs() {
  using std::regex_constants::icase;
  constexpr auto plain = std::regex_constants::ECMAScript;
  static const std::array<Sign, 10> table{
      Sign{R"(^\s*%PM\b)", plain, "Philips 432/532", {"%PM"}},
      Sign{R"(\bo(\d+|<[^>]*>)\s*(sub|endsub|call|if|elseif|else|endif|while|endwhile|do|repeat|endrepeat|return|break|continue)\b)",
           icase, "LinuxCNC (O-word subroutines)",
           {"SUB", "CALL", "IF", "ELSE", "WHILE", "DO", "REPEAT", "RETURN", "BREAK", "CONTINUE"},
           "O"},
      Sign{R"(#<[A-Za-z_])", plain, "LinuxCNC (named parameters)", {"#<"}},
      Sign{R"(\bG0*64\s*P)", icase, "LinuxCNC (G64 path blending with a P tolerance)", {"64"}, "P"},
      // LinuxCNC's lathe diameter / radius modes. Fanuc's G07.1 (cylindrical interpolation)
      // has a point and its G08 (look-ahead) a P: neither is taken.
      Sign{R"(\bG0*[78](?![.\d])(?!\s*P))", icase, "LinuxCNC (G7/G8 diameter and radius modes)",
           {"G7", "G07", "G8", "G08"}},
      Sign{R"(\bBEGIN\s+PGM\b)", icase, "Heidenhain", {"BEGIN"}},
      Sign{R"(\b(DIAMON|DIAMOF|DIAM90|CYCLE9[0-9]|LIMS\s*=)\b)", icase, "Siemens Sinumerik", {"DIAM", "CYCLE9", "LIMS"}},
      // Fagor 8055/8070 program header `%name,MX,` (the attribute field between commas).
      Sign{R"(^\s*%[^,]*,M[A-Z]*,)", icase, "Fagor 8055/8070", {","}, "%"},
      // Mazak's own EIA/ISO codes, which no Fanuc lathe has: G109 L_ (which turret head the
      // blocks after it drive, on a multi-turret machine) and G53.5/G52.5 (MAZATROL's work
      // coordinates on and off), as the Autodesk Mazak mill-turn post writes them. A Mazak
      // program without them is Fanuc-compatible and runs.
      Sign{R"(\bG0*(109(?![.\d])|5[23]\.5(?!\d)))", icase, "Mazak EIA/ISO (multi-turret G109, MAZATROL coordinates G53.5/G52.5)",
           {"109", "53.5", "52.5"}, "G"},
      // The tool call of Fagor and Siemens alike: T the tool, D its offset (Fanuc, GSK and
      // Haas give both in one T word).
      Sign{R"(\bT\s*\d+\s*D\s*\d+\b)", icase, "Fagor 8055/8070 or Siemens Sinumerik (T with its offset in D)",
           {"D"}, "T"},
  };
  return table;
}

}  // namespace

namespace detail {
void codeLineInto(std::string& line, std::string_view text, std::size_t begin, std::size_t end) {
  const std::string_view written = text.substr(begin, end - begin);
  line.assign(written.substr(0, regexTextLength(written)));  // cut first: a comment opened past the cut blanks nothing before it
  blankComments(line);
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
    if (std::regex_search(line, match, sign.pattern())) {
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
