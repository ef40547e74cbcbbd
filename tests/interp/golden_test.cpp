// Golden toolpaths: each tests/interp/golden/NAME.nc is interpreted and its moves compared
// with NAME.csv, written by hand from the spec (X as diameters, as in the program).

#include <gtest/gtest.h>

#include "tests/support/golden_rows.hpp"

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include "interp/interpreter.hpp"
#include "interp/output/toolpath_csv.hpp"
#include "test_support.hpp"
#include "tests/support/files.hpp"

namespace lathesim::interp {
namespace {

namespace fs = std::filesystem;

using lathesim::test::readFile;

void expectMatchesGolden(const std::string& name) {
  const fs::path dir = LATHESIM_INTERP_GOLDEN_DIR;
  // The rapids as the default control makes them: each axis at its own rate (a dog-leg).
  InterpreterOptions options = test::defaultOptions();
  options.control.rapidPath = RapidPath::NonLinear;
  const auto result = interpret(readFile(dir / (name + ".nc")), name + ".nc", options);
  ASSERT_TRUE(result.ok()) << format(result.diagnostics.at(0));

  std::ifstream goldenFile(dir / (name + ".csv"));
  lathesim::test::expectSameRows(lathesim::test::rowsOf(result.toolpath), readToolpathCsv(goldenFile), name + ".csv");
}

// Rapid rates X 6000 mm/min (radius), Z 8000. Line 2: X200 Z200 → X130 Z5: Δr 35 takes
// 35/6000 min, ΔZ 195 takes 195/8000: X arrives first, Z having moved 8000·35/6000 = 46.667,
// so the corner is X130 Z153.333, then Z alone. Line 5: X130 Z5 → X120 Z0: Δr 5 takes 5/6000,
// ΔZ 5 takes 5/8000: Z arrives first, X having moved 6000·5/8000 = 3.75 of radius: the corner
// is X122.5 Z0, then X alone.
TEST(GoldenToolpath, Seed000FaceCycleExample) { expectMatchesGolden("seed000_g94"); }

// Positions (radius, Z). Line 4: (10,-2) → (10,-10), chord 8 leftwards, centres 3 either side
// of (10,-6); G02 R5 takes the right of the travel, up: (13,-6), X26. Line 5: (10,-10) →
// (10,-18); G03 R5 would take the left, (7,-14); R-5 takes the other, (13,-14), X26. Line 6
// (G03 still): (10,-18) → (15,-23) about (10+5, -18) = (15,-18), X30, 5 from both ends.
// Line 7: I-5 with no end point: a full circle about (10,-23), X20.
// Rapids (X 6000, Z 8000 mm/min): line 2, X200 Z200 → X20 Z0: Δr 90 takes 90/6000 = 0.015 min,
// ΔZ 200 takes 0.025: X first, Z having moved 120: corner X20 Z80. Line 8, X30 Z-23 → X200
// Z200: Δr 85 takes 85/6000, ΔZ 223 takes 223/8000: X first, Z having moved 8000·85/6000 =
// 113.333: corner X200 Z90.333.
TEST(GoldenToolpath, Arcs) { expectMatchesGolden("arcs"); }

}  // namespace
}  // namespace lathesim::interp
