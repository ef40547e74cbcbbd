// The stock while it is revolved: writes go to the table (revolved_table.hpp), and the level
// set is written from it when something reads it.

#include <tbb/parallel_for.h>

#include <algorithm>
#include <cstring>

#include "sim/stock_grid.hpp"
#include "sim/table_grid.hpp"
#include "sim/table_leaf_image.hpp"

namespace lathesim::sim {
namespace {

// The most memory the table may take, as a share of the level set's.
constexpr double kMaxTableShareOfStock = 0.25;
// The most air voxels the table keeps apart (about 100 bytes each) before it hands the stock to
// the level set: seed 000 makes 324.
constexpr std::size_t kMaxAirVoxels = std::size_t{1} << 18;

}  // namespace

void StockGrid::settle() const {
  if (!table) return;
  const std::lock_guard<std::mutex> lock(settling_);
  if (!gridBuilt_) {
    // The level set is a copy of the table's stock, made whole when first read (table_grid.hpp);
    // it then only takes the table's changes.
    writeGridFromTable(const_cast<StockGrid&>(*this));
    gridBuilt_ = true;
    return;
  }
  const std::vector<VoxelIndex> origins = table->changedLeaves();
  // A batch at a time: the images are computed in parallel, the tree is changed serially.
  constexpr std::size_t kBatch = 2048;
  std::vector<LeafImage> images(std::min(kBatch, origins.size()));
  auto accessor = grid->getAccessor();
  for (std::size_t start = 0; start < origins.size(); start += kBatch) {
    const std::size_t count = std::min(kBatch, origins.size() - start);
    tbb::parallel_for(tbb::blocked_range<std::size_t>(0, count), [&](const auto& range) {
      for (std::size_t n = range.begin(); n != range.end(); ++n) imageOf(*table, origins[start + n], background, images[n]);
    });
    for (std::size_t n = 0; n < count; ++n) {
      const LeafImage& image = images[n];
      const Coord origin(origins[start + n].i, origins[start + n].j, origins[start + n].k);
      if (image.uniform) {
        if (accessor.probeLeaf(origin) || accessor.getValue(origin) != image.values[0] || accessor.isValueOn(origin))
          accessor.addTile(1, origin, image.values[0], false);
        continue;
      }
      Leaf* leaf = accessor.touchLeaf(origin);
      std::memcpy(leaf->buffer().data(), image.values, sizeof image.values);
      auto& mask = leaf->getValueMask();
      for (std::size_t b = 0; b < Leaf::NUM_VALUES / 8; ++b) mask.template getWord<std::uint8_t>(b) = image.activeBits[b];
    }
  }
}

void StockGrid::leaveTable() {
  settle();
  table.reset();
}

double StockGrid::writeThroughTable(const RevolvedRegion& region, const RevolvedRegion* changes) {
  const double lost = table->write(region, false, changes);
  tableInsideVoxels -= lost;
  if (table->airVoxelCount() > kMaxAirVoxels) leaveTable();  // settling makes them air in the level set
  return lost * voxel * voxel * voxel;
}

bool StockGrid::startTable(const RevolvedRegion& bar) {
  const openvdb::CoordBBox& box = materialBounds;
  const int halfWidth = std::max({-box.min().x(), box.max().x(), -box.min().y(), box.max().y()});
  // Beyond the bar's band nothing ever changes: the bar's distance there exceeds the band,
  // and a cut never changes air.
  const double airRadius = spec.diameterMm / 2.0 + background + 2.0 * voxel;
  if ((box.max().z() - box.min().z()) / kLeafDim + 2 > RevolvedTable::kMaxChunks) return false;
  auto built = std::make_unique<RevolvedTable>(halfWidth, box.min().z(), box.max().z(), voxel, background, airRadius);
  const double added = -built->write(bar, true);
  // The table follows the profile's band, as the level set does its surface's; should it
  // still outweigh its share of the level set (a bar so short or so fine that the per-class
  // indices dominate), the level set is built now and stays the only copy.
  if (static_cast<double>(built->bytes()) > kMaxTableShareOfStock * static_cast<double>(estimatedBarBytes(spec, voxel)))
    return false;
  table = std::move(built);
  tableInsideVoxels = added;
  gridBuilt_ = false;
  return true;
}

}  // namespace lathesim::sim
