#include "job/stock_option.hpp"

#include <charconv>
#include <cmath>
#include <map>

namespace lathesim::job {
namespace {

std::optional<double> numberIn(std::string_view text) {
  double value = 0;
  const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), value);
  if (ec != std::errc{} || end != text.data() + text.size() || !std::isfinite(value)) return std::nullopt;
  return value;
}

}  // namespace

std::variant<sim::StockSpec, std::string> parseStockOption(std::string_view text) {
  const std::string usage = "give the bar as D<diameter>xL<length>[xZ<face>], e.g. D40xL80 or D40xL80xZ1";
  std::map<char, double> parts;
  std::size_t begin = 0;
  while (begin <= text.size()) {
    std::size_t end = text.find_first_of("xX", begin);
    if (end == std::string_view::npos) end = text.size();
    const std::string_view part = text.substr(begin, end - begin);
    if (part.size() < 2) return "--stock " + std::string(text) + ": an empty part; " + usage;
    const char letter = part[0];
    if (letter == 'd') return "--stock " + std::string(text) + ": tube stock (a bore, d) is not simulated yet; " + usage;
    const auto value = numberIn(part.substr(1));
    if ((letter != 'D' && letter != 'L' && letter != 'Z') || !value)
      return "--stock " + std::string(text) + ": '" + std::string(part) + "' is not D, L or Z with a number; " + usage;
    if (!parts.emplace(letter, *value).second)
      return "--stock " + std::string(text) + ": " + std::string(1, letter) + " is given twice; " + usage;
    if (letter != 'Z' && *value <= 0)
      return "--stock " + std::string(text) + ": " + std::string(part) + " must be positive; " + usage;
    if (end == text.size()) break;
    begin = end + 1;
  }
  if (!parts.count('D') || !parts.count('L'))
    return "--stock " + std::string(text) + ": " + (parts.count('D') ? "L" : "D") + " is missing; " + usage;
  return sim::StockSpec{parts['D'], parts['L'], parts.count('Z') ? parts['Z'] : 0.0};
}

}  // namespace lathesim::job
