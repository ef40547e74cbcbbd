// `lathesim batch` as a user runs it: a batch mixing good programs, a program that alarms,
// one that is missing, one past its time limit and parts checked in and out of tolerance;
// every row of its summary against the parts' hand-worked figures; the exit status; resuming
// without running a finished job again (after Ctrl-C and after a kill); shards merged into the
// same summary; and the summary page in a real browser.

#include <gtest/gtest.h>

#include <signal.h>
#include <sys/stat.h>
#include <sys/wait.h>

#include <chrono>
#include <cmath>
#include <map>
#include <nlohmann/json.hpp>
#include <regex>
#include <set>
#include <thread>
#include <toml++/toml.h>

#include "batch/child_process.hpp"
#include "setup/setup.hpp"
#include "tests/render/png_pixels.hpp"
#include "tests/support/headless_chromium.hpp"
#include "tests/support/lathesim_process.hpp"
#include "tests/support/processes.hpp"
#include "tests/support/volume_tolerance.hpp"

namespace lathesim::batch {
namespace {

namespace fs = std::filesystem;
using Json = nlohmann::json;
using test::readFile;
using test::lathesim;
using test::ScratchDir;
using test::writeFile;

const fs::path kBinary = LATHESIM_BINARY;
const fs::path kPartsDir = LATHESIM_PARTS_DIR;
constexpr double kVoxelMm = 0.5;

std::string part(const std::string& name, const std::string& file) { return (kPartsDir / name / file).string(); }

/// A [[job]] of the manifest for a bundled part.
std::string partJob(const std::string& name, const std::string& partName, const std::string& more = "") {
  return "[[job]]\nname = \"" + name + "\"\nprogram = \"" + part(partName, "program.nc") + "\"\nsetup = \"" +
         part(partName, "setup.toml") + "\"\n" + more + "\n";
}

Json jsonFile(const fs::path& file) { return Json::parse(readFile(file)); }

/// The summary's rows by job name.
std::map<std::string, Json> rowsByName(const Json& summary) {
  std::map<std::string, Json> rows;
  for (const auto& row : summary.at("jobs")) rows[row.at("name").get<std::string>()] = row;
  return rows;
}

struct PartFigures {
  double finalVolumeMm3 = 0, removedVolumeMm3 = 0, toleranceMm3 = 0;
  std::optional<double> cycleTimeS;
  std::string diagnostic;
};

/// What parts/NAME/expected.toml works out by hand, and the volume tolerance at kVoxelMm.
PartFigures expectedOf(const std::string& partName) {
  const toml::table table = toml::parse_file(part(partName, "expected.toml"));
  PartFigures figures;
  figures.finalVolumeMm3 = table["final_volume_mm3"].value_or(0.0);
  figures.removedVolumeMm3 = table["removed_volume_mm3"].value_or(0.0);
  figures.cycleTimeS = table["cycle_time_s"].value<double>();
  figures.diagnostic = table["diagnostic"].value_or(std::string());
  const auto setup = setup::loadSetup(part(partName, "setup.toml")).setup;
  figures.toleranceMm3 = setup ? test::volumeToleranceMm3(setup->stock, kVoxelMm) : 0;
  return figures;
}

struct FileIdentity {
  ino_t inode = 0;
  std::int64_t modifiedNs = 0;
  bool operator==(const FileIdentity&) const = default;
};

/// Which file is at `file` and when it was written: a job run again writes a new one.
FileIdentity identityOf(const fs::path& file) {
  struct stat st {};
  if (::stat(file.c_str(), &st) != 0) return {};
  return {st.st_ino, static_cast<std::int64_t>(st.st_mtim.tv_sec) * 1000000000 + st.st_mtim.tv_nsec};
}

// ---------------------------------------------------------------------------------------
// The mixed batch, run once for the tests that read it.

class MixedBatch : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    dir_ = new ScratchDir("batch-mixed");
    const std::string drawing = "drawing = \"" + part("seed001-taper-r20", "drawing.toml") + "\"\ntolerance = 0.5\n";
    const std::string drawing24 = "drawing = \"" + part("seed001-taper-r24", "drawing.toml") + "\"\ntolerance = 0.5\n";
    writeFile(dir_->path() / "batch.toml",
              "[defaults]\nvoxel = 0.5\n\n" + partJob("arc-fillet", "arc-fillet") + partJob("g74-drill", "g74-drill") +
                  partJob("alarm", "seed004-o0006") +
                  // Seed 000 at 0.1 mm takes over ten seconds (README); one is all it gets.
                  partJob("too-slow", "seed000-face-taper", "voxel = 0.1\ntime_limit = 1") +
                  partJob("taper-r20", "seed001-taper-r20", drawing) + partJob("taper-r24", "seed001-taper-r24", drawing24) +
                  "[[job]]\nname = \"missing\"\nprogram = \"nowhere.nc\"\n");
    first_ = new test::ProcessOutcome(run({}));
    summary_ = new Json(jsonFile(out() / "summary.json"));
  }
  static void TearDownTestSuite() {
    delete summary_;
    delete first_;
    delete dir_;
  }
  static fs::path out() { return dir_->path() / "out"; }
  static test::ProcessOutcome run(std::vector<std::string> extra, const std::string& manifest = "batch.toml") {
    std::vector<std::string> args{"batch", (dir_->path() / manifest).string(), "--out", out().string(), "--jobs", "2"};
    args.insert(args.end(), extra.begin(), extra.end());
    return lathesim(args, dir_->path());
  }

