#pragma once
// Numbers as the batch writes them for programs to read back (command lines, CSV, sort keys).

#include <array>
#include <charconv>
#include <string>

namespace lathesim::batch {

/// The shortest text that reads back as the same double (0.25, 1e-07, 753994.1234).
inline std::string shortestText(double value) {
  std::array<char, 64> text{};
  const auto [end, ec] = std::to_chars(text.data(), text.data() + text.size(), value);
  return std::string(text.data(), ec == std::errc{} ? end : text.data());
}

}  // namespace lathesim::batch
