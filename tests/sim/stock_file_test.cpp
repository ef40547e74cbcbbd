// stock.vdb as other programs read it: OpenVDB's own reader finds the grid `stock` and every
// active voxel of the level set the run ended with.

#include <gtest/gtest.h>
#include <openvdb/io/File.h>
#include <openvdb/openvdb.h>

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
