// The setup file: defaults, a full valid file, and each error with its message and position.

#include "setup/setup.hpp"
#include "tests/setup/setup_text.hpp"
#include "setup/job.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>

namespace lathesim::setup {
namespace {

using interp::Diagnostic;

using test::onlyDiagnostic;
using test::parse;

std::vector<RZ> verticesOf(const ConvexPolygon& polygon) { return polygon.vertices(); }

TEST(DefaultSetup, IsTheSeedBarWithOneSharpTool) {
  const setup::Setup setup = defaultSetup();
  EXPECT_EQ(setup.sourceName, "(default setup)");
  EXPECT_DOUBLE_EQ(setup.stock.diameterMm, 125.0);
  EXPECT_DOUBLE_EQ(setup.stock.lengthMm, 112.0);
  EXPECT_DOUBLE_EQ(setup.stock.faceZMm, 2.0);
  EXPECT_DOUBLE_EQ(setup.startPosition.x(), 100.0);  // X200 is a diameter
  EXPECT_DOUBLE_EQ(setup.startPosition.y(), 200.0);
  EXPECT_FALSE(setup.voxelMm.has_value());
  ASSERT_EQ(setup.tools.size(), 1u);
  EXPECT_EQ(setup.tools[0].number, 1);
  // The tip is the programmed point; the body lies at r ≥ 0, z ≥ 0.
  EXPECT_NEAR(setup.tools[0].outline.area(), 0.5 * (0 * 1 - 10 * 0 + 10 * 12 - 12 * 1 + 12 * 10 - 1 * 12 + 1 * 0 - 0 * 10), 1e-12);
  EXPECT_EQ(setup.tools[0].outline.lowerBound(), RZ(0, 0));
  EXPECT_EQ(setup.tools[0].outline.upperBound(), RZ(12, 12));
}

TEST(ParseSetup, EmptyFileIsTheDefaultSetup) {
  const SetupResult result = parse("");
  ASSERT_TRUE(result.setup.has_value());
  EXPECT_TRUE(result.diagnostics.empty());
  const setup::Setup& setup = *result.setup;
  const setup::Setup expected = defaultSetup();
  EXPECT_EQ(setup.sourceName, "part.toml");
  EXPECT_DOUBLE_EQ(setup.stock.diameterMm, expected.stock.diameterMm);
  EXPECT_DOUBLE_EQ(setup.stock.lengthMm, expected.stock.lengthMm);
  EXPECT_DOUBLE_EQ(setup.stock.faceZMm, expected.stock.faceZMm);
  EXPECT_EQ(setup.startPosition, expected.startPosition);
  EXPECT_FALSE(setup.voxelMm.has_value());
  ASSERT_EQ(setup.tools.size(), 1u);
  EXPECT_EQ(verticesOf(setup.tools[0].outline), verticesOf(expected.tools[0].outline));
}

TEST(ParseSetup, MissingKeysKeepTheirDefaults) {
  const SetupResult result = parse("[stock]\ndiameter = 50\n");
  ASSERT_TRUE(result.setup.has_value());
  EXPECT_DOUBLE_EQ(result.setup->stock.diameterMm, 50.0);
  EXPECT_DOUBLE_EQ(result.setup->stock.lengthMm, 112.0);
  EXPECT_DOUBLE_EQ(result.setup->stock.faceZMm, 0.0);  // a [stock]'s face is at Z0 unless stated
  EXPECT_FALSE(result.setup->stockFaceGiven);
  EXPECT_EQ(result.setup->startPosition, RZ(100.0, 200.0));
  EXPECT_EQ(result.setup->tools.size(), 1u);
}

TEST(ParseSetup, FullFileGivesEveryValue) {
  const SetupResult result = parse(R"(# a complete setup
[stock]
diameter = 50.0
length = 60          # integers are accepted as mm
face_z = -0.5

[machine]
start = [54, 5.5]

[sim]
voxel = 0.1

[[tool]]
number = 3
polygon = [[0, 0], [12, 0], [12, 12], [0, 12]]

[[tool]]
number = 7
polygon = [[0, 0], [4, -1], [5, 5]]
)");
  ASSERT_TRUE(result.setup.has_value()) << (result.diagnostics.empty() ? "" : result.diagnostics[0].message);
  const setup::Setup& setup = *result.setup;
  EXPECT_DOUBLE_EQ(setup.stock.diameterMm, 50.0);
  EXPECT_DOUBLE_EQ(setup.stock.lengthMm, 60.0);
  EXPECT_DOUBLE_EQ(setup.stock.faceZMm, -0.5);
  EXPECT_DOUBLE_EQ(setup.startPosition.x(), 27.0);
  EXPECT_DOUBLE_EQ(setup.startPosition.y(), 5.5);
  ASSERT_TRUE(setup.voxelMm.has_value());
  EXPECT_DOUBLE_EQ(*setup.voxelMm, 0.1);
  ASSERT_EQ(setup.tools.size(), 2u);
  EXPECT_EQ(setup.tools[0].number, 3);
  EXPECT_DOUBLE_EQ(setup.tools[0].outline.area(), 144.0);
  EXPECT_EQ(setup.tools[1].number, 7);
  EXPECT_DOUBLE_EQ(setup.tools[1].outline.area(), 0.5 * (4 * 5 - (-1) * 5));
}

TEST(ParseSetup, MachineLimitsAndReferenceDefault) {
  const setup::Setup setup = defaultSetup();
  EXPECT_DOUBLE_EQ(setup.machine.rapidXMmPerMin, 6000.0);
  EXPECT_DOUBLE_EQ(setup.machine.rapidZMmPerMin, 8000.0);
  EXPECT_DOUBLE_EQ(setup.machine.maxRpm, 3000.0);
  EXPECT_EQ(setup.referencePosition, setup.startPosition);
  // Without reference, G28 returns to the start the file gives.
  const SetupResult result = parse("[machine]\nstart = [54, 5.5]\n");
  ASSERT_TRUE(result.setup.has_value());
  EXPECT_EQ(result.setup->referencePosition, RZ(27.0, 5.5));
}

TEST(ParseSetup, MachineRapidMaxRpmAndReference) {
  const SetupResult result = parse("[machine]\nrapid = [4000, 10000.5]\nmax_rpm = 2500\nreference = [300, 150]\n");
  ASSERT_TRUE(result.setup.has_value()) << result.diagnostics[0].message;
  const setup::Setup& setup = *result.setup;
  EXPECT_DOUBLE_EQ(setup.machine.rapidXMmPerMin, 4000.0);
  EXPECT_DOUBLE_EQ(setup.machine.rapidZMmPerMin, 10000.5);
  EXPECT_DOUBLE_EQ(setup.machine.maxRpm, 2500.0);
  EXPECT_EQ(setup.referencePosition, RZ(150.0, 150.0));  // X300 is a diameter
  EXPECT_EQ(setup.startPosition, RZ(100.0, 200.0));      // start keeps its default
}

TEST(ParseSetupErrors, RapidMustBeTwoPositiveRates) {
  for (const char* value : {"[6000]", "[6000, 0]", "[-1, 8000]", "6000", "[\"fast\", 8000]"}) {
    const Diagnostic d = onlyDiagnostic(std::string("[machine]\nrapid = ") + value + "\n");
    EXPECT_EQ(d.message.rfind("machine.rapid must be [X, Z] rapid rates, positive numbers of mm/min, got ", 0), 0u)
        << d.message;
    EXPECT_EQ(d.line, 2);
  }
}

TEST(ParseSetupErrors, MaxRpmMustBePositive) {
  const Diagnostic d = onlyDiagnostic("[machine]\n\nmax_rpm = 0\n");
  EXPECT_EQ(d.message, "machine.max_rpm must be a positive number of rpm, got 0");
  EXPECT_EQ(d.line, 3);
}

TEST(ParseSetup, DialectAndInitialFeedMode) {
  const SetupResult defaults = parse("");
  ASSERT_TRUE(defaults.setup.has_value());
  EXPECT_EQ(defaults.setup->dialect, interp::Dialect::FanucA);
  EXPECT_EQ(defaults.setup->control.parameters.powerOnFeedMode, interp::FeedMode::PerMinute);  // GSK's G98
  // initial_feed_mode is the older spelling of control.power_on_feed_mode.
  const SetupResult result = parse("[machine]\ndialect = \"hnc\"\ninitial_feed_mode = \"per_revolution\"\n");
  ASSERT_TRUE(result.setup.has_value()) << result.diagnostics[0].message;
  EXPECT_EQ(result.setup->dialect, interp::Dialect::Hnc);
  EXPECT_EQ(result.setup->control.parameters.powerOnFeedMode, interp::FeedMode::PerRevolution);
}

TEST(ParseSetup, ControlIsTheDefaultPresetUnlessNamed) {
  const SetupResult defaults = parse("");
  ASSERT_TRUE(defaults.setup.has_value());
  EXPECT_EQ(defaults.setup->control.preset, "gsk980tdi");
  const SetupResult fanuc = parse("[control]\nname = \"fanuc-0i-t\"\n");
  ASSERT_TRUE(fanuc.setup.has_value()) << fanuc.diagnostics[0].message;
  EXPECT_EQ(fanuc.setup->control.preset, "fanuc-0i-t");
  EXPECT_EQ(fanuc.setup->control.parameters.decimalPointInput, interp::DecimalPointInput::LeastIncrements);
}

TEST(ParseSetup, ControlKeysOverrideThePresetWhateverTheirOrder) {
  // The key before name still overrides the preset name chooses.
  const SetupResult result = parse(
      "[control]\ndecimal_point_input = \"calculator\"\nname = \"fanuc-0i-t\"\nleast_increment = 0.0001\n"
      "block_skip = false\ntool_word = [\"3+3\"]\n");
  ASSERT_TRUE(result.setup.has_value()) << result.diagnostics[0].message;
  const interp::Control& control = result.setup->control;
  EXPECT_EQ(control.preset, "fanuc-0i-t");
  EXPECT_EQ(control.parameters.decimalPointInput, interp::DecimalPointInput::Calculator);
  EXPECT_EQ(control.parameters.leastIncrementMm, 0.0001);
  EXPECT_FALSE(control.parameters.blockSkip);
  EXPECT_EQ(control.parameters.toolWordForms, std::vector<std::string>{"3+3"});
  EXPECT_EQ(control.parameters.powerOnFeedMode, interp::FeedMode::PerRevolution);  // fanuc-0i-t's own
}

TEST(ParseSetupErrors, ControlNamesAndValuesAreChecked) {
  Diagnostic d = onlyDiagnostic("[control]\nname = \"fanuc-0i-m\"\n");
  EXPECT_EQ(d.message, "control.name must be one of \"gsk980tdi\", \"fanuc-0i-t\", \"haas\", \"denford\" (a control preset)");
  EXPECT_EQ(d.line, 2);
  d = onlyDiagnostic("[control]\n\nrapid_positioning = \"straight\"\n");
  EXPECT_EQ(d.message, "control.rapid_positioning must be one of \"nonlinear\", \"linear\", got \"straight\"");
  EXPECT_EQ(d.line, 3);
  d = onlyDiagnostic("[control]\nrapid = \"linear\"\n");
  EXPECT_EQ(d.message.rfind("unknown key 'control.rapid' (expected name or one of rapid_positioning, ", 0), 0u)
      << d.message;
  d = onlyDiagnostic("[control]\ng71_depth = [1, 2]\n");
  EXPECT_EQ(d.message, "control.g71_depth must be a string, a number or a list of strings");
}

TEST(ParseSetupErrors, InitialFeedModeAndPowerOnFeedModeAreOneSetting) {
  const Diagnostic d = onlyDiagnostic("[control]\npower_on_feed_mode = \"G99\"\n[machine]\ninitial_feed_mode = \"per_minute\"\n");
  EXPECT_EQ(d.message, "machine.initial_feed_mode and control.power_on_feed_mode both set the feed mode at "
                       "power-on; give control.power_on_feed_mode alone");
  EXPECT_EQ(d.line, 4);
}

TEST(ParseSetup, TravelIsStatedOrDerivedFromTheReferenceTheStartAndTheBar) {
  // The default setup: Φ125 × 112 bar, face Z2; start = reference = X200 Z200.
  const interp::TravelLimits derived = travelOf(*parse("").setup);
  EXPECT_EQ(derived.xMinDiameterMm, -125);  // minus the bar's diameter
  EXPECT_EQ(derived.xMaxDiameterMm, 200);   // the reference's (and start's) X
  EXPECT_EQ(derived.zMinMm, 2 - 112 - 112);  // the bar's left end, less a bar's length
  EXPECT_EQ(derived.zMaxMm, 200);
  EXPECT_TRUE(derived.xDerived && derived.zDerived);
  // A start beyond the reference widens it; a stated axis is taken as stated.
  const SetupResult result =
      parse("[machine]\nstart = [250, 100]\nreference = [200, 150]\ntravel_z = [-300, 400]\n");
  ASSERT_TRUE(result.setup.has_value()) << result.diagnostics[0].message;
  const interp::TravelLimits travel = travelOf(*result.setup);
  EXPECT_EQ(travel.xMaxDiameterMm, 250);
  EXPECT_TRUE(travel.xDerived);
  EXPECT_EQ(travel.zMinMm, -300);
  EXPECT_EQ(travel.zMaxMm, 400);
  EXPECT_FALSE(travel.zDerived);
  EXPECT_EQ(onlyDiagnostic("[machine]\ntravel_x = [100, -10]\n").message,
            "machine.travel_x must be [min, max] in mm with min < max, got [100, -10]");
}

TEST(ParseSetupErrors, DialectAndFeedModeAreNamedChoices) {
  const Diagnostic d = onlyDiagnostic("[machine]\ndialect = \"fanuc-c\"\n");
  EXPECT_EQ(d.message, "machine.dialect must be one of \"fanuc-a\", \"fanuc-b\", \"hnc\", \"haas\", got \"fanuc-c\"");
  EXPECT_EQ(d.line, 2);
  EXPECT_EQ(onlyDiagnostic("[machine]\ninitial_feed_mode = 99\n").message,
            "machine.initial_feed_mode must be one of \"per_revolution\", \"per_minute\", got 99");
}

// [machine] thread_runout is the older spelling of control.thread_runout; both at once is an error.
TEST(ParseSetup, ThreadRunoutInLeads) {
  EXPECT_EQ(parse("").setup->control.parameters.threadRunoutLeads, 0.0);
  for (const char* text : {"[machine]\nthread_runout = 1.5\n", "[control]\nthread_runout = 1.5\n"}) {
    const SetupResult result = parse(text);
    ASSERT_TRUE(result.setup.has_value()) << text;
    EXPECT_EQ(interpreterOptionsOf(*result.setup).control.threadRunoutLeads, 1.5) << text;
  }
  EXPECT_EQ(onlyDiagnostic("[control]\nthread_runout = 1.5\n[machine]\nthread_runout = 1.0\n").message,
            "machine.thread_runout and control.thread_runout both set the thread run-out; give control.thread_runout "
            "alone");
  EXPECT_EQ(onlyDiagnostic("[control]\nthread_runout = 10\n").message,
            "control.thread_runout must be a number from 0 to 9.9, got 10");
  EXPECT_EQ(onlyDiagnostic("[machine]\nthread_runout = -1\n").message,
            "machine.thread_runout must be a number of leads from 0 to 9.9 (the control's G92/G76 run-out parameter, "
            "GSK No.19 and Fanuc No.5130 in 0.1 lead), got -1");
}

// control.thread_runout_angle: Fanuc No.5131, whole degrees 0–89 (0 means 45°), 0 by default.
TEST(ParseSetup, ThreadRunoutAngle) {
  EXPECT_EQ(interpreterOptionsOf(*parse("").setup).control.threadRunoutAngleDeg, 0);
  EXPECT_EQ(interpreterOptionsOf(*parse("[control]\nthread_runout_angle = 30\n").setup).control.threadRunoutAngleDeg, 30);
  EXPECT_EQ(onlyDiagnostic("[control]\nthread_runout_angle = 90\n").message,
            "control.thread_runout_angle must be a whole number from 0 to 89, got 90");
  EXPECT_EQ(onlyDiagnostic("[control]\nthread_runout_angle = 30.5\n").message,
            "control.thread_runout_angle must be a whole number from 0 to 89, got 30.5");
}

TEST(ParseSetupErrors, ReferenceIsAPositionLikeStart) {
  EXPECT_EQ(onlyDiagnostic("[machine]\nreference = [200]\n").message,
            "machine.reference must be [X diameter, Z] in mm, got [200]");
  EXPECT_EQ(onlyDiagnostic("[machine]\nreference = [-2, 200]\n").message,
            "machine.reference X is a diameter and must not be negative, got [-2, 200]");
}

TEST(ParseSetupErrors, UnknownMachineKeyListsTheKnownOnes) {
  const Diagnostic d = onlyDiagnostic("[machine]\nrapids = [1, 2]\n");
  EXPECT_EQ(d.message,
            "unknown key 'machine.rapids' (expected start, rapid, max_rpm, reference, travel_x, travel_z, dialect, "
            "initial_feed_mode, thread_runout, zero, second_reference or tailstock)");
}

TEST(ParseSetup, ClockwiseOutlineIsAccepted) {
  const SetupResult result = parse("[[tool]]\nnumber = 1\npolygon = [[0, 0], [0, 12], [12, 12], [12, 0]]\n");
  ASSERT_TRUE(result.setup.has_value());
  EXPECT_DOUBLE_EQ(result.setup->tools[0].outline.area(), 144.0);
}

TEST(ParseSetupErrors, SyntaxErrorCarriesTomlsPosition) {
  const Diagnostic d = onlyDiagnostic("[stock]\ndiameter = = 5\n");
  EXPECT_EQ(d.file, "part.toml");
  EXPECT_EQ(d.line, 2);
  EXPECT_GT(d.column, 0);
  EXPECT_EQ(d.message.rfind("TOML syntax error: ", 0), 0u) << d.message;
  EXPECT_EQ(d.sourceLine, "diameter = = 5");
}

TEST(ParseSetupErrors, UnknownKeyIsNamedWithItsSection) {
  const Diagnostic d = onlyDiagnostic("[stock]\ndiameter = 50\n  diamter = 5\n");
  EXPECT_EQ(d.message, "unknown key 'stock.diamter' (expected diameter, length, face_z, bore or material)");
  EXPECT_EQ(d.line, 3);
  EXPECT_EQ(d.column, 3);
  EXPECT_EQ(d.sourceLine, "  diamter = 5");
}

TEST(ParseSetupErrors, UnknownTopLevelTable) {
  const Diagnostic d = onlyDiagnostic("[stock]\ndiameter = 50\n[spindle]\nrpm = 5\n");
  EXPECT_EQ(d.message,
            "unknown table 'spindle' (expected stock, machine, control, sim, tool, chuck, offset, work_offset or macro)");
  EXPECT_EQ(d.line, 3);
}

TEST(ParseSetupErrors, UnknownTopLevelKey) {
  const Diagnostic d = onlyDiagnostic("voxel = 0.2\n");
  EXPECT_EQ(d.message,
            "unknown key 'voxel' (expected stock, machine, control, sim, tool, chuck, offset, work_offset or macro)");
  EXPECT_EQ(d.line, 1);
  EXPECT_EQ(d.column, 1);
}

TEST(ParseSetupErrors, UnknownKeyInATool) {
  const Diagnostic d = onlyDiagnostic("[[tool]]\nnumber = 1\n[[tool]]\nnumber = 2\nradius = 0.4\n");
  EXPECT_EQ(d.message, "unknown key 'tool[2].radius' (expected number, polygon, kind, thickness, insert, holder, tip, "
                       "width, corner_radius, depth, angle, pitch, nose_radius, diameter, point_angle or length)");
  EXPECT_EQ(d.line, 5);
}

TEST(ParseSetupErrors, NegativeDiameter) {
  const Diagnostic d = onlyDiagnostic("[stock]\ndiameter = -5\n");
  EXPECT_EQ(d.message, "stock.diameter must be a positive number of mm, got -5");
  EXPECT_EQ(d.line, 2);
  EXPECT_EQ(d.column, 12);
}

TEST(ParseSetup, ABoreMakesATube) {
  const SetupResult result = parse("[stock]\ndiameter = 60\nbore = 40.5\nlength = 80\n");
  ASSERT_TRUE(result.setup.has_value());
  EXPECT_DOUBLE_EQ(result.setup->stock.boreMm, 40.5);
  EXPECT_DOUBLE_EQ(result.setup->stock.diameterMm, 60.0);
  EXPECT_DOUBLE_EQ(parse("[stock]\ndiameter = 60\n").setup->stock.boreMm, 0.0);  // a solid bar
}

TEST(ParseSetupErrors, ABoreMustBePositiveAndInsideTheBar) {
  // As wide as the bar, wider (the bore given before the diameter), and the default Φ125 bar's.
  for (const auto& [text, bore] : {std::pair{"[stock]\ndiameter = 60\nbore = 60\n", "60.0"},
                                   {"[stock]\nbore = 70\ndiameter = 60\n", "70.0"},
                                   {"[stock]\nbore = 130\n", "130.0"}}) {
    const Diagnostic d = onlyDiagnostic(text);
    EXPECT_EQ(d.message, "stock.bore (the tube's inside diameter, " + std::string(bore) +
                             " mm) must be smaller than stock.diameter (" +
                             (std::string(text).find("60") != std::string::npos ? "60.0" : "125.0") + " mm)")
        << text;
    EXPECT_EQ(d.sourceLine.rfind("bore = ", 0), 0u) << d.sourceLine;
    EXPECT_EQ(d.column, 8);  // the value
  }
  for (const char* text : {"[stock]\nbore = 0\n", "[stock]\nbore = -5\n"}) {
    const Diagnostic d = onlyDiagnostic(text);
    EXPECT_EQ(d.line, 2) << text;
    EXPECT_NE(d.message.find("stock.bore must be a positive number of mm"), std::string::npos) << d.message;
  }
}

TEST(ParseSetupErrors, ZeroLength) {
  const Diagnostic d = onlyDiagnostic("[stock]\nlength = 0.0\n");
  EXPECT_EQ(d.message, "stock.length must be a positive number of mm, got 0.0");
  EXPECT_EQ(d.line, 2);
}

TEST(ParseSetupErrors, NonPositiveVoxel) {
  const Diagnostic d = onlyDiagnostic("[sim]\n\nvoxel = -0.2\n");
  EXPECT_EQ(d.message, "sim.voxel must be a positive number of mm, got -0.2");
  EXPECT_EQ(d.line, 3);
}

TEST(ParseSetupErrors, MaxMovesIsAWholePositiveNumber) {
  for (const char* value : {"0", "-5", "2.5", "\"many\""}) {
    const Diagnostic d = onlyDiagnostic(std::string("[sim]\nmax_moves = ") + value + "\n");
    EXPECT_EQ(d.message, std::string("sim.max_moves must be a whole number of moves, 1 or more, got ") + value);
    EXPECT_EQ(d.line, 2);
  }
  const SetupResult result = parse("[sim]\nmax_moves = 5000000\n");
  ASSERT_TRUE(result.setup);
  EXPECT_EQ(result.setup->maxMoves, 5'000'000u);
  EXPECT_EQ(parse("").setup->maxMoves, interp::kDefaultMaxMoves);
}

TEST(ParseSetupErrors, WrongTypeForANumber) {
  const Diagnostic d = onlyDiagnostic("[stock]\nface_z = \"2\"\n");
  EXPECT_EQ(d.message, "stock.face_z must be a number of mm, got \"2\"");
  EXPECT_EQ(d.line, 2);
}

TEST(ParseSetupErrors, WrongTypeForASection) {
  const Diagnostic d = onlyDiagnostic("stock = 125\n");
  EXPECT_EQ(d.message, "stock must be a table ([stock]), got 125");
  EXPECT_EQ(d.line, 1);
}

TEST(ParseSetupErrors, StartMustBeAPair) {
  const Diagnostic d = onlyDiagnostic("[machine]\nstart = [200]\n");
  EXPECT_EQ(d.message, "machine.start must be [X diameter, Z] in mm, got [200]");
  EXPECT_EQ(d.line, 2);
}

TEST(ParseSetupErrors, StartMustHoldNumbers) {
  const Diagnostic d = onlyDiagnostic("[machine]\nstart = [\"X200\", 200]\n");
  EXPECT_EQ(d.message.rfind("machine.start must be [X diameter, Z] in mm, got ", 0), 0u) << d.message;
}

TEST(ParseSetupErrors, StartDiameterMustNotBeNegative) {
  const Diagnostic d = onlyDiagnostic("[machine]\nstart = [-10, 200]\n");
  EXPECT_EQ(d.message, "machine.start X is a diameter and must not be negative, got [-10, 200]");
}

TEST(ParseSetupErrors, NonConvexPolygon) {
  const Diagnostic d = onlyDiagnostic(R"([[tool]]
number = 1
[[tool]]
number = 2
polygon = [[0, 0], [10, 0], [5, 2], [10, 10], [0, 10]]
)");
  EXPECT_EQ(d.message, "tool[2].polygon is not convex (it turns the other way at vertex 3)");
  EXPECT_EQ(d.line, 5);
  EXPECT_EQ(d.column, 11);
}

TEST(ParseSetupErrors, SelfIntersectingPolygon) {
  const Diagnostic d = onlyDiagnostic("[[tool]]\nnumber = 1\npolygon = [[0, 0], [10, 10], [10, 0], [0, 10]]\n");
  EXPECT_EQ(d.message, "tool[1].polygon is self-intersecting (edges 1 and 3 cross)");
  EXPECT_EQ(d.line, 3);
}

TEST(ParseSetupErrors, PolygonWithTooFewPoints) {
  const Diagnostic d = onlyDiagnostic("[[tool]]\nnumber = 1\npolygon = [[0, 0], [10, 1]]\n");
  EXPECT_EQ(d.message, "tool[1].polygon needs at least 3 vertices, got 2");
  EXPECT_EQ(d.line, 3);
}

TEST(ParseSetupErrors, PolygonPointsMustBePairs) {
  const Diagnostic d = onlyDiagnostic("[[tool]]\nnumber = 1\npolygon = [[0, 0], [10], [1, 10]]\n");
  EXPECT_EQ(d.message.rfind("tool[1].polygon must be a list of [radial, axial] points in mm, got ", 0), 0u)
      << d.message;
  EXPECT_EQ(d.line, 3);
}

TEST(ParseSetupErrors, ToolNumberOutOfRange) {
  const Diagnostic d = onlyDiagnostic("[[tool]]\nnumber = 100\n");
  EXPECT_EQ(d.message, "tool[1].number must be an integer 1..99, got 100");
  EXPECT_EQ(d.line, 2);
  EXPECT_EQ(d.column, 10);
}

TEST(ParseSetupErrors, ToolNumberZero) {
  const Diagnostic d = onlyDiagnostic("[[tool]]\nnumber = 0\n");
  EXPECT_EQ(d.message, "tool[1].number must be an integer 1..99, got 0");
}

TEST(ParseSetupErrors, ToolNumberMustBeAnInteger) {
  const Diagnostic d = onlyDiagnostic("[[tool]]\nnumber = 1.5\n");
  EXPECT_EQ(d.message, "tool[1].number must be an integer 1..99, got 1.5");
}

TEST(ParseSetupErrors, ToolWithoutNumber) {
  const Diagnostic d = onlyDiagnostic("[[tool]]\nnumber = 1\n\n[[tool]]\npolygon = [[0, 0], [10, 1], [1, 10]]\n");
  EXPECT_EQ(d.message, "tool[2] has no number (add number = 1..99)");
  EXPECT_EQ(d.line, 4);
}

TEST(ParseSetupErrors, DuplicateToolNumber) {
  const Diagnostic d = onlyDiagnostic("[[tool]]\nnumber = 1\n[[tool]]\nnumber = 2\n[[tool]]\nnumber = 1\n");
  EXPECT_EQ(d.message, "tool number 1 is defined twice (tool[1] and tool[3])");
  EXPECT_EQ(d.line, 6);
  EXPECT_EQ(d.column, 10);
}

TEST(ParseSetupErrors, ToolMustBeAnArrayOfTables) {
  const Diagnostic d = onlyDiagnostic("[tool]\nnumber = 1\n");
  EXPECT_EQ(d.message, "tool must be given as [[tool]] tables, got a table");
  EXPECT_EQ(d.line, 1);
}

TEST(ParseSetupErrors, EmptyToolList) {
  const Diagnostic d = onlyDiagnostic("tool = []\n");
  EXPECT_EQ(d.message, "tool lists no tools; give at least one [[tool]] or leave tool out");
  EXPECT_EQ(d.line, 1);
}

TEST(ParseSetupErrors, EveryErrorIsReported) {
  const SetupResult result = parse("[stock]\ndiameter = -1\nlength = -2\n[sim]\nvoxl = 1\n");
  EXPECT_FALSE(result.setup.has_value());
  ASSERT_EQ(result.diagnostics.size(), 3u);
  EXPECT_EQ(result.diagnostics[0].line, 2);
  EXPECT_EQ(result.diagnostics[1].line, 3);
  EXPECT_EQ(result.diagnostics[2].line, 5);
}

TEST(LoadSetup, MissingFileIsAWholeFileError) {
  const auto path = std::filesystem::temp_directory_path() / "lathesim-no-such-setup.toml";
  std::filesystem::remove(path);
  const SetupResult result = loadSetup(path);
  EXPECT_FALSE(result.setup.has_value());
  ASSERT_EQ(result.diagnostics.size(), 1u);
  EXPECT_EQ(result.diagnostics[0].file, path.string());
  EXPECT_EQ(result.diagnostics[0].line, 0);
  EXPECT_EQ(result.diagnostics[0].message, "setup file not found");
}

TEST(LoadSetup, DirectoryIsUnreadable) {
  const auto path = std::filesystem::temp_directory_path();
  const SetupResult result = loadSetup(path);
  ASSERT_EQ(result.diagnostics.size(), 1u);
  EXPECT_EQ(result.diagnostics[0].line, 0);
  EXPECT_EQ(result.diagnostics[0].message, "cannot read the setup file");
}

TEST(LoadSetup, ReadsAFileAndNamesIt) {
  const auto path = std::filesystem::temp_directory_path() / "lathesim-setup-test.toml";
  {
    std::ofstream out(path);
    out << "[stock]\ndiameter = 40\nlength = -50\n";
  }
  const SetupResult result = loadSetup(path);
  std::filesystem::remove(path);
  ASSERT_EQ(result.diagnostics.size(), 1u);
  EXPECT_EQ(result.diagnostics[0].file, path.string());
  EXPECT_EQ(result.diagnostics[0].line, 3);
  EXPECT_EQ(result.diagnostics[0].sourceLine, "length = -50");
}

TEST(LoadSetup, EveryBundledPartHasAValidSetup) {
  int parts = 0;
  for (const auto& entry : std::filesystem::directory_iterator(LATHESIM_PARTS_DIR)) {
    const auto file = entry.path() / "setup.toml";
    if (!std::filesystem::exists(file)) continue;
    ++parts;
    const SetupResult result = loadSetup(file);
    EXPECT_TRUE(result.setup.has_value())
        << file << ": " << (result.diagnostics.empty() ? "" : result.diagnostics[0].message);
  }
  EXPECT_GT(parts, 0);
}

TEST(ParseSetup, WorkOffsetsAndMachineZero) {
  const SetupResult result = parse(
      "[machine]\nzero = [300.0, 450.0]\n"
      "[[work_offset]]\ncode = \"G55\"\nz = -40.0\n"
      "[[work_offset]]\ncode = \"G59\"\nx = 1.0\nz = 2\n");
  ASSERT_TRUE(result.setup.has_value()) << result.diagnostics.at(0).message;
  const setup::Setup& setup = *result.setup;
  ASSERT_TRUE(setup.machineZero.has_value());
  EXPECT_EQ(*setup.machineZero, RZ(150.0, 450.0));  // X is a diameter
  EXPECT_EQ(setup.workOffsets[1], RZ(0, 0));        // G54 untouched
  EXPECT_EQ(setup.workOffsets[2], RZ(0, -40.0));
  EXPECT_EQ(setup.workOffsets[6], RZ(0.5, 2.0));
  EXPECT_FALSE(defaultSetup().machineZero.has_value());
}

TEST(ParseSetupErrors, WorkOffsetProblemsAreNamed) {
  EXPECT_EQ(onlyDiagnostic("[[work_offset]]\ncode = \"G60\"\n").message, "work_offset[1].code must be one of \"G54\" … \"G59\"");
  EXPECT_EQ(onlyDiagnostic("[[work_offset]]\nz = 1\n").message, "work_offset[1] has no code (add code = \"G54\" … \"G59\")");
  EXPECT_EQ(onlyDiagnostic("[[work_offset]]\ncode = \"G55\"\ny = 1\n").message,
            "unknown key 'work_offset[1].y' (expected code, x, z)");
  EXPECT_EQ(onlyDiagnostic("[[work_offset]]\ncode = \"G55\"\n[[work_offset]]\ncode = \"G55\"\n").message,
            "G55 is given twice (work_offset[1] and work_offset[2])");
}

}  // namespace
}  // namespace lathesim::setup
