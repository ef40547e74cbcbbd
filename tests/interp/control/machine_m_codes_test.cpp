// The machine M-code tables, entry class by entry class: a code that moves nothing near the
// work is a note; a code that moves something lathesim does not simulate (tailstock, probe
// arm, the bar freed in the chuck, the shop's own relays) is a warning, never silent; a code no
// table holds is an error naming the table looked in and any other family's table that holds it.

#include "interp/control/machine_m_codes.hpp"

#include <fmt/format.h>
#include <gtest/gtest.h>

#include <set>
#include <string>

#include "../test_support.hpp"
#include "interp/control/gcode_table.hpp"

namespace lathesim::interp {
namespace {

using test::expectError;
using test::run;

InterpreterOptions withCodes(MachineMCodes family) {
  InterpreterOptions options = test::defaultOptions();
  options.control.machineMCodes = family;
  return options;
}

// Every entry of every table, run in a program under its family: a note for the ones that move
// nothing, a warning (naming the code and its meaning) for the ones that move something.
TEST(MachineMCodeTables, EveryEntryIsSaidByItsClass) {
  for (const MachineMCodes family : machineMCodeFamilies()) {
    for (const MachineMCode& code : machineMCodes(family)) {
      const std::string written = fmt::format("M{:02}", code.number);
      SCOPED_TRACE(std::string(machineMCodeFamilyName(family)) + " " + written);
      const auto result = run("G00 X40 Z5\n" + written + "\n", withCodes(family));
      ASSERT_TRUE(result.ok()) << test::messageOf(result);
      const auto notes = test::notesOf(result);
      const auto warnings = test::warningsOf(result);
      const bool moves = code.motion == MachineMotion::Unsimulated;
      ASSERT_EQ(warnings.size(), moves ? 1u : 0u);
      ASSERT_EQ(notes.size(), moves ? 0u : 1u);
      const Diagnostic& said = moves ? warnings[0] : notes[0];
      EXPECT_EQ(said.line, 2);
      EXPECT_EQ(said.column, 1);
      EXPECT_NE(said.message.find(written + " (" + std::string(code.meaning) + ")"), std::string::npos) << said.message;
      EXPECT_NE(said.message.find(moves ? "a collision with it is not checked" : "changes nothing simulated"),
                std::string::npos)
          << said.message;
      EXPECT_FALSE(code.source.empty());
      EXPECT_EQ(result.toolpath.moves.size(), 1u);  // nothing moves in the simulation
    }
  }
}

// What moves, by name: these must never be accepted as a silent note.
TEST(MachineMCodeTables, TailstockChuckAndProbeArmAreWarnings) {
  const struct {
    MachineMCodes family;
    int number;
  } moving[] = {{MachineMCodes::Haas, 21},      {MachineMCodes::Haas, 22},      {MachineMCodes::Haas, 11},
                {MachineMCodes::Haas, 104},     {MachineMCodes::Haas, 110},     {MachineMCodes::Haas, 59},
                {MachineMCodes::Fanuc0iT, 21},  {MachineMCodes::Fanuc0iT, 22},  {MachineMCodes::Fanuc0iT, 11},
                {MachineMCodes::Fanuc0iT, 69},  {MachineMCodes::Gsk980tdi, 10}, {MachineMCodes::Gsk980tdi, 11},
                // Doosan's tailstock and part ejector; M10, a chuck or Doosan's parts catcher
                {MachineMCodes::Fanuc0iT, 78},  {MachineMCodes::Fanuc0iT, 79},  {MachineMCodes::Fanuc0iT, 116},
                {MachineMCodes::Fanuc0iT, 10}};
  for (const auto& m : moving) {
    const MachineMCode* code = findMachineMCode(m.number, m.family);
    ASSERT_NE(code, nullptr) << m.number;
    EXPECT_EQ(code->motion, MachineMotion::Unsimulated) << machineMCodeFamilyName(m.family) << " M" << m.number;
  }
  const auto tailstock = run("G00 X40. Z5.\nM21\n", test::haas());
  ASSERT_TRUE(tailstock.ok());
  ASSERT_EQ(test::warningsOf(tailstock).size(), 1u);
  EXPECT_EQ(test::warningsOf(tailstock)[0].message,
            "M21 (tailstock advance) moves something lathesim does not simulate: the program runs on, but a "
            "collision with it is not checked");
}

// Codes one builder gives a harmless meaning and another a moving one stay out of the Fanuc
// builders' table: Doosan's air blast M14/M15 is another lathe's live tool, Mazak's M200 its
// milling mode (the C axis engaged).
TEST(MachineMCodeTables, CodesThatMoveSomethingOnAnotherBuildersLatheAreNotAccepted) {
  for (const int number : {14, 15, 200}) {
    EXPECT_EQ(findMachineMCode(number, MachineMCodes::Fanuc0iT), nullptr) << number;
    const auto result = run(fmt::format("G00 X40 Z5\nM{}\n", number), withCodes(MachineMCodes::Fanuc0iT));
    EXPECT_FALSE(result.ok()) << number;
  }
}

// Live tool, second spindle and C axis codes are in no machine table: the common table refuses
// them by name, whichever family's table is in force.
TEST(MachineMCodeTables, LiveToolAndSecondSpindleAreRefusedNotAccepted) {
  for (const MachineMCodes family : machineMCodeFamilies()) {
    for (const int number : {133, 134, 135, 143, 144, 145, 154, 155}) {
      EXPECT_EQ(findMachineMCode(number, family), nullptr) << number;
      expectError(run("M" + std::to_string(number) + "\n", withCodes(family)), 1, 1, "which this lathe does not have");
    }
  }
}

// No table's code shadows a code the common table runs (M03, M30, M98 …): those keep their
// meaning. Only a code the common table refuses may be a family's own (Haas's M13 is its air
// jet, the live tool elsewhere).
TEST(MachineMCodeTables, NoEntryShadowsACommonCode) {
  for (const MachineMCodes family : machineMCodeFamilies()) {
    std::set<int> seen;
    for (const MachineMCode& code : machineMCodes(family)) {
      const MCodeInfo* common = findMCode(code.number);
      EXPECT_TRUE(common == nullptr || !common->supported) << machineMCodeFamilyName(family) << " M" << code.number;
      EXPECT_TRUE(seen.insert(code.number).second) << "twice: M" << code.number;
    }
  }
}

TEST(MachineMCodeTables, AnUnknownCodeNamesTheTablesLookedIn) {
  // M31 is Haas's chip auger: under the GSK's table it is an error naming that table and Haas's.
  const auto gsk = run("G00 X40 Z5\nM31\n");
  expectError(gsk, 2, 1, "unknown M code M31");
  EXPECT_NE(gsk.diagnostics[0].message.find("a machine code of this control's table, m_codes = gsk980tdi (M10 M11"),
            std::string::npos)
      << gsk.diagnostics[0].message;
  EXPECT_NE(gsk.diagnostics[0].message.find("the haas table has M31 (chip auger forward): set [control] m_codes"),
            std::string::npos)
      << gsk.diagnostics[0].message;
  // M200, an end code of some builders, is in no table: the message says so rather than guess.
  const auto none = run("G00 X40 Z5\nM200\n", withCodes(MachineMCodes::Fanuc0iT));
  expectError(none, 2, 1, "unknown M code M200");
  EXPECT_NE(none.diagnostics[0].message.find("m_codes = fanuc-0i-t"), std::string::npos) << none.diagnostics[0].message;
  EXPECT_NE(none.diagnostics[0].message.find("no machine table lathesim has holds it"), std::string::npos)
      << none.diagnostics[0].message;
}

}  // namespace
}  // namespace lathesim::interp
