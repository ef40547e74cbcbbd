// The simulation's warnings on whole programs, through interp and sim as `lathesim run`
// drives them.

#include <gtest/gtest.h>

#include "job/setup.hpp"
#include "interp/interpreter.hpp"
#include "sim/simulate.hpp"

namespace lathesim::app {
namespace {

sim::SimulationResult simulateProgram(std::string_view program) {
  const job::Setup setup = job::defaultSetup();  // Φ125 × 112 bar, face at Z2
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

TEST(ProgramWarnings, ACycleStartedInsideTheBarAfterAWrongG50) {
  // G50 X30 Z-10 declares the tool to stand at r 15, Z-10: deep inside the Φ125 bar.
  const auto result = simulateProgram("M03 S500\nG50 X30 Z-10\nG94 X20 Z-15 F0.2\n");
  ASSERT_FALSE(result.warnings.empty());
  EXPECT_EQ(result.warnings[0].line, 3);
  EXPECT_EQ(result.warnings[0].message.rfind("G94 starts at X30 Z-10 (the cycle start point), which is inside "
                                             "the stock",
                                             0),
            0u)
      << result.warnings[0].message;
}

TEST(ProgramWarnings, ACycleStartedClearOfTheBarGivesNone) {
  const auto result = simulateProgram("M03 S500\nG00 X130 Z5\nG94 X100 Z0 F0.2\n");
  EXPECT_TRUE(result.warnings.empty());
}

}  // namespace
}  // namespace lathesim::app
