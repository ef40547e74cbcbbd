// Programs of other control families are recognised by their own syntax; Fanuc programs
// that merely mention such words in comments are not.

#include "interp/text/control_family.hpp"

#include <gtest/gtest.h>

namespace lathesim::interp {
namespace {

TEST(ControlFamily, EachFamilyIsRecognisedWhereItShows) {
  struct Case {
    std::string_view text;
    std::string_view family;
    int line, column;
  };
  const Case cases[] = {
      {"(HEADER)\n  $SHAFT.MIN%\nG00 X10\n", "Okuma OSP", 2, 3},
      {"%PM\nN9000\n", "Philips 432/532", 1, 1},
      {"G21\n  o100 sub\n", "LinuxCNC (O-word subroutines)", 2, 3},
      {"G21\nO<thread> call [1]\n", "LinuxCNC (O-word subroutines)", 2, 1},
      {"#<depth> = 2\n", "LinuxCNC (named parameters)", 1, 1},
      {"G18 G64 P0.01\n", "LinuxCNC (G64 path blending with a P tolerance)", 1, 5},
      {"0 BEGIN PGM 12 MM\n", "Heidenhain", 1, 3},
      {"G18 DIAMON\n", "Siemens Sinumerik", 1, 5},
      {"%SHAFT,MX,\nG90 G95\n", "Fagor 8055/8070", 1, 1},
      {"G90 G95\nN10 T1 D1\n", "Fagor 8055/8070 or Siemens Sinumerik (T with its offset in D)", 2, 5},
      {"G7 G18\n", "LinuxCNC (G7/G8 diameter and radius modes)", 1, 1},
      {"G28 U0\nN2 G109 L1\n", "Mazak EIA/ISO (multi-turret G109, MAZATROL coordinates G53.5/G52.5)", 2, 4},
      {"G21\ng53.5\n", "Mazak EIA/ISO (multi-turret G109, MAZATROL coordinates G53.5/G52.5)", 2, 1},
      {"G18 G52.5 G99\n", "Mazak EIA/ISO (multi-turret G109, MAZATROL coordinates G53.5/G52.5)", 1, 5},
  };
  for (const Case& c : cases) {
    SCOPED_TRACE(std::string(c.text));
    const auto found = recogniseForeignProgram(c.text);
    ASSERT_TRUE(found.has_value());
    EXPECT_EQ(found->family, c.family);
    EXPECT_EQ(found->line, c.line);
    EXPECT_EQ(found->column, c.column);
  }
}

TEST(ControlFamily, FanucProgramsAreNotMistaken) {
  for (std::string_view text : {"%\nO1000 (O100 SUB CALLED LATER)\nG00 X10\nM98 P100\nM30\n%\n",
                                "G64\nG00 X10 (G64 P0.1 IS LINUXCNC)\n", "O0100\n#100=2\n#101=[#100+1]\nM99\n",
                                "(SET $ PRICE)\nG00 X10\n$ IS NOT FIRST\n",
                                // Fanuc's T word with its offset, a Haas roughing block's D, a % line
                                "%\nT0101 (T1 D1 IN THE CRIB)\nG71 P10 Q20 D1.5 U0.4 W0.1 F0.25\n%\n",
                                "G07.1 C20.\nG08 P1\nG70 P10 Q20\nG17 G18\n",
                                // Fanuc's G53 and G52 without Mazak's .5, numbers that hold 109, 53.5
                                "G53 X200. Z300.\nG52 Z10.\nG01 X109. Z-53.5 F0.2\nG1090\nG53.55\n"}) {
    SCOPED_TRACE(std::string(text));
    EXPECT_FALSE(recogniseForeignProgram(text).has_value());
  }
}

}  // namespace
}  // namespace lathesim::interp

namespace lathesim::interp {
namespace {

// A line of 300 000 characters overflowed the stack in std::regex (a crash): the signs are
// looked for in a line's first thousand characters.
TEST(ControlFamily, VeryLongLinesAreReadWithoutHarm) {
  EXPECT_FALSE(recogniseForeignProgram("G00 X1 Z1\no<" + std::string(300000, 'x') + "\nM30\n"));
  const auto siemens = recogniseForeignProgram(std::string(300000, ' ') + "\nDIAMON\n");
  ASSERT_TRUE(siemens);
  EXPECT_EQ(siemens->line, 2);
}

}  // namespace
}  // namespace lathesim::interp
