// The machine chosen from the program's evidence and what the user stated: each kind of
// evidence alone, each pair, statements winning (and warned of where the program disagrees),
// dialect and control as one choice.

#include "interp/text/machine_choice.hpp"

#include <gtest/gtest.h>

#include <algorithm>

#include <string>

#include "interp/control/control_preset.hpp"

namespace lathesim::interp {
namespace {

// One line of each kind, so that pairs are two lines.
std::string_view lineOf(EvidenceKind kind) {
  switch (kind) {
    case EvidenceKind::SystemA: return "G99 G01 Z-5. F0.2\n";
    case EvidenceKind::SystemB: return "G95 F0.2\n";
    case EvidenceKind::Hnc: return "G80 X30. Z-20. F0.2\n";
    case EvidenceKind::Haas: return "M97 P100\n";
    case EvidenceKind::FanucCorner: return "G01 X30. Z-10. ,C1.\n";
    case EvidenceKind::Inch: return "G20\n";
    case EvidenceKind::Trainer: return "M06 T0101\n";
  }
  return "";
}

MachineChoice inferred(const std::string& text) { return chooseMachine(readMachineEvidence(text), {}); }

TEST(MachineChoice, EachDialectKindAloneChoosesItsDialect) {
  struct Case {
    EvidenceKind kind;
    Dialect dialect;
    std::string_view control;
  };
  for (const Case& c : {Case{EvidenceKind::SystemA, Dialect::FanucA, "gsk980tdi"},
                        Case{EvidenceKind::SystemB, Dialect::FanucB, "gsk980tdi"},
                        Case{EvidenceKind::Hnc, Dialect::Hnc, "gsk980tdi"},
                        Case{EvidenceKind::Haas, Dialect::Haas, "haas"},
                        Case{EvidenceKind::FanucCorner, Dialect::FanucA, "fanuc-0i-t"},
                        Case{EvidenceKind::Inch, Dialect::FanucA, "gsk980tdi"},
                        Case{EvidenceKind::Trainer, Dialect::FanucA, "denford"}}) {
    SCOPED_TRACE(std::string(lineOf(c.kind)));
    const MachineChoice choice = inferred("G00 X40. Z2.\n" + std::string(lineOf(c.kind)));
    EXPECT_EQ(choice.dialect, c.dialect);
    EXPECT_EQ(choice.control, c.control);
    EXPECT_TRUE(choice.inferred());
    EXPECT_TRUE(choice.conflicts.empty());
    EXPECT_TRUE(choice.warnings.empty());
  }
}

TEST(MachineChoice, TheMarksAreGivenAsTheReason) {
  const MachineChoice choice = inferred("G00 X50.\nG92 S2500\nG95 F0.2\n");
  EXPECT_EQ(choice.dialect, Dialect::FanucB);
  ASSERT_EQ(choice.because.size(), 2u);
  EXPECT_EQ(choice.because[0], "G92 S2500 at line 2");
  EXPECT_EQ(choice.because[1], "G95 at line 3");
}

TEST(MachineChoice, EachPairOfKinds) {
  // Consistent pairs: the dialect both admit; inconsistent ones: the default, the conflict named.
  struct Case {
    EvidenceKind first, second;
    std::optional<Dialect> dialect;  // nullopt: a conflict
  };
  const Case cases[] = {
      {EvidenceKind::SystemA, EvidenceKind::SystemB, std::nullopt},
      {EvidenceKind::SystemA, EvidenceKind::Hnc, std::nullopt},
      {EvidenceKind::SystemA, EvidenceKind::Haas, Dialect::Haas},
      {EvidenceKind::SystemB, EvidenceKind::Hnc, Dialect::Hnc},
      {EvidenceKind::SystemB, EvidenceKind::Haas, std::nullopt},
      {EvidenceKind::Hnc, EvidenceKind::Haas, std::nullopt},
  };
  for (const Case& c : cases) {
    const std::string text = std::string(lineOf(c.first)) + std::string(lineOf(c.second));
    SCOPED_TRACE(text);
    const MachineChoice choice = inferred(text);
    if (c.dialect) {
      EXPECT_EQ(choice.dialect, *c.dialect);
      EXPECT_TRUE(choice.conflicts.empty());
      continue;
    }
    EXPECT_EQ(choice.dialect, Dialect::FanucA);  // the default kept
    ASSERT_EQ(choice.conflicts.size(), 1u);
    // One mark of each kind, each with its line.
    EXPECT_NE(choice.conflicts[0].find("at line 1"), std::string::npos) << choice.conflicts[0];
    EXPECT_NE(choice.conflicts[0].find("at line 2"), std::string::npos) << choice.conflicts[0];
    ASSERT_EQ(choice.warnings.size(), 1u);
    EXPECT_EQ(choice.warnings[0].line, 1);
  }
}

TEST(MachineChoice, ThinEvidenceTakesTheDefaultSayingWhatCouldNotBeToldApart) {
  const MachineChoice choice = inferred("G00 X40. Z2.\nG90 X35. Z-20. F0.2\n");
  EXPECT_EQ(choice.dialect, Dialect::FanucA);
  EXPECT_EQ(choice.control, "gsk980tdi");
  ASSERT_EQ(choice.because.size(), 1u);
  EXPECT_NE(choice.because[0].find("G90 with X/Z"), std::string::npos) << choice.because[0];
  EXPECT_NE(choice.because[0].find("the default, fanuc-a"), std::string::npos) << choice.because[0];
}

TEST(MachineChoice, ThinEvidenceNamesEachUnclearCodeOnce) {
  const MachineChoice choice =
      inferred("G00 X40. Z2.\nG94 X0 Z-1. F0.2\nG94 X0 Z-2.\nG90 X35. Z-20.\nG94 X0 Z-3.\nG90 X30. Z-20.\n");
  ASSERT_EQ(choice.because.size(), 1u);
  EXPECT_NE(choice.because[0].find("(G94 with X/Z, G90 with X/Z: a cycle in system A"), std::string::npos)
      << choice.because[0];
}

TEST(MachineChoice, AStatedDialectWinsAndIsWarnedOfWhereTheProgramDisagrees) {
  const MachineEvidence evidence = readMachineEvidence("G00 X40.\nG95 F0.2\n");
  const MachineChoice choice = chooseMachine(evidence, {Dialect::FanucA, "--dialect", {}, {}});
  EXPECT_EQ(choice.dialect, Dialect::FanucA);
  EXPECT_FALSE(choice.inferred());
  ASSERT_EQ(choice.warnings.size(), 1u);
  EXPECT_EQ(choice.warnings[0].line, 2);
  EXPECT_EQ(choice.warnings[0].column, 1);
  EXPECT_NE(choice.warnings[0].message.find("--dialect says fanuc-a"), std::string::npos) << choice.warnings[0].message;
  // A statement the program agrees with is not warned of.
  EXPECT_TRUE(chooseMachine(evidence, {Dialect::FanucB, "--dialect", {}, {}}).warnings.empty());
  EXPECT_TRUE(chooseMachine(evidence, {Dialect::Hnc, "--dialect", {}, {}}).warnings.empty());
}

TEST(MachineChoice, DialectAndControlAreOneChoice) {
  const MachineEvidence none = readMachineEvidence("G00 X40.\n");
  // --dialect haas: the haas control; --control haas: the haas dialect.
  const MachineChoice byDialect = chooseMachine(none, {Dialect::Haas, "--dialect", {}, {}});
  EXPECT_EQ(byDialect.control, "haas");
  const MachineChoice byControl = chooseMachine(none, {{}, {}, "haas", "--control"});
  EXPECT_EQ(byControl.dialect, Dialect::Haas);
  EXPECT_FALSE(byControl.dialectInferred);
  // A stated control that implies no dialect leaves it to the program.
  const MachineEvidence systemB = readMachineEvidence("G95 F0.2\n");
  const MachineChoice fanuc = chooseMachine(systemB, {{}, {}, "fanuc-0i-t", "--control"});
  EXPECT_EQ(fanuc.dialect, Dialect::FanucB);
  EXPECT_EQ(fanuc.control, "fanuc-0i-t");
  // Both stated: both win, whatever the program says.
  const MachineChoice both = chooseMachine(systemB, {Dialect::FanucA, "--dialect", "haas", "--control"});
  EXPECT_EQ(both.dialect, Dialect::FanucA);
  EXPECT_EQ(both.control, "haas");
  // Every pairing names a real preset.
  for (Dialect d : kDialects) {
    if (const auto control = controlImpliedBy(d)) {
      EXPECT_TRUE(controlPreset(*control).has_value()) << *control;
    }
  }
}

TEST(MachineChoice, FanucCornerWordsChooseFanucsControlUnlessOneIsStated) {
  const MachineEvidence evidence = readMachineEvidence("G95 F0.2\nG01 X30. Z-10. ,C1.\n");
  const MachineChoice choice = chooseMachine(evidence, {});
  EXPECT_EQ(choice.dialect, Dialect::FanucB);
  EXPECT_EQ(choice.control, "fanuc-0i-t");
  EXPECT_EQ(chooseMachine(evidence, {{}, {}, "gsk980tdi", "--control"}).control, "gsk980tdi");
}

// A trainer's stock line or tool change chooses the trainers' control, said with its mark; a
// stated control, or one the dialect implies (Haas), wins over it; with Fanuc's corners too the
// trainers' control reads them.
TEST(MachineChoice, ATrainersProgramChoosesTheTrainersControl) {
  const MachineChoice billet = inferred("[BILLET X30 Z60\nG00 X32. Z2.\n");
  EXPECT_EQ(billet.control, "denford");
  EXPECT_TRUE(billet.controlInferred);
  EXPECT_NE(std::find(billet.because.begin(), billet.because.end(), "[BILLET at line 1 (a school trainer's)"),
            billet.because.end());
  const MachineEvidence trainerAndB = readMachineEvidence("G95 F0.2\nM06 T0101\nG01 X30. Z-10. ,C1.\n");
  const MachineChoice both = chooseMachine(trainerAndB, {});
  EXPECT_EQ(both.dialect, Dialect::FanucB);
  EXPECT_EQ(both.control, "denford");
  EXPECT_EQ(controlPreset("denford")->parameters.cornerWords, CornerWords::CommaCR);
  EXPECT_EQ(chooseMachine(trainerAndB, {{}, {}, "gsk980tdi", "--control"}).control, "gsk980tdi");
  EXPECT_EQ(inferred("M06 T0101\nM97 P100\n").control, "haas");
}

TEST(MachineChoice, LengthsWithoutAPointUnderALeastIncrementControl) {
  const Control fanuc = *controlPreset("fanuc-0i-t");
  const Control gsk = *controlPreset("gsk980tdi");
  const MachineEvidence beside = readMachineEvidence("G00 X40. Z2.\nG01 Z-23 F0.2\n");
  const auto warnings = lengthWarnings(beside, fanuc.parameters, "fanuc-0i-t", 40);
  ASSERT_EQ(warnings.size(), 1u);
  EXPECT_EQ(warnings[0].line, 2);
  EXPECT_EQ(warnings[0].column, 5);
  EXPECT_NE(warnings[0].message.find("as -0.023 mm"), std::string::npos) << warnings[0].message;
  EXPECT_TRUE(lengthWarnings(beside, gsk.parameters, "gsk980tdi", 40).empty());
  // Written all in increments, of the bar's size read so: no warning.
  const MachineEvidence increments = readMachineEvidence("G00 X40000 Z2000\nG01 Z-23000 F0.2\n");
  EXPECT_TRUE(lengthWarnings(increments, fanuc.parameters, "fanuc-0i-t", 40).empty());
  // All bare and far too small for the bar read in increments: warned.
  const MachineEvidence small = readMachineEvidence("G00 X40 Z2\nG01 Z-23 F0.2\n");
  EXPECT_EQ(lengthWarnings(small, fanuc.parameters, "fanuc-0i-t", 40).size(), 1u);
}

TEST(MachineChoice, AnInchProgramWithoutItsG20IsWarnedOf) {
  const Control gsk = *controlPreset("gsk980tdi");
  const std::string inch = "G00 X.75 Z.1\nG01 Z-.5 F.008\nX.875\n";
  const auto warnings = lengthWarnings(readMachineEvidence(inch), gsk.parameters, "gsk980tdi", 25);
  ASSERT_EQ(warnings.size(), 1u);
  EXPECT_EQ(warnings[0].line, 3);  // the largest length, X.875
  EXPECT_NE(warnings[0].message.find("G20"), std::string::npos);
  // Its G20 given, a bar under 10 mm, or a length of a millimetre or more: no warning.
  EXPECT_TRUE(lengthWarnings(readMachineEvidence("G20\n" + inch), gsk.parameters, "gsk980tdi", 25).empty());
  EXPECT_TRUE(lengthWarnings(readMachineEvidence(inch), gsk.parameters, "gsk980tdi", 8).empty());
  EXPECT_TRUE(lengthWarnings(readMachineEvidence(inch + "Z-1.\n"), gsk.parameters, "gsk980tdi", 25).empty());
}

}  // namespace
}  // namespace lathesim::interp
