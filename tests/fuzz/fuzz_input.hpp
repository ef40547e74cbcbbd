#pragma once
// What every harness does with libFuzzer's bytes: take a few of them as choices, the rest as
// the text under test.

#include <cstddef>
#include <cstdint>
#include <string_view>

namespace lathesim::fuzz {

class FuzzInput {
 public:
  FuzzInput(const std::uint8_t* data, std::size_t size) : data_(reinterpret_cast<const char*>(data)), size_(size) {}

  /// The next byte as a choice among `count` (0 when the input is used up).
  unsigned choice(unsigned count) {
    if (size_ == 0) return 0;
    const auto byte = static_cast<unsigned char>(*data_);
    ++data_, --size_;
    return byte % count;
  }
  /// Whatever is left, as text.
  std::string_view rest() const { return {data_, size_}; }

 private:
  const char* data_;
  std::size_t size_;
};

}  // namespace lathesim::fuzz
