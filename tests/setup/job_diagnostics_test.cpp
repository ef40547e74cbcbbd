// setup/ prints nothing: what reading a job finds to say comes back with it, in order, for the
// command to print.

#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "setup/job.hpp"
#include "tests/support/lathesim_process.hpp"

namespace lathesim::setup {
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

// The tools named in comments are found as openJob reads the program through for the
// interpreter (one read for both, kept in the job until interpretJob runs it): a T word's
// first comment that names a tool mounts it, from the block's own comments or the lines
// above; a later comment for the same number mounts nothing more; a block that block delete
// skips is not read for one.
TEST(JobDiagnostics, ToolsNamedInCommentsAreFoundInTheReadTheInterpreterRuns) {
  test::ScratchDir dir("job-diagnostics");
  test::writeFile(dir.path() / "p.nc",
                  "G21 G99\nT0303 (FINISHING)\nG97 S1000 M03\nG00 X44. Z2.\n(DNMG 150608)\nT0303\n"
                  "T0303 (DRILL 10)\n/T0505 (DRILL 8)\nG00 X50. Z5.\nM30\n");
  for (const bool blockSkip : {false, true}) {
    SCOPED_TRACE(blockSkip ? "block skip on" : "block skip off");
    JobRequest request{dir.path() / "p.nc", {}, {}, {}, "D40xL60"};
    request.overrides.blockSkip = blockSkip;
    testing::internal::CaptureStderr();
    Reported<std::optional<Job>> opened = openJob(request);
    EXPECT_EQ(testing::internal::GetCapturedStderr(), "");
    ASSERT_TRUE(opened.value);
    std::vector<std::string> mounted;
    for (const interp::Diagnostic& d : opened.diagnostics)
      if (d.message.find("is mounted from the comment") != std::string::npos)
        mounted.push_back(std::to_string(d.line) + ": " + d.message.substr(0, d.message.find(':')));
    std::vector<std::string> expected{"6: tool 3 is mounted from the comment '(DNMG 150608)'"};
    if (!blockSkip) expected.push_back("8: tool 5 is mounted from the comment '(DRILL 8)'");
    EXPECT_EQ(mounted, expected);
    ASSERT_TRUE(opened.value->program);
    EXPECT_EQ(opened.value->program->blockCount(), 9u);  // the comment line belongs to the block below it
    std::vector<interp::Move> moves;
    interp::MoveCollector collector(moves);
    const Reported<bool> ran = interpretJob(*opened.value, request, collector);
    EXPECT_TRUE(ran.value);
    EXPECT_FALSE(opened.value->program);  // run, and let go
    // The moves of the program read again from its text, by the interpreter alone.
    const interp::InterpretResult fresh = interp::interpret(
        opened.value->programText.text(), request.program.string(), interpreterOptionsOf(opened.value->setup));
    const auto described = [](const std::vector<interp::Move>& made) {
      std::string text;
      for (const interp::Move& m : made)
        text += std::to_string(m.line) + " " + std::to_string(static_cast<int>(m.kind)) + " T" + std::to_string(m.tool) +
                " " + std::to_string(m.to.x()) + " " + std::to_string(m.to.y()) + ";";
      return text;
    };
    EXPECT_EQ(described(moves), described(fresh.toolpath.moves));
    ASSERT_FALSE(moves.empty());
    EXPECT_EQ(moves.back().line, 9);
    EXPECT_EQ(moves.back().tool, blockSkip ? 3 : 5);  // the last rapid: T0505 ran unless skipped
  }
}

}  // namespace
}  // namespace lathesim::setup
