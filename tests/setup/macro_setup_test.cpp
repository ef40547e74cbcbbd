// The setup file's [macro] table: the step limit and the common variables a run starts with.

#include "setup/job.hpp"
#include "setup/setup.hpp"

#include <gtest/gtest.h>

#include <string>

namespace lathesim::setup {
namespace {

TEST(MacroSetup, DefaultsWhenLeftOut) {
  const SetupResult result = parseSetup("", "part.toml");
  ASSERT_TRUE(result.setup);
  EXPECT_EQ(result.setup->macro.maxSteps, interp::kDefaultMaxSteps);
  EXPECT_TRUE(result.setup->macro.variables.empty());
}

TEST(MacroSetup, StepLimitAndVariables) {
  const SetupResult result =
      parseSetup("[macro]\nmax_steps = 5000\nvariables = { 500 = 20.5, 101 = 3 }\n", "part.toml");
  ASSERT_TRUE(result.setup) << (result.diagnostics.empty() ? "" : result.diagnostics[0].message);
  EXPECT_EQ(result.setup->macro.maxSteps, 5000);
  ASSERT_EQ(result.setup->macro.variables.size(), 2u);
  EXPECT_DOUBLE_EQ(result.setup->macro.variables.at(500), 20.5);
  EXPECT_DOUBLE_EQ(result.setup->macro.variables.at(101), 3.0);
  // They reach the interpreter.
  const interp::InterpreterOptions options = interpreterOptionsOf(*result.setup);
  EXPECT_EQ(options.maxSteps, 5000);
  EXPECT_DOUBLE_EQ(options.macroVariables.at(500), 20.5);
}

TEST(MacroSetup, EachProblemIsNamedAtItsKey) {
  struct Case {
    std::string text;
    int line;
    std::string message;
  };
  const Case cases[] = {
      {"[macro]\nmax_steps = 0\n", 2, "macro.max_steps must be a whole number ≥ 1"},
      {"[macro]\nmax_steps = 2.5\n", 2, "macro.max_steps must be a whole number ≥ 1"},
      {"[macro]\nvariables = { 1 = 2.0 }\n", 2, "macro.variables.1: the key must be the number of a common variable"},
      {"[macro]\nvariables = { 250 = 2.0 }\n", 2, "macro.variables.250: the key must be the number"},
      {"[macro]\nvariables = { 500 = \"x\" }\n", 2, "macro.variables.500 must be a number"},
      {"[macro]\nvariables = 3\n", 2, "macro.variables must be a table"},
      {"[macro]\nmaxsteps = 3\n", 2, "unknown key 'macro.maxsteps' (expected max_steps or variables)"},
  };
  for (const Case& c : cases) {
    SCOPED_TRACE(c.text);
    const SetupResult result = parseSetup(c.text, "part.toml");
    EXPECT_FALSE(result.setup);
    ASSERT_EQ(result.diagnostics.size(), 1u);
    EXPECT_EQ(result.diagnostics[0].line, c.line);
    EXPECT_NE(result.diagnostics[0].message.find(c.message), std::string::npos) << result.diagnostics[0].message;
  }
}

}  // namespace
}  // namespace lathesim::setup
