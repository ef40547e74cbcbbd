// job/ prints nothing: what reading a job finds to say comes back with it, in order, for the
// command to print.

#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "job/job.hpp"
#include "tests/support/lathesim_process.hpp"

namespace lathesim::job {
namespace {

/// loadJob on `request`, failing the test if it wrote anything to standard error.
Reported<std::optional<Job>> loadSilently(const JobRequest& request) {
  testing::internal::CaptureStderr();
  Reported<std::optional<Job>> loaded = loadJob(request);
  EXPECT_EQ(testing::internal::GetCapturedStderr(), "");
  return loaded;
}

TEST(JobDiagnostics, AnUnknownControlIsAnErrorOfTheCommandLine) {
  test::ScratchDir dir("job-diagnostics");
  test::writeFile(dir.path() / "p.nc", "G00 X40. Z2.\nM30\n");
  JobRequest request{dir.path() / "p.nc", {}, {}, {}, {}};
  request.overrides.controlPreset = "no-such-control";
  const auto loaded = loadSilently(request);
  EXPECT_FALSE(loaded.value);
  ASSERT_EQ(loaded.diagnostics.size(), 1u);
  const std::string said = interp::format(loaded.diagnostics[0]);
  EXPECT_EQ(said.rfind("lathesim: error: --control no-such-control: no such control preset (expected ", 0), 0u) << said;
}

TEST(JobDiagnostics, AProgramThatCannotBeReadIsAnErrorOfItsFile) {
  JobRequest request{"/nonexistent/lathesim/p.nc", {}, {}, {}, {}};
  const auto loaded = loadSilently(request);
  EXPECT_FALSE(loaded.value);
  ASSERT_EQ(loaded.diagnostics.size(), 1u);
  EXPECT_EQ(interp::format(loaded.diagnostics[0]),
            "/nonexistent/lathesim/p.nc: error: cannot read the program file (No such file or directory)");
}

TEST(JobDiagnostics, ABadStockOptionIsAnErrorOfTheCommandLine) {
  test::ScratchDir dir("job-diagnostics");
  test::writeFile(dir.path() / "p.nc", "G00 X40. Z2.\nM30\n");
  JobRequest request{dir.path() / "p.nc", {}, {}, {}, "D40xQ9"};
  const auto loaded = loadSilently(request);
  EXPECT_FALSE(loaded.value);
  ASSERT_EQ(loaded.diagnostics.size(), 1u);
  EXPECT_EQ(loaded.diagnostics[0].severity, interp::Severity::Error);
  EXPECT_EQ(loaded.diagnostics[0].file, "lathesim");
  EXPECT_EQ(loaded.diagnostics[0].line, 0);
}

TEST(JobDiagnostics, AProgramsErrorComesBackLocatedAndNoJobWithIt) {
  test::ScratchDir dir("job-diagnostics");
  test::writeFile(dir.path() / "p.nc", "G00 X40. Z2.\nG01 X30. Z-5. F0.2 Q7 Q8\nM30\n");
  const auto loaded = loadSilently({dir.path() / "p.nc", {}, {}, {}, {}});
  EXPECT_FALSE(loaded.value);
  ASSERT_FALSE(loaded.diagnostics.empty());
  const interp::Diagnostic& last = loaded.diagnostics.back();
  EXPECT_EQ(last.severity, interp::Severity::Error);
  EXPECT_EQ(last.file, (dir.path() / "p.nc").string());
  EXPECT_EQ(last.line, 2);
}

TEST(JobDiagnostics, AJobComesBackWithItsWarningsInTheOrderFound) {
  test::ScratchDir dir("job-diagnostics");
  // Tool 2 from its comment (found when the job is opened), then tool 1's (same pass, later line).
  test::writeFile(dir.path() / "p.nc",
                  "G21 G99\nT0202 (CNMG 120408)\nG97 S1000 M03\nG00 X44. Z2.\nT0101 (CNMG 120408)\n"
                  "G00 X44. Z2.\nM30\n");
  const auto loaded = loadSilently({dir.path() / "p.nc", {}, {}, {}, "D40xL60"});
  ASSERT_TRUE(loaded.value);
  std::vector<std::string> mounted;
  for (const interp::Diagnostic& d : loaded.diagnostics) {
    EXPECT_NE(d.severity, interp::Severity::Error) << interp::format(d);
    if (d.message.rfind("tool ", 0) == 0 && d.message.find("is mounted from the comment") != std::string::npos)
      mounted.push_back(std::to_string(d.line) + ": " + d.message.substr(0, 6));
  }
  EXPECT_EQ(mounted, (std::vector<std::string>{"2: tool 2", "5: tool 1"}));
  // What the job keeps as warnings is what it said as warnings, in the same order.
  std::vector<std::string> said, kept;
  for (const interp::Diagnostic& d : loaded.diagnostics)
    if (d.severity == interp::Severity::Warning) said.push_back(interp::format(d));
  for (const interp::Diagnostic& d : loaded.value->warnings) kept.push_back(interp::format(d));
  EXPECT_EQ(said, kept);
}

}  // namespace
}  // namespace lathesim::job
