// report.json's "tools" and "stock" (app/tool_table.hpp) against a setup whose every value is
// known by hand: an ISO turning tool (its insert's edge from the ISO size, its holder's shank),
// a groove blade on an undefined offset, a drill a comment mounts, a tool never used, an offset
// G10 changes during the run, a tube of a stated material; and the bar from --stock, from the
// program, and assumed.

#include <gtest/gtest.h>

#include <cmath>
#include <nlohmann/json.hpp>
#include <numbers>

#include "tests/support/lathesim_process.hpp"

namespace lathesim::app {
namespace {

using Json = nlohmann::json;

constexpr const char* kToolTableSetup = R"([stock]
diameter = 40.0
length = 60.0
face_z = 1.0
bore = 10.0
material = "C45"

[[tool]]
number = 1
insert = "CNMG120408"
holder = "PCLNR2525M12"

[[tool]]
number = 3
kind = "groove"
width = 3.0
depth = 12.0

[[tool]]
number = 7
kind = "drill"
diameter = 6.0

[[offset]]
number = 1
x = 0.4
z = -0.2
wear_x = -0.1
wear_z = 0.05
radius = 0.8
tip = 3
)";

// Line 4 is the first move under T0101; G10 on line 8 adds 0.1 to offset 1's Z wear, taken up
// by the T0101 of line 9; the drill's comment is on line 18, above its T word on line 19.
constexpr const char* kToolTableProgram = R"(G21 G99
T0101
G97 S1000 M03
G00 X42 Z3
G01 X38 Z2 F0.2
G01 Z-10
G00 X60 Z20
G10 P1 W0.1
T0101
G00 X39 Z3
G01 Z-5 F0.2
G00 X60 Z20
T0303
G00 X45 Z-15
G01 X36 F0.05
G00 X60
G00 Z20
(DRILL 8)
T0505
G00 X0 Z5
G01 Z-5 F0.1
G00 Z20
M30
)";

Json runReport(const test::ScratchDir& scratch, const std::vector<std::string>& extra) {
  std::vector<std::string> args{"run", (scratch.path() / "part.nc").string(), "--out", (scratch.path() / "out").string(),
                                "--outputs", "report,html"};
  args.insert(args.end(), extra.begin(), extra.end());
  const test::ProcessOutcome outcome = test::lathesim(args, scratch.path());
  EXPECT_EQ(outcome.status, 0) << outcome.err;
  return Json::parse(test::readFile(scratch.path() / "out" / "report.json"));
}

const Json& toolNumbered(const Json& tools, int number) {
  for (const Json& t : tools)
    if (t.at("number") == number) return t;
  throw std::runtime_error("no tool " + std::to_string(number));
}

