#include "batch/content_hash.hpp"

#include <array>
#include <cstdio>
#include <fstream>

namespace lathesim::batch {

void ContentHash::mix(std::string_view bytes) {
  constexpr std::uint64_t kPrime = 0x100000001b3ULL;
  for (unsigned char c : bytes) state_ = (state_ ^ c) * kPrime;
}

ContentHash& ContentHash::add(std::string_view bytes) {
  mix(std::to_string(bytes.size()));  // length first: no two sequences of parts run together
  mix(":");
  mix(bytes);
  return *this;
}

ContentHash& ContentHash::add(double value) {
  char text[40];
  std::snprintf(text, sizeof text, "%.17g", value);
  return add(text);
}

bool ContentHash::addFile(const std::filesystem::path& file) {
  const std::optional<std::string> contents = fileHash(file);
  add(contents.value_or("(unreadable)"));
  return contents.has_value();
}

std::string ContentHash::hex() const {
  char text[17];
  std::snprintf(text, sizeof text, "%016llx", static_cast<unsigned long long>(state_));
  return text;
}

std::optional<std::string> fileHash(const std::filesystem::path& file) {
  std::error_code ec;
  if (!std::filesystem::is_regular_file(file, ec)) return std::nullopt;
  std::ifstream in(file, std::ios::binary);
  if (!in) return std::nullopt;
  ContentHash contents;
  std::array<char, 1 << 16> buffer;
  while (in.read(buffer.data(), buffer.size()) || in.gcount() > 0)
    contents.add(std::string_view(buffer.data(), static_cast<std::size_t>(in.gcount())));
  if (in.bad()) return std::nullopt;
  return contents.hex();
}

}  // namespace lathesim::batch