  static ScratchDir* dir_;
  static test::ProcessOutcome* first_;
  static Json* summary_;
};
ScratchDir* MixedBatch::dir_ = nullptr;
test::ProcessOutcome* MixedBatch::first_ = nullptr;
Json* MixedBatch::summary_ = nullptr;

TEST_F(MixedBatch, ExitsOneWithEveryJobCounted) {
  EXPECT_EQ(first_->status, 1) << first_->out << first_->err;
  const Json& s = *summary_;
  EXPECT_EQ(s.at("exit_status"), 1);
  EXPECT_EQ(s.at("jobs_in_batch"), 7);
  EXPECT_EQ(s.at("counts"),
            Json::parse(R"({"ok": 3, "out_of_tolerance": 1, "collision": 0, "failed": 2, "timeout": 1, "crashed": 0, "not_run": 0})"));
  std::vector<std::string> names;
  for (const auto& row : s.at("jobs")) names.push_back(row.at("name"));
  EXPECT_EQ(names, (std::vector<std::string>{"arc-fillet", "g74-drill", "alarm", "too-slow", "taper-r20", "taper-r24",
                                              "missing"}));  // manifest order, whatever order they ran in
  for (int i = 0; i < 7; ++i) EXPECT_EQ(s.at("jobs")[i].at("index"), i + 1);
  EXPECT_NE(first_->out.find("3 ok, 1 out of tolerance, 2 failed, 1 timeout"), std::string::npos) << first_->out;
}

TEST_F(MixedBatch, GoodProgramsHaveTheirHandWorkedVolumesAndTimes) {
  const auto rows = rowsByName(*summary_);
  for (const auto& [name, partName] : {std::pair{"arc-fillet", "arc-fillet"}, std::pair{"g74-drill", "g74-drill"}}) {
    SCOPED_TRACE(name);
    const Json& row = rows.at(name);
    const PartFigures expected = expectedOf(partName);
    EXPECT_EQ(row.at("status"), "ok");
    EXPECT_EQ(row.at("command"), "run");
    EXPECT_EQ(row.at("exit_code"), 0);
    EXPECT_NEAR(row.at("final_volume_mm3").get<double>(), expected.finalVolumeMm3, expected.toleranceMm3);
    EXPECT_NEAR(row.at("removed_volume_mm3").get<double>(), expected.removedVolumeMm3, expected.toleranceMm3);
    ASSERT_TRUE(expected.cycleTimeS);
    EXPECT_NEAR(row.at("cycle_time_s").get<double>(), *expected.cycleTimeS, 0.005 * *expected.cycleTimeS);
    EXPECT_EQ(row.at("collisions"), Json::array());
    EXPECT_TRUE(row.at("check").is_null());
    // The row is the job's own report.json, and its warnings (none for these parts).
    const Json report = jsonFile(out() / name / "report.json");
    EXPECT_EQ(row.at("final_volume_mm3"), report.at("final_volume_mm3"));
    EXPECT_EQ(report.at("voxel_mm"), kVoxelMm);
    EXPECT_EQ(row.at("warnings"), report.at("warnings").size());
    EXPECT_TRUE(row.at("message").is_null());
    EXPECT_EQ(row.at("folder"), name);
    EXPECT_EQ(row.at("thumbnail"), "thumbnail.png");
    const render::test::Png thumbnail(out() / name / "thumbnail.png");
    EXPECT_EQ(thumbnail.width(), 1600 / 7);  // part.png (1600×1200) in 7×7 blocks
    EXPECT_EQ(thumbnail.height(), 1200 / 7);
    EXPECT_GT(row.at("elapsed_s").get<double>(), 0.0);
    EXPECT_FALSE(row.at("resumed").get<bool>());
    for (const char* file : {"part.stl", "part.png", "toolpath.csv", "stock.vdb", "lathesim.log", "batch-stamp.json"})
      EXPECT_TRUE(fs::exists(out() / name / file)) << file;
  }
}

