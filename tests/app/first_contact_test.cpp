// Programs as written, first time: short programs written for this test from the published
// formats of each family (tests/app/first_contact/), run with no --dialect, --control or
// setup. A program of a family lathesim reads runs, naming the machine it was read for, with
// the moves it makes with that machine given by hand; a program of a family it does not read
// is refused at the first line that shows the family, naming it. Every expected outcome below
// is worked out from the program's text and the family's manual, not recorded from a run.

#include <gtest/gtest.h>

#include <optional>
#include <string>
#include <vector>

#include "tests/support/lathesim_process.hpp"

namespace lathesim::test {
namespace {

const fs::path kCorpus = fs::path(LATHESIM_SOURCE_DIR) / "tests/app/first_contact";

struct Reads {
  std::string_view dialect;
  std::string_view control;
};
struct Refused {
  int line;
  std::string_view family;
};
struct Expected {
  std::string_view file;
  std::optional<Reads> reads;
  std::optional<Refused> refused;
  std::string_view because = "";   // a mark the machine is said to be read from
  std::string_view warning = "";   // a warning the run must give
};

// Why each outcome: the marks of lathe-gcode.md's table in the program, by line.
const Expected kCorpusOutcomes[] = {
    // Fanuc 0i-TD / Romi, system B: G95 feeds, G92 S clamps, G77/G78/G79 cycles, G90/G91 modes.
    {"b01_romi_g95_g92s.nc", Reads{"fanuc-b", "gsk980tdi"}, {}, "G92 S3000 at line 5"},
    {"b02_romi_g77_cycle.nc", Reads{"fanuc-b", "gsk980tdi"}, {}, "G92 S2500 at line 5"},
    {"b03_romi_g78_thread.nc", Reads{"fanuc-b", "gsk980tdi"}, {}, "G78 at line 8"},
    {"b04_romi_g71_g70.nc", Reads{"fanuc-b", "gsk980tdi"}, {}, "G95 at line 4"},
    {"b05_fanuc_g91_moves.nc", Reads{"fanuc-b", "gsk980tdi"}, {}, "G91 at line 8"},
    {"b06_g94_per_minute.nc", Reads{"fanuc-b", "gsk980tdi"}, {}, "G94 F150. at line 4"},
    // ,C / ,R corners: a control that reads them, Fanuc's.
    {"b07_fanuc_b_corners.nc", Reads{"fanuc-b", "fanuc-0i-t"}, {}, ",C1. at line 10 (Fanuc's corner word)"},
    {"b08_g79_face.nc", Reads{"fanuc-b", "gsk980tdi"}, {}, "G92 S2800 at line 6"},
    {"b09_g33_thread.nc", Reads{"fanuc-b", "gsk980tdi"}, {}, "G33 at line 7"},
    {"b10_german_cam_g95.nc", Reads{"fanuc-b", "gsk980tdi"}, {}, "G92 S2000 at line 6"},
    {"b11_romi_g71_ccsp.nc", Reads{"fanuc-b", "gsk980tdi"}, {}, "G92 S2200 at line 5"},
    // Fanuc / GSK system A: G98/G99, G50, G32, U/W beside moves.
    {"a01_gsk980tdi_g71.nc", Reads{"fanuc-a", "gsk980tdi"}, {}, "G99 at line 4"},
    {"a02_gsk_g90_uw.nc", Reads{"fanuc-a", "gsk980tdi"}, {}, "U20. beside a move at line 9"},
    {"a03_fanuc_a_g92_thread.nc", Reads{"fanuc-a", "gsk980tdi"}, {}, "G99 at line 3"},
    {"a04_g32_thread.nc", Reads{"fanuc-a", "gsk980tdi"}, {}, "G32 at line 7"},
    {"a05_fanuc_a_no_points.nc", Reads{"fanuc-a", "gsk980tdi"}, {}, "G50 at line 5"},
    {"a06_fanuc_a_points.nc", Reads{"fanuc-a", "gsk980tdi"}, {}, "G50 at line 5"},
    // Nothing only one system reads: the default, said so.
    {"a07_thin_evidence.nc", Reads{"fanuc-a", "gsk980tdi"}, {}, "no code only one G-code system reads"},
    {"a08_fanuc_a_corners.nc", Reads{"fanuc-a", "fanuc-0i-t"}, {}, ",C1. at line 9 (Fanuc's corner word)"},
    {"a09_gsk_g76.nc", Reads{"fanuc-a", "gsk980tdi"}, {}, "G99 at line 3"},
    {"a10_gsk_school.nc", Reads{"fanuc-a", "gsk980tdi"}, {}, "G98 at line 3"},
    {"a11_fanuc_a_g72.nc", Reads{"fanuc-a", "gsk980tdi"}, {}, "G50 at line 6"},
    // HNC: G80/G81/G82 with X and Z, and system B's G90/G95.
    {"h01_hnc_g80.nc", Reads{"hnc", "gsk980tdi"}, {}, "G80 with X and Z at line 8"},
    {"h02_hnc_g82_thread.nc", Reads{"hnc", "gsk980tdi"}, {}, "G82 with X and Z at line 8"},
    {"h03_hnc_g81_face.nc", Reads{"hnc", "gsk980tdi"}, {}, "G81 with X and Z at line 8"},
    // Haas: one-block G71 with D, M97; Haas's dialect brings Haas's control (M31, M33).
    {"s01_haas_one_block_g71.nc", Reads{"haas", "haas"}, {}, "one-block G71 with D0.06 at line 9"},
    {"s02_haas_m97.nc", Reads{"haas", "haas"}, {}, "M97 at line 8"},
    {"s03_haas_m31_conveyor.nc", Reads{"haas", "haas"}, {}, "one-block G71 with D1.5 at line 9"},
    // School trainers (Denford, Boxford, Emco): a [BILLET stock line or M06 beside its T word
    // brings the trainers' control, which reads bare numbers as mm and Fanuc's ,C corners.
    {"d01_denford_billet.nc", Reads{"fanuc-a", "denford"}, {}, "[BILLET at line 1 (a school trainer's)"},
    {"d02_trainer_m06_after_t.nc", Reads{"fanuc-a", "denford"}, {}, "M06 beside T01 at line 4 (a school trainer's)"},
    {"d03_denford_fanuc_corners.nc", Reads{"fanuc-a", "denford"}, {}, "[BILLET at line 1 (a school trainer's)"},
    // Inch: under a millimetre everywhere on a Φ25 bar with no G20 is warned of; with G20 not.
    {"i01_inch_without_g20.nc", Reads{"fanuc-a", "gsk980tdi"}, {}, "G99 at line 4", "inch program without its G20"},
    {"i02_inch_with_g20.nc", Reads{"fanuc-a", "gsk980tdi"}, {}, "G99 at line 3"},
    // Families lathesim does not read, at the first line that shows them.
    {"f01_fagor_header.nc", {}, Refused{1, "Fagor 8055/8070"}},
    {"f02_fagor_t_d.nc", {}, Refused{4, "Fagor 8055/8070"}},
    {"f03_okuma.nc", {}, Refused{1, "Okuma OSP"}},
    {"f04_siemens_cycle95.nc", {}, Refused{3, "Siemens Sinumerik"}},
    {"f05_siemens_diamon.nc", {}, Refused{2, "Siemens Sinumerik"}},
    {"f06_siemens_lims.nc", {}, Refused{1, "Siemens Sinumerik"}},
    {"f07_heidenhain.nc", {}, Refused{1, "Heidenhain"}},
    {"f08_linuxcnc_osub.nc", {}, Refused{2, "LinuxCNC (O-word subroutines)"}},
    {"f09_linuxcnc_named.nc", {}, Refused{2, "LinuxCNC (named parameters)"}},
    {"f10_linuxcnc_g7.nc", {}, Refused{2, "LinuxCNC (G7/G8"}},
    {"f11_linuxcnc_g64p.nc", {}, Refused{2, "LinuxCNC (G64"}},
    {"f13_philips.nc", {}, Refused{1, "Philips 432/532"}},
    // Mazak EIA/ISO: named at its own codes (G109 L1 at line 4, G53.5 at line 5); written as
    // Fanuc (G99 and G50 S of system A), it runs as Fanuc does.
    {"m01_mazak_eia_g109.nc", {}, Refused{4, "Mazak EIA/ISO"}},
    {"m02_mazak_eia_mazatrol_coordinates.nc", {}, Refused{5, "Mazak EIA/ISO"}},
    {"m03_mazak_eia_fanuc_compatible.nc", Reads{"fanuc-a", "gsk980tdi"}, {}, "G99 at line 4"},
};

ProcessOutcome expand(const fs::path& program, std::vector<std::string> flags, const fs::path& scratch) {
  std::vector<std::string> args{"expand", program.string()};
  args.insert(args.end(), flags.begin(), flags.end());
  return runProcess(LATHESIM_BINARY, args, scratch);
}

TEST(FirstContact, TheCorpusHasEveryProgramAndEveryProgramAnOutcome) {
  std::size_t files = 0;
  for (const auto& entry : fs::directory_iterator(kCorpus)) {
    ++files;
    const std::string name = entry.path().filename().string();
    const bool listed = std::any_of(std::begin(kCorpusOutcomes), std::end(kCorpusOutcomes),
                                    [&](const Expected& e) { return e.file == name; });
    EXPECT_TRUE(listed) << name << " has no expected outcome";
  }
  EXPECT_EQ(files, std::size(kCorpusOutcomes));
  EXPECT_GE(files, 40u);
}

TEST(FirstContact, EveryProgramRunsAsWrittenOrIsRefusedNamingItsFamily) {
  ScratchDir scratch("first-contact");
  for (const Expected& e : kCorpusOutcomes) {
    SCOPED_TRACE(std::string(e.file));
    const fs::path program = kCorpus / e.file;
    const ProcessOutcome plain = expand(program, {}, scratch.path());
    if (e.refused) {
      EXPECT_NE(plain.status, 0);
      const std::string at = program.string() + ":" + std::to_string(e.refused->line) + ":";
      EXPECT_NE(plain.err.find(at), std::string::npos) << plain.err;
      EXPECT_NE(plain.err.find(std::string(e.refused->family)), std::string::npos) << plain.err;
      EXPECT_TRUE(plain.out.empty());
      continue;
    }
    ASSERT_EQ(plain.status, 0) << plain.err;
    const std::string machine =
        "dialect " + std::string(e.reads->dialect) + ", control " + std::string(e.reads->control) + ", read from the program";
    EXPECT_NE(plain.err.find(machine), std::string::npos) << plain.err;
    EXPECT_NE(plain.err.find(std::string(e.because)), std::string::npos) << plain.err;
    if (!e.warning.empty()) {
      EXPECT_NE(plain.err.find(std::string(e.warning)), std::string::npos) << plain.err;
    }
    // The same moves as with the machine given by hand.
    const ProcessOutcome byHand = expand(
        program, {"--dialect", std::string(e.reads->dialect), "--control", std::string(e.reads->control)}, scratch.path());
    ASSERT_EQ(byHand.status, 0) << byHand.err;
    EXPECT_GT(std::count(plain.out.begin(), plain.out.end(), '\n'), 2);
    EXPECT_EQ(plain.out, byHand.out);
  }
}

// A stated dialect the program contradicts wins, is warned of at the line, and the refusal it
// leads to names the dialect that reads the code and the marks seen.
TEST(FirstContact, ARefusedSystemBCodeNamesItsDialectAndTheMarksSeen) {
  ScratchDir scratch("first-contact-cure");
  const fs::path program = kCorpus / "b01_romi_g95_g92s.nc";
  const ProcessOutcome outcome = expand(program, {"--dialect", "fanuc-a"}, scratch.path());
  EXPECT_NE(outcome.status, 0);
  EXPECT_NE(outcome.err.find(program.string() + ":4:"), std::string::npos) << outcome.err;
  EXPECT_NE(outcome.err.find("G95 is system B's (fanuc-b or hnc), but --dialect says fanuc-a"), std::string::npos)
      << outcome.err;
  EXPECT_NE(outcome.err.find("unknown G code G95"), std::string::npos) << outcome.err;
  EXPECT_NE(outcome.err.find("run with --dialect fanuc-b (seen: G95 at line 4, G90 at line 4, G92 S3000 at line 5)"),
            std::string::npos)
      << outcome.err;
}

// Under a least-increment control, Z-5 is 0.005 mm: the contour it breaks says so, and names
// both cures; the one it names runs.
TEST(FirstContact, ALengthReadInIncrementsThatBreaksACycleIsShownAsRead) {
  ScratchDir scratch("first-contact-increments");
  const fs::path program = scratch.path() / "g71.nc";
  writeFile(program,
            "G21 G99\nT0101\nG00 X42. Z2.\nG71 U1.5 R0.5\nG71 P10 Q20 U0.4 W0.1 F0.25\nN10 G00 X20.\n"
            "G01 Z-2. F0.15\nX24. Z-5\nZ-20.\nN20 X42.\nG70 P10 Q20\nM30\n");
  const ProcessOutcome outcome = expand(program, {"--control", "fanuc-0i-t"}, scratch.path());
  EXPECT_NE(outcome.status, 0);
  EXPECT_NE(outcome.err.find(program.string() + ":8:"), std::string::npos) << outcome.err;
  EXPECT_NE(outcome.err.find("must be monotonic in Z"), std::string::npos) << outcome.err;
  EXPECT_NE(outcome.err.find("Z-5 at line 8 is -0.005 mm under fanuc-0i-t: no decimal point; write Z-5. or use "
                             "--control gsk980tdi"),
            std::string::npos)
      << outcome.err;
  EXPECT_EQ(expand(program, {"--control", "gsk980tdi"}, scratch.path()).status, 0);
}

// Dialect and control are one choice: --dialect haas brings Haas's M codes (M31, M33), and
// --control haas Haas's dialect (the one-block G71).
TEST(FirstContact, HaasDialectAndControlComeTogether) {
  ScratchDir scratch("first-contact-haas");
  const fs::path program = kCorpus / "s03_haas_m31_conveyor.nc";
  for (const std::vector<std::string>& flags :
       {std::vector<std::string>{"--dialect", "haas"}, std::vector<std::string>{"--control", "haas"}}) {
    SCOPED_TRACE(flags[0]);
    const ProcessOutcome outcome = expand(program, flags, scratch.path());
    ASSERT_EQ(outcome.status, 0) << outcome.err;
    EXPECT_NE(outcome.err.find("dialect haas, control haas, as stated"), std::string::npos) << outcome.err;
  }
  // Under GSK's list, M31 names the control whose list has it.
  const ProcessOutcome gsk = expand(program, {"--dialect", "haas", "--control", "gsk980tdi"}, scratch.path());
  EXPECT_NE(gsk.status, 0);
  EXPECT_NE(gsk.err.find("run with --control haas"), std::string::npos) << gsk.err;
}

}  // namespace
}  // namespace lathesim::test
