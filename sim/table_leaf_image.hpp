#pragma once
// Inside sim only: one leaf of the level set as the revolved table has it. The one place a
// leaf's values are read off the table, for settling the grid (revolved_stock.cpp) and for
// building it whole (table_grid.cpp), so that both write the same leaves.

#include <cstdint>

#include "sim/revolved_table.hpp"
#include "sim/stock_grid.hpp"

namespace lathesim::sim {

/// A leaf's values and active bits as the table has them, and whether they are one inactive
/// value at or beyond the band (then the leaf is a tile, as the writer prunes it).
struct LeafImage {
  float values[Leaf::NUM_VALUES];
  std::uint8_t activeBits[Leaf::NUM_VALUES / 8];  // one byte per column along Z, as Leaf's mask
  bool uniform;
};

/// The image of the leaf at `origin` (a multiple of 8 on every axis); `band` is the stock's
/// background, the value of the columns the table does not hold.
void imageOf(const RevolvedTable& table, const VoxelIndex& origin, float band, LeafImage& image);

}  // namespace lathesim::sim
