// stock.vdb as other programs read it: OpenVDB's own reader finds the grid `stock` and every
// active voxel of the level set the run ended with.

#include <gtest/gtest.h>
#include <openvdb/io/File.h>
#include <openvdb/openvdb.h>

#include <cmath>
#include <filesystem>

#include "sim/stock.hpp"
#include "tests/support/lathesim_process.hpp"

namespace lathesim::sim {
namespace {

TEST(StockFile, OpenVdbReadsBackTheWholeGrid) {
  test::ScratchDir scratch("vdb");
  Stock stock(StockSpec{30.0, 20.0, 0.0}, 0.5);
  stock.remove(RevolvedRegion({ConvexPolygon::hullOf(std::vector<RZ>{{10, -5}, {20, -5}, {20, 1}, {10, 1}})}));
  const std::filesystem::path file = scratch.path() / "stock.vdb";
  stock.writeVdb(file);

  openvdb::initialize();
  openvdb::io::File in(file.string());
  in.open();
  ASSERT_TRUE(in.hasGrid("stock"));
  const openvdb::GridBase::Ptr grid = in.readGrid("stock");
  in.close();
  EXPECT_EQ(grid->activeVoxelCount(), stock.activeVoxelCount());
  EXPECT_GT(stock.activeVoxelCount(), 0u);
}

// The file holds half floats: every value read back is the stock's to within a half's
// rounding (11 significant bits), at voxel sizes where the band's values differ in scale.
TEST(StockFile, ValuesReadBackWithinAHalfsRounding) {
  openvdb::initialize();
  for (const double voxel : {0.5, 0.23, 0.1}) {
    test::ScratchDir scratch("vdb-half");
    Stock stock(StockSpec{12.0, 8.0, 0.0}, voxel);
    stock.remove(RevolvedRegion({ConvexPolygon::hullOf(std::vector<RZ>{{4, -3}, {7, -3}, {7, 1}, {4, 1}})}));
    const std::filesystem::path file = scratch.path() / "stock.vdb";
    stock.writeVdb(file);
    openvdb::io::File in(file.string());
    in.open();
    const auto grid = openvdb::gridPtrCast<openvdb::FloatGrid>(in.readGrid("stock"));
    in.close();
    ASSERT_TRUE(grid);
    EXPECT_TRUE(grid->saveFloatAsHalf());
    std::size_t compared = 0;
    for (auto v = grid->cbeginValueOn(); v; ++v, ++compared) {
      const openvdb::Vec3d p = grid->indexToWorld(v.getCoord());
      const double expected = stock.signedDistanceAt(p.x(), p.y(), p.z());
      ASSERT_NEAR(*v, expected, std::abs(expected) * std::ldexp(1.0, -11) + 1e-7) << "voxel " << voxel << " at " << p;
    }
    EXPECT_EQ(compared, stock.activeVoxelCount());
  }
}

TEST(StockFile, AFolderThatTakesNoFileIsAnErrorNamingIt) {
  test::ScratchDir scratch("vdb-missing");
  const Stock stock(StockSpec{30.0, 20.0, 0.0}, 0.5);
  const std::filesystem::path file = scratch.path() / "no-such-folder" / "stock.vdb";
  try {
    stock.writeVdb(file);
    FAIL() << "wrote into a folder that does not exist";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("cannot write " + file.string() + ": No such file or directory"),
              std::string::npos)
        << e.what();
  }
}

}  // namespace
}  // namespace lathesim::sim