TEST_F(MixedBatch, TheAlarmAndTheMissingProgramFailAloneWithTheirReason) {
  const auto rows = rowsByName(*summary_);
  const Json& alarm = rows.at("alarm");
  EXPECT_EQ(alarm.at("status"), "failed");
  EXPECT_EQ(alarm.at("exit_code"), 1);
  // parts/seed004-o0006/expected.toml: "program.nc:5:21: error: <message>".
  const std::string diagnostic = expectedOf("seed004-o0006").diagnostic;
  const std::string prefix = "program.nc:5:21: error: ";
  ASSERT_EQ(diagnostic.rfind(prefix, 0), 0u) << diagnostic;
  EXPECT_EQ(alarm.at("message").at("kind"), "error");
  EXPECT_EQ(alarm.at("message").at("file"), part("seed004-o0006", "program.nc"));
  EXPECT_EQ(alarm.at("message").at("line"), 5);
  EXPECT_EQ(alarm.at("message").at("column"), 21);
  EXPECT_EQ(alarm.at("message").at("text"), diagnostic.substr(prefix.size()));
  EXPECT_TRUE(alarm.at("final_volume_mm3").is_null());
  EXPECT_TRUE(alarm.at("thumbnail").is_null());
  EXPECT_FALSE(fs::exists(out() / "alarm" / "report.json"));  // a bad program writes nothing
  EXPECT_NE(readFile(out() / "alarm" / "lathesim.log").find("5:21: error"), std::string::npos);
  const Json& missing = rows.at("missing");
  EXPECT_EQ(missing.at("status"), "failed");
  EXPECT_NE(missing.at("exit_code"), 0);
  EXPECT_NE(missing.at("message").at("text").get<std::string>().find("nowhere.nc"), std::string::npos)
      << missing.at("message");
}

TEST_F(MixedBatch, TheSlowJobIsStoppedAtItsLimitAndLeavesNothingHalfWritten) {
  const Json row = rowsByName(*summary_).at("too-slow");
  EXPECT_EQ(row.at("status"), "timeout");
  EXPECT_TRUE(row.at("exit_code").is_null());
  EXPECT_EQ(row.at("signal"), SIGKILL);
  EXPECT_EQ(row.at("time_limit_s"), 1.0);
  EXPECT_EQ(row.at("message").at("text"), "stopped at the time limit of 1 s");
  EXPECT_GE(row.at("elapsed_s").get<double>(), 1.0);
  EXPECT_LT(row.at("elapsed_s").get<double>(), 5.0);
  std::set<std::string> files;
  for (const auto& entry : fs::directory_iterator(out() / "too-slow")) files.insert(entry.path().filename().string());
  EXPECT_EQ(files, (std::set<std::string>{"lathesim.log", "batch-stamp.json"}));
  EXPECT_EQ(test::processesMentioning(out().string()), std::vector<std::string>{});
}

