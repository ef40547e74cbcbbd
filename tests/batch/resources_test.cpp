// How many jobs may run at once: slots and memory, and each job's memory estimate.

#include <gtest/gtest.h>

#include <cstdlib>

#include "batch/build_id.hpp"
#include "batch/resources.hpp"
#include "setup/setup.hpp"
#include "sim/stock.hpp"
#include "tests/support/lathesim_process.hpp"

namespace lathesim::batch {
namespace {

namespace fs = std::filesystem;
using test::ScratchDir;
using test::writeFile;

constexpr std::uint64_t MB = 1 << 20;

TEST(MayStart, ASlotAndRoomInTheBudget) {
  EXPECT_TRUE(mayStart(0, 0, 300 * MB, 2, 1000 * MB));
  EXPECT_TRUE(mayStart(1, 600 * MB, 400 * MB, 2, 1000 * MB));   // exactly fills it
  EXPECT_FALSE(mayStart(1, 600 * MB, 401 * MB, 2, 1000 * MB));  // a megabyte over
  EXPECT_FALSE(mayStart(2, 200 * MB, 100 * MB, 2, 1000 * MB));  // no slot
  EXPECT_TRUE(mayStart(0, 0, 5000 * MB, 2, 1000 * MB));         // alone, however big
  EXPECT_TRUE(mayStart(3, 9000 * MB, 9000 * MB, 4, std::nullopt));  // memory unknown: slots alone
}

// The estimate is the process base plus the level set sim/ expects for the job's stock and
// voxel, read from its setup, its own voxel over the setup's over the default.
TEST(EstimatedJobBytes, FromTheSetupsStockAndTheVoxel) {
  ScratchDir dir("estimate");
  writeFile(dir.path() / "s.toml", "[stock]\ndiameter = 60\nlength = 80\nface_z = 0\n[sim]\nvoxel = 0.25\n");
  BatchJob job;
  job.program = "p.nc";
  job.settings.setup = dir.path() / "s.toml";
  const sim::StockSpec bar{60, 80, 0};
  EXPECT_EQ(estimatedJobBytes(job), kProcessBaseBytes + sim::estimatedStockBytes(bar, 0.25));
  job.settings.voxelMm = 0.1;
  EXPECT_EQ(estimatedJobBytes(job), kProcessBaseBytes + sim::estimatedStockBytes(bar, 0.1));
  // Halving the voxel quadruples the level set (its surface voxels).
  const double ratio = static_cast<double>(sim::estimatedStockBytes(bar, 0.05)) /
                       static_cast<double>(sim::estimatedStockBytes(bar, 0.1));
  EXPECT_NEAR(ratio, 4.0, 1e-6);
  job.settings.setup.reset();  // the default setup, the default voxel
  job.settings.voxelMm.reset();
  EXPECT_EQ(estimatedJobBytes(job), kProcessBaseBytes + sim::estimatedStockBytes(lathesim::setup::defaultSetup().stock, 0.2));
  job.settings.setup = dir.path() / "missing.toml";  // fails fast: the base alone
  EXPECT_EQ(estimatedJobBytes(job), kProcessBaseBytes);
}

// The bar is chosen as `run` chooses it: --stock, else the setup's [stock], else the bar the
// program states (a billet line), else the default setup's.
TEST(EstimatedJobBytes, TheBarRunWouldSimulate) {
  ScratchDir dir("estimate-bar");
  writeFile(dir.path() / "stated.nc", "[BILLET X56 Z84\nG0 X60 Z2\n");
  writeFile(dir.path() / "plain.nc", "G0 X60 Z2\n");
  writeFile(dir.path() / "with-stock.toml", "[stock]\ndiameter = 30\nlength = 40\nface_z = 0\n");
  writeFile(dir.path() / "no-stock.toml", "[sim]\nvoxel = 0.25\n");
  const auto bytes = [](double diameter, double length, double voxel) {
    return kProcessBaseBytes + sim::estimatedStockBytes({diameter, length, 0}, voxel);
  };
  BatchJob job;
  job.program = dir.path() / "stated.nc";
  job.settings.setup = dir.path() / "no-stock.toml";
  EXPECT_EQ(estimatedJobBytes(job), bytes(56, 84, 0.25));  // the program's billet line
  job.settings.setup = dir.path() / "with-stock.toml";
  EXPECT_EQ(estimatedJobBytes(job), bytes(30, 40, 0.2));  // the setup's [stock] over it
  job.settings.options = {"--stock", "D80xL100"};
  EXPECT_EQ(estimatedJobBytes(job), bytes(80, 100, 0.2));  // --stock over both
  job.settings.options = {"--stock=D80xL100xZ3"};
  EXPECT_EQ(estimatedJobBytes(job), bytes(80, 100, 0.2));
  job.settings.options = {"--stock", "D80"};  // unreadable: the job stops at once
  EXPECT_EQ(estimatedJobBytes(job), kProcessBaseBytes);
  job.settings.options.clear();
  job.program = dir.path() / "plain.nc";
  job.settings.setup = dir.path() / "no-stock.toml";
  const sim::StockSpec fallback = lathesim::setup::defaultSetup().stock;
  EXPECT_EQ(estimatedJobBytes(job), bytes(fallback.diameterMm, fallback.lengthMm, 0.25));
}

TEST(Resources, CpusAndMemoryUnderSlurmLimits) {
  const int cpus = availableCpus();
  EXPECT_GE(cpus, 1);
  const auto memory = availableMemoryBytes();
  ASSERT_TRUE(memory);
  ::setenv("SLURM_CPUS_ON_NODE", "1", 1);
  ::setenv("SLURM_MEM_PER_NODE", "100", 1);  // MB
  EXPECT_EQ(availableCpus(), 1);
  EXPECT_EQ(availableMemoryBytes(), 100 * MB);
  ::setenv("SLURM_CPUS_ON_NODE", "4096", 1);  // more than the machine has: the machine's
  EXPECT_EQ(availableCpus(), cpus);
  ::unsetenv("SLURM_CPUS_ON_NODE");
  ::unsetenv("SLURM_MEM_PER_NODE");
}

/// The build ID as binutils' readelf prints it: an independent reading of the same note.
std::string readelfBuildId(const fs::path& binary) {
  const std::string command = "readelf -n '" + binary.string() + "' 2>/dev/null";
  FILE* pipe = ::popen(command.c_str(), "r");
  std::string text;
  char buffer[512];
  while (pipe && std::fgets(buffer, sizeof buffer, pipe)) text += buffer;
  if (pipe) ::pclose(pipe);
  const auto at = text.find("Build ID: ");
  return at == std::string::npos ? "" : text.substr(at + 10, text.find('\n', at) - at - 10);
}

TEST(BuildId, TheLinkersNoteOrTheFilesHash) {
  const fs::path binary = LATHESIM_BINARY;
  const std::string expected = readelfBuildId(binary);
  if (expected.empty()) GTEST_SKIP() << "readelf (binutils) is not installed";
  EXPECT_EQ(buildIdOf(binary), expected);
  ScratchDir dir("build-id");
  writeFile(dir.path() / "script", "#!/bin/sh\n");
  EXPECT_EQ(buildIdOf(dir.path() / "script").substr(0, 5), "file-");
  EXPECT_THROW(buildIdOf(dir.path() / "missing"), std::runtime_error);
}

}  // namespace
}  // namespace lathesim::batch
