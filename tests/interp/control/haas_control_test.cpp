// The haas dialect and control preset: the machine M codes each control accepts as ignored,
// Haas's T words, G04 P in seconds, a bare G28. Each expected value is the Haas manual's rule
// applied by hand.

#include <gtest/gtest.h>

#include <algorithm>
#include <string>

#include "../test_support.hpp"
#include "interp/control/control_preset.hpp"

namespace lathesim::interp {
namespace {

using test::expectError;
using test::run;

using test::haas;
using test::notesOf;

TEST(HaasPreset, IsBasedOnFanucWithHaasValues) {
  const auto control = controlPreset("haas");
  ASSERT_TRUE(control);
  const ControlParameters& p = control->parameters;
  EXPECT_EQ(p.decimalPointInput, DecimalPointInput::LeastIncrements);  // Setting 162 Off
  EXPECT_EQ(p.powerOnFeedMode, FeedMode::PerRevolution);
  EXPECT_EQ(p.machineMCodes, MachineMCodes::Haas);
  EXPECT_EQ(p.dwellPWord, DwellPWord::SecondsWithPoint);
  EXPECT_EQ(p.toolWordForms, std::vector<std::string>{"haas"});
  EXPECT_DOUBLE_EQ(p.roughingDepthMm, 2.54);   // Setting 72, 0.100 in
  EXPECT_DOUBLE_EQ(p.roughingRetractMm, 1.27);  // Setting 73, 0.050 in
  EXPECT_DOUBLE_EQ(p.threadMinDepthMm, 0.0254);  // Setting 99, 0.0010 in
  const auto names = controlPresets();
  EXPECT_NE(std::find(names.begin(), names.end(), "haas"), names.end());
  for (const ControlSetting& s : control->settings) EXPECT_FALSE(s.manual.empty()) << s.key;
}

TEST(HaasDialect, HasItsNameAndReadsSystemACodes) {
  EXPECT_EQ(dialectNamed("haas"), Dialect::Haas);
  EXPECT_EQ(dialectName(Dialect::Haas), "haas");
  const auto result = run("G00 X40. Z5.\nG01 Z-10. F0.2\n", haas());
  ASSERT_TRUE(result.ok()) << result.diagnostics[0].message;
  EXPECT_NEAR(result.toolpath.moves.back().to.y(), -10.0, 1e-12);
}

// A machine M code of the chosen control changes nothing and is listed once as a note, at the
// line it first appears; the same code on another control is an error naming what it takes.
TEST(MachineMCodes, AcceptedOncePerCodeUnderTheirControl) {
  const auto result = run("M31\nG00 X40. Z5. M88\nM31\nM41\n", haas());
  ASSERT_TRUE(result.ok()) << result.diagnostics[0].message;
  const auto notes = notesOf(result);
  ASSERT_EQ(notes.size(), 3u);
  EXPECT_EQ(notes[0].line, 1);
  EXPECT_NE(notes[0].message.find("M31 (chip auger forward)"), std::string::npos) << notes[0].message;
  EXPECT_EQ(notes[1].line, 2);
  EXPECT_EQ(notes[1].column, 14);
  EXPECT_EQ(notes[2].line, 4);
  EXPECT_EQ(result.toolpath.moves.size(), 1u);
}

TEST(MachineMCodes, UnknownToTheControlIsAnErrorListingItsCodes) {
  const auto gsk = run("G00 X40 Z5\nM31\n");  // a Haas chip auger code: not the GSK's
  expectError(gsk, 2, 1, "unknown M code M31");
  EXPECT_NE(gsk.diagnostics[0].message.find("a machine code of this control's table, m_codes = gsk980tdi (M10 M11 M12 M32"), std::string::npos)
      << gsk.diagnostics[0].message;
  EXPECT_TRUE(run("M41\nM32\n").ok());  // the GSK's gear range and lubrication
  expectError(run("M32\n", haas()), 1, 1, "unknown M code M32");
  // M13 is Haas's air jet off; under the GSK and Fanuc it is a live tool, refused by name.
  EXPECT_TRUE(run("M13\n", haas()).ok());
  expectError(run("M13\n"), 1, 1, "needs live tooling");
  expectError(run("M13\n", test::under("fanuc-0i-t", Dialect::FanucA)), 1, 1, "needs live tooling");
  // A code no control knows.
  expectError(run("G00 X40. M777\n", haas()), 1, 10, "unknown M code M777");
}

TEST(MachineMCodes, OverriddenByTheSetup) {
  InterpreterOptions options = test::defaultOptions();
  auto control = *controlPreset("gsk980tdi");
  ASSERT_FALSE(control.set("m_codes", std::string("haas"), "setup"));
  options.control = control.parameters;
  EXPECT_TRUE(run("M31\n", options).ok());
}

// Haas reads T101 as tool 1 offset 1, and a short T1 as tool 1 with its own offset 1.
TEST(HaasToolWord, ShortFormsNameTheTool) {
  const auto onePlusOne = run("T101\nG00 X40. Z5.\n", haas());
  ASSERT_TRUE(onePlusOne.ok()) << onePlusOne.diagnostics[0].message;
  const auto shortForm = run("T2\nG00 X40. Z5.\n", haas());
  ASSERT_TRUE(shortForm.ok()) << shortForm.diagnostics[0].message;
  const auto warnings = test::warningsOf(shortForm);
  ASSERT_EQ(warnings.size(), 1u);
  EXPECT_NE(warnings[0].message.find("T2 is read as tool 2 with offset 2"), std::string::npos) << warnings[0].message;
  EXPECT_EQ(shortForm.toolpath.moves.back().tool, 2);
  expectError(run("T01001\n", haas()), 1, 1, "not a tool word of this control");
  expectError(run("T3\n", haas()), 1, 1, "T3");  // tool 3 is not defined: not offset 3 of tool 1
}

// Haas G04: P with a decimal point counts seconds, without it milliseconds; GSK and Fanuc P
// is always milliseconds.
TEST(HaasDwell, PWithAPointIsSeconds) {
  const auto result = run("G04 P1.5\nG04 P1500\nG04 P2.\nG04 X0.5\n", haas());
  ASSERT_TRUE(result.ok()) << result.diagnostics[0].message;
  const double seconds[] = {1.5, 1.5, 2.0, 0.5};
  ASSERT_EQ(result.toolpath.moves.size(), 4u);
  for (std::size_t i = 0; i < 4; ++i) EXPECT_DOUBLE_EQ(result.toolpath.moves[i].dwellS, seconds[i]) << i;
  const auto gsk = run("G04 P1500\n");
  ASSERT_TRUE(gsk.ok());
  EXPECT_DOUBLE_EQ(gsk.toolpath.moves[0].dwellS, 1.5);
}

// A bare G28 on a Haas sends every axis home straight from where the tool stands; other
// dialects still need the axes named.
TEST(HaasReferenceReturn, BareG28ReturnsEveryAxis) {
  const auto result = run("G00 X40. Z5.\nG28\n", haas());
  ASSERT_TRUE(result.ok()) << result.diagnostics[0].message;
  ASSERT_EQ(result.toolpath.moves.size(), 2u);
  const Move& home = result.toolpath.moves[1];
  EXPECT_EQ(home.kind, MoveKind::Rapid);
  EXPECT_NEAR(home.from.x(), 20.0, 1e-12);
  EXPECT_NEAR(home.from.y(), 5.0, 1e-12);
  EXPECT_NEAR(home.to.x(), 100.0, 1e-12);
  EXPECT_NEAR(home.to.y(), 200.0, 1e-12);
  // G28 U0 W0 and G28 G00 U0 W0 go the same way.
  for (const char* line : {"G28 U0. W0.\n", "G28 G00 U0. W0.\n"}) {
    const auto named = run(std::string("G00 X40. Z5.\n") + line, haas());
    ASSERT_TRUE(named.ok()) << line << named.diagnostics[0].message;
    ASSERT_EQ(named.toolpath.moves.size(), 2u) << line;
    EXPECT_NEAR(named.toolpath.moves[1].to.x(), 100.0, 1e-12);
    EXPECT_NEAR(named.toolpath.moves[1].to.y(), 200.0, 1e-12);
  }
  expectError(run("G00 X40 Z5\nG28\n"), 2, 1, "G28 needs X(U) and/or Z(W)");
}

}  // namespace
}  // namespace lathesim::interp

