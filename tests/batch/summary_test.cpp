// The batch's summary: exit status, CSV, JSON, the HTML page's content, and merging shards.

#include <gtest/gtest.h>

#include <regex>

#include "batch/merge.hpp"
#include "batch/summary.hpp"
#include "batch/summary_html.hpp"
#include "tests/support/lathesim_process.hpp"

namespace lathesim::batch {
namespace {

namespace fs = std::filesystem;
using test::readFile;
using test::ScratchDir;
using test::writeFile;

JobResult row(int index, JobStatus status) {
  JobResult r;
  r.index = index;
  r.name = "job" + std::to_string(index);
  r.program = "progs/job" + std::to_string(index) + ".nc";
  r.command = "run";
  r.folder = r.name;
  r.status = status;
  r.exitCode = status == JobStatus::OutOfTolerance ? 3 : status == JobStatus::Ok ? 0 : 1;
  if (status == JobStatus::Ok || status == JobStatus::OutOfTolerance) {
    r.finalVolumeMm3 = 1000.0 + index;
    r.stockVolumeMm3 = 2000.0;
    r.removedVolumeMm3 = 1000.0 - index;
    r.cycleTimeS = 10.0 * index;
  }
  if (status == JobStatus::OutOfTolerance) {
    r.command = "check";
    r.check = CheckFigures{0.5, false, 0.125, 1.5};
  }
  r.elapsedS = 1.5;
  return r;
}

BatchSummary summaryOf(std::vector<JobStatus> statuses) {
  BatchSummary s;
  s.version = "0.1.0";
  s.buildId = "abc";
  s.source = "class/";
  s.jobsHash = "0123456789abcdef";
  s.jobsInBatch = static_cast<int>(statuses.size());
  for (std::size_t i = 0; i < statuses.size(); ++i) s.jobs.push_back(row(static_cast<int>(i), statuses[i]));
  return s;
}

TEST(BatchSummary, ExitStatusFailureOverToleranceOverSuccess) {
  using S = JobStatus;
  EXPECT_EQ(summaryOf({}).exitStatus(), 0);
  EXPECT_EQ(summaryOf({S::Ok, S::Ok}).exitStatus(), 0);
  EXPECT_EQ(summaryOf({S::Ok, S::OutOfTolerance}).exitStatus(), 3);
  for (S bad : {S::Failed, S::Timeout, S::Crashed, S::NotRun}) {
    EXPECT_EQ(summaryOf({S::Ok, bad}).exitStatus(), 1) << statusName(bad);
    EXPECT_EQ(summaryOf({S::OutOfTolerance, bad, S::Ok}).exitStatus(), 1) << statusName(bad);
  }
  EXPECT_EQ(summaryOf({S::Ok, S::Failed, S::Failed, S::OutOfTolerance}).countsText(),
            "1 ok, 1 out of tolerance, 2 failed");
}

// A crash (exit 4) is counted apart from failures; it wins over out of tolerance and loses to a
// failure.
TEST(BatchSummary, CollisionsAreCountedApartAndExitFour) {
  using S = JobStatus;
  EXPECT_EQ(summaryOf({S::Ok, S::Collision}).exitStatus(), 4);
  EXPECT_EQ(summaryOf({S::OutOfTolerance, S::Collision, S::Ok}).exitStatus(), 4);
  EXPECT_EQ(summaryOf({S::Collision, S::Failed}).exitStatus(), 1);
  const BatchSummary s = summaryOf({S::Ok, S::Collision, S::Collision, S::Failed});
  EXPECT_EQ(s.countsText(), "1 ok, 2 collision, 1 failed");
  const nlohmann::ordered_json json = toJson(s);
  EXPECT_EQ(json.at("counts").at("collision"), 2);
  EXPECT_EQ(json.at("counts").at("failed"), 1);
  EXPECT_EQ(json.at("jobs").at(1).at("status"), "collision");
  EXPECT_EQ(toJson(summaryFromJson(nlohmann::json::parse(json.dump()))), json);
}

TEST(BatchSummary, CsvOneQuotedLinePerJob) {
  BatchSummary s = summaryOf({JobStatus::Ok, JobStatus::Failed, JobStatus::OutOfTolerance});
  s.jobs[1].message = JobMessage{"error", "progs/job1.nc", 5, 21, "R-5.5 and W3, \"opposite\" signs"};
  s.jobs[0].collisions.push_back({7, 1, "rapid_into_stock", 3.5});
  s.jobs[0].partedOff = PartedOff{12, 1, -41.5, 1234.25, 800.5};
  std::ostringstream csv;
  writeSummaryCsv(s, csv);
  std::istringstream lines(csv.str());
  std::string header, first, second, third, rest;
  std::getline(lines, header);
  std::getline(lines, first);
  std::getline(lines, second);
  std::getline(lines, third);
  EXPECT_FALSE(std::getline(lines, rest));
  EXPECT_EQ(header,
            "index,name,status,exit_code,program,command,message_kind,message_file,message_line,message_column,"
            "message,warnings,stock_volume_mm3,final_volume_mm3,removed_volume_mm3,cycle_time_s,moves,collisions,"
            "first_collision_line,first_collision_kind,tolerance_mm,within_tolerance,max_gouge_mm,max_excess_mm,"
            "peak_memory_mb,elapsed_s,folder,parted_off_line,parted_off_z,parted_off_volume_mm3");
  EXPECT_EQ(first,
            "1,job0,ok,0,progs/job0.nc,run,,,,,,0,2000,1000,1000,0,,1,7,rapid_into_stock,,,,,,1.5,job0,12,-41.5,1234.25");
  EXPECT_EQ(second,
            "2,job1,failed,1,progs/job1.nc,run,error,progs/job1.nc,5,21,\"R-5.5 and W3, \"\"opposite\"\" signs\",0,,,,,,"
            "0,,,,,,,,1.5,job1,,,");
  EXPECT_EQ(third,
            "3,job2,out_of_tolerance,3,progs/job2.nc,check,,,,,,0,2000,1002,998,20,,0,,,0.5,false,0.125,1.5,,1.5,job2,,,");
}

TEST(BatchSummary, JsonRoundTrip) {
  BatchSummary s = summaryOf({JobStatus::Ok, JobStatus::Timeout, JobStatus::OutOfTolerance});
  s.jobs[0].partedOff = PartedOff{12, 3, -41.5, 1234.25, 800.5};
  const nlohmann::ordered_json json = toJson(s);
  EXPECT_EQ(json.at("jobs").at(0).at("parted_off"),
            nlohmann::ordered_json({{"line", 12}, {"column", 3}, {"z", -41.5}, {"volume_mm3", 1234.25},
                                    {"stub_volume_mm3", 800.5}}));
  EXPECT_TRUE(json.at("jobs").at(1).at("parted_off").is_null());
  EXPECT_EQ(json.at("exit_status"), 1);
  EXPECT_EQ(json.at("counts").at("timeout"), 1);
  EXPECT_EQ(json.at("counts").at("ok"), 1);
  EXPECT_EQ(toJson(summaryFromJson(nlohmann::json::parse(json.dump()))), json);
}

/// The bytes base64 encodes, decoded independently of the writer (RFC 4648 alphabet).
std::string decodeBase64(const std::string& text) {
  const std::string digits = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
  std::string bytes;
  int bits = 0, value = 0;
  for (char c : text) {
    if (c == '=') break;
    value = (value << 6) | static_cast<int>(digits.find(c));
    bits += 6;
    if (bits >= 8) {
      bits -= 8;
      bytes += static_cast<char>((value >> bits) & 0xFF);
    }
  }
  return bytes;
}

TEST(SummaryHtml, OneRowPerJobWithItsThumbnailInside) {
  ScratchDir dir("html");
  BatchSummary s = summaryOf({JobStatus::Ok, JobStatus::Failed, JobStatus::OutOfTolerance});
  s.jobs[1].message = JobMessage{"error", "", 5, 21, "<b>&\"bad\"</b>"};
  s.jobs[0].partedOff = PartedOff{12, 1, -41.5, 1234.375, 800.5};
  // Thumbnails of 1, 2 and 3 bytes cover base64's three paddings; the failed job has none.
  const std::vector<std::string> thumbnails{"A", std::string("\x89P", 2), std::string("\0\xff\x10", 3)};
  for (int i : {0, 2}) {
    fs::create_directories(dir.path() / s.jobs[i].folder);
    writeFile(dir.path() / s.jobs[i].folder / "thumbnail.png", thumbnails[i]);
    s.jobs[i].thumbnail = "thumbnail.png";
  }
  std::ostringstream out;
  writeSummaryHtml(s, dir.path(), out);
  const std::string html = out.str();
  EXPECT_EQ(html.find("http"), std::string::npos);  // nothing to fetch
  EXPECT_EQ(html.find("<b>&"), std::string::npos);  // the message is escaped
  EXPECT_NE(html.find("&lt;b&gt;&amp;&quot;bad&quot;&lt;/b&gt;"), std::string::npos);
  EXPECT_NE(html.find("line 5:21 error: "), std::string::npos);
  // Cut to a few lines in the table, whole on hover.
  EXPECT_NE(html.find("<div class=\"clamp\" title=\"line 5:21 error: &lt;b&gt;&amp;&quot;bad&quot;&lt;/b&gt;\">"),
            std::string::npos);
  const std::regex image(R"re(src="data:image/png;base64,([A-Za-z0-9+/=]*)")re");
  std::vector<std::string> embedded;
  for (std::sregex_iterator m(html.begin(), html.end(), image), end; m != end; ++m) embedded.push_back((*m)[1]);
  ASSERT_EQ(embedded.size(), 2u);
  EXPECT_EQ(embedded[0], "QQ==");
  EXPECT_EQ(decodeBase64(embedded[0]), thumbnails[0]);
  EXPECT_EQ(decodeBase64(embedded[1]), thumbnails[2]);
  EXPECT_EQ(embedded[1], "AP8Q");
  const std::regex rowStart("<tr><td class=\"num\" data-value=\"(\\d+)\">");
  std::vector<std::string> places;
  for (std::sregex_iterator m(html.begin(), html.end(), rowStart), end; m != end; ++m) places.push_back((*m)[1]);
  EXPECT_EQ(places, (std::vector<std::string>{"1", "2", "3"}));
  EXPECT_NE(html.find("<span class=\"badge out_of_tolerance\">out of tolerance</span>"), std::string::npos);
  EXPECT_NE(html.find("href=\"job2/deviation.png\""), std::string::npos);  // a check links its deviation picture
  EXPECT_NE(html.find("href=\"job0/part.png\""), std::string::npos);
  // The part-off column: sorted by the fallen piece's volume, showing it with the cut's Z and line.
  EXPECT_NE(html.find("data-key=\"parted_off_volume_mm3\" data-type=\"number\">parted off mm³</th>"), std::string::npos);
  EXPECT_NE(html.find("<td class=\"num\" data-value=\"1234.375\">1234.4<div class=\"path\">Z-41.500, line 12</div></td>"),
            std::string::npos);
}

/// Writes `whole` as `count` shard summaries into `folder`, as `--shard I/N` runs would.
std::vector<fs::path> writeShards(const BatchSummary& whole, int count, const fs::path& folder) {
  std::vector<fs::path> files;
  for (int i = 1; i <= count; ++i) {
    BatchSummary shard = whole;
    shard.shard = {i, count};
    shard.jobs.clear();
    for (const auto& job : whole.jobs)
      if (shard.shard.holds(job.index)) shard.jobs.push_back(job);
    writeSummaryFiles(shard, folder);
    files.push_back(folder / (summaryStem(shard.shard) + ".json"));
  }
  return files;
}

TEST(MergeSummaries, ShardsJoinIntoTheWholeBatchsSummary) {
  ScratchDir dir("merge");
  using S = JobStatus;
  const BatchSummary whole = summaryOf({S::Ok, S::Failed, S::OutOfTolerance, S::Ok, S::Timeout, S::Ok, S::Ok});
  for (int count : {1, 2, 3, 7}) {
    const fs::path shards = dir.path() / ("n" + std::to_string(count));
    fs::create_directories(shards);
    std::vector<fs::path> files = writeShards(whole, count, shards);
    std::reverse(files.begin(), files.end());  // in any order
    EXPECT_EQ(mergeSummaries(files, std::nullopt), 1) << count;
    const auto merged = nlohmann::json::parse(readFile(shards / "summary.json"));
    EXPECT_EQ(merged, nlohmann::json::parse(toJson(whole).dump())) << count;
    std::ostringstream wholeCsv;
    writeSummaryCsv(whole, wholeCsv);
    EXPECT_EQ(readFile(shards / "summary.csv"), wholeCsv.str());
    EXPECT_TRUE(fs::exists(shards / "summary.html"));
  }
}

TEST(MergeSummaries, FoldersAreRelativeToWhereTheMergedSummaryGoes) {
  ScratchDir dir("merge-out");
  const BatchSummary whole = summaryOf({JobStatus::Ok, JobStatus::Ok});
  fs::create_directories(dir.path() / "run");
  const auto files = writeShards(whole, 2, dir.path() / "run");
  EXPECT_EQ(mergeSummaries(files, dir.path() / "report"), 0);
  const auto merged = nlohmann::json::parse(readFile(dir.path() / "report" / "summary.json"));
  EXPECT_EQ(merged.at("jobs")[0].at("folder"), "../run/job0");
  EXPECT_EQ(merged.at("jobs")[1].at("folder"), "../run/job1");
}

TEST(MergeSummaries, RefusesMissingRepeatedOrForeignShards) {
  ScratchDir dir("merge-bad");
  const BatchSummary whole = summaryOf({JobStatus::Ok, JobStatus::Ok, JobStatus::Ok});
  const auto files = writeShards(whole, 3, dir.path());
  testing::internal::CaptureStderr();
  EXPECT_EQ(mergeSummaries({files[0], files[2]}, dir.path() / "a"), 1);
  EXPECT_NE(testing::internal::GetCapturedStderr().find("shard 2-of-3 is missing"), std::string::npos);
  testing::internal::CaptureStderr();
  EXPECT_EQ(mergeSummaries({files[0], files[1], files[2], files[1]}, dir.path() / "b"), 1);
  EXPECT_NE(testing::internal::GetCapturedStderr().find("shard 2-of-3 is also"), std::string::npos);
  BatchSummary other = whole;
  other.jobsHash = "ffffffffffffffff";
  const fs::path foreign = dir.path() / "other";
  fs::create_directories(foreign);
  const auto otherFiles = writeShards(other, 3, foreign);
  testing::internal::CaptureStderr();
  EXPECT_EQ(mergeSummaries({files[0], files[1], otherFiles[2]}, dir.path() / "c"), 1);
  EXPECT_NE(testing::internal::GetCapturedStderr().find("a shard of another batch"), std::string::npos);
  writeFile(dir.path() / "junk.json", "{\"jobs\": []}");
  testing::internal::CaptureStderr();
  EXPECT_EQ(mergeSummaries({dir.path() / "junk.json"}, dir.path() / "d"), 1);
  EXPECT_NE(testing::internal::GetCapturedStderr().find("not a lathesim batch summary"), std::string::npos);
  for (const char* out : {"a", "b", "c", "d"}) EXPECT_FALSE(fs::exists(dir.path() / out / "summary.json")) << out;
}

}  // namespace
}  // namespace lathesim::batch
