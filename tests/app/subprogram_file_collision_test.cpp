// A crash inside a subprogram kept in a file of its own (M98 P2000 → O2000.nc in --programs)
// is located in that file, at the line of the block that made it, with the M98 that called it
// as context: "O2000.nc:3:1: error: … (called from main.nc:4)".
//
// The bar and the crash are crash_cli_test's: seed 001's bar (Φ50, face at Z0), the default
// tool at X30 rapids 1 mm into the face (575.96 mm³ by Pappus there). The subprogram's rapid
// is incremental (W-3.), so where it ends depends on where the call finds the tool: from Z5 it
// ends at Z2, in the air; from Z2 at Z-1, in the bar. So which call crashed is known by hand.

#include <gtest/gtest.h>

#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "tests/support/lathesim_process.hpp"

namespace lathesim::app {
namespace {

namespace fs = std::filesystem;
using test::lathesim;
using test::readFile;
using test::ScratchDir;
using test::writeFile;

const fs::path kSubprogramSetup = fs::path(LATHESIM_PARTS_DIR) / "seed001-taper-r20" / "setup.toml";

struct SubprogramRun {
  test::ProcessOutcome outcome;
  nlohmann::json collisions;
};

// Runs main.nc with the files `subprograms` (name → text) in DIR/subs, given as --programs.
SubprogramRun runWithSubprograms(ScratchDir& dir, const std::string& main,
                                 const std::vector<std::pair<std::string, std::string>>& subprograms) {
  const fs::path subs = dir.path() / "subs", out = dir.path() / "out";
  fs::create_directories(subs);
  for (const auto& [name, text] : subprograms) writeFile(subs / name, text);
  writeFile(dir.path() / "main.nc", main);
  SubprogramRun run;
  run.outcome = lathesim({"run", (dir.path() / "main.nc").string(), "--setup", kSubprogramSetup.string(), "--programs",
                          subs.string(), "--out", out.string(), "--voxel", "0.25"},
                         dir.path());
  if (fs::exists(out / "report.json")) run.collisions = nlohmann::json::parse(readFile(out / "report.json")).at("collisions");
  return run;
}

// O2000 with its rapid into the bar as its block `wrong` (1-based line of the file; line 1 is
// the O line), the others harmless.
std::string subprogramWithCrashAt(int wrong) {
  std::string text = "O2000;\n";
  for (int line = 2; line <= 5; ++line) text += line == wrong ? "G00 Z-1.;\n" : "M03 S500;\n";
  return text + "G00 X54 Z5;\nM99;\n";
}

TEST(SubprogramFileCollision, IsAnErrorAtTheLineOfTheSubprogramsFileSweptOverWhichBlockIsWrong) {
  for (int wrong = 2; wrong <= 5; ++wrong) {
    ScratchDir dir("subfile-crash-" + std::to_string(wrong));
    const auto run = runWithSubprograms(dir, "M03 S500;\nG00 X54 Z5;\nG00 X30 Z2;\nM98 P2000;\nM30;\n",
                                        {{"O2000.nc", subprogramWithCrashAt(wrong)}});
    EXPECT_EQ(run.outcome.status, 4) << run.outcome.err;
    const std::string file = (dir.path() / "subs" / "O2000.nc").string();
    const std::string located = file + ":" + std::to_string(wrong) + ":1: error: rapid into the stock removes ";
    const auto at = run.outcome.err.find(located);
    ASSERT_NE(at, std::string::npos) << "block " << wrong << "\n" << run.outcome.err;
    EXPECT_NE(run.outcome.err.find("(the tool ends at X30 Z-1) (called from " + (dir.path() / "main.nc").string() +
                                       ":4)\nG00 Z-1.;\n^",
                                   at),
              std::string::npos)
        << run.outcome.err;
    ASSERT_EQ(run.collisions.size(), 1u) << run.collisions.dump();
    EXPECT_EQ(run.collisions[0].at("file"), file);
    EXPECT_EQ(run.collisions[0].at("line"), wrong);
    EXPECT_EQ(run.collisions[0].at("block"), "G00 Z-1.;");
  }
}

TEST(SubprogramFileCollision, NamesTheCallThatLedToItWhenCalledFromTwoLines) {
  ScratchDir dir("subfile-two-calls");
  // The first call (line 3) takes the tool from Z5 to Z2; the second (line 4) from Z2 to Z-1.
  const auto run = runWithSubprograms(dir, "M03 S500;\nG00 X30 Z5;\nM98 P2000;\nM98 P2000;\nG00 X54 Z5;\nM30;\n",
                                      {{"O2000.nc", "O2000;\nM03 S500;\nG00 W-3.;\nM99;\n"}});
  EXPECT_EQ(run.outcome.status, 4) << run.outcome.err;
  const std::string main = (dir.path() / "main.nc").string();
  EXPECT_NE(run.outcome.err.find((dir.path() / "subs" / "O2000.nc").string() +
                                 ":3:1: error: rapid into the stock removes "),
            std::string::npos)
      << run.outcome.err;
  EXPECT_NE(run.outcome.err.find("(called from " + main + ":4)\nG00 W-3.;\n^"), std::string::npos) << run.outcome.err;
  EXPECT_EQ(run.outcome.err.find("called from " + main + ":3"), std::string::npos) << run.outcome.err;
  ASSERT_EQ(run.collisions.size(), 1u) << run.collisions.dump();
  EXPECT_EQ(run.collisions[0].at("line"), 3);
}

TEST(SubprogramFileCollision, NamesEveryCallOfANestedCall) {
  ScratchDir dir("subfile-nested");
  const auto run = runWithSubprograms(dir, "M03 S500;\nG00 X54 Z5;\nG00 X30 Z2;\nM98 P2000;\nM30;\n",
                                      {{"O2000.nc", "O2000;\nM98 P3000;\nM99;\n"},
                                       {"O3000.nc", "O3000;\nM03 S500;\nG00 Z-1.;\nG00 X54 Z5;\nM99;\n"}});
  EXPECT_EQ(run.outcome.status, 4) << run.outcome.err;
  const fs::path subs = dir.path() / "subs";
  EXPECT_NE(run.outcome.err.find((subs / "O3000.nc").string() + ":3:1: error: rapid into the stock removes "),
            std::string::npos)
      << run.outcome.err;
  EXPECT_NE(run.outcome.err.find("(called from " + (subs / "O2000.nc").string() + ":2, from " +
                                 (dir.path() / "main.nc").string() + ":4)\nG00 Z-1.;\n^"),
            std::string::npos)
      << run.outcome.err;
}

TEST(SubprogramFileCollision, TheMainProgramsOwnCrashStaysAtItsOwnLine) {
  ScratchDir dir("subfile-main-crash");
  // The subprogram runs first and cuts nothing; the main program's line 5 crashes.
  const auto run = runWithSubprograms(dir, "M03 S500;\nG00 X54 Z5;\nM98 P2000;\nG00 X30 Z2;\nG00 Z-1.;\nG00 X54 Z5;\nM30;\n",
                                      {{"O2000.nc", "O2000;\nG00 X60 Z10;\nM99;\n"}});
  EXPECT_EQ(run.outcome.status, 4) << run.outcome.err;
  const std::string main = (dir.path() / "main.nc").string();
  const auto at = run.outcome.err.find(main + ":5:1: error: rapid into the stock removes ");
  ASSERT_NE(at, std::string::npos) << run.outcome.err;
  EXPECT_NE(run.outcome.err.find("(the tool ends at X30 Z-1)\nG00 Z-1.;\n^", at), std::string::npos) << run.outcome.err;
  ASSERT_EQ(run.collisions.size(), 1u);
  EXPECT_EQ(run.collisions[0].at("file"), main);
}

}  // namespace
}  // namespace lathesim::app