namespace lathesim::interp {
namespace {

// M97 P100 L2 runs N100 … M99 of the same program twice, then goes on after the M97.
TEST(HaasLocalSubprogram, M97RunsTheBlocksFromItsNTwice) {
  const auto result = run("G00 X40. Z5.\nM97 P100 L2\nG00 X60.\nM30\nN100 G01 W-1. F0.2\nM99\n", haas());
  ASSERT_TRUE(result.ok()) << result.diagnostics[0].message;
  const auto& moves = result.toolpath.moves;
  ASSERT_EQ(moves.size(), 4u);
  EXPECT_NEAR(moves[1].to.y(), 4.0, 1e-12);
  EXPECT_NEAR(moves[2].to.y(), 3.0, 1e-12);
  EXPECT_EQ(moves[2].line, 5);
  EXPECT_NEAR(moves[3].to.x(), 30.0, 1e-12);
  EXPECT_NEAR(moves[3].to.y(), 3.0, 1e-12);
}

TEST(HaasLocalSubprogram, BadCalls) {
  expectError(run("M97 P200\nM30\nN100 M99\n", haas()), 1, 5, "no block N200");
  expectError(run("M97\n", haas()), 1, 1, "M97 needs P");
  expectError(run("M97 P100 L0\nM30\nN100 M99\n", haas()), 1, 10, "not a repeat count");
  expectError(run("M97 P100\nM30\nN100 M97 P100\nM99\n", haas()), 3, 10, "already running");
  expectError(run("M97 P100\nM30\nN100 M99\n"), 1, 1, "M97 is Haas's local subprogram call");
}

}  // namespace
}  // namespace lathesim::interp

