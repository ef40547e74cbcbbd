#include "batch/shard.hpp"

#include <charconv>

namespace lathesim::batch {

std::optional<Shard> parseShard(const std::string& text) {
  const auto slash = text.find('/');
  if (slash == std::string::npos) return std::nullopt;
  Shard shard;
  const char* first = text.data();
  const char* middle = first + slash;
  const char* last = first + text.size();
  const auto i = std::from_chars(first, middle, shard.index);
  const auto n = std::from_chars(middle + 1, last, shard.count);
  if (i.ec != std::errc{} || i.ptr != middle || n.ec != std::errc{} || n.ptr != last) return std::nullopt;
  if (shard.count < 1 || shard.index < 1 || shard.index > shard.count) return std::nullopt;
  return shard;
}

}  // namespace lathesim::batch
