// What a run leaves in --out: one run's files. The outputs an earlier run wrote there and this
// one does not write go; the user's own files stay and are named in a warning. And the '/'
// blocks a run skipped, in report.json and on the summary line.

#include <gtest/gtest.h>

#include <filesystem>
#include <nlohmann/json.hpp>
#include <set>
#include <string>
#include <vector>

#include "tests/support/lathesim_process.hpp"

namespace lathesim::app {
namespace {

namespace fs = std::filesystem;

using test::kBinary;
using test::kPartsDir;

test::ProcessOutcome lathesim(std::vector<std::string> args, const fs::path& out, const fs::path& scratch) {
  const fs::path part = kPartsDir / "g71-g70-shaft";
  std::vector<std::string> all{"run", (part / "program.nc").string(), "--setup", (part / "setup.toml").string(),
                               "--voxel", "0.5", "--out", out.string()};
  all.insert(all.end(), args.begin(), args.end());
  return test::runProcess(kBinary, all, scratch);
}

std::set<std::string> filesIn(const fs::path& folder) {
  std::set<std::string> names;
  for (const auto& entry : fs::directory_iterator(folder)) names.insert(entry.path().filename().string());
  return names;
}

TEST(OutFolder, HoldsOneRunAndLeavesTheUsersFilesListed) {
  test::ScratchDir dir("out-one-run");
  const fs::path out = dir.path() / "out";
  // Run 1: a video and the views, besides the default files.
  auto first = lathesim({"--animate", "--frames", "4", "--views", "front,section"}, out, dir.path());
  ASSERT_EQ(first.status, 0) << first.err;
  ASSERT_TRUE(fs::exists(out / "cut.mp4"));
  ASSERT_TRUE(fs::exists(out / "part-front.png"));
  test::writeFile(out / "notes.txt", "mine\n");
  fs::create_directories(out / "old");
  // Run 2: the report and the STL only.
  auto second = lathesim({"--outputs", "stl,report"}, out, dir.path());
  ASSERT_EQ(second.status, 0) << second.err;
  EXPECT_EQ(filesIn(out), (std::set<std::string>{"part.stl", "report.json", "notes.txt", "old"}));
  EXPECT_EQ(test::readFile(out / "notes.txt"), "mine\n");
  EXPECT_NE(second.err.find("holds files lathesim does not write, left as they are: notes.txt, old"),
            std::string::npos)
      << second.err;
  const auto report = nlohmann::json::parse(test::readFile(out / "report.json"));
  bool listed = false;
  for (const auto& w : report.at("warnings"))
    listed |= w.at("message").get<std::string>().find("notes.txt, old") != std::string::npos;
  EXPECT_TRUE(listed) << report.at("warnings").dump();
  // Run 3 into a folder holding only lathesim's files: no warning.
  fs::remove(out / "notes.txt");
  fs::remove(out / "old");
  auto third = lathesim({"--outputs", "report"}, out, dir.path());
  ASSERT_EQ(third.status, 0) << third.err;
  EXPECT_EQ(filesIn(out), (std::set<std::string>{"report.json"}));
  EXPECT_EQ(third.err.find("does not write"), std::string::npos) << third.err;
}

TEST(OutFolder, AFailedRunRemovesNothing) {
  test::ScratchDir dir("out-failed");
  const fs::path out = dir.path() / "out";
  ASSERT_EQ(lathesim({"--outputs", "stl,report"}, out, dir.path()).status, 0);
  const fs::path bad = dir.path() / "bad.nc";
  test::writeFile(bad, "G00 X20.3.\n");
  const auto failed = test::runProcess(kBinary, {"run", bad.string(), "--out", out.string()}, dir.path());
  ASSERT_NE(failed.status, 0);
  EXPECT_EQ(filesIn(out), (std::set<std::string>{"part.stl", "report.json"}));
}

TEST(SkippedBlocks, AreListedInTheReportAndCountedOnTheSummaryLine) {
  test::ScratchDir dir("skipped");
  const fs::path program = dir.path() / "p.nc";
  test::writeFile(program,
                  "G99 M03 S800 T0101\n"  // 1
                  "G00 X52 Z2\n"           // 2
                  "/G01 X48 F0.2\n"        // 3
                  "G01 Z-10 F0.2\n"        // 4
                  "/ G01 X60\n"            // 5: a feed out (a rapid through the bar is a crash)
                  "G00 X60 Z5\n"           // 6
                  "M30\n");
  const fs::path out = dir.path() / "out";
  const auto run = test::runProcess(kBinary, {"run", program.string(), "--stock", "D50xL60", "--voxel", "0.5",
                                              "--outputs", "report", "--out", out.string()},
                                    dir.path());
  ASSERT_EQ(run.status, 0) << run.err;
  EXPECT_NE(run.out.find(" moves, 2 blocks skipped by '/' (lines 3, 5), final volume"), std::string::npos) << run.out;
  const auto report = nlohmann::json::parse(test::readFile(out / "report.json"));
  EXPECT_EQ(report.at("skipped_blocks"),
            nlohmann::json::parse(R"([{"line": 3, "column": 1}, {"line": 5, "column": 1}])"));
  // Block skip off: nothing skipped, none listed.
  const auto all = test::runProcess(kBinary, {"run", program.string(), "--stock", "D50xL60", "--voxel", "0.5",
                                              "--block-skip", "off", "--outputs", "report", "--out", out.string()},
                                    dir.path());
  ASSERT_EQ(all.status, 0) << all.err;
  EXPECT_EQ(all.out.find("blocks skipped"), std::string::npos) << all.out;
  EXPECT_TRUE(nlohmann::json::parse(test::readFile(out / "report.json")).at("skipped_blocks").empty());
}

}  // namespace
}  // namespace lathesim::app