// Seed 001: R-24 cuts the drawn cone, R-20 leaves 2√5/3 mm of excess at (Ø50, Z−50/3)
// (worked by hand in tests/app/check_cli_test.cpp).
TEST_F(MixedBatch, CheckedPartsCarryTheirDeviationAgainstTheDrawing) {
  const auto rows = rowsByName(*summary_);
  const Json& r20 = rows.at("taper-r20");
  EXPECT_EQ(r20.at("status"), "out_of_tolerance");
  EXPECT_EQ(r20.at("command"), "check");
  EXPECT_EQ(r20.at("exit_code"), 3);
  EXPECT_EQ(r20.at("check").at("tolerance_mm"), 0.5);
  EXPECT_EQ(r20.at("check").at("within_tolerance"), false);
  EXPECT_NEAR(r20.at("check").at("max_excess_mm").get<double>(), 2 * std::sqrt(5.0) / 3, kVoxelMm / 2);
  EXPECT_LT(r20.at("check").at("max_gouge_mm").get<double>(), kVoxelMm / 2);
  const PartFigures expected20 = expectedOf("seed001-taper-r20");
  EXPECT_NEAR(r20.at("final_volume_mm3").get<double>(), expected20.finalVolumeMm3, expected20.toleranceMm3);
  const Json& r24 = rows.at("taper-r24");
  EXPECT_EQ(r24.at("status"), "ok");
  EXPECT_EQ(r24.at("exit_code"), 0);
  EXPECT_EQ(r24.at("check").at("within_tolerance"), true);
  EXPECT_LT(r24.at("check").at("max_excess_mm").get<double>(), kVoxelMm / 2);
  EXPECT_LT(r24.at("check").at("max_gouge_mm").get<double>(), kVoxelMm / 2);
  // A checked part's thumbnail is of its deviation picture (same size as part.png).
  for (const char* name : {"taper-r20", "taper-r24"}) {
    EXPECT_TRUE(fs::exists(out() / name / "deviation.png")) << name;
    EXPECT_EQ(rows.at(name).at("thumbnail"), "thumbnail.png");
  }
  // Seed 001's programs start the spindle (parts/README.md) and warn of nothing: no message.
  const Json report = jsonFile(out() / "taper-r20" / "report.json");
  EXPECT_TRUE(report.at("warnings").empty());
  EXPECT_TRUE(r20.at("message").is_null());
}

TEST_F(MixedBatch, CsvHasOneLinePerJobInManifestOrder) {
  std::istringstream csv(readFile(out() / "summary.csv"));
  std::string line;
  std::getline(csv, line);
  EXPECT_EQ(line.substr(0, 30), "index,name,status,exit_code,pr");
  std::vector<std::string> starts;
  while (std::getline(csv, line)) starts.push_back(line.substr(0, line.find(',', line.find(',', line.find(',') + 1) + 1)));
  EXPECT_EQ(starts, (std::vector<std::string>{"1,arc-fillet,ok", "2,g74-drill,ok", "3,alarm,failed", "4,too-slow,timeout",
                                              "5,taper-r20,out_of_tolerance", "6,taper-r24,ok", "7,missing,failed"}));
}

Json withoutResumed(Json summary) {
  for (auto& row : summary.at("jobs")) row.erase("resumed");
  return summary;
}

TEST_F(MixedBatch, RunAgainNothingIsRedoneAndSubsetsGiveTheirOwnExitStatus) {
  std::map<std::string, FileIdentity> before;
  for (const auto& [name, row] : rowsByName(*summary_)) before[name] = identityOf(out() / name / "batch-stamp.json");
  const test::ProcessOutcome again = run({});
  EXPECT_EQ(again.status, 1) << again.out << again.err;
  EXPECT_NE(again.out.find("7 jobs, 7 up to date from an earlier run"), std::string::npos) << again.out;
  const Json resumed = jsonFile(out() / "summary.json");
  for (const auto& row : resumed.at("jobs")) EXPECT_TRUE(row.at("resumed").get<bool>()) << row.at("name");
  EXPECT_EQ(withoutResumed(resumed), withoutResumed(*summary_));
  for (const auto& [name, identity] : before) EXPECT_EQ(identityOf(out() / name / "batch-stamp.json"), identity) << name;

  // The same jobs in other manifests: their results stand, the exit status is the subset's.
  writeFile(dir_->path() / "tolerance.toml", "[defaults]\nvoxel = 0.5\n" + partJob("arc-fillet", "arc-fillet") +
                                                 partJob("taper-r20", "seed001-taper-r20",
                                                         "drawing = \"" + part("seed001-taper-r20", "drawing.toml") +
                                                             "\"\ntolerance = 0.5"));
  EXPECT_EQ(run({}, "tolerance.toml").status, 3);
  writeFile(dir_->path() / "good.toml",
            "[defaults]\nvoxel = 0.5\n" + partJob("arc-fillet", "arc-fillet") + partJob("g74-drill", "g74-drill"));
  const test::ProcessOutcome good = run({}, "good.toml");
  EXPECT_EQ(good.status, 0) << good.out;
  EXPECT_NE(good.out.find("2 jobs, 2 up to date"), std::string::npos) << good.out;
  for (const auto& [name, identity] : before) EXPECT_EQ(identityOf(out() / name / "batch-stamp.json"), identity) << name;
  run({});  // the whole batch's summary back, for the tests after this one
}

