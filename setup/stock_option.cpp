#include "setup/stock_option.hpp"

#include <charconv>
#include <cmath>
#include <map>

#include <fmt/format.h>

namespace lathesim::setup {
namespace {

std::optional<double> numberIn(std::string_view text) {
  double value = 0;
  const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), value);
  if (ec != std::errc{} || end != text.data() + text.size() || !std::isfinite(value)) return std::nullopt;
  return value;
}

}  // namespace

std::variant<sim::StockSpec, std::string> parseStockOption(std::string_view text) {
  const std::string usage =
      "give the bar as D<diameter>[xd<bore>]xL<length>[xZ<face>], e.g. D40xL80, D40xL80xZ1 or D60xd40xL80";
  const std::string option = "--stock " + std::string(text) + ": ";
  std::map<char, double> parts;
  std::size_t begin = 0;
  while (begin <= text.size()) {
    std::size_t end = text.find_first_of("xX", begin);
    if (end == std::string_view::npos) end = text.size();
    const std::string_view part = text.substr(begin, end - begin);
    if (part.size() < 2) return option + "an empty part; " + usage;
    const char letter = part[0];
    const auto value = numberIn(part.substr(1));
    if ((letter != 'D' && letter != 'd' && letter != 'L' && letter != 'Z') || !value)
      return option + "'" + std::string(part) + "' is not D, d, L or Z with a number; " + usage;
    if (!parts.emplace(letter, *value).second) return option + std::string(1, letter) + " is given twice; " + usage;
    if (letter != 'Z' && *value <= 0) return option + std::string(part) + " must be positive; " + usage;
    if (end == text.size()) break;
    begin = end + 1;
  }
  if (!parts.count('D') || !parts.count('L')) return option + (parts.count('D') ? "L" : "D") + " is missing; " + usage;
  if (parts.count('d') && parts['d'] >= parts['D'])
    return option + fmt::format("the bore d{:g} must be smaller than the diameter D{:g}; ", parts['d'], parts['D']) + usage;
  return sim::StockSpec{parts['D'], parts['L'], parts.count('Z') ? parts['Z'] : 0.0,
                        parts.count('d') ? parts['d'] : 0.0};
}

bool stockOptionStatesFace(std::string_view text) {
  // Z is the only part its letter names after a separator or at the start: D40xL80xZ1.
  for (std::size_t at = text.find('Z'); at != std::string_view::npos; at = text.find('Z', at + 1))
    if (at == 0 || text[at - 1] == 'x' || text[at - 1] == 'X') return true;
  return false;
}

}  // namespace lathesim::setup