TEST(ToolTable, EveryToolWithItsInsertHolderOffsetsAndSource) {
  test::ScratchDir scratch("tool-table");
  const auto setup = scratch.path() / "setup.toml";
  test::writeFile(setup, kToolTableSetup);
  test::writeFile(scratch.path() / "part.nc", kToolTableProgram);
  const Json report = runReport(scratch, {"--setup", setup.string()});
  const Json& tools = report.at("tools");
  ASSERT_EQ(tools.size(), 4u) << tools.dump(2);  // 1, 3, 7 from the setup, 5 from the comment

  const Json& turning = toolNumbered(tools, 1);
  EXPECT_EQ(turning.at("kind"), "turning");
  EXPECT_EQ(turning.at("insert"), "CNMG120408");
  // An 80° rhombus of inscribed circle 12.7 mm (size 12): its edge is 12.7 / sin 80°.
  EXPECT_NEAR(turning.at("cutting_edge_length_mm").get<double>(), 12.7 / std::sin(80.0 * std::numbers::pi / 180), 0.01);
  EXPECT_DOUBLE_EQ(turning.at("insert_angle_deg").get<double>(), 80.0);
  EXPECT_DOUBLE_EQ(turning.at("nose_radius_mm").get<double>(), 0.8);
  EXPECT_EQ(turning.at("holder"), "PCLNR2525M12");
  EXPECT_DOUBLE_EQ(turning.at("entering_angle_deg").get<double>(), 95.0);
  EXPECT_DOUBLE_EQ(turning.at("shank_mm").at("width").get<double>(), 25.0);
  EXPECT_DOUBLE_EQ(turning.at("shank_mm").at("height").get<double>(), 25.0);
  EXPECT_EQ(turning.at("tip"), 3);
  EXPECT_EQ(turning.at("from"), setup.string() + ":8 tool[1]");
  ASSERT_EQ(turning.at("offsets_used").size(), 1u);
  const Json& offset = turning.at("offsets_used")[0];
  EXPECT_EQ(offset.at("t_word"), "T0101");
  EXPECT_EQ(offset.at("first_line"), 4);
  EXPECT_DOUBLE_EQ(offset.at("table").at("x_diameter_mm").get<double>(), 0.4);
  EXPECT_DOUBLE_EQ(offset.at("table").at("wear_z_mm").get<double>(), 0.05);
  // Geometry + wear: X 0.4 − 0.1, Z −0.2 + 0.05; then G10 adds 0.1 to the Z wear.
  const Json& shifts = offset.at("shifts_used");
  ASSERT_EQ(shifts.size(), 2u) << shifts.dump();
  EXPECT_NEAR(shifts[0].at("x_diameter_mm").get<double>(), 0.3, 1e-9);
  EXPECT_NEAR(shifts[0].at("z_mm").get<double>(), -0.15, 1e-9);
  EXPECT_NEAR(shifts[1].at("x_diameter_mm").get<double>(), 0.3, 1e-9);
  EXPECT_NEAR(shifts[1].at("z_mm").get<double>(), -0.05, 1e-9);

  const Json& groove = toolNumbered(tools, 3);
  EXPECT_EQ(groove.at("kind"), "groove");
  EXPECT_TRUE(groove.at("insert").is_null());
  EXPECT_TRUE(groove.at("holder").is_null());
  EXPECT_EQ(groove.at("from"), setup.string() + ":13 tool[2]");
  ASSERT_EQ(groove.at("offsets_used").size(), 1u);
  EXPECT_EQ(groove.at("offsets_used")[0].at("first_line"), 14);
  EXPECT_TRUE(groove.at("offsets_used")[0].at("table").is_null());  // no [[offset]] 3: all zero
  EXPECT_NEAR(groove.at("offsets_used")[0].at("shifts_used")[0].at("z_mm").get<double>(), 0.0, 1e-12);

  const Json& unused = toolNumbered(tools, 7);
  EXPECT_FALSE(unused.at("used").get<bool>());
  EXPECT_TRUE(unused.at("offsets_used").empty());
  EXPECT_EQ(unused.at("kind"), "drill");

  const Json& drill = toolNumbered(tools, 5);
  EXPECT_EQ(drill.at("kind"), "drill");
  EXPECT_DOUBLE_EQ(drill.at("insert_angle_deg").get<double>(), 118.0);
  EXPECT_EQ(drill.at("from"), "the comment '(DRILL 8)' of the T word at " + (scratch.path() / "part.nc").string() + ":19");
  EXPECT_TRUE(drill.at("used").get<bool>());
  EXPECT_EQ(drill.at("offsets_used")[0].at("first_line"), 20);

  const Json& stock = report.at("stock");
  EXPECT_DOUBLE_EQ(stock.at("diameter_mm").get<double>(), 40.0);
  EXPECT_DOUBLE_EQ(stock.at("length_mm").get<double>(), 60.0);
  EXPECT_DOUBLE_EQ(stock.at("bore_mm").get<double>(), 10.0);
  EXPECT_DOUBLE_EQ(stock.at("face_z_mm").get<double>(), 1.0);
  EXPECT_EQ(stock.at("material"), "C45");
  EXPECT_EQ(stock.at("from"), setup.string() + ":1 [stock]");
  EXPECT_EQ(stock.at("face_z_from"), stock.at("from"));

  // The page shows the same table.
  const std::string html = test::readFile(scratch.path() / "out" / "report.html");
  EXPECT_NE(html.find("<h2>Stock and tools</h2>"), std::string::npos);
  EXPECT_NE(html.find("<b>CNMG120408</b>"), std::string::npos);
  EXPECT_NE(html.find("<b>PCLNR2525M12</b>, κr 95°, shank 25×25 mm"), std::string::npos);
  EXPECT_NE(html.find("T0101 from line <a href=\"#L4\">4</a>: X+0.3 Z-0.15, then X+0.3 Z-0.05"), std::string::npos);
  EXPECT_NE(html.find("C45"), std::string::npos);
  EXPECT_EQ(html.find("cut.mp4"), std::string::npos);  // no video, no link to one
}

TEST(ToolTable, TheBarSaysWhoStatedIt) {
  test::ScratchDir scratch("tool-table-stock");
  test::writeFile(scratch.path() / "part.nc", "G00 X150 Z150\nM30\n");
  const Json assumed = runReport(scratch, {});
  EXPECT_DOUBLE_EQ(assumed.at("stock").at("diameter_mm").get<double>(), 125.0);  // the default setup's bar
  EXPECT_EQ(assumed.at("stock").at("from").get<std::string>().rfind("assumed", 0), 0u) << assumed.at("stock");
  EXPECT_EQ(assumed.at("stock").at("face_z_from").get<std::string>().rfind("assumed: Z2", 0), 0u);
  EXPECT_TRUE(assumed.at("stock").at("material").is_null());
  ASSERT_EQ(assumed.at("tools").size(), 1u);
  EXPECT_EQ(assumed.at("tools")[0].at("kind"), "default");
  EXPECT_EQ(assumed.at("tools")[0].at("from").get<std::string>().rfind("the default setup", 0), 0u);

  const Json given = runReport(scratch, {"--stock", "D30xd8xL50"});
  EXPECT_DOUBLE_EQ(given.at("stock").at("diameter_mm").get<double>(), 30.0);
  EXPECT_DOUBLE_EQ(given.at("stock").at("bore_mm").get<double>(), 8.0);
  EXPECT_EQ(given.at("stock").at("from"), "--stock D30xd8xL50");
  EXPECT_EQ(given.at("stock").at("face_z_from"), "assumed: Z0");

  test::writeFile(scratch.path() / "part.nc", "G00 X150 Z150\n(STOCK D40 L80)\nM30\n");
  const Json stated = runReport(scratch, {});
  EXPECT_DOUBLE_EQ(stated.at("stock").at("length_mm").get<double>(), 80.0);
  EXPECT_EQ(stated.at("stock").at("from"),
            "the program at " + (scratch.path() / "part.nc").string() + ":2: (STOCK D40 L80)");
}

}  // namespace
}  // namespace lathesim::app