TEST_F(MixedBatch, ShardsMergedAreTheWholeBatch) {
  std::vector<std::string> files;
  for (int i = 1; i <= 3; ++i) {
    const std::string shard = std::to_string(i) + "/3";
    const test::ProcessOutcome outcome = run({"--shard", shard});
    EXPECT_NE(outcome.status, 0) << shard;  // each holds a failed or timed-out job
    files.push_back((out() / ("summary-" + std::to_string(i) + "-of-3.json")).string());
    const Json part = jsonFile(files.back());
    for (const auto& row : part.at("jobs")) EXPECT_EQ((row.at("index").get<int>() - 1) % 3, i - 1);
  }
  const fs::path merged = dir_->path() / "merged";
  std::vector<std::string> args{"batch", "merge"};
  args.insert(args.end(), files.begin(), files.end());
  args.insert(args.end(), {"--out", merged.string()});
  const test::ProcessOutcome outcome = lathesim(args, dir_->path());
  EXPECT_EQ(outcome.status, 1) << outcome.out << outcome.err;
  Json whole = withoutResumed(*summary_);
  for (auto& row : whole.at("jobs")) row["folder"] = "../out/" + row.at("folder").get<std::string>();
  EXPECT_EQ(withoutResumed(jsonFile(merged / "summary.json")), whole);
}

// ---------------------------------------------------------------------------------------
// The summary page in headless Chromium (Debian's; scripts/packages.txt installs it).

using test::BrowserRun;
using test::kChromium;
using test::openInChromium;

TEST_F(MixedBatch, SummaryPageOpensInChromiumWithoutConsoleErrors) {
  if (!fs::exists(kChromium)) GTEST_SKIP() << "chromium is not installed (scripts/setup.sh installs it)";
  ScratchDir browser("chromium");
  // The console is read from Chromium's log: a page with an error must show up there.
  writeFile(browser.path() / "bad.html", "<!DOCTYPE html><p>x</p><script>undefinedFunction();</script>");
  const BrowserRun control = openInChromium(browser, "file://" + (browser.path() / "bad.html").string(), {"--dump-dom"});
  ASSERT_EQ(control.consoleLines.size(), 1u) << control.outcome.err;
  EXPECT_NE(control.consoleLines[0].find("undefinedFunction is not defined"), std::string::npos);

  const fs::path shot = browser.path() / "summary.png";
  const std::string page = "file://" + (out() / "summary.html").string();
  const BrowserRun opened = openInChromium(browser, page, {"--screenshot=" + shot.string()});
  EXPECT_TRUE(opened.consoleLines.empty()) << opened.outcome.err;
  ASSERT_TRUE(fs::exists(shot)) << opened.outcome.err;
  const render::test::Png png(shot);
  ASSERT_EQ(png.width(), 1400);
  ASSERT_EQ(png.height(), 1000);
  // The status badges in their colours (style in summary_html.cpp): three ok, one out of
  // tolerance, three failed or timed out — each badge some hundreds of pixels.
  const auto near = [](const render::test::PngColour& c, int r, int g, int b) {
    return std::abs(c.r - r) < 12 && std::abs(c.g - g) < 12 && std::abs(c.b - b) < 12;
  };
  const int green = png.count(0, 1400, 0, 1000, [&](auto c) { return near(c, 0x1e, 0x8e, 0x3e); });
  const int orange = png.count(0, 1400, 0, 1000, [&](auto c) { return near(c, 0xe3, 0x74, 0x00); });
  const int red = png.count(0, 1400, 0, 1000, [&](auto c) { return near(c, 0xc5, 0x22, 0x1f); });
  EXPECT_GT(green, 3 * 150);
  EXPECT_GT(orange, 150);
  EXPECT_GT(red, 150);  // the rows below the fold may hide some
  // The thumbnails are drawn: the part column (x 55–215 at this width, the first row's
  // picture from y 105 to its 160×120 end) is mostly picture, not white page with text.
  const int top = 1000 - 240, bottom = 1000 - 110;  // PNG rows count from the bottom
  const int painted = png.count(60, 210, top, bottom, [](auto c) { return c.r + c.g + c.b < 3 * 245; });
  EXPECT_GT(painted, 150 * (bottom - top) / 2) << "of " << 150 * (bottom - top);
}

