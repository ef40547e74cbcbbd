// Each kind of evidence of the machine, alone, where it stands; and the look-alikes that are
// not evidence (the same numbers with other words, text in comments).

#include "interp/text/machine_evidence.hpp"

#include <gtest/gtest.h>

#include <array>

namespace lathesim::interp {
namespace {

struct Case {
  std::string_view text;
  EvidenceKind kind;
  int line, column;
  std::string_view written;
};

TEST(MachineEvidence, EachKindAloneIsFoundWhereItStands) {
  const Case cases[] = {
      {"G00 X20.\nG99 G01 Z-5. F0.2\n", EvidenceKind::SystemA, 2, 1, "G99"},
      {"G98 F100\n", EvidenceKind::SystemA, 1, 1, "G98"},
      {"G50 S2000\n", EvidenceKind::SystemA, 1, 1, "G50"},
      {"G32 Z-20. F1.5\n", EvidenceKind::SystemA, 1, 1, "G32"},
      {"G00 X20.\nG01 U-2. F0.2\n", EvidenceKind::SystemA, 2, 5, "U-2. beside a move"},
      {"G00 X20.\n  W-3.\n", EvidenceKind::SystemA, 2, 3, "W-3. beside a move"},
      {"G21 G95 F0.2\n", EvidenceKind::SystemB, 1, 5, "G95"},
      {"G94 F120.\n", EvidenceKind::SystemB, 1, 1, "G94 F120."},
      {"G00 X50.\nG92 S2500\n", EvidenceKind::SystemB, 2, 1, "G92 S2500"},
      {"G77 X30. Z-20. F0.2\n", EvidenceKind::SystemB, 1, 1, "G77"},
      {"G78 X19. Z-15. F1.5\n", EvidenceKind::SystemB, 1, 1, "G78"},
      {"G79 X0 Z-2. F0.2\n", EvidenceKind::SystemB, 1, 1, "G79"},
      {"G91 G01 X-2. F0.1\n", EvidenceKind::SystemB, 1, 1, "G91"},
      {"G90\n", EvidenceKind::SystemB, 1, 1, "G90"},
      {"G33 Z-20. F1.5\n", EvidenceKind::SystemB, 1, 1, "G33"},
      {"G80 X30. Z-20. F0.2\n", EvidenceKind::Hnc, 1, 1, "G80 with X and Z"},
      {"G81 X0 Z-2. F0.2\n", EvidenceKind::Hnc, 1, 1, "G81 with X and Z"},
      {"G82 X19. Z-15. F1.5\n", EvidenceKind::Hnc, 1, 1, "G82 with X and Z"},
      {"G71 P10 Q20 D1.5 U0.4 W0.1 F0.25\n", EvidenceKind::Haas, 1, 1, "one-block G71 with D1.5"},
      {"G72 P10 Q20 D1. U0.4 W0.1 F0.25\n", EvidenceKind::Haas, 1, 1, "one-block G72 with D1."},
      {"M97 P100\n", EvidenceKind::Haas, 1, 1, "M97"},
      {"G187 P1\n", EvidenceKind::Haas, 1, 1, "G187"},
      {"G01 X30. Z-10. ,C1.\n", EvidenceKind::FanucCorner, 1, 16, ",C1."},
      {"G01 Z-10. ,R2.\n", EvidenceKind::FanucCorner, 1, 11, ",R2."},
      {"G20\n", EvidenceKind::Inch, 1, 1, "G20"},
      {"  [BILLET X30 Z60\n", EvidenceKind::Trainer, 1, 3, "[BILLET"},
      {"[billet x50 z100\n", EvidenceKind::Trainer, 1, 1, "[BILLET"},
      {"G00 X40. Z2.\nM06 T0101\n", EvidenceKind::Trainer, 2, 1, "M06 beside T0101"},
      {"N30 T02 M6\n", EvidenceKind::Trainer, 1, 9, "M06 beside T02"},
  };
  for (const Case& c : cases) {
    SCOPED_TRACE(std::string(c.text));
    const MachineEvidence evidence = readMachineEvidence(c.text);
    ASSERT_EQ(evidence.count(c.kind), 1u);
    const EvidenceMark& m = evidence.of(c.kind).front();
    EXPECT_EQ(m.line, c.line);
    EXPECT_EQ(m.column, c.column);
    EXPECT_EQ(m.text, c.written);
    for (std::size_t k = 0; k < kEvidenceKinds; ++k) {
      if (static_cast<EvidenceKind>(k) != c.kind) {
        EXPECT_EQ(evidence.counts[k], 0u) << "kind " << k;
      }
    }
  }
}

// A code is a whole number however it is written (leading zeros, beside codes past 255), and
// a point makes it another code: what the block index answers must be what the words say.
TEST(MachineEvidence, CodesAreWholeNumbersAsWritten) {
  const MachineEvidence leadingZero = readMachineEvidence("G095 F0.2\n");
  ASSERT_EQ(leadingZero.count(EvidenceKind::SystemB), 1u);
  EXPECT_EQ(leadingZero.of(EvidenceKind::SystemB).front().column, 1);
  const MachineEvidence pastTheIndex = readMachineEvidence("G300 M200 G95\n");
  ASSERT_EQ(pastTheIndex.count(EvidenceKind::SystemB), 1u);
  EXPECT_EQ(pastTheIndex.of(EvidenceKind::SystemB).front().column, 11);
  EXPECT_EQ(readMachineEvidence("G95. F0.2\nG20.\nM97.\n").counts, (std::array<std::size_t, kEvidenceKinds>{}));
  EXPECT_EQ(readMachineEvidence("g95 f0.2\n").count(EvidenceKind::SystemB), 1u);  // in any case
}

// Codes both systems write with other words, and words in comments, are no evidence.
TEST(MachineEvidence, LookAlikesAreNotEvidence) {
  for (std::string_view text : {
           "G94 X0 Z-1. F0.1\n",         // system A's face cycle
           "G92 X19. Z-15. F1.5\n",      // system A's thread cycle (system B's coordinate set)
           "G90 X30. Z-20. F0.2\n",      // system A's axial cycle
           "G71 U2. R1.\nG71 P10 Q20 U0.4 W0.1 F0.2\n",  // U/W of a cycle, not a move
           "G04 U1.5\n",                 // a dwell's U
           "G81 X0 Z-10. R2. F0.1\n",    // Fanuc's drilling cycle takes an R point
           "G83 X0 Z-20. Q5000 F0.1\n",
           "G80\n",                      // drilling cancel
           "(G95 G92 S2500 M97 ,C1. G20)\nG00 X20. (U-2.)\n",
           "G01 Z-5. F0.2 ; G95 after the end of block\n",
           "T0101\nM06\n",              // a T word and an M06 in blocks of their own
           "(M06 T01)\nG00 X20. (T02 M06)\n",
           "[TOOLDEF T1 D6\n[BILLETS X30\n",  // other directives, and no lengths from them
       }) {
    SCOPED_TRACE(std::string(text));
    const MachineEvidence evidence = readMachineEvidence(text);
    for (std::size_t k = 0; k < kEvidenceKinds; ++k) EXPECT_EQ(evidence.counts[k], 0u) << "kind " << k;
  }
}

TEST(MachineEvidence, MarksAreCountedAndTheFirstFewKept) {
  std::string text;
  for (int i = 0; i < 10; ++i) text += "G95 F0.2\n";
  const MachineEvidence evidence = readMachineEvidence(text);
  EXPECT_EQ(evidence.count(EvidenceKind::SystemB), 10u);
  ASSERT_EQ(evidence.of(EvidenceKind::SystemB).size(), MachineEvidence::kMarksKept);
  EXPECT_EQ(evidence.of(EvidenceKind::SystemB)[2].line, 3);
}

TEST(MachineEvidence, LengthsWithAndWithoutAPoint) {
  const MachineEvidence evidence = readMachineEvidence("G00 X40. Z2.\nG01 X0 Z-23 F0.2\nG01 X35 W-1.5\n");
  EXPECT_EQ(evidence.pointLengths, 3u);  // X40. Z2. W-1.5
  EXPECT_EQ(evidence.bareLengths, 2u);   // Z-23 X35 (X0 is zero whatever the reading)
  ASSERT_TRUE(evidence.firstBareLength);
  EXPECT_EQ(evidence.firstBareLength->text, "Z-23");
  EXPECT_EQ(evidence.firstBareLength->line, 2);
  EXPECT_EQ(evidence.firstBareLength->column, 8);
  EXPECT_DOUBLE_EQ(evidence.largestBareLength, 35.0);
  EXPECT_DOUBLE_EQ(evidence.largestPointLength, 40.0);
  const auto bare = bareLengthsIn("G01 X35 Z-2. (Z-9) W-7", 4);
  ASSERT_EQ(bare.size(), 2u);
  EXPECT_EQ(bare[0].text, "X35");
  EXPECT_EQ(bare[1].text, "W-7");
  EXPECT_EQ(bare[1].column, 20);
}

// A trainer's directive line is skipped as the interpreter skips it: its X and Z are the bar's,
// not lengths of the program; a pasted citation is read as a block.
TEST(MachineEvidence, DirectiveLinesHoldNoLengths) {
  const MachineEvidence evidence = readMachineEvidence("[BILLET X30 Z60\nG00 X32. Z2.\n");
  EXPECT_EQ(evidence.bareLengths, 0u);
  EXPECT_EQ(evidence.pointLengths, 2u);
  const MachineEvidence cited = readMachineEvidence("G00 X32. Z2. [cite: 133]\n[cite: 7] G95 F0.2\n");
  EXPECT_EQ(cited.count(EvidenceKind::SystemB), 1u);
  EXPECT_EQ(cited.count(EvidenceKind::Trainer), 0u);
}

// Numbers as written: signs, a point at either end, and a number too long to be finite.
TEST(MachineEvidence, LengthValuesAsWritten) {
  struct Case {
    std::string_view text;
    double largestPoint, largestBare;
  };
  for (const Case& c : {Case{"G01 X+.5 Z-12.\n", 12.0, 0.0}, Case{"G01 X-.25 W+7\n", 0.25, 7.0},
                        Case{"G01 X 17 Z -3.5\n", 3.5, 17.0}, Case{"G01 U1e3 Z4.\n", 4.0, 1.0}}) {
    SCOPED_TRACE(std::string(c.text));
    const MachineEvidence evidence = readMachineEvidence(c.text);
    EXPECT_DOUBLE_EQ(evidence.largestPointLength, c.largestPoint);
    EXPECT_DOUBLE_EQ(evidence.largestBareLength, c.largestBare);
  }
  // Signed as written, and exact to the last digit written.
  const auto bare = bareLengthsIn("G01 W-7 U+3 X1234567890123 Z-0000000000000000012", 1);
  ASSERT_EQ(bare.size(), 4u);
  EXPECT_EQ(bare[0].value, -7.0);
  EXPECT_EQ(bare[1].value, 3.0);
  EXPECT_EQ(bare[2].value, 1234567890123.0);
  EXPECT_EQ(bare[3].value, -12.0);  // 19 digits: read by from_chars
  EXPECT_EQ(readMachineEvidence("G01 X37.999 Z-30.125\n").largestPointLength, 37.999);
  // Four hundred digits are no finite number: read as zero, not as an error.
  const MachineEvidence huge = readMachineEvidence("G01 X" + std::string(400, '9') + " Z5.\n");
  EXPECT_EQ(huge.bareLengths, 0u);
  EXPECT_DOUBLE_EQ(huge.largestPointLength, 5.0);
}

TEST(MachineEvidence, TheForeignFamilyIsFoundInTheSamePass) {
  const MachineEvidence evidence = readMachineEvidence("G95 F0.2\nN20 T2 D2\n");
  ASSERT_TRUE(evidence.foreign);
  EXPECT_EQ(evidence.foreign->family, "Fagor 8055/8070 or Siemens Sinumerik (T with its offset in D)");
  EXPECT_EQ(evidence.foreign->line, 2);
  EXPECT_EQ(evidence.count(EvidenceKind::SystemB), 1u);
}

}  // namespace
}  // namespace lathesim::interp
