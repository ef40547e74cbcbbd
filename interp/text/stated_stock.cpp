#include "interp/text/stated_stock.hpp"

#include <regex>
#include <string>

#include "interp/text/regex_text.hpp"
#include "interp/base/utf8.hpp"

namespace lathesim::interp {
namespace {

using std::regex_constants::icase;

const std::string kNumber = R"(([0-9]+\.?[0-9]*|\.[0-9]+))";

// The bar the two matched numbers give, or nullopt when either is too long to be a number.
std::optional<StatedStock> stated(const std::string& diameter, const std::string& length) {
  const auto d = matchedNumber(diameter);
  const auto l = matchedNumber(length);
  if (!d || !l) return std::nullopt;
  return StatedStock{*d, *l, 0, 0, {}};
}

std::optional<StatedStock> billet(const std::string& line) {
  static const std::regex pattern(R"(^\s*\[\s*BILLET\s+X\s*)" + kNumber + R"(\s+Z\s*)" + kNumber, icase);
  std::smatch m;
  if (!std::regex_search(line, m, pattern)) return std::nullopt;
  return stated(m[1], m[2]);
}

std::optional<StatedStock> stockComment(const std::string& comment) {
  static const std::regex keyword(R"(^\s*(STOCK|BLANK|BAR|BILLET|RAW|MATERIAL|毛坯))", icase);
  if (!std::regex_search(comment, keyword)) return std::nullopt;
  static const std::regex diameter(R"((?:\bDIA(?:METER)?|\bD|Ø|Φ|⌀)\s*[=:]?\s*)" + kNumber, icase);
  static const std::regex length(R"((?:\bLENGTH|\bLG|\bL)\s*[=:]?\s*)" + kNumber, icase);
  static const std::regex byTimes(R"((?:Ø|Φ|⌀|\bD|\bDIA)?\s*)" + kNumber + R"(\s*(?:X|×|\*)\s*)" + kNumber, icase);
  std::smatch d, l, t;
  if (std::regex_search(comment, d, diameter) && std::regex_search(comment, l, length)) return stated(d[1], l[1]);
  if (std::regex_search(comment, t, byTimes)) return stated(t[1], t[2]);
  return std::nullopt;
}

}  // namespace

std::optional<StatedStock> stockStatedOn(std::string_view written, int lineNumber) {
  // Both statements open with a bracket: most lines are passed over without a pattern tried
  // (two searches for one character: memchr, which find_first_of is not).
  if (written.find('(') == std::string_view::npos && written.find('[') == std::string_view::npos) return std::nullopt;
  std::string line = regexText(written);
  if (!line.empty() && line.back() == '\r') line.pop_back();
  std::optional<StatedStock> found = billet(line);
  std::size_t at = found ? line.find('[') : std::string::npos;
  std::string text = found ? line.substr(at) : std::string();
  for (std::size_t open = line.find('('); !found && open != std::string::npos; open = line.find('(', open + 1)) {
    const std::size_t close = line.find(')', open);
    if (close == std::string::npos) break;
    found = stockComment(line.substr(open + 1, close - open - 1));
    at = open;
    text = line.substr(open, close + 1 - open);
  }
  if (!found || found->diameterMm <= 0 || found->lengthMm <= 0) return std::nullopt;
  found->line = lineNumber;
  found->column = codePointCount(std::string_view(line).substr(0, at)) + 1;
  found->text = text;
  return found;
}

}  // namespace lathesim::interp
