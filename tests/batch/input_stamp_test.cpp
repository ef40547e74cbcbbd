// Resuming: what changes a job's input stamp (and so runs it again), what does not, and
// which stamped results stand.

#include <gtest/gtest.h>

#include "batch/content_hash.hpp"
#include "batch/input_stamp.hpp"
#include "tests/support/lathesim_process.hpp"

namespace lathesim::batch {
namespace {

namespace fs = std::filesystem;
using test::ScratchDir;
using test::writeFile;

struct StampFixture : ::testing::Test {
  ScratchDir dir{"stamp"};
  BatchJob job;
  void SetUp() override {
    writeFile(dir.path() / "p.nc", "G0 X10 Z2\nG1 Z-5 F0.1\n");
    writeFile(dir.path() / "s.toml", "[stock]\ndiameter = 40\n");
    writeFile(dir.path() / "d.toml", "profile = []\n");
    job.name = "p";
    job.program = dir.path() / "p.nc";
    job.settings.setup = dir.path() / "s.toml";
    job.settings.drawing = dir.path() / "d.toml";
    job.settings.voxelMm = 0.25;
    job.settings.options = {"--dialect", "hnc"};
  }
  std::string stamp() const { return InputStamper("build-1").stampOf(job); }
};

TEST_F(StampFixture, AnyInputChangesIt) {
  const std::string original = stamp();
  EXPECT_EQ(stamp(), original);  // the same inputs, the same stamp
  EXPECT_NE(InputStamper("build-2").stampOf(job), original);
  const auto changed = [&](auto&& change) {
    BatchJob saved = job;
    change();
    const std::string changedStamp = stamp();
    job = saved;
    return changedStamp != original;
  };
  EXPECT_TRUE(changed([&] { writeFile(dir.path() / "p.nc", "G0 X10 Z2\nG1 Z-6 F0.1\n"); }));
  writeFile(dir.path() / "p.nc", "G0 X10 Z2\nG1 Z-5 F0.1\n");
  EXPECT_TRUE(changed([&] { writeFile(dir.path() / "s.toml", "[stock]\ndiameter = 41\n"); }));
  writeFile(dir.path() / "s.toml", "[stock]\ndiameter = 40\n");
  EXPECT_TRUE(changed([&] { writeFile(dir.path() / "d.toml", "profile = [] \n"); }));
  writeFile(dir.path() / "d.toml", "profile = []\n");
  EXPECT_EQ(stamp(), original);  // back as it was
  EXPECT_TRUE(changed([&] { job.settings.voxelMm = 0.2; }));
  EXPECT_TRUE(changed([&] { job.settings.toleranceMm = 0.1; }));
  EXPECT_TRUE(changed([&] { job.settings.options = {"--dialect", "fanuc-b"}; }));
  EXPECT_TRUE(changed([&] { job.settings.drawing.reset(); }));  // run instead of check
  EXPECT_FALSE(changed([&] { job.settings.timeLimitS = 5; }));   // not an input of the result
  EXPECT_FALSE(changed([&] { job.name = "renamed"; }));
}

TEST_F(StampFixture, MovedFilesKeepItTheirContentsDecide) {
  const std::string original = stamp();
  const fs::path moved = dir.path() / "moved";
  fs::create_directories(moved);
  for (const char* name : {"p.nc", "s.toml", "d.toml"}) fs::copy_file(dir.path() / name, moved / name);
  job.program = moved / "p.nc";
  job.settings.setup = moved / "s.toml";
  job.settings.drawing = moved / "d.toml";
  EXPECT_EQ(stamp(), original);
}

// M98 may read a subprogram from a file beside the program or in a --programs folder
// (O1234.nc and the like): such files are inputs; other files there are not.
TEST_F(StampFixture, SubprogramFilesBesideTheProgramOrInProgramsFoldersAreInputs) {
  const std::string original = stamp();
  writeFile(dir.path() / "notes.txt", "not a program");
  writeFile(dir.path() / "other-student.nc", "G0 X1");
  EXPECT_EQ(stamp(), original);
  writeFile(dir.path() / "O1234.nc", "O1234\nG1 W-2\nM99\n");
  const std::string withSubprogram = stamp();
  EXPECT_NE(withSubprogram, original);
  writeFile(dir.path() / "O1234.nc", "O1234\nG1 W-3\nM99\n");
  EXPECT_NE(stamp(), withSubprogram);
  const fs::path library = dir.path() / "library";
  fs::create_directories(library);
  job.settings.options = {"--dialect", "hnc", "--programs", library.string()};
  const std::string withLibrary = stamp();
  writeFile(library / "7615", "O7615\nM99\n");
  EXPECT_NE(stamp(), withLibrary);
  writeFile(library / "readme.md", "");
  EXPECT_EQ(stamp(), InputStamper("build-1").stampOf(job));
}

JobResult resultWith(JobStatus status, std::optional<double> timeLimitS = std::nullopt) {
  JobResult r;
  r.name = "old-name";
  r.program = "old/p.nc";
  r.command = "run";
  r.status = status;
  r.exitCode = 0;
  r.finalVolumeMm3 = 1234.5;
  r.timeLimitS = timeLimitS;
  return r;
}

TEST_F(StampFixture, AStampedResultStandsForTheSameInputs) {
  const fs::path folder = dir.path() / "out";
  fs::create_directories(folder);
  EXPECT_FALSE(stampedResult(folder, stamp(), job));  // none yet
  writeStamp(folder, stamp(), resultWith(JobStatus::Ok));
  job.index = 7;
  auto kept = stampedResult(folder, stamp(), job);
  ASSERT_TRUE(kept);
  EXPECT_TRUE(kept->resumed);
  EXPECT_EQ(kept->finalVolumeMm3, 1234.5);
  EXPECT_EQ(kept->index, 7);  // today's place, name and program
  EXPECT_EQ(kept->name, "p");
  EXPECT_EQ(kept->program, job.program.string());
  EXPECT_FALSE(stampedResult(folder, InputStamper("build-2").stampOf(job), job));
  EXPECT_FALSE(fs::exists(folder / "batch-stamp.json.tmp"));
}

TEST_F(StampFixture, CrashesAndOtherTimeLimitsRunAgain) {
  const fs::path folder = dir.path() / "out";
  fs::create_directories(folder);
  for (JobStatus status : {JobStatus::Failed, JobStatus::OutOfTolerance}) {
    writeStamp(folder, stamp(), resultWith(status));
    EXPECT_TRUE(stampedResult(folder, stamp(), job)) << statusName(status);
  }
  writeStamp(folder, stamp(), resultWith(JobStatus::Crashed));
  EXPECT_FALSE(stampedResult(folder, stamp(), job));
  job.settings.timeLimitS = 5;
  writeStamp(folder, stamp(), resultWith(JobStatus::Timeout, 5.0));
  EXPECT_TRUE(stampedResult(folder, stamp(), job));
  job.settings.timeLimitS = 50;
  EXPECT_FALSE(stampedResult(folder, stamp(), job));
  writeFile(folder / "batch-stamp.json", "{\"inputs\": \"" + stamp() + "\", \"result\": {\"index\": ");
  EXPECT_FALSE(stampedResult(folder, stamp(), job));  // damaged: run again
}

TEST(ContentHash, PartsDoNotRunTogetherAndFilesHashTheirBytes) {
  EXPECT_NE(ContentHash().add("ab").add("c").hex(), ContentHash().add("a").add("bc").hex());
  EXPECT_EQ(ContentHash().add("abc").hex(), ContentHash().add("abc").hex());
  EXPECT_EQ(ContentHash().hex().size(), 16u);
  ScratchDir dir("hash");
  std::string big(200000, 'x');  // across several read chunks
  writeFile(dir.path() / "a", big);
  writeFile(dir.path() / "b", big);
  EXPECT_EQ(fileHash(dir.path() / "a"), fileHash(dir.path() / "b"));
  big[150000] = 'y';
  writeFile(dir.path() / "b", big);
  EXPECT_NE(fileHash(dir.path() / "a"), fileHash(dir.path() / "b"));
  EXPECT_FALSE(fileHash(dir.path() / "missing"));
  EXPECT_FALSE(fileHash(dir.path()));  // a folder is not a file
}

}  // namespace
}  // namespace lathesim::batch
