// The bar a program states: billet lines and stock comments, and what does not count, as the
// one walk of the lines that reads the machine's evidence finds it (machine_evidence.hpp: a
// run, and batch sizing its jobs, read the text once for both).

#include "interp/text/stated_stock.hpp"

#include <gtest/gtest.h>

#include "interp/text/machine_evidence.hpp"

namespace lathesim::interp {
namespace {

std::optional<StatedStock> statedBar(const std::string& text) { return readMachineEvidence(text).stock; }

TEST(StatedStock, BilletLinesAndStockCommentsGiveDiameterAndLength) {
  struct Case {
    std::string_view text;
    double diameter, length;
    int line, column;
  };
  const Case cases[] = {
      {"[BILLET X56.4 Z84\nG00 X60\n", 56.4, 84, 1, 1},
      {"O1\n  [billet x50 z100\n", 50, 100, 2, 3},
      {"(STOCK D40 L80)\n", 40, 80, 1, 1},
      {"G21 (BLANK DIA 40 LENGTH 80)\n", 40, 80, 1, 5},
      {"(MATERIAL: ALU Ø40 X 80)\n", 40, 80, 1, 1},
      {"(BAR 25.4x120 LONG)\n", 25.4, 120, 1, 1},
      {"(毛坯 Φ50×60)\n", 50, 60, 1, 1},
      {"(T1 CNMG)\n(STOCK: D=63.5, L=150)\n", 63.5, 150, 2, 1},
      // The first statement, wherever it stands: after code, a '\r', a blank line, a second one.
      {"G21 G95\nG00 X44. Z2.\r\n\n(STOCK D40 L80)\r\n(STOCK D50 L90)\n", 40, 80, 4, 1},
      {"(T1 CNMG)\n(BAR 30 X 90)\n[BILLET X56.4 Z84\n", 30, 90, 2, 1},
      {"(STOCK D40 L80)", 40, 80, 1, 1},  // no line end
  };
  for (const Case& c : cases) {
    SCOPED_TRACE(std::string(c.text));
    const auto stated = statedBar(std::string(c.text));
    ASSERT_TRUE(stated.has_value());
    EXPECT_DOUBLE_EQ(stated->diameterMm, c.diameter);
    EXPECT_DOUBLE_EQ(stated->lengthMm, c.length);
    EXPECT_EQ(stated->line, c.line);
    EXPECT_EQ(stated->column, c.column);
  }
}

TEST(StatedStock, StatementsWithoutBothNumbersOrKeywordDoNotCount) {
  for (std::string_view text : {"(STOCK ALUMINIUM)\n", "(STOCK D40)\n", "(TOOL D40 L80)\n",
                                "G00 X40 Z80 (40 X 80)\n", "[TOOLDEF T1 D10\n"}) {
    SCOPED_TRACE(std::string(text));
    EXPECT_FALSE(statedBar(std::string(text)).has_value());
  }
}

// A line that states the bar is evidence of the machine all the same: the walk reads both.
TEST(StatedStock, TheLineThatStatesTheBarIsStillReadForTheMachine) {
  const MachineEvidence evidence = readMachineEvidence("G95 F0.2 (STOCK D40 L80)\nG01 Z-23 F0.2\n");
  ASSERT_TRUE(evidence.stock);
  EXPECT_EQ(evidence.stock->line, 1);
  EXPECT_EQ(evidence.stock->column, 10);
  EXPECT_EQ(evidence.stock->text, "(STOCK D40 L80)");
  EXPECT_EQ(evidence.count(EvidenceKind::SystemB), 1u);
  EXPECT_EQ(evidence.bareLengths, 1u);
}

}  // namespace
}  // namespace lathesim::interp

namespace lathesim::interp {
namespace {

// Hostile lines: std::regex recursed once per character and overflowed the stack on a line of
// 300 000 characters (a crash); a number of 400 digits made std::stod throw.
TEST(StatedStock, VeryLongLinesAndNumbersAreReadWithoutHarm) {
  EXPECT_FALSE(statedBar("G00 X1 Z1\n(STOCK D" + std::string(300000, '1') + ")\nM30\n"));
  EXPECT_FALSE(statedBar("(STOCK D" + std::string(400, '9') + " L80)\n"));
  EXPECT_FALSE(statedBar("[BILLET X" + std::string(400, '9') + " Z80\n"));
  EXPECT_FALSE(statedBar(std::string(100000, '(') + ")\n"));
  const auto stated = statedBar(std::string(200000, ' ') + "\n(STOCK D40 L80)\n");
  ASSERT_TRUE(stated);
  EXPECT_EQ(stated->line, 2);
}

}  // namespace
}  // namespace lathesim::interp
