// M98/M99 in one file: calls, repeat counts (P digits and L), nesting, recursion, and the
// errors. Positions are (radius, Z); the tool starts at X200 Z200 = (100, 200).

#include <gtest/gtest.h>

#include <fmt/format.h>

#include <filesystem>
#include <fstream>

#include "../test_support.hpp"

namespace lathesim::interp {
namespace {

using test::expectError;
using test::expectMoves;
using test::kFeed;
using test::kRapid;
using test::run;

// The subprogram feeds U-2 (radius −1) each time it runs.
constexpr std::string_view kSubprogram =
    "O1000\n"           // line 4
    "G01 U-2 F0.1\n"    // 5
    "M99\n";            // 6

std::string withMain(std::string_view callBlock) {
  return "G00 X50 Z2\n" + std::string(callBlock) + "\nM30\n" + std::string(kSubprogram);
}

TEST(Subprogram, RepeatCountInFrontOfTheProgramNumber) {
  // P31000: three runs of O1000, radius 25 → 24 → 23 → 22, then M30.
  const auto result = run(withMain("M98 P31000"));
  ASSERT_TRUE(result.ok()) << result.diagnostics[0].message;
  expectMoves(result.toolpath.moves, {{kRapid, 100, 200, 25, 2, 0, 0},
                                      {kFeed, 25, 2, 24, 2, 0.1, 0},
                                      {kFeed, 24, 2, 23, 2, 0.1, 0},
                                      {kFeed, 23, 2, 22, 2, 0.1, 0}});
  // A move made by the subprogram carries the subprogram block's line.
  for (std::size_t i = 1; i < 4; ++i) EXPECT_EQ(result.toolpath.moves[i].line, 5);
}

TEST(Subprogram, FourDigitsOrFewerCallOnce) {
  const auto result = run(withMain("M98 P1000"));
  ASSERT_TRUE(result.ok()) << result.diagnostics[0].message;
  expectMoves(result.toolpath.moves,
              {{kRapid, 100, 200, 25, 2, 0, 0}, {kFeed, 25, 2, 24, 2, 0.1, 0}});
}

TEST(Subprogram, RepeatCountAsL) {
  const auto result = run(withMain("M98 P1000 L2"));
  ASSERT_TRUE(result.ok()) << result.diagnostics[0].message;
  expectMoves(result.toolpath.moves, {{kRapid, 100, 200, 25, 2, 0, 0},
                                      {kFeed, 25, 2, 24, 2, 0.1, 0},
                                      {kFeed, 24, 2, 23, 2, 0.1, 0}});
}

TEST(Subprogram, ExecutionGoesOnAfterTheCall) {
  // Line 2 calls O1000, line 3 moves in Z from where the subprogram left the tool.
  const auto result = run("G00 X50 Z2\nM98 P1000\nG00 Z5\nM30\n" + std::string(kSubprogram));
  ASSERT_TRUE(result.ok()) << result.diagnostics[0].message;
  expectMoves(result.toolpath.moves, {{kRapid, 100, 200, 25, 2, 0, 0},
                                      {kFeed, 25, 2, 24, 2, 0.1, 0},
                                      {kRapid, 24, 2, 24, 5, 0, 0}});
  EXPECT_EQ(result.toolpath.moves[2].line, 3);
}

// Main → O1 → O2 → O3 → O4 is four levels; each level feeds U-2 before calling the next.
std::string nested(int levels) {
  std::string text = "G00 X50 Z2 F0.1\nM98 P1\nM30\n";
  for (int level = 1; level <= levels; ++level) {
    text += fmt::format("O{}\nG01 U-2\n", level);
    if (level < levels) text += fmt::format("M98 P{}\n", level + 1);
    text += "M99\n";
  }
  return text;
}

TEST(Subprogram, FourLevelsNest) {
  const auto result = run(nested(4));
  ASSERT_TRUE(result.ok()) << result.diagnostics[0].message;
  expectMoves(result.toolpath.moves, {{kRapid, 100, 200, 25, 2, 0, 0},
                                      {kFeed, 25, 2, 24, 2, 0.1, 0},
                                      {kFeed, 24, 2, 23, 2, 0.1, 0},
                                      {kFeed, 23, 2, 22, 2, 0.1, 0},
                                      {kFeed, 22, 2, 21, 2, 0.1, 0}});
}

TEST(Subprogram, FifthLevelIsAnError) {
  // Lines: 1–3 main, O1 4–7, O2 8–11, O3 12–15, O4 16–19 (its M98 P5 on line 18).
  expectError(run(nested(5)), 18, 5,
              "M98 calls O0005 from 4 levels of subprograms (O0001 → O0002 → O0003 → O0004 → "
              "O0005): the control nests at most 4 levels");
}

TEST(Subprogram, DirectRecursionIsAnErrorNamingTheChain) {
  expectError(run("M98 P1000\nM30\nO1000\nM98 P1000\nM99\n"), 4, 5,
              "M98 calls O1000 while it is already running (O1000 → O1000)");
}

TEST(Subprogram, IndirectRecursionIsAnErrorNamingTheChain) {
  expectError(run("M98 P1000\nM30\nO1000\nM98 P2000\nM99\nO2000\nM98 P1000\nM99\n"), 7, 5,
              "(O1000 → O2000 → O1000)");
}

TEST(Subprogram, MainProgramCallingItselfIsRecursion) {
  expectError(run("O0001\nM98 P1\nM30\n"), 2, 5, "(O0001 → O0001)");
}

TEST(Subprogram, UnknownProgramIsAnError) {
  expectError(run(withMain("M98 P1234")), 2, 5, "M98 calls O1234, which is neither in this program nor in a file");
}

TEST(Subprogram, M99EndingTheMainProgramRunsItOnceWithAWarning) {
  // The control would start the program over, forever: simulated once, and said.
  const auto result = run("G00 X50\nM99\nG00 X60\n");
  ASSERT_TRUE(result.ok()) << result.diagnostics[0].message;
  expectMoves(result.toolpath.moves, {{kRapid, 100, 200, 25, 200, 0, 0}});
  ASSERT_EQ(result.diagnostics.size(), 1u);
  EXPECT_EQ(result.diagnostics[0].line, 2);
  EXPECT_EQ(result.diagnostics[0].message,
            "M99 ends the main program: the control runs it again from the start, forever; lathesim simulates it once");
}

TEST(Subprogram, TextEndingInsideASubprogramIsAnError) {
  expectError(run("M98 P1000\nM30\nO1000\nG00 X10\n"), 1, 5,
              "O1000 called here has no M99: the program text ends inside it");
}

TEST(Subprogram, M98NeedsP) { expectError(run("M98 L2\n"), 1, 1, "M98 needs P"); }

TEST(Subprogram, CountGivenTwiceIsAnError) {
  expectError(run(withMain("M98 P21000 L2")), 2, 12, "P21000 and L2 both give the repeat count");
}

TEST(Subprogram, ZeroRepeatCountIsAnError) {
  expectError(run(withMain("M98 P01000")), 2, 5,
              "P01000: the digits before the four-digit program number are the repeat count, "
              "expected 1 to 9999");
}

TEST(Subprogram, LMustBeAWholeCount) {
  expectError(run(withMain("M98 P1000 L0")), 2, 11, "L0 is not a repeat count");
}

TEST(Subprogram, ProgramNumberWithADecimalPointIsAnError) {
  expectError(run(withMain("M98 P1000.")), 2, 5, "P1000. is not a program number");
}

TEST(Subprogram, M99PReturnsToThatSequenceOfTheCaller) {
  // O1000 feeds U-2 and returns to N20, skipping N10's G00 X80: then N20's G00 Z10.
  const auto result = run("G00 X50 Z2\nM98 P1000\nN10 G00 X80\nN20 G00 Z10\nM30\nO1000\nG01 U-2 F0.1\nM99 P20\n");
  ASSERT_TRUE(result.ok()) << result.diagnostics[0].message;
  expectMoves(result.toolpath.moves, {{kRapid, 100, 200, 25, 2, 0, 0},
                                      {kFeed, 25, 2, 24, 2, 0.1, 0},
                                      {kRapid, 24, 2, 24, 10, 0, 0}});
  // After the last of several runs only; a number the caller lacks is an error at P.
  const auto twice = run("G00 X50 Z2\nM98 P21000\nN10 G00 X80\nN20 G00 Z10\nM30\nO1000\nG01 U-2 F0.1\nM99 P20\n");
  ASSERT_TRUE(twice.ok());
  EXPECT_EQ(twice.toolpath.moves.back().to, RZ(23, 10));
  expectError(run("M98 P1000\nM30\nO1000\nM99 P10\n"), 4, 5,
              "M99 P10 returns to N10 of the calling program, which has no block N10");
}

}  // namespace
}  // namespace lathesim::interp

