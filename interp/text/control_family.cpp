#include "interp/text/control_family.hpp"

#include <algorithm>
#include <array>
#include <cctype>
#include <regex>
#include <string>
#include <vector>

#include "interp/text/regex_text.hpp"
#include "interp/text/utf8.hpp"

namespace lathesim::interp {
namespace {

// A line with its ( ) comments blanked out, so that columns stay where they were.
std::string withoutComments(std::string_view line) {
  std::string text(line);
  bool inComment = false;
  for (char& c : text) {
    if (c == '(') inComment = true;
    const bool close = c == ')';
    if (inComment) c = ' ';
    if (close) inComment = false;
  }
  return text;
}

// A control family's sign: a pattern, and words one of which a line must hold (in any case)
// for the pattern to match there. std::regex is slow (each of a million lines tried six
// times took most of a long program's reading): a line that holds none is not searched.
struct Sign {
  std::regex pattern;
  std::string_view family;
  std::vector<std::string_view> needles;  // upper case
};

std::string upperCase(std::string_view text) {
  std::string upper(text);
  for (char& c : upper) c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
  return upper;
}

bool mayMatch(const Sign& sign, const std::string& upperLine) {
  return std::any_of(sign.needles.begin(), sign.needles.end(),
                     [&](std::string_view needle) { return upperLine.find(needle) != std::string::npos; });
}

const std::array<Sign, 6>& signs() {
  using std::regex_constants::icase;
  static const std::array<Sign, 6> table{
      Sign{std::regex(R"(^\s*%PM\b)"), "Philips 432/532", {"%PM"}},
      Sign{std::regex(R"(\bo(\d+|<[^>]*>)\s*(sub|endsub|call|if|elseif|else|endif|while|endwhile|do|repeat|endrepeat|return|break|continue)\b)", icase),
           "LinuxCNC (O-word subroutines)",
           {"SUB", "CALL", "IF", "ELSE", "WHILE", "DO", "REPEAT", "RETURN", "BREAK", "CONTINUE"}},
      Sign{std::regex(R"(#<[A-Za-z_])"), "LinuxCNC (named parameters)", {"#<"}},
      Sign{std::regex(R"(\bG0*64\s*P)", icase), "LinuxCNC (G64 path blending with a P tolerance)", {"64"}},
      Sign{std::regex(R"(\bBEGIN\s+PGM\b)", icase), "Heidenhain", {"BEGIN"}},
      Sign{std::regex(R"(\b(DIAMON|DIAMOF|DIAM90|CYCLE9[0-9]|LIMS\s*=)\b)", icase), "Siemens Sinumerik",
           {"DIAM", "CYCLE9", "LIMS"}},
  };
  return table;
}

}  // namespace

std::optional<ForeignProgram> recogniseForeignProgram(PagedText paged) {
  const std::string_view text = paged.view();
  int lineNumber = 0;
  bool firstLine = true;
  std::size_t begin = 0;
  while (begin <= text.size()) {
    paged.readingAt(begin);
    std::size_t end = text.find('\n', begin);
    if (end == std::string_view::npos) end = text.size();
    ++lineNumber;
    const std::string line = regexText(withoutComments(text.substr(begin, end - begin)));
    const std::size_t first = line.find_first_not_of(" \t\r");
    if (first != std::string::npos) {
      if (firstLine && line[first] == '$') {
        return ForeignProgram{lineNumber, codePointCount(std::string_view(line).substr(0, first)) + 1,
                              "Okuma OSP", line.substr(first, line.find_last_not_of(" \t\r") + 1 - first)};
      }
      firstLine = false;
      const std::string upperLine = upperCase(line);
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
    }
    if (end == text.size()) break;
    begin = end + 1;
  }
  return std::nullopt;
}

}  // namespace lathesim::interp
