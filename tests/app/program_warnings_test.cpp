// The simulation's warnings on whole programs, through interp and sim as `lathesim run`
// drives them.

#include <gtest/gtest.h>

#include "setup/setup.hpp"
#include "interp/interpreter.hpp"
#include "sim/simulate.hpp"

namespace lathesim::app {
namespace {

sim::SimulationResult simulateProgram(std::string_view program) {
  const setup::Setup setup = setup::defaultSetup();  // Φ125 × 112 bar, face at Z2
  interp::InterpreterOptions options;
  options.startPosition = setup.startPosition;
  options.toolNumbers = {1};
  const interp::InterpretResult result = interp::interpret(program, "test.nc", options);
  EXPECT_TRUE(result.ok());
  sim::ToolOutlines tools;
  tools.emplace(1, setup.tools[0].outline);
  sim::Stock stock(setup.stock, 1.0);
  return sim::simulate(result.toolpath, tools, stock);
}

TEST(ProgramWarnings, AG50ThatDisagreesWithTheSetupShiftsTheFirstCutIntoTheBar) {
  // The tool stands at X200 Z200 of the setup (the Φ125 bar spans Z-110..2). G50 X200 Z300
  // calls that Z300: the program's zero lies at Z200 − 300 = Z-100 of the setup. G00 X130 Z5
  // goes to setup (r 65, Z-95), above the bar; G90 X100 Z-20 then rapids to the start of its
  // cut, B = (X100, Z5) = setup (r 50, Z-95), 12.5 mm deep in the bar.
  const auto result = simulateProgram("M03 S500\nG50 X200 Z300\nG00 X130 Z5\nG90 X100 Z-20 F0.2\n");
  ASSERT_EQ(result.warnings.size(), 1u);
  EXPECT_EQ(result.warnings[0].line, 4);
  EXPECT_EQ(result.warnings[0].message,
            "this rapid after G50 ends inside the bar, at X100 Z-95 of the setup: G50 declared a position "
            "the tool is not at, which moved the program's zero to X0 Z-100 of the setup; check the G50 against "
            "[machine] start");
}

TEST(ProgramWarnings, AG50ThatAgreesWithTheSetupGivesNone) {
  // G50 X200 Z200 where the tool stands: the frame stays; the G90 cuts from Z5, clear of the face.
  const auto result = simulateProgram("M03 S500\nG50 X200 Z200\nG00 X130 Z5\nG90 X120 Z-20 F0.2\n");
  EXPECT_TRUE(result.warnings.empty()) << result.warnings[0].message;
}

TEST(ProgramWarnings, AG50ThatPutsTheCutsInTheAirGivesNone) {
  // G50 X200 Z100: the program's zero at setup Z100, so the G90 cuts at Z80..105, far from the bar.
  const auto result = simulateProgram("M03 S500\nG50 X200 Z100\nG00 X130 Z5\nG90 X120 Z-20 F0.2\n");
  EXPECT_TRUE(result.warnings.empty()) << result.warnings[0].message;
}

TEST(ProgramWarnings, ACycleStartedClearOfTheBarGivesNone) {
  const auto result = simulateProgram("M03 S500\nG00 X130 Z5\nG94 X100 Z0 F0.2\n");
  EXPECT_TRUE(result.warnings.empty());
}

}  // namespace
}  // namespace lathesim::app
