#pragma once
// What reading a catalogue code (an ISO 1832 insert, an ISO 5608 holder) gives back: the
// value, or the first character that is wrong and why; plus warnings that do not stop it.

#include <cstddef>
#include <optional>
#include <string>
#include <vector>

namespace lathesim {

struct CodeProblem {
  std::size_t index = 0;  // 0-based index of the offending character in the code
  std::string message;    // e.g. "insert TBXG120408: position 3 'X' is not a tolerance class; expected …"
};

template <typename T>
struct ParsedCode {
  std::optional<T> value;
  std::optional<CodeProblem> problem;  // set exactly when value is not
  std::vector<std::string> warnings;   // e.g. a vendor-special size
};

}  // namespace lathesim