TEST_F(MixedBatch, SummaryPageSortsByTheColumnInItsAddress) {
  if (!fs::exists(kChromium)) GTEST_SKIP() << "chromium is not installed (scripts/setup.sh installs it)";
  ScratchDir browser("chromium-sort");
  const std::string page = "file://" + (out() / "summary.html").string() + "#sort=-removed_volume_mm3";
  const BrowserRun sorted = openInChromium(browser, page, {"--dump-dom"});
  EXPECT_TRUE(sorted.consoleLines.empty()) << sorted.outcome.err;
  std::vector<int> shown;
  const std::regex rowStart("<tr><td class=\"num\" data-value=\"(\\d+)\">");
  for (std::sregex_iterator m(sorted.outcome.out.begin(), sorted.outcome.out.end(), rowStart), end; m != end; ++m)
    shown.push_back(std::stoi((*m)[1]));
  // Worked out from summary.json: removed volume, largest first, jobs without one last in
  // manifest order.
  std::vector<std::pair<double, int>> withVolume;
  std::vector<int> without;
  for (const auto& row : summary_->at("jobs")) {
    if (row.at("removed_volume_mm3").is_null()) without.push_back(row.at("index"));
    else withVolume.emplace_back(-row.at("removed_volume_mm3").get<double>(), row.at("index").get<int>());
  }
  std::sort(withVolume.begin(), withVolume.end());
  std::vector<int> expected;
  for (const auto& [volume, index] : withVolume) expected.push_back(index);
  expected.insert(expected.end(), without.begin(), without.end());
  EXPECT_EQ(shown, expected);
  EXPECT_NE(sorted.outcome.out.find("data-key=\"removed_volume_mm3\" data-type=\"number\" tabindex=\"0\" aria-sort=\"descending\""),
            std::string::npos);
}

// ---------------------------------------------------------------------------------------
// Stopped and resumed: Ctrl-C, then a kill, then to the end — each job run once in all.

/// Waits until `count` jobs of the batch in `out` have stamped their result; their names.
std::set<std::string> waitForStamps(const fs::path& out, std::size_t count, std::chrono::seconds timeout) {
  const auto deadline = std::chrono::steady_clock::now() + timeout;
  for (;;) {
    std::set<std::string> stamped;
    std::error_code ec;
    for (const auto& entry : fs::directory_iterator(out, ec))
      if (fs::exists(entry.path() / "batch-stamp.json")) stamped.insert(entry.path().filename().string());
    if (stamped.size() >= count || std::chrono::steady_clock::now() >= deadline) return stamped;
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
  }
}

// A program that crashes (parts/dogleg-groove-retract: its retract's dog-leg runs into the
// groove's wall on line 8) is counted as a collision, apart from failures; its outputs are
// written, and the batch exits 4.
TEST(BatchCollision, ACrashIsCountedApartAndTheBatchExitsFour) {
  ScratchDir dir("batch-crash");
  writeFile(dir.path() / "batch.toml",
            "[defaults]\nvoxel = 0.5\n\n" + partJob("dogleg", "dogleg-groove-retract") + partJob("arc-fillet", "arc-fillet"));
  const fs::path out = dir.path() / "out";
  const auto outcome = lathesim({"batch", (dir.path() / "batch.toml").string(), "--out", out.string()}, dir.path());
  EXPECT_EQ(outcome.status, 4) << outcome.out << outcome.err;
  const Json summary = jsonFile(out / "summary.json");
  EXPECT_EQ(summary.at("exit_status"), 4);
  EXPECT_EQ(summary.at("counts").at("collision"), 1);
  EXPECT_EQ(summary.at("counts").at("ok"), 1);
  EXPECT_EQ(summary.at("counts").at("failed"), 0);
  auto rows = rowsByName(summary);
  const Json& crash = rows.at("dogleg");
  EXPECT_EQ(crash.at("status"), "collision");
  EXPECT_EQ(crash.at("exit_code"), 4);
  ASSERT_EQ(crash.at("collisions").size(), 1u);
  EXPECT_EQ(crash.at("collisions")[0].at("line"), 8);
  EXPECT_EQ(crash.at("message").at("line"), 8);
  EXPECT_NE(crash.at("message").at("text").get<std::string>().find("rapid into the stock removes"), std::string::npos);
  EXPECT_NE(outcome.out.find("1 ok, 1 collision"), std::string::npos) << outcome.out;
}

