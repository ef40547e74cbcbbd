// Golden toolpaths: each tests/interp/golden/NAME.nc is interpreted and its moves compared
// with NAME.csv, written by hand from the spec (X as diameters, as in the program).

#include <gtest/gtest.h>

#include "tests/support/golden_rows.hpp"

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include "interp/interpreter.hpp"
#include "interp/toolpath_csv.hpp"
#include "test_support.hpp"

namespace lathesim::interp {
namespace {

namespace fs = std::filesystem;

std::string readFile(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

void expectMatchesGolden(const std::string& name) {
  const fs::path dir = LATHESIM_INTERP_GOLDEN_DIR;
  const auto result = interpret(readFile(dir / (name + ".nc")), name + ".nc",
                                test::defaultOptions());
  ASSERT_TRUE(result.ok()) << format(result.diagnostics.at(0));

  std::ifstream goldenFile(dir / (name + ".csv"));
  lathesim::test::expectSameRows(lathesim::test::rowsOf(result.toolpath), readToolpathCsv(goldenFile), name + ".csv");
}

TEST(GoldenToolpath, Seed000FaceCycleExample) { expectMatchesGolden("seed000_g94"); }

// Positions (radius, Z). Line 4: (10,-2) → (10,-10), chord 8 leftwards, centres 3 either side
// of (10,-6); G02 R5 takes the right of the travel, up: (13,-6), X26. Line 5: (10,-10) →
// (10,-18); G03 R5 would take the left, (7,-14); R-5 takes the other, (13,-14), X26. Line 6
// (G03 still): (10,-18) → (15,-23) about (10+5, -18) = (15,-18), X30, 5 from both ends.
// Line 7: I-5 with no end point: a full circle about (10,-23), X20.
TEST(GoldenToolpath, Arcs) { expectMatchesGolden("arcs"); }

}  // namespace
}  // namespace lathesim::interp
