#include "sim/block_rows.hpp"

#include <cstring>

namespace lathesim::sim {

void SpooledBlockRows::forEach(const std::function<void(const BlockRemoval&)>& visit) const {
  constexpr std::size_t kRowsAChunk = 4096;
  file_.readBack(kRowsAChunk * sizeof(BlockRemoval), [&](std::string_view chunk) {
    for (std::size_t at = 0; at + sizeof(BlockRemoval) <= chunk.size(); at += sizeof(BlockRemoval)) {
      BlockRemoval row;
      std::memcpy(&row, chunk.data() + at, sizeof row);
      visit(row);
    }
  });
}

}  // namespace lathesim::sim
