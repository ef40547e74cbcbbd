#include "interp/text/label_number.hpp"

#include <string>

#include <fmt/format.h>

namespace lathesim::interp {

Result<int> labelNumberOf(const Word& word, int line, int maxDigits, std::string_view what) {
  const std::string& digits = word.number;
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
