// Every refusal a flag would cure names the flag: a G code another dialect reads, Fanuc's
// corner words under a control with L/D corners, an M code another control's list has.

#include <gtest/gtest.h>

#include <fmt/format.h>

#include "interp/control/gcode_table.hpp"
#include "interp/control/machine_m_codes.hpp"
#include "tests/interp/test_support.hpp"

namespace lathesim::interp {
namespace {

using test::defaultOptions;
using test::under;

std::string firstError(const InterpretResult& result) {
  for (const Diagnostic& d : result.diagnostics)
    if (d.severity == Severity::Error) return d.message;
  return "";
}

// Each code of each dialect that another dialect reads: the refusal names one that does.
TEST(Cure, AGCodeAnotherDialectReadsNamesItsDialect) {
  int swept = 0;
  for (Dialect dialect : kDialects)
    for (int code = 0; code <= 999; ++code) {
      if (findGCode(code, dialect) != nullptr) continue;
      std::vector<Dialect> readers;
      for (Dialect other : kDialects)
        if (const GCodeInfo* info = findGCode(code, other); info && info->supported) readers.push_back(other);
      if (readers.empty()) continue;
      ++swept;
      const std::string program = fmt::format("G{:02}\n", code);
      SCOPED_TRACE(fmt::format("{} in {}", program, dialectName(dialect)));
      const std::string message = firstError(interpret(program, "p.nc", under("gsk980tdi", dialect)));
      ASSERT_NE(message.find(fmt::format("unknown G code G{:02}", code)), std::string::npos) << message;
      EXPECT_NE(message.find(fmt::format("run with --dialect {}", dialectName(readers.front()))), std::string::npos)
          << message;
    }
  EXPECT_GE(swept, 20);  // fanuc-a alone lacks G77–G79, G33, G90/G91 as modes, G95 …
}

TEST(Cure, AGCodeNoDialectReadsNamesNoDialect) {
  const std::string message = firstError(interpret("G199\n", "p.nc", defaultOptions()));
  EXPECT_NE(message.find("unknown G code G199"), std::string::npos) << message;
  EXPECT_EQ(message.find("--dialect"), std::string::npos) << message;
}

TEST(Cure, FanucsCornerWordsUnderLDCornersNameFanucsControl) {
  for (std::string_view word : {",C1.", ",R2."}) {
    const std::string program = fmt::format("G00 X20. Z2.\nG01 Z-10. F0.2 {}\nX30.\n", word);
    SCOPED_TRACE(program);
    const std::string message = firstError(interpret(program, "p.nc", defaultOptions()));
    EXPECT_NE(message.find("Fanuc's corner word"), std::string::npos) << message;
    EXPECT_NE(message.find("--control fanuc-0i-t"), std::string::npos) << message;
    // Fanuc's control reads it.
    EXPECT_TRUE(interpret(program, "p.nc", under("fanuc-0i-t")).ok());
  }
}

TEST(Cure, AnMCodeAnotherControlListsNamesThatControl) {
  // Every machine code on one control's list and on no other's, asked of each other control.
  const std::pair<MachineMCodes, std::string_view> controls[] = {
      {MachineMCodes::Gsk980tdi, "gsk980tdi"}, {MachineMCodes::Fanuc0iT, "fanuc-0i-t"}, {MachineMCodes::Haas, "haas"}};
  int swept = 0;
  for (const auto& [owner, ownerName] : controls)
    for (const MachineMCode& code : machineMCodes(owner))
      for (const auto& [other, otherName] : controls) {
        if (other == owner || findMachineMCode(code.number, other) != nullptr || findMCode(code.number) != nullptr)
          continue;
        ++swept;
        const std::string program = fmt::format("M{:02}\n", code.number);
        SCOPED_TRACE(fmt::format("{} under {}", program, otherName));
        const std::string message = firstError(interpret(program, "p.nc", under(otherName)));
        EXPECT_NE(message.find("run with --control"), std::string::npos) << message;
      }
  EXPECT_GE(swept, 5);
}

}  // namespace
}  // namespace lathesim::interp
