#include "interp/text/label_number.hpp"

#include <string>

#include <fmt/format.h>

namespace lathesim::interp {

std::string decimalPointSlip(const Word& word) {
  const std::string& number = word.number;
  const std::size_t point = number.find('.');
  if (point == std::string::npos || number.find_first_not_of("0123456789.") != std::string::npos) return {};
  const std::string whole = number.substr(0, point);
  const bool noFraction = number.find_first_not_of('0', point + 1) == std::string::npos;
  if (noFraction && !whole.empty())
    return fmt::format("a decimal point where a whole number is meant; write {}{}", word.text().substr(0, word.text().size() - number.size()), whole);
  return "a decimal point where a whole number is meant; a count has no fraction";
}

Result<int> labelNumberOf(const Word& word, int line, int maxDigits, std::string_view what) {
  const std::string& digits = word.number;
  if (const std::string slip = decimalPointSlip(word); !slip.empty())
    return Error{line, word.column, fmt::format("{} is not {}: {}", word.text(), what, slip)};
  if (digits.empty() || digits.find_first_not_of("0123456789") != std::string::npos) {
    return Error{line, word.column,
                 fmt::format("{} is not {}: expected digits only, e.g. {}10", word.text(), what, word.text().front())};
  }
  const std::size_t first = std::min(digits.find_first_not_of('0'), digits.size());
  if (static_cast<int>(digits.size() - first) > maxDigits) {
    return Error{line, word.column,
                 fmt::format("{} is not {}: it has {} digits, at most {} are allowed", word.text(), what,
                             digits.size() - first, maxDigits)};
  }
  return first == digits.size() ? 0 : std::stoi(digits.substr(first));
}

}  // namespace lathesim::interp
