// The names M98 reads a program from: exactly programFileNames' names, in any case.

#include <gtest/gtest.h>

#include "interp/text/program_library.hpp"

namespace lathesim::interp {
namespace {

TEST(ProgramFileName, TheNamesM98ReadsAProgramFrom) {
  for (const char* name : {"O7615", "O7615.nc", "o7615.NC", "O7615.tap", "O7615.txt", "7615", "7615.nc", "O0015",
                           "O15", "0015.tap", "15.txt", "O12345.nc", "O0000"})
    EXPECT_TRUE(isProgramFileName(name)) << name;
  for (const char* name : {"O00015", "O7615.gcode", "O7615.nc.bak", "alice.nc", "program.nc", "O12a.nc", "O", ".nc",
                           "O-15.nc", "setup.toml", "O 15.nc", "O1234567890.nc"})
    EXPECT_FALSE(isProgramFileName(name)) << name;
}

// Every name programFileNames gives is one, for numbers of one to five digits.
TEST(ProgramFileName, AgreesWithTheNamesLookedFor) {
  for (int number : {0, 1, 9, 10, 99, 100, 999, 1000, 7615, 9999, 10000, 65535})
    for (const std::string& name : programFileNames(number)) EXPECT_TRUE(isProgramFileName(name)) << name;
}

}  // namespace
}  // namespace lathesim::interp