namespace lathesim::interp {
namespace {

TEST(Subprogram, ColonProgramNumbersNameSubprogramsToo) {
  // `:0100` is O0100: M98 P100 calls it (leading zeros do not matter), twice by L2.
  const auto result = test::run(":0001 (MAIN)\nG00 X50 Z2\nM98 P100 L2\nM30\n:0100\nG01 U-2 F0.1\nM99\n");
  ASSERT_TRUE(result.ok()) << result.diagnostics[0].message;
  test::expectMoves(result.toolpath.moves, {{test::kRapid, 100, 200, 25, 2, 0, 0},
                                            {test::kFeed, 25, 2, 24, 2, 0.1, 0},
                                            {test::kFeed, 24, 2, 23, 2, 0.1, 0}});
}

}  // namespace
}  // namespace lathesim::interp

namespace lathesim::interp {
namespace {

namespace fs = std::filesystem;

// A directory of program files for one test, removed after it.
class ProgramDirectory {
 public:
  explicit ProgramDirectory(const std::string& name) : path_(fs::temp_directory_path() / ("lathesim_" + name)) {
    fs::remove_all(path_);
    fs::create_directories(path_);
  }
  ~ProgramDirectory() { fs::remove_all(path_); }
  void write(const std::string& file, std::string_view text) const { std::ofstream(path_ / file) << text; }
  const fs::path& path() const { return path_; }

