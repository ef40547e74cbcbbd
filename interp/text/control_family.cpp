#include "interp/text/control_family.hpp"

#include <array>
#include <cctype>
#include <regex>
#include <string>

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

struct Sign {
  std::regex pattern;
  std::string_view family;
};

const std::array<Sign, 6>& signs() {
  using std::regex_constants::icase;
  static const std::array<Sign, 6> table{
      Sign{std::regex(R"(^\s*%PM\b)"), "Philips 432/532"},
      Sign{std::regex(R"(\bo(\d+|<[^>]*>)\s*(sub|endsub|call|if|elseif|else|endif|while|endwhile|do|repeat|endrepeat|return|break|continue)\b)", icase),
           "LinuxCNC (O-word subroutines)"},
      Sign{std::regex(R"(#<[A-Za-z_])"), "LinuxCNC (named parameters)"},
      Sign{std::regex(R"(\bG0*64\s*P)", icase), "LinuxCNC (G64 path blending with a P tolerance)"},
      Sign{std::regex(R"(\bBEGIN\s+PGM\b)", icase), "Heidenhain"},
      Sign{std::regex(R"(\b(DIAMON|DIAMOF|DIAM90|CYCLE9[0-9]|LIMS\s*=)\b)", icase), "Siemens Sinumerik"},
  };
  return table;
}

}  // namespace

std::optional<ForeignProgram> recogniseForeignProgram(std::string_view text) {
  int lineNumber = 0;
  bool firstLine = true;
  std::size_t begin = 0;
  while (begin <= text.size()) {
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
      for (const Sign& sign : signs()) {
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
