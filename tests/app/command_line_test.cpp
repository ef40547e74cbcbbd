// The command's contract with scripts: its exit statuses (0 done, 1 bad input, 2 bad command
// line; 3, out of tolerance, is check_cli_test's; 130 and 143 interrupted_run_test's),
// --version, --help with an example for every subcommand, and messages that never hand a
// terminal the control characters a program holds.

#include <gtest/gtest.h>

#include <filesystem>
#include <string>
#include <vector>

#include "tests/support/lathesim_process.hpp"

namespace lathesim::app {
namespace {

namespace fs = std::filesystem;
using test::readFile;
using test::lathesim;
using test::writeFile;

using test::kPartsDir;

using test::partFile;

bool hasRawControlCharacter(const std::string& text) {
  for (char c : text) {
    const auto byte = static_cast<unsigned char>(c);
    if ((byte < 0x20 && c != '\n' && c != '\t') || byte == 0x7F) return true;
  }
  return false;
}

// Every way a command line can be wrong exits 2 and says what is wrong, writing nothing.
TEST(ExitStatus, BadCommandLinesExitTwo) {
  test::ScratchDir scratch("cmdline");
  const std::string program = partFile("seed001-taper-r24", "program.nc");
  const std::string out = (scratch.path() / "out").string();
  const std::vector<std::pair<std::vector<std::string>, std::string>> cases = {
      {{}, "subcommand is required"},
      {{"fly"}, "fly"},
      {{"run"}, "program is required"},
      {{"run", (scratch.path() / "missing.nc").string(), "--out", out}, "missing.nc"},
      {{"run", program, "--bogus", "--out", out}, "--bogus"},
      {{"run", program, "--voxel", "abc", "--out", out}, "abc"},
      {{"run", program, "--voxel", "-0.2", "--out", out}, "-0.2"},
      {{"run", program, "--voxel", "--out", out}, "--voxel"},
      {{"run", program, "--at-line", "0", "--out", out}, "--at-line"},
      {{"run", program, "--stock", "D40", "--out", out}, "--stock"},
      {{"run", program, "--control", "okuma-osp", "--out", out}, "okuma-osp"},
      {{"run", program, "--dialect", "siemens", "--out", out}, "siemens"},
      {{"run", program, "--block-skip", "maybe", "--out", out}, "maybe"},
      {{"run", program, "--max-moves", "0", "--out", out}, "--max-moves"},
      {{"check", program, "--out", out}, "--target"},
      {{"check", program, "--target", partFile("seed001-taper-r24", "drawing.toml"), "--tol", "-1", "--out", out}, "--tol"},
      {{"expand", program, "--setup", (scratch.path() / "none.toml").string()}, "none.toml"},
      {{"batch"}, "manifest"},
      {{"batch", kPartsDir.string(), "--shard", "3/2", "--out", out}, "3/2"},
      {{"batch", "merge"}, "summaries"},
  };
  for (const auto& [args, named] : cases) {
    std::string shown;
    for (const auto& a : args) shown += a + " ";
    SCOPED_TRACE(shown);
    const auto outcome = lathesim(args, scratch.path());
    EXPECT_EQ(outcome.status, 2) << outcome.err;
    EXPECT_NE(outcome.err.find(named), std::string::npos) << outcome.err;
    EXPECT_FALSE(fs::exists(out));
  }
}

TEST(ExitStatus, BadProgramExitsOneAndGoodRunZero) {
  test::ScratchDir scratch("status");
  writeFile(scratch.path() / "bad.nc", "G00 X20 Z2\nG01 X10.5.5 F0.1\nM30\n");
  EXPECT_EQ(lathesim({"expand", (scratch.path() / "bad.nc").string()}, scratch.path()).status, 1);
  const auto good = lathesim({"expand", partFile("seed001-taper-r24", "program.nc"), "--setup",
                              partFile("seed001-taper-r24", "setup.toml")},
                             scratch.path());
  EXPECT_EQ(good.status, 0) << good.err;
}

// Seed 001 makes 6 moves (its first rapid is a dog-leg): 6 pass, 5 are refused with the figure.
TEST(ExitStatus, MoreMovesThanTheLimitIsABadProgram) {
  test::ScratchDir scratch("max-moves");
  const auto args = [&](const char* limit) {
    return std::vector<std::string>{"expand", partFile("seed001-taper-r24", "program.nc"), "--setup",
                                    partFile("seed001-taper-r24", "setup.toml"), "--max-moves", limit};
  };
  EXPECT_EQ(lathesim(args("6"), scratch.path()).status, 0);
  const auto refused = lathesim(args("5"), scratch.path());
  EXPECT_EQ(refused.status, 1);
  EXPECT_NE(refused.err.find("program.nc:2:1: error: the program makes more than 5 moves (the limit)"), std::string::npos)
      << refused.err;
}

TEST(CommandLine, VersionNamesTheProgramAndExitsZero) {
  test::ScratchDir scratch("version");
  const auto outcome = lathesim({"--version"}, scratch.path());
  EXPECT_EQ(outcome.status, 0);
  EXPECT_EQ(outcome.out.rfind("lathesim ", 0), 0u) << outcome.out;
  EXPECT_NE(outcome.out.find_first_of("0123456789"), std::string::npos) << outcome.out;
}

// Each subcommand's help shows its options, an example command line, and the exit statuses.
TEST(CommandLine, HelpOfEverySubcommandHasAnExample) {
  test::ScratchDir scratch("help");
  const std::vector<std::pair<std::vector<std::string>, std::string>> cases = {
      {{"run", "--help"}, "lathesim run parts/"},
      {{"check", "--help"}, "lathesim check parts/"},
      {{"expand", "--help"}, "lathesim expand parts/"},
      {{"batch", "--help"}, "lathesim batch parts"},
      {{"batch", "merge", "--help"}, "lathesim batch merge "},
  };
  for (const auto& [args, example] : cases) {
    SCOPED_TRACE(args.front());
    const auto outcome = lathesim(args, scratch.path());
    EXPECT_EQ(outcome.status, 0) << outcome.err;
    EXPECT_NE(outcome.out.find("Example:\n  " + example), std::string::npos) << outcome.out;
    if (args.front() != "batch") {
      EXPECT_NE(outcome.out.find("Exit status: 0 done"), std::string::npos) << outcome.out;
    }
  }
  // The examples name files that exist (a help that shows a broken command is worse than none).
  for (const char* file : {"seed000-face-taper/program.nc", "seed000-face-taper/setup.toml",
                           "seed001-taper-r20/drawing.toml", "g71-g70-shaft/setup.toml"})
    EXPECT_TRUE(fs::exists(kPartsDir / file)) << file;
}

// A program that opens with ESC and hides one inside: the error quotes the line with ESC
// written out, the caret still under the character it means.
TEST(TerminalSafety, ControlCharactersInAProgramAreEscapedInMessages) {
  test::ScratchDir scratch("escape");
  const fs::path program = scratch.path() / "esc.nc";
  writeFile(program, "\x1b\x12%\nG00 X10 Z10\n\x1b[2JG01 X5 F0.1\nM30\n");  // a DNC leader, then ESC inside
  const auto outcome = lathesim({"expand", program.string()}, scratch.path());
  EXPECT_EQ(outcome.status, 1);
  EXPECT_FALSE(hasRawControlCharacter(outcome.err)) << outcome.err;
  EXPECT_NE(outcome.err.find("esc.nc:3:1: error: control character ESC (0x1B)"), std::string::npos) << outcome.err;
  EXPECT_NE(outcome.err.find("\n\\x1b[2JG01 X5 F0.1\n^"), std::string::npos) << outcome.err;

  // Further along the line, the caret moves by the escape's width (four), not one.
  writeFile(program, "G00 X10 Z10\nG01 X5 (\x07) Z2 @ F0.1\nM30\n");
  const auto later = lathesim({"expand", program.string()}, scratch.path());
  EXPECT_EQ(later.status, 1);
  EXPECT_NE(later.err.find(":2:15: error: unexpected character '@'"), std::string::npos) << later.err;
  EXPECT_NE(later.err.find("\nG01 X5 (\\x07) Z2 @ F0.1\n" + std::string(17, ' ') + "^"), std::string::npos) << later.err;
}

// Bytes that are not UTF-8, and a file name holding ESC, are written out too.
TEST(TerminalSafety, InvalidUtf8AndFileNamesAreEscaped) {
  test::ScratchDir scratch("escape-name");
  const fs::path program = scratch.path() / "bad\x1b[0mname.nc";
  writeFile(program, "G00 X10 Z10\nG01 X5 \xff\xfe F0.1\nM30\n");
  const auto outcome = lathesim({"expand", program.string()}, scratch.path());
  EXPECT_EQ(outcome.status, 1);
  EXPECT_FALSE(hasRawControlCharacter(outcome.err)) << outcome.err;
  EXPECT_NE(outcome.err.find("bad\\x1b[0mname.nc:2:8: error:"), std::string::npos) << outcome.err;
  EXPECT_NE(outcome.err.find("'\\xff'"), std::string::npos) << outcome.err;

  // A bad command line naming such a file: the same.
  const auto missing = lathesim({"run", (scratch.path() / "gone\x1b]0;title\x07.nc").string()}, scratch.path());
  EXPECT_EQ(missing.status, 2);
  EXPECT_FALSE(hasRawControlCharacter(missing.err)) << missing.err;
  EXPECT_NE(missing.err.find("gone\\x1b]0;title\\x07.nc"), std::string::npos) << missing.err;
}

}  // namespace
}  // namespace lathesim::app