 private:
  fs::path path_;
};

InterpreterOptions searching(std::vector<fs::path> directories) {
  InterpreterOptions options = test::defaultOptions();
  options.programDirectories = std::move(directories);
  return options;
}

constexpr std::string_view kMain = "G00 X50 Z2\nM98 P17615\nG00 X60\nM30\n";  // line 2 calls O7615 once

TEST(ExternalSubprogram, FoundBesideTheProgramUnderEachNameInOrder) {
  // Each name alone is found; its move carries its line in the file (3: G01 U-4), and its
  // source names the file and the calling M98 (line 2 of the program).
  for (const std::string name : {"O7615", "o7615.NC", "7615.nc", "7615.tap", "O7615.txt"}) {
    SCOPED_TRACE(name);
    ProgramDirectory dir("external_" + std::to_string(std::hash<std::string>{}(name)));
    dir.write(name, "%\nO7615 (SUB)\nG01 U-4 F0.1\nM99\n%\n");
    const auto result = test::run(kMain, searching({dir.path()}));
    ASSERT_TRUE(result.ok()) << result.diagnostics[0].message;
    test::expectMoves(result.toolpath.moves, {{test::kRapid, 100, 200, 25, 2, 0, 0},
                                              {test::kFeed, 25, 2, 23, 2, 0.1, 0},
                                              {test::kRapid, 23, 2, 30, 2, 0, 0}});
    EXPECT_EQ(result.toolpath.moves[1].line, 3);
    const int source = result.toolpath.moves[1].source;
    EXPECT_EQ(source, 1);
    EXPECT_EQ(result.toolpath.fileOf(source), (dir.path() / name).string());
    EXPECT_EQ(result.toolpath.calledFrom(source), "called from test.nc:2");
    EXPECT_EQ(result.toolpath.moves[0].source, 0);
    EXPECT_EQ(result.toolpath.moves[2].source, 0);
  }
}

TEST(ExternalSubprogram, SearchOrderDirectoriesFirstThenNames) {
  ProgramDirectory first("external_first");
  ProgramDirectory second("external_second");
  first.write("7615.nc", "G01 U-2 F0.1\nM99\n");   // a file without its O line is the program
  second.write("O7615", "G01 U-8 F0.1\nM99\n");
  // The first directory wins, though the second holds a name tried earlier.
  auto result = test::run(kMain, searching({first.path(), second.path()}));
  ASSERT_TRUE(result.ok()) << result.diagnostics[0].message;
  EXPECT_NEAR(result.toolpath.moves[1].to.x(), 24, 1e-12);
  // Within one directory, O7615 comes before 7615.nc.
  first.write("O7615", "G01 U-6 F0.1\nM99\n");
  result = test::run(kMain, searching({first.path(), second.path()}));
  ASSERT_TRUE(result.ok()) << result.diagnostics[0].message;
  EXPECT_NEAR(result.toolpath.moves[1].to.x(), 22, 1e-12);
}

TEST(ExternalSubprogram, CountInPAndInLAndNesting) {
  ProgramDirectory dir("external_nesting");
  dir.write("O7615.nc", "O7615\nG01 U-2 F0.1\nM98 P7616\nM99\n");
  dir.write("O7616.nc", "O7616\nG01 W-1\nM99\n");
  // P27615: twice; each run feeds U-2 then calls O7616 (W-1).
  const auto result = test::run("G00 X50 Z2\nM98 P27615\nM30\n", searching({dir.path()}));
  ASSERT_TRUE(result.ok()) << result.diagnostics[0].message;
  test::expectMoves(result.toolpath.moves, {{test::kRapid, 100, 200, 25, 2, 0, 0},
                                            {test::kFeed, 25, 2, 24, 2, 0.1, 0},
                                            {test::kFeed, 24, 2, 24, 1, 0.1, 0},
                                            {test::kFeed, 24, 1, 23, 1, 0.1, 0},
                                            {test::kFeed, 23, 1, 23, 0, 0.1, 0}});
  const auto withL = test::run("G00 X50 Z2\nM98 P7615 L2\nM30\n", searching({dir.path()}));
  ASSERT_TRUE(withL.ok());
  EXPECT_EQ(withL.toolpath.moves.size(), result.toolpath.moves.size());
}

TEST(ExternalSubprogram, AnErrorInsideItNamesItsFileAndLine) {
  ProgramDirectory dir("external_error");
  dir.write("O7615.nc", "O7615\nG01 U-2 F0.1\nG01 X20.3.\nM99\n");
  const auto result = test::run(kMain, searching({dir.path()}));
  ASSERT_FALSE(result.ok());
  const Diagnostic& d = result.diagnostics.at(0);
  EXPECT_EQ(d.file, (dir.path() / "O7615.nc").string());
  EXPECT_EQ(d.line, 3);
  EXPECT_EQ(d.column, 5);
  EXPECT_EQ(d.sourceLine, "G01 X20.3.");
}

// Machine M codes (the GSK's M32/M33 lubrication, M41 gear range) in a subprogram's file are
// listed as ignored as the main program's are: each code once in the whole run, at the first
// place that names it, in its file. M41 is the main program's already; the file's second M32
// and its second run (P2…) add nothing.
TEST(ExternalSubprogram, ItsMachineMCodesAreNotedOnceInItsFile) {
  ProgramDirectory dir("external_machine_codes");
  dir.write("O7615.nc", "O7615\nM32\nG01 U-2 F0.1\nM41\nM33 M32\nM99\n");
  const auto result = test::run("G00 X50 Z2\nM41\nM98 P27615\nM30\n", searching({dir.path()}));
  ASSERT_TRUE(result.ok()) << result.diagnostics[0].message;
  const std::vector<Diagnostic> notes = test::notesOf(result);
  ASSERT_EQ(notes.size(), 3u);
  const std::string file = (dir.path() / "O7615.nc").string();
  EXPECT_EQ(notes[0].file, "test.nc");
  EXPECT_EQ(notes[0].line, 2);
  EXPECT_NE(notes[0].message.find("M41"), std::string::npos) << notes[0].message;
  EXPECT_EQ(notes[1].file, file);
  EXPECT_EQ(notes[1].line, 2);
  EXPECT_EQ(notes[1].column, 1);
  EXPECT_NE(notes[1].message.find("M32"), std::string::npos) << notes[1].message;
  EXPECT_NE(notes[1].message.find("ignored"), std::string::npos) << notes[1].message;
  EXPECT_EQ(notes[2].file, file);
  EXPECT_EQ(notes[2].line, 5);
  EXPECT_EQ(notes[2].column, 1);
  EXPECT_NE(notes[2].message.find("M33"), std::string::npos) << notes[2].message;
  EXPECT_EQ(notes[2].sourceLine, "M33 M32");
}

TEST(ExternalSubprogram, MissingNamesWhatWasLookedForWhere) {
  ProgramDirectory dir("external_missing");
  const auto result = test::run(kMain, searching({dir.path()}));
  test::expectError(result, 2, 5, "M98 calls O7615, which is neither in this program nor in a file");
  EXPECT_NE(result.diagnostics[0].message.find(dir.path().string()), std::string::npos);
}

}  // namespace
}  // namespace lathesim::interp
