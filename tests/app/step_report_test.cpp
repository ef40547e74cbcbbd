// report.html's stepping (app/step_recording.hpp, app/report_steps.hpp): the stock's section
// after each block, as the page decodes it, against the sizes worked out by hand from the
// program; each block's figures against the run's totals; the page's script in a browser.

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <nlohmann/json.hpp>
#include <regex>

#include "tests/support/headless_chromium.hpp"
#include "tests/support/lathesim_process.hpp"

namespace lathesim::test {
namespace {

using Json = nlohmann::json;
using Polyline = std::vector<std::array<double, 2>>;  // (r, z) mm

const fs::path kShaft = fs::path(LATHESIM_PARTS_DIR) / "g71-g70-shaft";

Json stepData(const std::string& html) {
  std::smatch data;
  const std::regex script(R"re(<script type="application/json" id="step-data">([^<]*)</script>)re");
  if (!std::regex_search(html, data, script)) return nullptr;
  return Json::parse(data[1].str());
}

/// The sections as the page decodes them: each polyline [from, head, tail, middle] keeps `head`
/// points of the section before's polyline `from`, then the middle, then its last `tail`.
std::vector<std::vector<Polyline>> decodedSections(const Json& sections) {
  std::vector<std::vector<Polyline>> decoded;
  for (const Json& section : sections) {
    std::vector<Polyline> lines;
    for (const Json& change : section[1]) {
      const int from = change[0];
      const std::size_t head = change[1], tail = change[2];
      const Polyline none;
      const Polyline& old = from >= 0 ? decoded.back().at(static_cast<std::size_t>(from)) : none;
      Polyline line(old.begin(), old.begin() + static_cast<long>(head));
      const Json& middle = change[3];
      for (std::size_t i = 0; i + 1 < middle.size(); i += 2)
        line.push_back({middle[i].get<double>() / 1000, middle[i + 1].get<double>() / 1000});
      line.insert(line.end(), old.end() - static_cast<long>(tail), old.end());
      lines.push_back(line);
    }
    decoded.push_back(lines);
  }
  return decoded;
}

/// The section's outer radius at `z`: the largest r where one of its polylines crosses z.
double radiusAt(const std::vector<Polyline>& section, double z) {
  double most = 0;
  for (const Polyline& line : section)
    for (std::size_t i = 1; i < line.size(); ++i) {
      const auto& [r0, z0] = line[i - 1];
      const auto& [r1, z1] = line[i];
      if ((z0 - z) * (z1 - z) > 0 || z0 == z1) continue;
      most = std::max(most, r0 + (r1 - r0) * (z - z0) / (z1 - z0));
    }
  return most;
}

/// The section the page shows after step `s`: the last taken at or before its end.
const std::vector<Polyline>& sectionAfter(const Json& data, const std::vector<std::vector<Polyline>>& sections, std::size_t s) {
  const long end = data["steps"][s][2];
  std::size_t at = 0;
  for (std::size_t i = 0; i < data["sections"].size(); ++i)
    if (data["sections"][i][0].get<long>() <= end) at = i;
  return sections[at];
}

class ShaftSteps : public ::testing::TestWithParam<double> {};

// The Φ50 bar (r 25) roughed by G71 U2 with allowances U0.5 (on the diameter: r + 0.25) and W0.1
// (the contour 0.1 to +Z), then finished by G70 with a sharp tool: Ø20 to Z-15, a taper to Ø32
// at Z-30, Ø32 to Z-45, Ø44 to Z-55, the bar beyond.
TEST_P(ShaftSteps, TheSectionAfterEachBlockHasTheSizesOfTheProgram) {
  const double voxel = GetParam();
  ScratchDir dir("steps");
  const auto run = runProcess(LATHESIM_BINARY,
                              {"run", (kShaft / "program.nc").string(), "--setup", (kShaft / "setup.toml").string(), "--out",
                               (dir.path() / "out").string(), "--outputs", "report,html", "--voxel", std::to_string(voxel)},
                              dir.path());
  ASSERT_EQ(run.status, 0) << run.err;
  const Json report = Json::parse(readFile(dir.path() / "out" / "report.json"));
  const Json data = stepData(readFile(dir.path() / "out" / "report.html"));
  ASSERT_TRUE(data.is_object());
  const auto sections = decodedSections(data["sections"]);
  const Json& steps = data["steps"];
  ASSERT_GE(steps.size(), 4u);

  double removed = 0, time = 0;
  for (const Json& s : steps) removed += s[3].get<double>(), time += s[4].get<double>();
  EXPECT_NEAR(removed, report["removed_volume_mm3"].get<double>(), 0.05 * steps.size() + 0.1);
  EXPECT_NEAR(time, report["cycle_time_s"].get<double>(), 0.005 * steps.size() + 0.01);
  EXPECT_EQ(steps.back()[2], report["moves"]) << "the last step ends with the last move";

  const double within = voxel / 2 + 0.02;
  const auto& bar = sectionAfter(data, sections, 0);  // G00 X52 Z2: nothing cut yet
  for (double z : {-10.0, -37.5, -60.0}) EXPECT_NEAR(radiusAt(bar, z), 25, within) << "bar at Z" << z;

  std::size_t roughing = 0;
  while (roughing < steps.size() && steps[roughing][0] != 6) ++roughing;  // line 6: G71 P10 Q80 …
  ASSERT_LT(roughing, steps.size());
  const auto& roughed = sectionAfter(data, sections, roughing);
  EXPECT_NEAR(radiusAt(roughed, -10), 10.25, within);
  EXPECT_NEAR(radiusAt(roughed, -37.5), 16.25, within);
  EXPECT_NEAR(radiusAt(roughed, -50), 22.25, within);
  EXPECT_NEAR(radiusAt(roughed, -60), 25, within);

  const auto& finished = sectionAfter(data, sections, steps.size() - 1);
  EXPECT_NEAR(radiusAt(finished, -10), 10, within);
  EXPECT_NEAR(radiusAt(finished, -22.5), 14.5, within);  // halfway up the taper
  EXPECT_NEAR(radiusAt(finished, -37.5), 16, within);
  EXPECT_NEAR(radiusAt(finished, -50), 22, within);
  EXPECT_NEAR(radiusAt(finished, -60), 25, within);

  // Block by block, what the section lost is what the step says it removed: π ∫ r² dz over the
  // bar's length (every section here is one outer profile), against the simulation's own
  // figure. A section shown a block early or late moves a removal to the wrong step.
  const auto volume = [](const std::vector<Polyline>& section) {
    double sum = 0;
    for (double z = -80 + 0.025; z < 0; z += 0.05) sum += M_PI * std::pow(radiusAt(section, z), 2) * 0.05;
    return sum;
  };
  for (std::size_t s = 1; s < steps.size(); ++s) {
    const double lost = volume(sectionAfter(data, sections, s - 1)) - volume(sectionAfter(data, sections, s));
    const double said = steps[s][3];
    EXPECT_NEAR(lost, said, 0.001 * said + 250 * voxel) << "step " << s << ", line " << steps[s][0];
  }

  // Each step's end is where its last move ends (the toolpath's, in µm; X as a radius).
  for (const Json& s : steps) EXPECT_LE(s[1].get<long>(), s[2].get<long>());
  EXPECT_EQ(steps.back()[5], 50000) << "G00 X100.0: r 50";
  EXPECT_EQ(steps.back()[6], 50000) << "Z50.0";
  EXPECT_TRUE(data["tools"].contains("1"));
}

INSTANTIATE_TEST_SUITE_P(Voxels, ShaftSteps, ::testing::Values(0.2, 0.1));

TEST(StepReport, ThePageStepsToTheBlockInItsAddressAndStartsAtTheEnd) {
  ScratchDir dir("steps-page");
  const auto run = runProcess(LATHESIM_BINARY,
                              {"run", (kShaft / "program.nc").string(), "--setup", (kShaft / "setup.toml").string(), "--out",
                               (dir.path() / "out").string(), "--outputs", "report,html"},
                              dir.path());
  ASSERT_EQ(run.status, 0) << run.err;
  const std::size_t blocks = stepData(readFile(dir.path() / "out" / "report.html"))["steps"].size();
  const std::string page = "file://" + (dir.path() / "out" / "report.html").string();
  const BrowserRun second = openInChromium(dir, page + "#step=2", {"--dump-dom"});
  EXPECT_NE(second.outcome.out.find("block 2 of " + std::to_string(blocks) + ", line 6:  G71 P10 Q80 U0.5 W0.1 F0.25"),
            std::string::npos);
  EXPECT_TRUE(std::regex_search(second.outcome.out, std::regex(R"(<tr id="L6"[^>]*class="current")")))
      << "the listing's line";
  const BrowserRun last = openInChromium(dir, page, {"--dump-dom"});
  EXPECT_NE(last.outcome.out.find("block " + std::to_string(blocks) + " of " + std::to_string(blocks)), std::string::npos);
  for (const std::string& line : last.consoleLines) EXPECT_EQ(line.find("Uncaught"), std::string::npos) << line;
}

}  // namespace
}  // namespace lathesim::test