namespace lathesim::interp {
namespace {

// A program with neither G20 nor G21 runs in the control's power-on unit (power_on_units).
TEST(PowerOnUnits, AProgramWithoutG20OrG21RunsInTheControlsUnit) {
  InterpreterOptions options = test::defaultOptions();
  const auto metric = run("G00 X2. Z1.\n", options);
  ASSERT_TRUE(metric.ok());
  EXPECT_NEAR(metric.toolpath.moves.back().to.x(), 1.0, 1e-12);
  auto control = *controlPreset("haas");
  ASSERT_FALSE(control.set("power_on_units", std::string("G20"), "setup"));
  options.control = control.parameters;
  options.control.rapidPath = RapidPath::Linear;
  const auto inch = run("G00 X2. Z1.\nG21 G00 X2. Z1.\n", options);
  ASSERT_TRUE(inch.ok()) << inch.diagnostics[0].message;
  EXPECT_NEAR(inch.toolpath.moves[0].to.x(), 25.4, 1e-12);  // X2. inch: Φ50.8, radius 25.4
  EXPECT_NEAR(inch.toolpath.moves[0].to.y(), 25.4, 1e-12);
  EXPECT_NEAR(inch.toolpath.moves.back().to.x(), 1.0, 1e-12);  // after G21, mm
}

}  // namespace
}  // namespace lathesim::interp

namespace lathesim::interp {
namespace {

// G30: to the second reference point the setup gives, through the intermediate point, as G28.
TEST(SecondReference, G30GoesToTheSetupsSecondReferencePoint) {
  InterpreterOptions options = test::defaultOptions();
  options.secondReferencePosition = RZ(60.0, 150.0);
  const auto result = run("G00 X40 Z5\nG30 U0 W0\n", options);
  ASSERT_TRUE(result.ok()) << result.diagnostics[0].message;
  ASSERT_EQ(result.toolpath.moves.size(), 2u);
  EXPECT_NEAR(result.toolpath.moves[1].to.x(), 60.0, 1e-12);
  EXPECT_NEAR(result.toolpath.moves[1].to.y(), 150.0, 1e-12);
  expectError(run("G00 X40 Z5\nG30 U0 W0\n"), 2, 1, "second_reference");
  expectError(run("G30 P3 U0 W0\n", options), 1, 5, "only the second reference point");
}

}  // namespace
}  // namespace lathesim::interp
