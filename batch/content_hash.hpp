#pragma once
// A 64-bit FNV-1a hash of bytes, for telling whether a batch job's inputs changed since its
// result was written. Not for security: it only has to tell an edited file from the same
// one (a chance collision is 2⁻⁶⁴ per edit).

#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <string_view>

namespace lathesim::batch {

class ContentHash {
 public:
  /// Adds `bytes`, then a separator, so ("ab", "c") and ("a", "bc") hash apart.
  ContentHash& add(std::string_view bytes);
  ContentHash& add(double value);
  /// Adds the file's whole contents; false (and nothing added but a marker) if unreadable.
  bool addFile(const std::filesystem::path& file);

  std::uint64_t value() const { return state_; }
  std::string hex() const;  // 16 lower-case hex digits

 private:
  void mix(std::string_view bytes);
  std::uint64_t state_ = 0xcbf29ce484222325ULL;  // FNV-1a offset basis
};

/// The hash of a file's contents as 16 hex digits, or nullopt if it cannot be read.
std::optional<std::string> fileHash(const std::filesystem::path& file);

}  // namespace lathesim::batch
