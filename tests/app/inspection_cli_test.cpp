// `lathesim check` as an inspection report: a diameter measured as a diameter against the
// drawing's own tolerance, and the line to blame for each size that is wrong — swept over
// which block of a plain contour, a G90 and a G70 is wrong. Every figure is worked by hand.

#include <gtest/gtest.h>

#include <cmath>
#include <nlohmann/json.hpp>
#include <string>

#include "tests/support/lathesim_process.hpp"

namespace lathesim::app {
namespace {

namespace fs = std::filesystem;
using test::ScratchDir;

using test::kBinary;

struct Checked {
  test::ProcessOutcome outcome;
  nlohmann::json check;
};

/// Checks `program` on a Φ40 × 50 bar (face Z0, the default tool: its tip on the path, its
/// body above and right of it) against `drawing`.
Checked checkProgram(const ScratchDir& dir, const std::string& program, const std::string& drawing, double voxelMm,
                     const std::vector<std::string>& extra = {}) {
  test::writeFile(dir.path() / "p.nc", program);
  test::writeFile(dir.path() / "setup.toml", "[stock]\ndiameter = 40\nlength = 50\nface_z = 0\n");
  test::writeFile(dir.path() / "drawing.toml", drawing);
  std::vector<std::string> args{"check", (dir.path() / "p.nc").string(), "--setup", (dir.path() / "setup.toml").string(),
                                "--target", (dir.path() / "drawing.toml").string(), "--voxel", std::to_string(voxelMm),
                                "--out", (dir.path() / "out").string(), "--outputs", "report"};
  args.insert(args.end(), extra.begin(), extra.end());
  Checked run{test::runProcess(kBinary, args, dir.path()), {}};
  const fs::path report = dir.path() / "out" / "report.json";
  if (fs::exists(report)) run.check = nlohmann::json::parse(test::readFile(report)).at("check");
  return run;
}

/// The stepped shaft drawn: Φ20 Z0..-10, Φ28 to Z-20, Φ36 to Z-30, then the bar's Φ40.
/// `tolerance` on each of the three diameters.
std::string steppedDrawing(const std::string& tolerance) {
  return "profile = [{x = 20, z = 0}, {x = 20, z = -10, tolerance = " + tolerance +
         "},\n  {x = 28, z = -10}, {x = 28, z = -20, tolerance = " + tolerance +
         "},\n  {x = 36, z = -20}, {x = 36, z = -30, tolerance = " + tolerance + "},\n  {x = 40, z = -30}, {x = 40, z = -50}]\n";
}

const nlohmann::json* sizeAt(const nlohmann::json& check, const std::string& kind, double nominal) {
  for (const auto& s : check.at("sizes"))
    if (s.at("kind") == kind && std::abs(s.at("nominal_mm").get<double>() - nominal) < 1e-9) return &s;
  return nullptr;
}

// The case: Φ20 programmed Φ19.5. Against ±0.1 (on the diameter) it is 0.5 under,
// 0.4 beyond its limit, out by far more than a diameter's ±0.0125 at voxel 0.1: exit 3, the
// report says so as a diameter, and names line 3 (the cut) with its X from line 2.
TEST(InspectionReport, UndersizeJournalFailsAsADiameter) {
  ScratchDir dir("inspect-journal");
  const std::string program = "G99 G00 X100 Z5 M03 S1000\nG00 X19.5 Z2\nG01 Z-10 F0.1\nX28\nZ-20\nX36\nZ-30\nX42\nG00 X100 Z5\nM30\n";
  const Checked run = checkProgram(dir, program, steppedDrawing("0.1"), 0.1);
  ASSERT_EQ(run.outcome.status, 3) << run.outcome.out << run.outcome.err;
  EXPECT_EQ(run.check.at("verdict"), "out");
  const nlohmann::json* d20 = sizeAt(run.check, "diameter", 20);
  ASSERT_NE(d20, nullptr) << run.check.dump(1);
  EXPECT_NEAR(d20->at("worst_mm").get<double>(), 19.5, 0.02);
  EXPECT_NEAR(d20->at("beyond_mm").get<double>(), 0.4, 0.02);
  EXPECT_EQ(d20->at("verdict"), "out");
  EXPECT_EQ(d20->at("lines"), nlohmann::json::array({3}));
  EXPECT_EQ(d20->at("value_line"), 2);
  EXPECT_NE(run.outcome.out.find("Ø19.500 ±0.013 measured at Z"), std::string::npos) << run.outcome.out;
  EXPECT_NE(run.outcome.out.find("(drawn Ø20.000 ±0.1, drawing line 1): 0.500 undersize, 0.400 beyond its limit: OUT; "
                                 "made by line 3 `G01 Z-10 F0.1` (its X from line 2 `G00 X19.5 Z2`)"),
            std::string::npos)
      << run.outcome.out;
  // The others are as drawn: within.
  EXPECT_EQ(sizeAt(run.check, "diameter", 28)->at("verdict"), "within");
  EXPECT_EQ(sizeAt(run.check, "diameter", 36)->at("verdict"), "within");
}

// Without a tolerance on the row the general one holds: ISO 2768-m on Φ20 is ±0.2 (over 6 up
// to 30 mm), so 0.05 under passes at voxel 0.1 (0.15 inside, far more than ±0.0125); h7
// (0/−0.021) fails it, 0.029 beyond.
TEST(InspectionReport, GeneralToleranceFromTheDrawingOrTheCommandLine) {
  ScratchDir dir("inspect-general");
  const std::string program = "G99 G00 X100 Z5 M03 S1000\nG00 X19.95 Z2\nG01 Z-10 F0.1\nX28\nZ-20\nX36\nZ-30\nX42\nG00 X100 Z5\nM30\n";
  const std::string plain = "profile = [{x = 20, z = 0}, {x = 20, z = -10}, {x = 28, z = -10}, {x = 28, z = -20},\n"
                            "  {x = 36, z = -20}, {x = 36, z = -30}, {x = 40, z = -30}, {x = 40, z = -50}]\n";
  const Checked m = checkProgram(dir, program, plain, 0.1);
  EXPECT_EQ(m.outcome.status, 0) << m.outcome.out;
  EXPECT_EQ(sizeAt(m.check, "diameter", 20)->at("verdict"), "within") << m.outcome.out;
  EXPECT_EQ(sizeAt(m.check, "diameter", 20)->at("tolerance_source"), "ISO 2768-m for Ø20 (±0.2)");
  EXPECT_NE(m.outcome.out.find("else ISO 2768-m (the default)"), std::string::npos) << m.outcome.out;
  const Checked h7 = checkProgram(dir, program, steppedDrawing("\"h7\""), 0.1);
  EXPECT_EQ(h7.outcome.status, 3) << h7.outcome.out;
  EXPECT_EQ(sizeAt(h7.check, "diameter", 20)->at("verdict"), "out") << h7.outcome.out;
  // The drawing's general_tolerance = "f" is ±0.1 on Φ20, --general-tolerance c ±0.5 over it.
  const Checked f = checkProgram(dir, program, "general_tolerance = \"f\"\n" + plain, 0.1);
  EXPECT_EQ(sizeAt(f.check, "diameter", 20)->at("tolerance_source"), "ISO 2768-f for Ø20 (±0.1)");
  const Checked c = checkProgram(dir, program, "general_tolerance = \"f\"\n" + plain, 0.1, {"--general-tolerance", "c"});
  EXPECT_EQ(sizeAt(c.check, "diameter", 20)->at("tolerance_source"), "ISO 2768-c for Ø20 (±0.5)");
}

// 0.01 under h7 lies 0.01 inside its upper limit (Φ20): at voxel 0.2 a diameter is known to
// ±0.025, so the check cannot tell. It must not pass: exit 3, "undecided", and the voxel that
// decides: 0.9·0.2·0.01/0.025 = 0.072. At 0.05 (±0.00625) it passes.
TEST(InspectionReport, UndecidedIsNoPass) {
  ScratchDir dir("inspect-undecided");
  const std::string program = "G99 G00 X100 Z5 M03 S1000\nG00 X19.99 Z2\nG01 Z-10 F0.1\nX28\nZ-20\nX36\nZ-30\nX42\nG00 X100 Z5\nM30\n";
  const Checked coarse = checkProgram(dir, program, steppedDrawing("\"h7\""), 0.2);
  EXPECT_EQ(coarse.outcome.status, 3) << coarse.outcome.out;
  EXPECT_EQ(coarse.check.at("verdict"), "undecided");
  EXPECT_FALSE(coarse.check.at("within_tolerance").get<bool>());
  EXPECT_EQ(sizeAt(coarse.check, "diameter", 20)->at("verdict"), "undecided") << coarse.outcome.out;
  EXPECT_NE(coarse.outcome.out.find("undecided at this voxel; rerun with --voxel 0.072"), std::string::npos) << coarse.outcome.out;
  const Checked fine = checkProgram(dir, program, steppedDrawing("\"h7\""), 0.05);
  EXPECT_EQ(sizeAt(fine.check, "diameter", 20)->at("verdict"), "within") << fine.outcome.out;
}

// What the uncertainty claims, measured: diameters and faces cut at sub-voxel offsets read
// within a sixteenth of a voxel of where they were programmed (in fact to 1e-4 voxel), at
// three voxels.
TEST(InspectionReport, SurfacesWithinTheirUncertainty) {
  for (const double h : {0.2, 0.1, 0.05}) {
    for (const double off : {0.013, 0.041, 0.077, 0.111}) {
      ScratchDir dir("inspect-uncertainty");
      const double x = 20 - off, z = -10 - 0.3 * off;
      char program[256];
      std::snprintf(program, sizeof program, "G99 G00 X100 Z5 M03 S1000\nG00 X%.4f Z2\nG01 Z%.4f F0.1\nX28\nZ-20\nX36\nZ-30\nX42\nG00 X100 Z5\nM30\n",
                    x, z);
      const Checked run = checkProgram(dir, program, steppedDrawing("1"), h);
      const nlohmann::json* d20 = sizeAt(run.check, "diameter", 20);
      ASSERT_NE(d20, nullptr) << run.outcome.out << run.outcome.err;
      EXPECT_NEAR(d20->at("least_mm").get<double>(), x, d20->at("uncertainty_mm").get<double>()) << h << " " << off;
      EXPECT_NEAR(d20->at("greatest_mm").get<double>(), x, d20->at("uncertainty_mm").get<double>()) << h << " " << off;
      const nlohmann::json* face = sizeAt(run.check, "face", -10);
      ASSERT_NE(face, nullptr);
      EXPECT_NEAR(face->at("worst_mm").get<double>(), z, face->at("uncertainty_mm").get<double>()) << h << " " << off;
    }
  }
}

// The line to blame, swept over which block is wrong. The stepped shaft as a plain contour,
//   1 G99 G00 X100 Z5 M03 S1000 / 2 G00 X20 Z2 / 3 G01 Z-10 F0.1 / 4 X28 / 5 Z-20 / 6 X36 / 7 Z-30 / 8 X42 / 9 G00 X100 Z5
// with one X made 0.5 smaller (a gouge, undersize) or larger (excess, oversize): the diameter
// it turns is out, made by the next line's cut, its X from the changed line.
TEST(InspectionReport, BlamesTheChangedBlockOfAPlainContour) {
  struct Case {
    int changedLine;
    double nominal, delta;
    int cutLine;
  };
  for (const Case& c : {Case{2, 20, -0.5, 3}, Case{4, 28, -0.5, 5}, Case{6, 36, -0.5, 7}, Case{4, 28, +0.5, 5},
                        Case{6, 36, +0.5, 7}}) {
    ScratchDir dir("inspect-contour");
    double x[3] = {20, 28, 36};
    x[c.changedLine / 2 - 1] += c.delta;
    char program[256];
    std::snprintf(program, sizeof program,
                  "G99 G00 X100 Z5 M03 S1000\nG00 X%g Z2\nG01 Z-10 F0.1\nX%g\nZ-20\nX%g\nZ-30\nX42\nG00 X100 Z5\nM30\n", x[0], x[1], x[2]);
    const Checked run = checkProgram(dir, program, steppedDrawing("0.1"), 0.1);
    EXPECT_EQ(run.outcome.status, 3) << run.outcome.out;
    for (double nominal : {20.0, 28.0, 36.0}) {
      const nlohmann::json* d = sizeAt(run.check, "diameter", nominal);
      ASSERT_NE(d, nullptr);
      if (nominal != c.nominal) {
        EXPECT_EQ(d->at("verdict"), "within") << "Ø" << nominal << " with line " << c.changedLine << " changed";
        continue;
      }
      EXPECT_EQ(d->at("verdict"), "out") << run.outcome.out;
      EXPECT_NEAR(d->at("worst_mm").get<double>(), nominal + c.delta, 0.02);
      EXPECT_EQ(d->at("lines"), nlohmann::json::array({c.cutLine})) << "line " << c.changedLine << " changed";
      EXPECT_EQ(d->at("value_line"), c.changedLine);
    }
  }
}

// The same shaft in G90 passes, one block a pass: 2 G00 X42 Z2 / 3 G90 X36 Z-30 F0.1 /
// 4 X28 Z-20 / 5 X20 Z-10. A pass's X wrong: the diameter it finishes names its block.
TEST(InspectionReport, BlamesTheChangedPassOfAG90) {
  for (const int changed : {3, 4, 5}) {
    ScratchDir dir("inspect-g90");
    double x[3] = {36, 28, 20};
    x[changed - 3] -= 0.5;
    char program[256];
    std::snprintf(program, sizeof program, "G99 G00 X100 Z5 M03 S1000\nG00 X42 Z2\nG90 X%g Z-30 F0.1\nX%g Z-20\nX%g Z-10\nG00 X100 Z5\nM30\n",
                  x[0], x[1], x[2]);
    const Checked run = checkProgram(dir, program, steppedDrawing("0.1"), 0.1);
    EXPECT_EQ(run.outcome.status, 3) << run.outcome.out;
    const double nominal = 36 - 8 * (changed - 3);
    const nlohmann::json* d = sizeAt(run.check, "diameter", nominal);
    ASSERT_NE(d, nullptr);
    EXPECT_EQ(d->at("verdict"), "out") << run.outcome.out;
    EXPECT_EQ(d->at("lines"), nlohmann::json::array({changed})) << run.outcome.out;
    EXPECT_EQ(d->at("value_line"), changed);
  }
}

// A G70 finishing the shaft roughed by G71: the contour blocks N10–N20
//   3 G71 U1 R0.5 / 4 G71 P10 Q20 U0.4 W0.1 F0.2 / 5 N10 G00 X20 / 6 G01 Z-10 F0.1 / 7 X28 /
//   8 Z-20 / 9 X36 / 10 Z-30 / 11 N20 X42 / 12 G70 P10 Q20
// with one contour block's X made 0.5 small: the G70's cut along it is made on the contour
// block after it, its X from the changed block.
TEST(InspectionReport, BlamesTheChangedContourBlockOfAG70) {
  for (const int changed : {5, 7, 9}) {
    ScratchDir dir("inspect-g70");
    double x[3] = {20, 28, 36};
    x[(changed - 5) / 2] -= 0.5;
    char program[512];
    std::snprintf(program, sizeof program,
                  "G99 G00 X100 Z5 M03 S1000\nG00 X42 Z2\nG71 U1 R0.5\nG71 P10 Q20 U0.4 W0.1 F0.2\nN10 G00 X%g\nG01 Z-10 F0.1\nX%g\n"
                  "Z-20\nX%g\nZ-30\nN20 X42\nG70 P10 Q20\nG00 X100 Z5\nM30\n",
                  x[0], x[1], x[2]);
    const Checked run = checkProgram(dir, program, steppedDrawing("0.1"), 0.1);
    EXPECT_EQ(run.outcome.status, 3) << run.outcome.out;
    const double nominal = 20 + 8 * (changed - 5) / 2;
    const nlohmann::json* d = sizeAt(run.check, "diameter", nominal);
    ASSERT_NE(d, nullptr);
    EXPECT_EQ(d->at("verdict"), "out") << run.outcome.out;
    EXPECT_EQ(d->at("lines"), nlohmann::json::array({changed + 1})) << run.outcome.out;
    EXPECT_EQ(d->at("value_line"), changed) << run.outcome.out;
  }
}

// The line to blame for undersize and for excess alike, with its block's text, swept over
// which block is wrong in four ways of turning the stepped shaft: a plain contour, G90 passes,
// a G71 with no G70 (U0 W0: its last pass along the contour makes the surface) and a G71 with
// its G70. The diameter a wrong X turns is made by the cut along it: the contour block after
// the changed one (its X from the changed one), or the G90 block itself. A G71's last pass is
// blamed on its P–Q block, as G70's cut is, not on the G71 line.
TEST(InspectionReport, BlamesTheChangedBlockWithItsTextForUndersizeAndExcess) {
  // A block's text with its one number in place of %g.
  const auto block = [](const char* format, double v) {
    char text[64];
    std::snprintf(text, sizeof text, format, v);
    return std::string(text);
  };
  for (const std::string form : {"plain", "g90", "g71", "g71+g70"})
    for (const double delta : {-0.5, +0.5})
      for (int which = 0; which < 3; ++which) {
        double x[3] = {20, 28, 36};
        x[which] += delta;
        std::vector<std::string> lines{"G99 G00 X100 Z5 M03 S1000"};
        int changed = 0, cut = 0;
        if (form == "plain") {
          for (const std::string& l : {block("G00 X%g Z2", x[0]), std::string("G01 Z-10 F0.1"), block("X%g", x[1]),
                                       std::string("Z-20"), block("X%g", x[2]), std::string("Z-30"), std::string("X42")})
            lines.push_back(l);
          changed = 2 + 2 * which, cut = changed + 1;
        } else if (form == "g90") {
          for (const std::string& l : {std::string("G00 X42 Z2"), block("G90 X%g Z-30 F0.1", x[2]), block("X%g Z-20", x[1]),
                                       block("X%g Z-10", x[0])})
            lines.push_back(l);
          changed = 5 - which, cut = changed;
        } else {
          const bool finish = form == "g71+g70";
          for (const std::string& l :
               {std::string("G00 X42 Z2"), std::string("G71 U1 R0.5"),
                std::string(finish ? "G71 P10 Q20 U0.4 W0.1 F0.2" : "G71 P10 Q20 U0 W0 F0.1"), block("N10 G00 X%g", x[0]),
                std::string("G01 Z-10 F0.1"), block("X%g", x[1]), std::string("Z-20"), block("X%g", x[2]), std::string("Z-30"),
                std::string("N20 X42")})
            lines.push_back(l);
          if (finish) lines.push_back("G70 P10 Q20");
          changed = 5 + 2 * which, cut = changed + 1;
        }
        lines.push_back("G00 X100 Z5");
        lines.push_back("M30");
        std::string program;
        for (const std::string& l : lines) program += l + "\n";
        const double nominal = 20 + 8 * which;
        SCOPED_TRACE(testing::Message() << form << ", Ø" << nominal << (delta < 0 ? " undersize" : " oversize") << ":\n" << program);
        ScratchDir dir("inspect-blame");
        const Checked run = checkProgram(dir, program, steppedDrawing("0.1"), 0.1);
        EXPECT_EQ(run.outcome.status, 3) << run.outcome.out << run.outcome.err;
        const nlohmann::json* d = sizeAt(run.check, "diameter", nominal);
        ASSERT_NE(d, nullptr) << run.outcome.out;
        EXPECT_EQ(d->at("verdict"), "out") << run.outcome.out;
        EXPECT_NEAR(d->at("worst_mm").get<double>(), nominal + delta, 0.02);
        EXPECT_EQ(d->at("lines"), nlohmann::json::array({cut})) << run.outcome.out;
        EXPECT_EQ(d->at("value_line"), changed) << run.outcome.out;
        std::string said = "made by line ";  // appended piece by piece (GCC 12 warns of "…" + string&&)
        said += std::to_string(cut) + " `" + lines[cut - 1] + "`";
        if (cut != changed) said += " (its X from line " + std::to_string(changed) + " `" + lines[changed - 1] + "`)";
        EXPECT_NE(run.outcome.out.find(said), std::string::npos) << said << "\n" << run.outcome.out;
      }
}

// report.html gives check.sizes as a table, as the text report does: the journal's Φ20 cut
// Φ19.5 is OUT 0.400 beyond ±0.1, made by line 3, its X from line 2; Φ28 and Φ36 within, with
// no line named.
// The face next to an oversize: Φ28 programmed Φ28.5 up to the face at Z-20, cut where
// drawn. The face was probed at Ø28.4, inside the oversize, and read at Z-10 ("9.800 beyond:
// OUT"). It is read past the oversize (radius 14.25 and two voxels: columns from 14.25 + 2h,
// Ø28.9 at voxel 0.1, Ø29.3 at 0.2), at Z-20: within; the diameter alone is out.
TEST(InspectionReport, AFaceBesideAnOversizeDiameterIsReadAtItsOwnZ) {
  for (const double voxel : {0.2, 0.1}) {
    ScratchDir dir("inspect-face-oversize");
    const std::string program = "G99 G00 X100 Z5 M03 S1000\nG00 X20 Z2\nG01 Z-10 F0.1\nX28.5\nZ-20\nX36\nZ-30\nX42\nG00 X100 Z5\nM30\n";
    const Checked run = checkProgram(dir, program, steppedDrawing("0.1"), voxel);
    ASSERT_EQ(run.outcome.status, 3) << run.outcome.out << run.outcome.err;
    const nlohmann::json* face = sizeAt(run.check, "face", -20);
    ASSERT_NE(face, nullptr) << run.check.dump(1);
    EXPECT_NEAR(face->at("worst_mm").get<double>(), -20, 1e-3) << voxel;
    EXPECT_EQ(face->at("verdict"), "within") << voxel;
    EXPECT_GE(face->at("worst_at").at("diameter").get<double>(), 2 * (14.25 + 2 * voxel) - 1e-9) << voxel;
    EXPECT_EQ(sizeAt(run.check, "diameter", 28)->at("verdict"), "out");
    EXPECT_EQ(run.outcome.out.find("beyond its limit: OUT; made by line 4"), std::string::npos) << run.outcome.out;
  }
}

// The same shoulder where the part beside it covers the whole face: Φ28 programmed Φ37, over
// the drawn face Z-20 (Ø28 to Ø36) and past it. No column crosses that face alone: it is
// undecided and not measured (no figure, rather than the face at Z-10 the columns meet).
TEST(InspectionReport, AFaceTheNeighbourCoversIsNotMeasured) {
  ScratchDir dir("inspect-face-covered");
  const std::string program = "G99 G00 X100 Z5 M03 S1000\nG00 X20 Z2\nG01 Z-10 F0.1\nX37\nZ-20\nX36\nZ-30\nX42\nG00 X100 Z5\nM30\n";
  const Checked run = checkProgram(dir, program, steppedDrawing("0.1"), 0.2);
  ASSERT_EQ(run.outcome.status, 3) << run.outcome.out << run.outcome.err;
  const nlohmann::json* face = sizeAt(run.check, "face", -20);
  ASSERT_NE(face, nullptr) << run.check.dump(1);
  EXPECT_EQ(face->at("probed"), false);
  EXPECT_TRUE(face->at("worst_mm").is_null());
  EXPECT_EQ(face->at("verdict"), "undecided");
  EXPECT_NE(run.outcome.out.find("face drawn Z-20.000 (±0.2, ISO 2768-m for the length 20 mm from the front face Z0 (±0.2), "
                                 "drawing line 3): undecided: not measured"),
            std::string::npos)
      << run.outcome.out;
}

TEST(InspectionReport, ReportHtmlTablesTheSizes) {
  ScratchDir dir("inspect-html");
  test::writeFile(dir.path() / "p.nc", "G99 G00 X100 Z5 M03 S1000\nG00 X19.5 Z2\nG01 Z-10 F0.1\nX28\nZ-20\nX36\nZ-30\nX42\nG00 X100 Z5\nM30\n");
  test::writeFile(dir.path() / "setup.toml", "[stock]\ndiameter = 40\nlength = 50\nface_z = 0\n");
  test::writeFile(dir.path() / "drawing.toml", steppedDrawing("0.1"));
  const auto outcome = test::runProcess(kBinary, {"check", (dir.path() / "p.nc").string(), "--setup", (dir.path() / "setup.toml").string(),
                                                  "--target", (dir.path() / "drawing.toml").string(), "--voxel", "0.1", "--out",
                                                  (dir.path() / "out").string(), "--outputs", "report,html"},
                                        dir.path());
  ASSERT_EQ(outcome.status, 3) << outcome.out << outcome.err;
  const std::string html = test::readFile(dir.path() / "out" / "report.html");
  const auto row = [&](double nominal) {
    char drawn[64];
    std::snprintf(drawn, sizeof drawn, "<td class=\"num\">Ø%.3f</td>", nominal);
    const std::size_t at = html.find(drawn);
    if (at == std::string::npos) return std::string();
    return html.substr(html.rfind("<tr", at), html.find("</tr>", at) - html.rfind("<tr", at));
  };
  ASSERT_NE(html.find("<h3>Sizes</h3>"), std::string::npos);
  const std::string out = row(20);
  ASSERT_FALSE(out.empty()) << html;
  EXPECT_NE(out.find("class=\"problem-collision\""), std::string::npos) << out;
  EXPECT_NE(out.find("<td>±0.1</td>"), std::string::npos) << out;  // the drawing's own ±, its source said once
  EXPECT_NE(out.find("<td class=\"num\">Ø19.5"), std::string::npos) << out;
  EXPECT_NE(out.find("<td>OUT, 0.4"), std::string::npos) << out;
  EXPECT_NE(out.find("<td><a href=\"#L3\">3</a></td><td><a href=\"#L2\">2</a></td>"), std::string::npos) << out;
  for (const double nominal : {28.0, 36.0}) {
    const std::string within = row(nominal);
    ASSERT_FALSE(within.empty()) << nominal;
    EXPECT_NE(within.find("<td>within</td><td></td><td></td>"), std::string::npos) << within;
    EXPECT_EQ(within.find("problem-"), std::string::npos) << within;
  }
}

}  // namespace
}  // namespace lathesim::app