TEST(BatchInterrupted, ResumesWithoutRedoingFinishedJobs) {
  ScratchDir dir("batch-resume");
  const fs::path out = dir.path() / "out";
  writeFile(dir.path() / "batch.toml", "[defaults]\nvoxel = 0.5\n" + partJob("a", "arc-fillet") +
                                           partJob("b", "g74-drill") + partJob("c", "nose-comp-g42") +
                                           partJob("d", "seed004-o0003"));
  const std::vector<std::string> args{"batch", (dir.path() / "batch.toml").string(), "--out", out.string(), "--jobs", "1"};
  std::map<std::string, FileIdentity> firstWritten;  // each job's report.json when it first ran
  const auto remember = [&](const std::set<std::string>& stamped) {
    for (const auto& name : stamped)
      if (!firstWritten.count(name)) firstWritten[name] = identityOf(out / name / "report.json");
  };

  // Ctrl-C after the first job: the batch stops its running job and writes the summary.
  ChildProcess batch = ChildProcess::start(kBinary, args, dir.path() / "first.log");
  std::set<std::string> stamped = waitForStamps(out, 1, std::chrono::seconds(60));
  ASSERT_EQ(stamped.size(), 1u);
  ::kill(batch.pid(), SIGINT);
  int status = batch.wait();
  ASSERT_TRUE(WIFEXITED(status)) << readFile(dir.path() / "first.log");
  EXPECT_EQ(WEXITSTATUS(status), 128 + SIGINT);
  stamped = waitForStamps(out, 1, std::chrono::seconds(0));  // one may have finished meanwhile
  remember(stamped);
  EXPECT_EQ(test::processesLeftMentioning(out.string(), std::chrono::seconds(5)), std::vector<std::string>{});
  const Json interrupted = jsonFile(out / "summary.json");
  int notRun = 0;
  for (const auto& row : interrupted.at("jobs")) {
    const std::string name = row.at("name");
    if (stamped.count(name)) {
      EXPECT_EQ(row.at("status"), "ok") << name;
      continue;
    }
    EXPECT_EQ(row.at("status"), "not_run") << name;
    ++notRun;
    std::error_code none;  // a job never started has no folder; a stopped one its log alone
    for (const auto& entry : fs::directory_iterator(out / name, none))
      EXPECT_EQ(entry.path().filename(), "lathesim.log") << name;
  }
  EXPECT_EQ(notRun, 4 - static_cast<int>(stamped.size()));
  EXPECT_EQ(interrupted.at("exit_status"), 1);

  // A kill (a node lost): nothing of the batch may go on running.
  batch = ChildProcess::start(kBinary, args, dir.path() / "second.log");
  std::set<std::string> more = waitForStamps(out, stamped.size() + 1, std::chrono::seconds(60));
  ASSERT_GT(more.size(), stamped.size());
  ::kill(batch.pid(), SIGKILL);
  batch.wait();
  remember(more);
  EXPECT_EQ(test::processesLeftMentioning(out.string(), std::chrono::seconds(5)), std::vector<std::string>{});

  // To the end: the stamped jobs are taken as they are, the rest run.
  const test::ProcessOutcome last = lathesim(args, dir.path());
  EXPECT_EQ(last.status, 0) << last.out << last.err;
  const std::set<std::string> done = waitForStamps(out, 4, std::chrono::seconds(0));
  EXPECT_EQ(done.size(), 4u);
  const Json summary = jsonFile(out / "summary.json");
  for (const auto& row : summary.at("jobs")) {
    const std::string name = row.at("name");
    EXPECT_EQ(row.at("status"), "ok") << name;
    EXPECT_EQ(row.at("resumed").get<bool>(), firstWritten.count(name) == 1) << name;
  }
  remember(done);
  for (const auto& [name, identity] : firstWritten) EXPECT_EQ(identityOf(out / name / "report.json"), identity) << name;
}

}  // namespace
}  // namespace lathesim::batch
