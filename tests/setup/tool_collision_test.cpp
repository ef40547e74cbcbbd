// Catalogue tools end to end: the seed's STFCR2525M11 + TBHG120408 from a setup file, run
// through the interpreter and the simulation with its holder body and the chuck checked.

#include <gtest/gtest.h>

#include "setup/collision_checks.hpp"
#include "setup/setup.hpp"
#include "interp/interpreter.hpp"
#include "sim/simulate.hpp"

namespace lathesim::setup {
namespace {

// Φ50 × 60 bar, face Z0; the default chuck: jaws r 25..45 over Z −80..−60, behind the bar.
constexpr std::string_view kSetup = R"([stock]
diameter = 50
length = 60
face_z = 0
[machine]
start = [100, 50]
[[tool]]
number = 1
insert = "TBHG120408"
holder = "STFCR2525M11"
)";

std::vector<sim::Collision> collisionsOf(std::string_view program) {
  const SetupResult setup = parseSetup(kSetup, "setup.toml");
  EXPECT_TRUE(setup.setup.has_value());
  interp::InterpreterOptions options;
  options.startPosition = setup.setup->startPosition;
  options.toolNumbers = {1};
  const interp::InterpretResult run = interp::interpret(program, "program.nc", options);
  EXPECT_TRUE(run.ok()) << (run.diagnostics.empty() ? "" : run.diagnostics[0].message);
  sim::Stock stock(setup.setup->stock, 0.25);
  sim::ToolOutlines outlines{{1, setup.setup->tools[0].outline}};
  const sim::CollisionChecks checks = collisionChecksOf(*setup.setup);
  return sim::simulate(run.toolpath, outlines, stock, {{}, &checks, {}, {}}).collisions;
}

TEST(ToolCollisions, ShallowTurningPassTouchesNothing) {
  // 2.5 mm deep (Φ50 → Φ45) to Z−30: the insert's leading edge rises 9.6 mm above its tip.
  EXPECT_TRUE(collisionsOf("G00 X60 Z1 M3 S500\nG01 X45 F0.2\nG01 Z-30\n").empty());
}

TEST(ToolCollisions, RetractingStraightUpScrapesTheShoulderTheLeaningEdgeLeft) {
  // Style F is a facing tool: turning toward the chuck, its leading edge leans back at 60° to Z,
  // so it leaves a 60° shoulder, and a rapid straight out in +X drives that edge into it (the
  // programs above end at the shoulder for this reason).
  const auto collisions = collisionsOf("G00 X60 Z1 M3 S500\nG01 X45 F0.2\nG01 Z-30\nG00 X60\n");
  ASSERT_EQ(collisions.size(), 1u);
  EXPECT_EQ(collisions[0].kind, "rapid_into_stock");
  EXPECT_EQ(collisions[0].line, 4);
}

TEST(ToolCollisions, CutDeeperThanTheInsertDrivesTheHolderIntoTheStock) {
  // 15 mm deep (Φ50 → Φ20): the insert reaches 9.6 mm above its tip, so from r 19.6 to 25 the
  // head and shank plough through the bar on line 3.
  const auto collisions = collisionsOf("G00 X60 Z1 M3 S500\nG01 X20 F0.2\nG01 Z-30\n");
  ASSERT_EQ(collisions.size(), 1u);
  EXPECT_EQ(collisions[0].kind, "holder_into_stock");
  EXPECT_EQ(collisions[0].line, 3);
  EXPECT_GT(collisions[0].volumeMm3, 100.0);
}

TEST(ToolCollisions, TurningIntoTheJawsIsIntoChuck) {
  // 2 mm deep to Z−62: the insert (r 23 up) passes the bar's end at Z−60, the jaws' face, on line 3.
  const auto collisions = collisionsOf("G00 X60 Z1 M3 S500\nG01 X46 F0.2\nG01 Z-62\n");
  ASSERT_EQ(collisions.size(), 1u);
  EXPECT_EQ(collisions[0].kind, "into_chuck");
  EXPECT_EQ(collisions[0].line, 3);
  EXPECT_GT(collisions[0].volumeMm3, 0.0);
}

}  // namespace
}  // namespace lathesim::setup
