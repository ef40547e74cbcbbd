// A job's row from how its process ended, its log and its report.json; the first error in
// a log; the row's JSON round trip.

#include <gtest/gtest.h>

#include <csignal>

#include "batch/job_result.hpp"

namespace lathesim::batch {
namespace {

using Json = nlohmann::json;

BatchJob job(bool check = false) {
  BatchJob j;
  j.index = 4;
  j.name = "part";
  j.program = "class/p.nc";
  if (check) j.settings.drawing = "d.toml";
  j.settings.timeLimitS = 30;
  return j;
}

Json report() {
  return Json::parse(R"({
    "program": "class/p.nc", "stock_volume_mm3": 1000.5, "final_volume_mm3": 800.25, "removed_volume_mm3": 200.25,
    "moves": 12, "cycle_time_s": 42.5, "peak_memory_mb": 260.0,
    "collisions": [{"line": 7, "column": 1, "kind": "rapid_into_stock", "volume_mm3": 3.5}],
    "warnings": [{"line": 3, "column": 5, "message": "G96 without G50 S"}, {"line": 9, "column": 1, "message": "x"}],
    "timing_s": {"parse": 0.5, "simulate": 1.0, "mesh": 0.25, "render": 0.25}})");
}

ChildOutcome exited(int code) {
  ChildOutcome o;
  o.exitCode = code;
  o.elapsedS = 2.5;
  return o;
}

TEST(JobResult, ARunThatExitedZeroIsOkWithItsReportsFigures) {
  const JobResult r = resultOf(job(), "part", exited(0), "", report());
  EXPECT_EQ(r.status, JobStatus::Ok);
  EXPECT_EQ(r.command, "run");
  EXPECT_EQ(r.index, 4);
  EXPECT_EQ(r.exitCode, 0);
  EXPECT_EQ(r.finalVolumeMm3, 800.25);
  EXPECT_EQ(r.stockVolumeMm3, 1000.5);
  EXPECT_EQ(r.removedVolumeMm3, 200.25);
  EXPECT_EQ(r.cycleTimeS, 42.5);
  EXPECT_EQ(r.moves, 12);
  EXPECT_EQ(r.peakMemoryMb, 260.0);
  EXPECT_EQ(r.pipelineS, 2.0);
  EXPECT_EQ(r.elapsedS, 2.5);
  ASSERT_EQ(r.collisions.size(), 1u);
  EXPECT_EQ(r.collisions[0].line, 7);
  EXPECT_EQ(r.collisions[0].kind, "rapid_into_stock");
  EXPECT_EQ(r.warnings, 2);
  ASSERT_TRUE(r.message);  // the first warning, with its place
  EXPECT_EQ(r.message->kind, "warning");
  EXPECT_EQ(r.message->file, "class/p.nc");
  EXPECT_EQ(r.message->line, 3);
  EXPECT_EQ(r.message->column, 5);
  EXPECT_EQ(r.message->text, "G96 without G50 S");
  EXPECT_FALSE(r.check);
  EXPECT_FALSE(r.partedOff);  // the report says nothing parted off
}

// report.json's parted_off is carried into the row, and back from its JSON.
TEST(JobResult, APartOffIsTakenFromTheReport) {
  Json parted = report();
  parted["parted_off"] = {{"line", 21}, {"column", 1}, {"z", -40.0}, {"volume_mm3", 5654.87},
                          {"stub_volume_mm3", 3141.59}, {"mesh_volume_mm3", 3141.2}, {"parts_catcher", nullptr}};
  const JobResult r = resultOf(job(), "part", exited(0), "", parted);
  ASSERT_TRUE(r.partedOff);
  EXPECT_EQ(r.partedOff->line, 21);
  EXPECT_EQ(r.partedOff->column, 1);
  EXPECT_EQ(r.partedOff->zMm, -40.0);
  EXPECT_EQ(r.partedOff->volumeMm3, 5654.87);
  EXPECT_EQ(r.partedOff->stubVolumeMm3, 3141.59);
  const JobResult back = resultFromJson(toJson(r));
  ASSERT_TRUE(back.partedOff);
  EXPECT_EQ(toJson(back), toJson(r));
  Json old = toJson(r);  // a stamp written before rows had parted_off
  old.erase("parted_off");
  EXPECT_FALSE(resultFromJson(old).partedOff);
}

// A report that times its whole command gives that total as the command's own time: its
// steps overlap (stock.vdb is written while the part is meshed) and add up to more.
TEST(JobResult, TheCommandsOwnTimeIsItsTotalWhenTheReportGivesOne) {
  Json timed = report();
  timed["timing_s"] = {{"parse", 0.5}, {"simulate", 1.0}, {"bar", 0.25}, {"mesh", 0.25}, {"render", 0.5},
                       {"write", 0.75}, {"total", 2.25}};
  EXPECT_EQ(resultOf(job(), "part", exited(0), "", timed).pipelineS, 2.25);
}

TEST(JobResult, ACheckExitingThreeIsOutOfTolerance) {
  Json checked = report();
  checked["check"] = {{"tolerance_mm", 0.5}, {"within_tolerance", false}, {"max_gouge_mm", 0.1}, {"max_excess_mm", 1.49}};
  const JobResult r = resultOf(job(true), "part", exited(3), "", checked);
  EXPECT_EQ(r.status, JobStatus::OutOfTolerance);
  EXPECT_EQ(r.command, "check");
  ASSERT_TRUE(r.check);
  EXPECT_EQ(r.check->toleranceMm, 0.5);
  EXPECT_FALSE(r.check->withinTolerance);
  EXPECT_EQ(r.check->maxGougeMm, 0.1);
  EXPECT_EQ(r.check->maxExcessMm, 1.49);
  // Exit 3 without a failed check is not "out of tolerance": something else went wrong.
  EXPECT_EQ(resultOf(job(), "part", exited(3), "", report()).status, JobStatus::Failed);
}

// Exit 4 with a report that lists the collision: the program crashes (its outputs are written),
// counted apart from failures, with the crash's located error as its message.
TEST(JobResult, ExitFourWithACollisionIsACollision) {
  Json crashed = report();
  const std::string log = "p.nc:8:1: error: rapid into the stock removes 249.7 mm³ (the tool ends at X38 Z-1)\n"
                          "G00 Z-1.\n^\n";
  const JobResult r = resultOf(job(), "part", exited(4), log, crashed);
  EXPECT_EQ(r.status, JobStatus::Collision);
  ASSERT_TRUE(r.message);
  EXPECT_EQ(r.message->kind, "error");
  EXPECT_EQ(r.message->line, 8);
  EXPECT_EQ(r.message->text, "rapid into the stock removes 249.7 mm³ (the tool ends at X38 Z-1)");
  EXPECT_EQ(statusNamed("collision"), JobStatus::Collision);
  // Exit 4 without a collision in the report is no crash: something else went wrong.
  Json clean = report();
  clean["collisions"] = Json::array();
  EXPECT_EQ(resultOf(job(), "part", exited(4), "", clean).status, JobStatus::Failed);
}

TEST(JobResult, ABadProgramFailsWithItsFirstErrorAndPlace) {
  const std::string log =
      "class/p.nc:2:1: warning: G96 without G50 S\n"
      "class/p.nc:5:21: error: R-5.5 and W3 have opposite signs\n"
      "   N40 G94 X20 Z5.0 R-5.5\n"
      "                    ^\n"
      "class/p.nc:9:1: error: a later one\n";
  const JobResult r = resultOf(job(), "part", exited(1), log, std::nullopt);
  EXPECT_EQ(r.status, JobStatus::Failed);
  EXPECT_EQ(r.exitCode, 1);
  ASSERT_TRUE(r.message);
  EXPECT_EQ(r.message->kind, "error");
  EXPECT_EQ(r.message->file, "class/p.nc");
  EXPECT_EQ(r.message->line, 5);
  EXPECT_EQ(r.message->column, 21);
  EXPECT_EQ(r.message->text, "R-5.5 and W3 have opposite signs");
  EXPECT_FALSE(r.finalVolumeMm3);
}

TEST(JobResult, KilledAtTheTimeLimitOrEndedByASignal) {
  ChildOutcome killed;
  killed.signal = SIGKILL;
  killed.timedOut = true;
  JobResult r = resultOf(job(), "part", killed, "", std::nullopt);
  EXPECT_EQ(r.status, JobStatus::Timeout);
  EXPECT_EQ(r.message->text, "stopped at the time limit of 30 s");
  EXPECT_EQ(r.signal, SIGKILL);
  EXPECT_FALSE(r.exitCode);
  ChildOutcome crashed;
  crashed.signal = SIGSEGV;
  r = resultOf(job(), "part", crashed, "half a line", std::nullopt);
  EXPECT_EQ(r.status, JobStatus::Crashed);
  EXPECT_EQ(r.message->text, "lathesim was ended by signal 11 (Segmentation fault)");
}

TEST(JobResult, ExitZeroWithoutAReportOrANonZeroExitWithoutWordsStillFails) {
  JobResult r = resultOf(job(), "part", exited(0), "", std::nullopt);
  EXPECT_EQ(r.status, JobStatus::Failed);
  EXPECT_EQ(r.message->text, "lathesim wrote no report.json");
  r = resultOf(job(), "part", exited(2), "", std::nullopt);
  EXPECT_EQ(r.status, JobStatus::Failed);
  EXPECT_EQ(r.message->text, "lathesim exited with status 2");
  // A report with a non-zero exit (a status other than 0 and 3): failed, the figures kept.
  r = resultOf(job(), "part", exited(2), "", report());
  EXPECT_EQ(r.status, JobStatus::Failed);
  EXPECT_EQ(r.finalVolumeMm3, 800.25);
}

TEST(FirstError, LocatedFiledOrTheFirstWords) {
  auto e = firstError("\nsetup.toml:3:1: error: unknown key 'x'\n");
  ASSERT_TRUE(e);
  EXPECT_EQ(e->file, "setup.toml");
  EXPECT_EQ(e->line, 3);
  EXPECT_EQ(e->text, "unknown key 'x'");
  e = firstError("C:/odd:name.nc:12:3: error: msg: with colons\r\n");  // the earliest LINE:COL
  ASSERT_TRUE(e);
  EXPECT_EQ(e->file, "C:/odd:name.nc");
  EXPECT_EQ(e->line, 12);
  EXPECT_EQ(e->text, "msg: with colons");
  e = firstError("drawing.toml: error: the profile is not closed\n");
  EXPECT_EQ(e->file, "drawing.toml");
  EXPECT_EQ(e->line, 0);
  e = firstError("lathesim: error: a 0.01 mm voxel needs about 40 GiB\n");
  EXPECT_EQ(e->file, "");
  EXPECT_EQ(e->text, "a 0.01 mm voxel needs about 40 GiB");
  e = firstError("  \nprogram: File does not exist: x.nc\nRun with --help for more information.\n");
  EXPECT_EQ(e->text, "program: File does not exist: x.nc");
  EXPECT_FALSE(firstError(" \n\n"));
}

TEST(JobResult, JsonRoundTrip) {
  Json checked = report();
  checked["check"] = {{"tolerance_mm", 0.5}, {"within_tolerance", false}, {"max_gouge_mm", 0.1}, {"max_excess_mm", 1.49}};
  JobResult r = resultOf(job(true), "part", exited(3), "", checked);
  r.thumbnail = "thumbnail.png";
  r.resumed = true;
  const Json json = toJson(r);
  EXPECT_EQ(json.at("index"), 5);  // counted from 1 in the files
  EXPECT_EQ(json.at("status"), "out_of_tolerance");
  const JobResult back = resultFromJson(json);
  EXPECT_EQ(toJson(back), toJson(r));
  EXPECT_EQ(back.index, 4);
  JobResult failed = resultOf(job(), "part", exited(1), "p.nc:1:2: error: x\n", std::nullopt);
  EXPECT_EQ(toJson(resultFromJson(toJson(failed))), toJson(failed));
  Json broken = toJson(failed);
  broken["status"] = "fine";
  EXPECT_THROW(resultFromJson(broken), nlohmann::json::exception);
}

}  // namespace
}  // namespace lathesim::batch
