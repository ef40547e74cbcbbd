// Manifests (TOML, CSV) and folders of programs → the batch's jobs: keys, layering of the
// defaults, paths relative to the manifest, names, and every diagnostic with its place.

#include <gtest/gtest.h>

#include "batch/manifest.hpp"
#include "tests/support/lathesim_process.hpp"

namespace lathesim::batch {
namespace {

namespace fs = std::filesystem;
using test::ScratchDir;
using test::writeFile;

JobList tomlJobs(const ScratchDir& dir, const std::string& text, const JobSettings& defaults = {}) {
  writeFile(dir.path() / "batch.toml", text);
  return readJobs(dir.path() / "batch.toml", defaults);
}

JobList csvJobs(const ScratchDir& dir, const std::string& text, const JobSettings& defaults = {}) {
  writeFile(dir.path() / "batch.csv", text);
  return readJobs(dir.path() / "batch.csv", defaults);
}

/// "file:line:col: message" of the only diagnostic (fails the test if there is not one).
std::string onlyProblem(const JobList& list) {
  EXPECT_FALSE(list.jobs.has_value());
  EXPECT_EQ(list.diagnostics.size(), 1u);
  if (list.diagnostics.empty()) return "";
  const auto& d = list.diagnostics.front();
  return fs::path(d.file).filename().string() + ":" + std::to_string(d.line) + ":" + std::to_string(d.column) + ": " +
         d.message;
}

TEST(TomlManifest, JobsInOrderWithTheirKeysAndPathsFromTheManifestsFolder) {
  ScratchDir dir("manifest-toml");
  const JobList list = tomlJobs(dir, R"(
[[job]]
program = "class/alice.nc"
setup = "setup.toml"
drawing = "drawing.toml"
tolerance = 0.05
voxel = 0.25
time_limit = 60
options = ["--dialect", "hnc"]

[[job]]
name = "bob-second-try"
program = "/elsewhere/bob.nc"
target_program = "reference.nc"
)");
  ASSERT_TRUE(list.jobs) << (list.diagnostics.empty() ? "" : interp::format(list.diagnostics[0]));
  const auto& jobs = *list.jobs;
  ASSERT_EQ(jobs.size(), 2u);
  EXPECT_EQ(jobs[0].index, 0);
  EXPECT_EQ(jobs[0].name, "alice");
  EXPECT_EQ(jobs[0].program, dir.path() / "class/alice.nc");
  EXPECT_EQ(jobs[0].manifestLine, 2);
  EXPECT_EQ(jobs[0].settings.setup, dir.path() / "setup.toml");
  EXPECT_EQ(jobs[0].settings.drawing, dir.path() / "drawing.toml");
  EXPECT_EQ(jobs[0].settings.toleranceMm, 0.05);
  EXPECT_EQ(jobs[0].settings.voxelMm, 0.25);
  EXPECT_EQ(jobs[0].settings.timeLimitS, 60.0);
  EXPECT_EQ(jobs[0].settings.options, (std::vector<std::string>{"--dialect", "hnc"}));
  EXPECT_EQ(jobs[1].index, 1);
  EXPECT_EQ(jobs[1].name, "bob-second-try");
  EXPECT_EQ(jobs[1].program, fs::path("/elsewhere/bob.nc"));
  EXPECT_EQ(jobs[1].settings.targetProgram, dir.path() / "reference.nc");
  EXPECT_FALSE(jobs[1].settings.setup);
}

TEST(TomlManifest, JobKeysOverTheDefaultsOverTheCommandLine) {
  ScratchDir dir("manifest-layers");
  JobSettings commandLine;
  commandLine.voxelMm = 0.5;
  commandLine.timeLimitS = 100;
  commandLine.setup = "cli-setup.toml";
  commandLine.options = {"--block-skip", "on"};
  const JobList list = tomlJobs(dir, R"(
[defaults]
setup = "shared.toml"
drawing = "drawing.toml"
time_limit = 30
options = ["--dialect", "fanuc-b"]

[[job]]
program = "a.nc"
time_limit = 5
options = ["--at-line", "7"]

[[job]]
program = "b.nc"
drawing = ""

[[job]]
program = "c.nc"
target_program = "c-reference.nc"
)",
                                commandLine);
  ASSERT_TRUE(list.jobs);
  const auto& a = (*list.jobs)[0].settings;
  EXPECT_EQ(a.voxelMm, 0.5);                             // only the command line says
  EXPECT_EQ(a.setup, dir.path() / "shared.toml");        // [defaults] over the command line
  EXPECT_EQ(a.timeLimitS, 5.0);                          // the job over [defaults]
  EXPECT_EQ(a.options, (std::vector<std::string>{"--block-skip", "on", "--dialect", "fanuc-b", "--at-line", "7"}));
  EXPECT_TRUE((*list.jobs)[0].checksDrawing());
  const BatchJob& b = (*list.jobs)[1];
  EXPECT_FALSE(b.checksDrawing());  // drawing = "" cancels the default drawing
  const BatchJob& c = (*list.jobs)[2];
  EXPECT_TRUE(c.checksDrawing());  // its own target replaces the default drawing
  EXPECT_FALSE(c.settings.drawing.has_value());
  EXPECT_EQ(c.settings.targetProgram, dir.path() / "c-reference.nc");
}

TEST(TomlManifest, EveryMistakeIsNamedWhereItIs) {
  ScratchDir dir("manifest-errors");
  EXPECT_EQ(onlyProblem(tomlJobs(dir, "[[job]]\nprogram = \"a.nc\"\nvoxle = 0.2\n")),
            "batch.toml:3:1: unknown key 'voxle' (expected program, name, setup, drawing, target_program, tolerance, "
            "voxel, time_limit, options)");
  EXPECT_EQ(onlyProblem(tomlJobs(dir, "[[job]]\nprogram = \"a.nc\"\nvoxel = \"fine\"\n")),
            "batch.toml:3:9: voxel must be a number");
  EXPECT_EQ(onlyProblem(tomlJobs(dir, "[[job]]\nprogram = \"a.nc\"\nvoxel = 0\n")),
            "batch.toml:3:9: voxel must be more than zero mm");
  EXPECT_EQ(onlyProblem(tomlJobs(dir, "[[job]]\nprogram = \"a.nc\"\ntolerance = -1\n")),
            "batch.toml:3:13: tolerance must be zero or more mm");
  EXPECT_EQ(onlyProblem(tomlJobs(dir, "[[job]]\nprogram = \"a.nc\"\ntime_limit = 0\n")),
            "batch.toml:3:14: time_limit must be more than zero seconds");
  EXPECT_EQ(onlyProblem(tomlJobs(dir, "[[job]]\nprogram = \"a.nc\"\noptions = \"--dialect hnc\"\n")),
            "batch.toml:3:11: options must be a list of strings");
  EXPECT_EQ(onlyProblem(tomlJobs(dir, "[[job]]\nprogram = \"a.nc\"\noptions = [\"--voxel=0.1\"]\n")),
            "batch.toml:3:11: options must not give --voxel: the batch sets it from voxel");
  EXPECT_EQ(onlyProblem(tomlJobs(dir, "[[job]]\nprogram = \"a.nc\"\noptions = [\"--out\", \"x\"]\n")),
            "batch.toml:3:11: options must not give --out: the batch sets it from the batch's --out");
  EXPECT_EQ(onlyProblem(tomlJobs(dir, "[[job]]\nsetup = \"s.toml\"\n")), "batch.toml:1:1: the job has no program");
  EXPECT_EQ(onlyProblem(tomlJobs(dir, "[[job]]\nprogram = \"a.nc\"\ndrawing = \"d.toml\"\ntarget_program = \"b.nc\"\n")),
            "batch.toml:1:1: give drawing or target_program, not both");
  EXPECT_EQ(onlyProblem(tomlJobs(dir, "[defaults]\nprogram = \"a.nc\"\n[[job]]\nprogram = \"a.nc\"\n")),
            "batch.toml:1:1: defaults cannot give program; each job gives its own");
  EXPECT_EQ(onlyProblem(tomlJobs(dir, "[job]\nprogram = \"a.nc\"\n")), "batch.toml:1:2: job must be written [[job]]");
  EXPECT_EQ(onlyProblem(tomlJobs(dir, "jobs = 1\n")),
            "batch.toml:1:1: unknown key 'jobs' (expected [defaults] and [[job]] tables)");
  EXPECT_EQ(onlyProblem(tomlJobs(dir, "[defaults]\nvoxel = 0.2\n")), "batch.toml:0:0: the manifest lists no [[job]]");
  EXPECT_EQ(onlyProblem(tomlJobs(dir, "[[job]]\nprogram = \"a.nc\"\nname = \"a/b\"\n")),
            "batch.toml:3:8: a job's name names its output folder: no '/', '\\' or control characters (got \"a/b\")");
  EXPECT_EQ(onlyProblem(tomlJobs(dir, "[[job]]\nprogram = \"a.nc\"\nname = \"summary.html\"\n")),
            "batch.toml:3:8: a job's name must not be that of a summary file (summary.html)");
  const JobList syntax = tomlJobs(dir, "[[job]]\nprogram = \"a.nc\n");
  ASSERT_EQ(syntax.diagnostics.size(), 1u);
  EXPECT_EQ(syntax.diagnostics[0].line, 2);
  EXPECT_NE(syntax.diagnostics[0].message.find("TOML syntax error"), std::string::npos);
}

TEST(TomlManifest, TwoJobsCannotShareAnOutputFolder) {
  ScratchDir dir("manifest-names");
  const JobList list = tomlJobs(dir, "[[job]]\nprogram = \"a/part.nc\"\n\n[[job]]\nprogram = \"b/part.nc\"\n");
  EXPECT_EQ(onlyProblem(list),
            "batch.toml:4:1: two jobs are named \"part\" (" + (dir.path() / "b/part.nc").string() +
                " and the job on line 1); each needs its own output folder, give one a name");
}

TEST(CsvManifest, HeaderNamesTheColumnsAndEmptyCellsKeepTheDefaults) {
  ScratchDir dir("manifest-csv");
  JobSettings commandLine;
  commandLine.voxelMm = 0.4;
  const JobList list = csvJobs(dir,
                               "program,name,setup,voxel,options,drawing,tolerance\r\n"
                               "alice.nc,,setup.toml,0.25,--dialect hnc  --block-skip on,,\r\n"
                               "\r\n"
                               "\"bob, second.nc\",bob,,,,d.toml,0.1\r\n"
                               "\"multi\nline.nc\",\"say \"\"hi\"\"\",,,,,\n",
                               commandLine);
  ASSERT_TRUE(list.jobs) << (list.diagnostics.empty() ? "" : interp::format(list.diagnostics[0]));
  const auto& jobs = *list.jobs;
  ASSERT_EQ(jobs.size(), 3u);
  EXPECT_EQ(jobs[0].name, "alice");
  EXPECT_EQ(jobs[0].manifestLine, 2);
  EXPECT_EQ(jobs[0].settings.setup, dir.path() / "setup.toml");
  EXPECT_EQ(jobs[0].settings.voxelMm, 0.25);
  EXPECT_EQ(jobs[0].settings.options, (std::vector<std::string>{"--dialect", "hnc", "--block-skip", "on"}));
  EXPECT_FALSE(jobs[0].checksDrawing());
  EXPECT_EQ(jobs[1].program, dir.path() / "bob, second.nc");
  EXPECT_EQ(jobs[1].manifestLine, 4);
  EXPECT_EQ(jobs[1].settings.voxelMm, 0.4);  // empty cell: the command line's
  EXPECT_EQ(jobs[1].settings.drawing, dir.path() / "d.toml");
  EXPECT_EQ(jobs[1].settings.toleranceMm, 0.1);
  EXPECT_EQ(jobs[2].program, dir.path() / "multi\nline.nc");
  EXPECT_EQ(jobs[2].name, "say \"hi\"");
  EXPECT_EQ(jobs[2].manifestLine, 5);
}

TEST(CsvManifest, EveryMistakeIsNamedWhereItIs) {
  ScratchDir dir("manifest-csv-errors");
  EXPECT_EQ(onlyProblem(csvJobs(dir, "program,voxels\na.nc,0.2\n")),
            "batch.csv:1:9: unknown column 'voxels' (expected program, name, setup, drawing, target_program, "
            "tolerance, voxel, time_limit, options)");
  EXPECT_EQ(onlyProblem(csvJobs(dir, "name,setup\na,s.toml\n")), "batch.csv:1:1: the header row has no program column");
  EXPECT_EQ(onlyProblem(csvJobs(dir, "program,voxel\na.nc,0.2mm\n")),
            "batch.csv:2:6: voxel must be a number, got \"0.2mm\"");
  EXPECT_EQ(onlyProblem(csvJobs(dir, "program,voxel\na.nc,-1\n")), "batch.csv:2:6: voxel must be more than zero mm");
  EXPECT_EQ(onlyProblem(csvJobs(dir, "program,voxel\na.nc,0.2,x\n")), "batch.csv:2:10: the row has 3 cells, the header 2");
  EXPECT_EQ(onlyProblem(csvJobs(dir, "program,options\na.nc,--setup s.toml\n")),
            "batch.csv:2:6: options must not give --setup: the batch sets it from setup");
  EXPECT_EQ(onlyProblem(csvJobs(dir, "program,name\n,a\n")), "batch.csv:2:1: the job has no program");
  EXPECT_EQ(onlyProblem(csvJobs(dir, "program\n\"a.nc\n")), "batch.csv:2:1: a quoted field is not closed (a \" is missing)");
  EXPECT_EQ(onlyProblem(csvJobs(dir, "program\n")), "batch.csv:1:1: the manifest lists no jobs below its header");
  EXPECT_EQ(onlyProblem(csvJobs(dir, "")),
            "batch.csv:1:1: the manifest is empty; its first row names the columns (program, name, setup, …)");
}

TEST(ProgramFolder, EveryProgramBesideItsOwnSetupAndDrawing) {
  ScratchDir dir("folder");
  const fs::path root = dir.path() / "class";
  for (const char* sub : {"p1", "p2", ".hidden", "notes"}) fs::create_directories(root / sub);
  writeFile(root / "p1/program.nc", "G0 X1\n");
  writeFile(root / "p1/setup.toml", "");
  writeFile(root / "p1/drawing.toml", "");
  writeFile(root / "p2/main.NC", "");
  writeFile(root / "p2/drawing.stl", "");
  writeFile(root / ".hidden/program.nc", "");
  writeFile(root / "notes/readme.txt", "");
  writeFile(root / "alice.tap", "");
  writeFile(root / "setup.toml", "");
  JobSettings commandLine;
  commandLine.setup = dir.path() / "common.toml";
  commandLine.drawing = dir.path() / "common-drawing.toml";
  const JobList list = readJobs(root, commandLine);
  ASSERT_TRUE(list.jobs) << (list.diagnostics.empty() ? "" : interp::format(list.diagnostics[0]));
  const auto& jobs = *list.jobs;
  ASSERT_EQ(jobs.size(), 3u);  // path order; hidden folders and other files left out
  EXPECT_EQ(jobs[0].name, "alice");
  EXPECT_EQ(jobs[0].settings.setup, root / "setup.toml");
  EXPECT_EQ(jobs[0].settings.drawing, dir.path() / "common-drawing.toml");
  EXPECT_EQ(jobs[1].name, "p1");
  EXPECT_EQ(jobs[1].settings.setup, root / "p1/setup.toml");
  EXPECT_EQ(jobs[1].settings.drawing, root / "p1/drawing.toml");
  EXPECT_EQ(jobs[2].name, "p2-main");
  EXPECT_EQ(jobs[2].settings.setup, dir.path() / "common.toml");
  EXPECT_EQ(jobs[2].settings.drawing, root / "p2/drawing.stl");
  for (int i = 0; i < 3; ++i) EXPECT_EQ(jobs[i].index, i);
}

TEST(ProgramFolder, NoProgramsIsAnError) {
  ScratchDir dir("folder-empty");
  writeFile(dir.path() / "readme.txt", "");
  const JobList list = readJobs(dir.path(), {});
  ASSERT_EQ(list.diagnostics.size(), 1u);
  EXPECT_EQ(list.diagnostics[0].message,
            "no programs (*.nc, *.ngc, *.tap, *.cnc, *.gcode) in the folder or its subfolders");
  EXPECT_EQ(onlyProblem(readJobs(dir.path() / "readme.txt", {})),
            "readme.txt:0:0: a manifest must be a .toml or .csv file (or give a folder of programs)");
  EXPECT_EQ(onlyProblem(readJobs(dir.path() / "missing.toml", {})), "missing.toml:0:0: no such manifest or folder");
}

TEST(JobCommand, RunOrCheckWithTheJobsOptionsAndFolder) {
  BatchJob job;
  job.program = "p.nc";
  job.settings.setup = "s.toml";
  job.settings.voxelMm = 0.25;
  job.settings.toleranceMm = 0.1;  // only for check
  job.settings.options = {"--dialect", "hnc"};
  EXPECT_EQ(commandArguments(job, "out/p"),
            (std::vector<std::string>{"run", "p.nc", "--setup", "s.toml", "--voxel", "0.25", "--dialect", "hnc",
                                      "--out", "out/p"}));
  job.settings.drawing = "d.toml";
  EXPECT_EQ(commandArguments(job, "out/p"),
            (std::vector<std::string>{"check", "p.nc", "--setup", "s.toml", "--target", "d.toml", "--tol", "0.1",
                                      "--voxel", "0.25", "--dialect", "hnc", "--out", "out/p"}));
  job.settings.drawing.reset();
  job.settings.targetProgram = "ref.nc";
  job.settings.toleranceMm.reset();
  EXPECT_EQ(commandArguments(job, "o"), (std::vector<std::string>{"check", "p.nc", "--setup", "s.toml",
                                                                  "--target-program", "ref.nc", "--voxel", "0.25",
                                                                  "--dialect", "hnc", "--out", "o"}));
}

TEST(JobCommand, OptionValuesSpacedOrJoined) {
  const std::vector<std::string> options{"--programs", "lib", "shared", "--stock=D40xL80", "--dialect", "hnc",
                                         "--programs=more", "--stock", "D50xL90"};
  EXPECT_EQ(optionValues(options, "--programs"), (std::vector<std::string>{"lib", "shared", "more"}));
  EXPECT_EQ(optionValues(options, "--stock"), (std::vector<std::string>{"D40xL80", "D50xL90"}));
  EXPECT_EQ(optionValues(options, "--dialect"), (std::vector<std::string>{"hnc"}));
  EXPECT_EQ(optionValues(options, "--voxel"), std::vector<std::string>{});
}

TEST(JobNames, DefaultsAndRules) {
  EXPECT_EQ(defaultJobName("class/alice.nc"), "alice");
  EXPECT_EQ(defaultJobName("parts/g74-drill/program.nc"), "g74-drill");
  EXPECT_EQ(defaultJobName("program.nc"), "program");
  EXPECT_FALSE(badJobName("Zoë Ångström 3"));
  EXPECT_FALSE(badJobName("summary"));
  EXPECT_FALSE(badJobName("summary-1-of-2"));
  EXPECT_TRUE(badJobName("summary-1-of-2.json"));
  EXPECT_TRUE(badJobName(".."));
  EXPECT_TRUE(badJobName(""));
  EXPECT_TRUE(badJobName("a\\b"));
  EXPECT_TRUE(badJobName("tab\there"));
}

}  // namespace
}  // namespace lathesim::batch
