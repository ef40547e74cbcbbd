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

}  // namespace
}  // namespace lathesim::interp
