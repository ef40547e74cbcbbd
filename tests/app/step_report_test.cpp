// report.html's stepping (app/step_recording.hpp, app/report_steps.hpp): the stock's section
// after each block, as the page decodes it, against the sizes worked out by hand from the
// program; each block's figures against the run's totals; the page's script in a browser.

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <nlohmann/json.hpp>
#include <cstdio>
#include <cstdlib>
#include <iostream>
#include <regex>

#include "app/step_recording.hpp"
#include "tests/support/headless_chromium.hpp"
#include "tests/support/lathesim_process.hpp"

namespace lathesim::test {
namespace {

using Json = nlohmann::json;
using Polyline = std::vector<std::array<double, 2>>;  // (r, z) mm

const fs::path kShaft = fs::path(LATHESIM_PARTS_DIR) / "g71-g70-shaft";

Json stepData(const std::string& html) {  // found by hand: std::regex recurses per character
  const std::string open = "<script type=\"application/json\" id=\"step-data\">";
  const auto begin = html.find(open);
  if (begin == std::string::npos) return nullptr;
  const auto end = html.find("</script>", begin);
  return Json::parse(html.substr(begin + open.size(), end - begin - open.size()));
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

/// The volume the section turns into: Pappus, 2π ∫∫ r dA, which Green's theorem makes
/// π |∮ r² dz| around the section closed along the axis (where r² is 0); an edge from
/// (r0, z0) to (r1, z1) adds (z1 − z0)(r0² + r0 r1 + r1²) / 3.
double revolvedVolume(const std::vector<Polyline>& section) {
  double sum = 0;
  for (const Polyline& line : section)
    for (std::size_t i = 1; i < line.size(); ++i) {
      const auto& [r0, z0] = line[i - 1];
      const auto& [r1, z1] = line[i];
      sum += (z1 - z0) * (r0 * r0 + r0 * r1 + r1 * r1) / 3;
    }
  return M_PI * std::abs(sum);
}

/// The section the page shows after step `s`: the last taken at or before its end.
// A CAM finishing contour program of `blocks` one-line blocks, r = 17 + 0.3 sin(z / 4) from Z0
// to Z-60 (never steeper than the sharp tool's 1-in-10 flank), with `decimals` places, for the
// shaft's Φ50 bar: a rapid in, a feed to the face, the contour, a rapid home.
std::string camFinishProgram(const char* number, int blocks, int decimals) {
  std::string program = std::string(number) + " (CAM FINISH)\nT0101\nG99 G97 S800 M03\nG00 X52.0 Z1.0\nG01 X34.0 Z0 F0.1\n";
  char block[64];
  for (int i = 1; i <= blocks; ++i) {
    const double z = -60.0 * i / blocks;
    std::snprintf(block, sizeof block, "X%.*f Z%.*f\n", decimals, 2 * (17 + 0.3 * std::sin(z / 4)), decimals, z);
    program += block;
  }
  return program + "G00 X100.0 Z50.0\nM30\n";
}

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

  // Block by block, what the section lost (revolvedVolume) is what the step says it removed,
  // the simulation's own figure. A section shown a block early or late moves a removal to the
  // wrong step.
  const auto volume = revolvedVolume;
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

// A CAM finishing contour of 2,000 one-line blocks, r = 17 + 0.3 sin(z / 4) from Z0 to Z-60 (never
// steeper than the sharp tool's 1-in-10 flank), on the shaft's Φ50 bar: at every hundredth block, what the section lost since the last one is
// what those blocks removed; the page stays small.
TEST(StepReport, ALongCamProgramsPageHoldsEveryBlockInLittleSpace) {
  ScratchDir dir("steps-cam");
  writeFile(dir.path() / "cam.nc", camFinishProgram("O2000", 2000, 3));
  const auto run = runProcess(LATHESIM_BINARY,
                              {"run", (dir.path() / "cam.nc").string(), "--setup", (kShaft / "setup.toml").string(), "--out",
                               (dir.path() / "out").string(), "--outputs", "report,html"},
                              dir.path());
  ASSERT_EQ(run.status, 0) << run.err;
  const std::string html = readFile(dir.path() / "out" / "report.html");
  EXPECT_LT(html.size(), 8u << 20);
  const Json data = stepData(html);
  ASSERT_TRUE(data.is_object());
  const Json& steps = data["steps"];
  ASSERT_EQ(steps.size(), 2003u) << "G00, G01 to the face, 2,000 contour blocks, G00 home";
  const auto sections = decodedSections(data["sections"]);
  const auto volume = revolvedVolume;
  // Sections may be thinned here (they take at most a tenth of the run's time): compare each
  // tenth section with the one ten before, against what the blocks between them removed (each
  // block here is one group of moves, so a section stands between two blocks).
  const Json& taken = data["sections"];
  for (std::size_t a = 0, b = 10; a + 1 < sections.size(); a = b, b = std::min(b + 10, sections.size() - 1)) {
    double removed = 0;
    for (const Json& step : steps)
      if (step[2].get<long>() > taken[a][0].get<long>() && step[2].get<long>() <= taken[b][0].get<long>())
        removed += step[3].get<double>();
    EXPECT_NEAR(volume(sections[a]) - volume(sections[b]), removed, 0.002 * removed + 50)
        << "sections " << a << " to " << b << ", after moves " << taken[a][0] << " to " << taken[b][0];
  }
  std::cout << sections.size() << " sections for " << steps.size() << " blocks, " << html.size() << " bytes\n";
  const auto& finished = sectionAfter(data, sections, steps.size() - 1);
  for (double z = -2; z > -58; z -= 7.3) EXPECT_NEAR(radiusAt(finished, z), 17 + 0.3 * std::sin(z / 4), 0.12) << "Z" << z;
}

// A CAM contour of 12,000 one-line blocks (r = 17 + 0.3 sin(z / 4), Z0 to Z-60), more than
// StepRecording::kMaxSteps: the page still steps, each step covering 4 blocks (12,000 blocks
// halved twice to fit), and each step holds exactly the report.json rows of its
// blocks: their lines from first to last, their removed volume and time summed.
TEST(StepReport, AProgramPastTheStepLimitStepsSeveralBlocksAStep) {
  ScratchDir dir("steps-12000");
  writeFile(dir.path() / "cam.nc", camFinishProgram("O2001", 12000, 4));
  const auto run = runProcess(LATHESIM_BINARY,
                              {"run", (dir.path() / "cam.nc").string(), "--setup", (kShaft / "setup.toml").string(), "--voxel",
                               "0.25", "--out", (dir.path() / "out").string(), "--outputs", "report,html"},
                              dir.path());
  ASSERT_EQ(run.status, 0) << run.err;
  const std::string html = readFile(dir.path() / "out" / "report.html");
  const Json report = Json::parse(readFile(dir.path() / "out" / "report.json"));
  const Json& rows = report["blocks"];
  ASSERT_GT(rows.size(), 2 * app::StepRecording::kMaxSteps) << "the contour's 12,000 blocks, and those around it";
  ASSERT_LE(rows.size(), 4 * app::StepRecording::kMaxSteps);
  const Json data = stepData(html);
  ASSERT_TRUE(data.is_object()) << "the page steps";
  const std::size_t perStep = data["blocks_per_step"];
  EXPECT_EQ(perStep, 4u) << rows.size() << " blocks: 2 a step would make more steps than the limit";
  EXPECT_NE(html.find("Each step here covers " + std::to_string(perStep) + " blocks"), std::string::npos);
  const Json& steps = data["steps"];
  EXPECT_LE(steps.size(), app::StepRecording::kMaxSteps);
  EXPECT_EQ(steps.size(), (rows.size() + perStep - 1) / perStep);
  double removed = 0, rowsRemoved = 0;
  std::size_t row = 0;
  for (std::size_t s = 0; s < steps.size(); ++s) {
    const Json& step = steps[s];
    const std::size_t blocks = step[12];
    EXPECT_EQ(blocks, s + 1 < steps.size() ? perStep : rows.size() - perStep * (steps.size() - 1)) << "step " << s;
    ASSERT_LE(row + blocks, rows.size()) << "step " << s;
    EXPECT_EQ(step[0], rows[row]["line"]) << "step " << s << ": its first line";
    EXPECT_EQ(step[11], rows[row + blocks - 1]["line"]) << "step " << s << ": its last line";
    if (s > 0) {
      EXPECT_EQ(step[0].get<int>(), steps[s - 1][11].get<int>() + 1) << "step " << s << ": the lines run on";
    }
    double ownRemoved = 0, ownTime = 0;
    for (std::size_t b = row; b < row + blocks; ++b)
      ownRemoved += rows[b]["removed_volume_mm3"].get<double>(), ownTime += rows[b]["time_s"].get<double>();
    EXPECT_NEAR(step[3].get<double>(), ownRemoved, 1e-6) << "step " << s;
    EXPECT_NEAR(step[4].get<double>(), ownTime, 0.006) << "step " << s;
    removed += step[3].get<double>(), rowsRemoved += ownRemoved;
    row += blocks;
  }
  EXPECT_EQ(row, rows.size()) << "every block in some step";
  const double total = report["removed_volume_mm3"];
  EXPECT_NEAR(removed, total, 1e-6 * total);
  EXPECT_FALSE(data["path_left_out"].get<bool>()) << "12,000 moves are within StepRecording::kMaxMoves";
  std::cout << steps.size() << " steps of " << perStep << " blocks, " << html.size() << " bytes\n";
  // The page says which blocks and lines the step holds; the listing marks all its lines.
  const bool networkOff = std::system("unshare --net true 2>/dev/null") == 0;  // root only
  const std::string page = "file://" + (dir.path() / "out" / "report.html").string();
  const BrowserRun second = openInChromium(dir, page + "#step=2", {"--dump-dom"}, networkOff);
  const int line = steps[1][0], lastLine = steps[1][11];
  EXPECT_NE(second.outcome.out.find("step 2 of " + std::to_string(steps.size()) + ": blocks 5–8, lines " +
                                    std::to_string(line) + "–" + std::to_string(lastLine) + " (4 blocks a step)"),
            std::string::npos);
  for (int l = line; l <= lastLine; ++l)
    EXPECT_TRUE(std::regex_search(second.outcome.out, std::regex("<tr id=\"L" + std::to_string(l) + "\"[^>]*class=\"current\"")))
        << "line " << l;
  for (const std::string& console : second.consoleLines) EXPECT_EQ(console.find("Uncaught"), std::string::npos) << console;
}

TEST(StepReport, ThePageStepsToTheBlockInItsAddressAndStartsAtTheEnd) {
  ScratchDir dir("steps-page");
  const auto run = runProcess(LATHESIM_BINARY,
                              {"run", (kShaft / "program.nc").string(), "--setup", (kShaft / "setup.toml").string(), "--out",
                               (dir.path() / "out").string(), "--outputs", "report,html"},
                              dir.path());
  ASSERT_EQ(run.status, 0) << run.err;
  const std::size_t blocks = stepData(readFile(dir.path() / "out" / "report.html"))["steps"].size();
  const std::string page = "file://" + (dir.path() / "out" / "report.html").string();
  // With the network off, as report.html's own 3D test opens it (pictures_cli_test.cpp): the
  // stepping works from the one file.
  const bool networkOff = std::system("unshare --net true 2>/dev/null") == 0;  // root only
  EXPECT_TRUE(networkOff || std::getenv("CI") == nullptr) << "CI runs as root: the page must be opened offline";
  const BrowserRun second = openInChromium(dir, page + "#step=2", {"--dump-dom"}, networkOff);
  EXPECT_NE(second.outcome.out.find("block 2 of " + std::to_string(blocks) + ", line 6:  G71 P10 Q80 U0.5 W0.1 F0.25"),
            std::string::npos);
  EXPECT_TRUE(std::regex_search(second.outcome.out, std::regex(R"(<tr id="L6"[^>]*class="current")")))
      << "the listing's line";
  const BrowserRun last = openInChromium(dir, page, {"--dump-dom"}, networkOff);
  EXPECT_NE(last.outcome.out.find("block " + std::to_string(blocks) + " of " + std::to_string(blocks)), std::string::npos);
  for (const std::string& line : last.consoleLines) EXPECT_EQ(line.find("Uncaught"), std::string::npos) << line;
  const BrowserRun measured = openInChromium(dir, page + "#measure", {"--dump-dom"}, networkOff);
  std::smatch redraw;
  ASSERT_TRUE(std::regex_search(measured.outcome.out, redraw, std::regex(R"re(data-redraw-ms="([0-9.]+)")re")));
  std::cout << "report.html: a step redraws in " << redraw[1] << " ms (median of 100)\n";
}

}  // namespace
}  // namespace lathesim::test
