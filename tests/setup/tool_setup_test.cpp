// [[tool]] by catalogue code and by kind: the seed's tool from its two codes, each kind's
// keys, and each error with its key, line and the column of the bad character.

#include "setup/setup.hpp"
#include "tests/setup/setup_text.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

namespace lathesim::setup {
namespace {

using interp::Diagnostic;
using interp::Severity;

using test::onlyError;
using test::parse;

const ToolDefinition& onlyTool(const SetupResult& result) {
  EXPECT_TRUE(result.setup.has_value()) << (result.diagnostics.empty() ? "" : result.diagnostics[0].message);
  static const Setup fallback = defaultSetup();
  if (!result.setup) return fallback.tools[0];
  EXPECT_EQ(result.setup->tools.size(), 1u);
  return result.setup->tools[0];
}

TEST(ToolSetup, SeedsToolIsDefinedByItsTwoCodes) {
  const SetupResult result = parse(R"([[tool]]
number = 1
insert = "TBHG120408"
holder = "STFCR2525M11"
)");
  const ToolDefinition& tool = onlyTool(result);
  EXPECT_EQ(tool.number, 1);
  EXPECT_EQ(tool.tipNumber, 3);
  EXPECT_DOUBLE_EQ(tool.noseRadiusMm, 0.8);
  ASSERT_TRUE(tool.holderBody.has_value());
  // Tip 3: the programmed point is the corner of the nose's bounding square on the −X, −Z
  // side, and this end-cutting F style's nose faces both: the outline starts at (0, 0).
  EXPECT_NEAR(tool.outline.lowerBound().x(), 0.0, 1e-9);
  EXPECT_NEAR(tool.outline.lowerBound().y(), 0.0, 1e-9);
  // Three warnings, no errors: the vendor-special size, the seat size 11 ≠ 12, clearance C ≠ B.
  ASSERT_EQ(result.diagnostics.size(), 3u);
  for (const auto& d : result.diagnostics) EXPECT_EQ(d.severity, Severity::Warning) << d.message;
  EXPECT_NE(result.diagnostics[0].message.find("tool[1].insert: insert TBHG120408: size 12 is not in the inch IC series"),
            std::string::npos)
      << result.diagnostics[0].message;
  EXPECT_EQ(result.diagnostics[0].line, 3);
}

TEST(ToolSetup, TipOverride) {
  const SetupResult result = parse("[[tool]]\nnumber = 2\ninsert = \"CNMG120408\"\nholder = \"PCLNR2525M12\"\ntip = 8\n");
  const ToolDefinition& tool = onlyTool(result);
  EXPECT_EQ(tool.tipNumber, 8);
  // Tip 8: the programmed point is r below the nose centre, so the lowest radial point is 0 but the
  // outline reaches r = 0.8 to either side in Z.
  EXPECT_NEAR(tool.outline.lowerBound().x(), 0.0, 1e-9);
  EXPECT_NEAR(tool.outline.lowerBound().y(), -0.8, 1e-9);
  EXPECT_TRUE(result.diagnostics.empty());
}

TEST(ToolSetup, PolygonToolKeepsWorkingAndMayGiveATip) {
  const SetupResult result = parse("[[tool]]\nnumber = 1\npolygon = [[0, 0], [12, 0], [12, 12], [0, 12]]\ntip = 2\n");
  const ToolDefinition& tool = onlyTool(result);
  EXPECT_DOUBLE_EQ(tool.outline.area(), 144.0);
  EXPECT_EQ(tool.tipNumber, 2);
  EXPECT_FALSE(tool.holderBody.has_value());
  EXPECT_DOUBLE_EQ(tool.noseRadiusMm, 0.0);
}

TEST(ToolSetup, GrooveThreadAndDrill) {
  const SetupResult result = parse(R"([[tool]]
number = 1
kind = "groove"
width = 3
corner_radius = 0.2
depth = 15
[[tool]]
number = 2
kind = "thread"
pitch = 1.5
[[tool]]
number = 3
kind = "drill"
diameter = 10
)");
  ASSERT_TRUE(result.setup.has_value()) << result.diagnostics[0].message;
  const auto& tools = result.setup->tools;
  ASSERT_EQ(tools.size(), 3u);
  EXPECT_EQ(tools[0].tipNumber, 3);
  EXPECT_NEAR(tools[0].outline.upperBound().y(), 3.0, 1e-9);   // width along Z
  EXPECT_NEAR(tools[0].outline.upperBound().x(), 15.0, 1e-9);  // depth along X
  EXPECT_DOUBLE_EQ(tools[0].noseRadiusMm, 0.2);
  // Thread: 60° by default, root radius 0.125·P = 0.1875; the profile is P = 1.5 wide at its top.
  EXPECT_EQ(tools[1].tipNumber, 8);
  EXPECT_DOUBLE_EQ(tools[1].noseRadiusMm, 0.125 * 1.5);
  EXPECT_NEAR(tools[1].outline.upperBound().y() - tools[1].outline.lowerBound().y(), 1.5, 1e-9);
  // Drill: 118° by default, length 10·D = 100; area 10·100 − 5·(5/tan 59°).
  EXPECT_EQ(tools[2].tipNumber, 0);
  EXPECT_NEAR(tools[2].outline.area(), 1000.0 - 5.0 * 5.0 / std::tan(59.0 * std::numbers::pi / 180), 1e-9);
}

TEST(ToolSetup, GrooveCornersMayDiffer) {
  const SetupResult result = parse("[[tool]]\nnumber = 1\nkind = \"groove\"\nwidth = 4\ndepth = 10\n"
                                   "corner_radius = [0.2, 0.8]\ntip = 4\n");
  const ToolDefinition& tool = onlyTool(result);
  EXPECT_DOUBLE_EQ(tool.noseRadiusMm, 0.8);  // tip 4 references the +Z corner
  EXPECT_EQ(onlyError("[[tool]]\nnumber = 1\nkind = \"groove\"\nwidth = 4\ndepth = 10\ncorner_radius = [0.2]\n").message,
            "tool[1].corner_radius must be a radius or [−Z corner, +Z corner], non-negative mm");
}

// The insert's thickness, for cuts made with the spindle stopped: an ISO insert's own
// (TBHG120408: 04 = 4.76 mm, iso-tools.md §1.6), or the thickness key of any tool.
TEST(ToolSetup, InsertThickness) {
  EXPECT_DOUBLE_EQ(*onlyTool(parse("[[tool]]\nnumber = 1\ninsert = \"TBHG120408\"\nholder = \"STFCR2525M11\"\n")).thicknessMm,
                   4.76);
  EXPECT_DOUBLE_EQ(*onlyTool(parse("[[tool]]\nnumber = 1\npolygon = [[0, 0], [4, 0], [4, 4]]\nthickness = 3\n")).thicknessMm,
                   3.0);
  EXPECT_DOUBLE_EQ(*onlyTool(parse("[[tool]]\nnumber = 1\nkind = \"groove\"\nwidth = 3\ndepth = 10\nthickness = 5\n"))
                        .thicknessMm,
                   5.0);
  EXPECT_FALSE(onlyTool(parse("[[tool]]\nnumber = 1\npolygon = [[0, 0], [4, 0], [4, 4]]\n")).thicknessMm);
  EXPECT_EQ(onlyError("[[tool]]\nnumber = 1\nthickness = -2\n").message,
            "tool[1].thickness must be a positive number of mm, got -2");
}

// A laydown threading insert by its code alone: the thread kind, its pitch's fundamental
// triangle (2 mm wide at the top), the 0.125·P root radius, tip 8; an internal one tip 6.
TEST(ToolSetup, LaydownThreadingInsert) {
  const SetupResult external = parse("[[tool]]\nnumber = 1\ninsert = \"16ER200ISO\"\n");
  const ToolDefinition& tool = onlyTool(external);
  EXPECT_EQ(tool.tipNumber, 8);
  EXPECT_DOUBLE_EQ(tool.noseRadiusMm, 0.25);
  EXPECT_NEAR(tool.outline.upperBound().y() - tool.outline.lowerBound().y(), 2.0, 1e-12);
  EXPECT_NEAR(tool.outline.lowerBound().x(), 0.0, 1e-12);
  const SetupResult internalResult =
      parse("[[tool]]\nnumber = 1\nkind = \"thread\"\ninsert = \"16IR1.5ISO\"\nnose_radius = 0.1\n");
  const ToolDefinition& internal = onlyTool(internalResult);
  EXPECT_EQ(internal.tipNumber, 6);
  EXPECT_DOUBLE_EQ(internal.noseRadiusMm, 0.1);
  EXPECT_NEAR(internal.outline.upperBound().x(), 0.0, 1e-12);
  const Diagnostic bad = onlyError("[[tool]]\nnumber = 1\ninsert = \"16ER2TR\"\n");
  EXPECT_NE(bad.message.find("tool[1].insert: threading insert 16ER2TR: the thread standard is not one"), std::string::npos)
      << bad.message;
  EXPECT_EQ(onlyError("[[tool]]\nnumber = 1\ninsert = \"16ER200ISO\"\npitch = 2\n").message,
            "tool[1].pitch comes from the insert code; give one or the other");
}

TEST(ToolSetupErrors, BadInsertCodePointsAtTheCharacter) {
  const Diagnostic d = onlyError("[[tool]]\nnumber = 1\ninsert = \"TBXG120408\"\nholder = \"STFCR2525M11\"\n");
  EXPECT_EQ(d.message, "tool[1].insert: insert TBXG120408: position 3 'X' is not a tolerance class; "
                       "expected one of A F C H E G J K L M N U");
  EXPECT_EQ(d.line, 3);
  EXPECT_EQ(d.column, 13);  // insert = "TBXG…: the quote is column 10, 'X' is 3 further
}

TEST(ToolSetupErrors, BadHolderCodePointsAtTheCharacter) {
  const Diagnostic d = onlyError("[[tool]]\nnumber = 1\ninsert = \"TBHG120408\"\nholder = \"STFCR2525Z11\"\n");
  EXPECT_NE(d.message.find("tool[1].holder: holder STFCR2525Z11: position 8 'Z' is not a tool length letter"),
            std::string::npos)
      << d.message;
  EXPECT_EQ(d.line, 4);
  EXPECT_EQ(d.column, 20);  // the quote at 10, 'Z' is the 10th character
}

TEST(ToolSetupErrors, ShapeMismatchIsAnError) {
  const Diagnostic d = onlyError("[[tool]]\nnumber = 1\ninsert = \"CNMG120408\"\nholder = \"PDJNR2525M15\"\n");
  EXPECT_EQ(d.message, "tool[1]: insert CNMG120408 is shape C but holder PDJNR2525M15 seats shape D");
  EXPECT_EQ(d.line, 4);
}

TEST(ToolSetupErrors, MissingHalfOfThePair) {
  const Diagnostic d = onlyError("[[tool]]\nnumber = 1\ninsert = \"CNMG120408\"\n");
  EXPECT_EQ(d.message, "tool[1] has an insert but no holder (add holder = \"PCLNR2525M12\")");
  EXPECT_EQ(d.line, 1);
}

TEST(ToolSetupErrors, TipOutOfRange) {
  const Diagnostic d = onlyError("[[tool]]\nnumber = 1\ninsert = \"CNMG120408\"\nholder = \"PCLNR2525M12\"\ntip = 12\n");
  EXPECT_EQ(d.message, "tool[1].tip must be an integer 0..9 (the imaginary tool tip number), got 12");
  EXPECT_EQ(d.line, 5);
}

TEST(ToolSetupErrors, KindsAndTheirKeys) {
  EXPECT_EQ(onlyError("[[tool]]\nnumber = 1\nkind = \"boring\"\n").message,
            "tool[1].kind must be \"turning\", \"groove\", \"thread\" or \"drill\", got \"boring\"");
  EXPECT_EQ(onlyError("[[tool]]\nnumber = 1\nwidth = 3\n").message, "tool[1].width needs kind = \"groove\"");
  EXPECT_EQ(onlyError("[[tool]]\nnumber = 1\nkind = \"turning\"\n").message,
            "tool[1] (kind \"turning\") needs insert and holder (e.g. insert = \"CNMG120408\", holder = \"PCLNR2525M12\")");
  EXPECT_EQ(onlyError("[[tool]]\nnumber = 1\nkind = \"groove\"\nwidth = 3\n").message,
            "tool[1] (kind \"groove\") needs depth (mm)");
  EXPECT_EQ(onlyError("[[tool]]\nnumber = 1\nkind = \"groove\"\nwidth = -3\ndepth = 10\n").message,
            "tool[1].width must be a positive number of mm, got -3");
  EXPECT_EQ(onlyError("[[tool]]\nnumber = 1\nkind = \"drill\"\ndiameter = 10\npitch = 2\n").message,
            "tool[1].pitch does not apply to a drill tool");
  EXPECT_EQ(onlyError("[[tool]]\nnumber = 1\nkind = \"groove\"\nwidth = 3\ndepth = 10\ntip = 6\n").message,
            "tool[1]: tip 6 does not apply to a groove tool; expected 3, 4, 8");
  const Diagnostic both = onlyError("[[tool]]\nnumber = 1\npolygon = [[0, 0], [1, 0], [0, 1]]\n"
                                    "insert = \"CNMG120408\"\nholder = \"PCLNR2525M12\"\n");
  EXPECT_EQ(both.message, "tool[1].polygon cannot be combined with a turning tool's keys; give one or the other");
  EXPECT_EQ(both.line, 3);
}

TEST(ChuckSetup, DefaultsAndKeys) {
  EXPECT_DOUBLE_EQ(defaultSetup().chuck.gripLengthMm, 20.0);
  EXPECT_FALSE(defaultSetup().chuck.jawDiameterMm.has_value());  // bar + 40 when used
  const SetupResult result = parse("[chuck]\ngrip_length = 30\njaw_diameter = 200\nface_z = -120\n");
  ASSERT_TRUE(result.setup.has_value());
  EXPECT_DOUBLE_EQ(result.setup->chuck.gripLengthMm, 30.0);
  EXPECT_DOUBLE_EQ(result.setup->chuck.jawDiameterMm.value_or(0), 200.0);
  EXPECT_DOUBLE_EQ(result.setup->chuck.faceZMm.value_or(0), -120.0);
}

TEST(ChuckSetupErrors, JawsMustReachBeyondTheBar) {
  const Diagnostic d = onlyError("[stock]\ndiameter = 50\n[chuck]\njaw_diameter = 40\n");
  EXPECT_EQ(d.message, "chuck.jaw_diameter must exceed the stock's diameter (50.0 mm)");
  EXPECT_EQ(d.line, 4);
  EXPECT_EQ(onlyError("[chuck]\ngrip = 5\n").message, "unknown key 'chuck.grip' (expected grip_length, jaw_diameter or face_z)");
}

}  // namespace
}  // namespace lathesim::setup
