#include "sim/table_leaf_image.hpp"

#include <algorithm>
#include <cmath>
#include <cstring>

namespace lathesim::sim {

void imageOf(const RevolvedTable& table, const VoxelIndex& origin, float band, LeafImage& image) {
  for (int i = 0; i < kLeafDim; ++i)
    for (int j = 0; j < kLeafDim; ++j) {
      const int column = (i << 6) | (j << 3);  // LeafNode<float, 3>::coordToOffset
      std::uint8_t bits = 0;
      if (const float* cells = table.column(origin.i + i, origin.j + j, origin.k, bits))
        std::memcpy(image.values + column, cells, kLeafDim * sizeof(float));
      else
        std::fill_n(image.values + column, kLeafDim, band);
      image.activeBits[column >> 3] = bits;
    }
  table.applyAirVoxels(origin, image.values, image.activeBits);
  const float first = image.values[0];
  image.uniform = std::abs(first) >= band;
  for (std::size_t n = 0; n < Leaf::NUM_VALUES / 8 && image.uniform; ++n) image.uniform = image.activeBits[n] == 0;
  for (std::size_t n = 1; n < Leaf::NUM_VALUES && image.uniform; ++n) image.uniform = image.values[n] == first;
}

}  // namespace lathesim::sim
