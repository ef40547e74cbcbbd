// Golden toolpaths: each tests/interp/golden/NAME.nc is interpreted and its moves compared
// with NAME.csv, written by hand from the spec (X as diameters, as in the program).

#include <gtest/gtest.h>

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

  std::stringstream written;
  writeToolpathCsv(result.toolpath, written);
  const auto actual = readToolpathCsv(written);
  std::ifstream goldenFile(dir / (name + ".csv"));
  const auto expected = readToolpathCsv(goldenFile);

  ASSERT_EQ(actual.size(), expected.size());
  for (std::size_t i = 0; i < expected.size(); ++i) {
    SCOPED_TRACE(testing::Message() << name << ".csv row " << i + 2);
    EXPECT_EQ(actual[i].line, expected[i].line);
    EXPECT_EQ(actual[i].kind, expected[i].kind);
    EXPECT_NEAR(actual[i].x0, expected[i].x0, 1e-4);
    EXPECT_NEAR(actual[i].z0, expected[i].z0, 1e-4);
    EXPECT_NEAR(actual[i].x1, expected[i].x1, 1e-4);
    EXPECT_NEAR(actual[i].z1, expected[i].z1, 1e-4);
    EXPECT_NEAR(actual[i].feed, expected[i].feed, 1e-4);
  }
}

TEST(GoldenToolpath, Seed000FaceCycleExample) { expectMatchesGolden("seed000_g94"); }

}  // namespace
}  // namespace lathesim::interp
