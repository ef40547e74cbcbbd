// The E word of a thread block (G32, G92, G76) as the control reads it (control.thread_e_word):
// the lead in the unit in force with more digits (Fanuc ⚠), threads per inch, or not a thread
// word at all (GSK980TDi: F or I). In hnc E is the run-out, never a lead.

#include <gtest/gtest.h>

#include <cmath>

#include "../test_support.hpp"

namespace lathesim::interp {
namespace {

using test::defaultOptions;
using test::expectError;
using test::run;

InterpreterOptions reading(ThreadEWord e, Dialect dialect = Dialect::FanucA) {
  InterpreterOptions options = defaultOptions();
  options.control.threadEWord = e;
  options.dialect = dialect;
  return options;
}

// The lead of every thread move of `result`, which must have some and agree.
double threadLead(const InterpretResult& result) {
  double lead = NAN;
  for (const Move& m : result.toolpath.moves) {
    if (m.kind != MoveKind::Thread) continue;
    if (std::isnan(lead)) lead = m.thread.leadMm;
    EXPECT_EQ(m.thread.leadMm, lead);
  }
  EXPECT_FALSE(std::isnan(lead));
  return lead;
}

// 13 threads per inch: the lead 1/13 inch = 1.953846… mm, which F0.0769 (four digits) misses by
// 0.0008 mm a turn; E0.076923 is within 0.00001 mm. Under G21 E is a lead in mm.
TEST(ThreadLeadE, LeadWithMoreDigitsInTheUnitInForce) {
  const auto options = reading(ThreadEWord::Lead);
  const auto inch = run("G20\nG00 X1.2 Z0.2\nG32 Z-1.0 E0.076923\n", options);
  ASSERT_TRUE(inch.ok()) << inch.diagnostics[0].message;
  EXPECT_NEAR(threadLead(inch), 0.076923 * 25.4, 1e-12);
  EXPECT_NEAR(threadLead(inch), 25.4 / 13.0, 1e-5);
  const auto metric = run("G00 X30 Z5\nG32 Z-20 E1.5\n", options);
  ASSERT_TRUE(metric.ok()) << metric.diagnostics[0].message;
  EXPECT_NEAR(threadLead(metric), 1.5, 1e-12);
}

// E in each thread code: G92 and G76's second block (and, modal like F, in the next G92).
TEST(ThreadLeadE, EveryThreadCodeTakesIt) {
  const auto options = reading(ThreadEWord::Lead);
  const auto g92 = run("G20\nG00 X1.3 Z0.2\nG92 X1.1 Z-1.0 E0.0625\nX1.05\n", options);
  ASSERT_TRUE(g92.ok()) << g92.diagnostics[0].message;
  EXPECT_NEAR(threadLead(g92), 1.5875, 1e-12);
  const auto g76 = run("G00 X32 Z5\nG76 P010060 Q100 R0\nG76 X27.546 Z-30 P1227 Q400 E2.0\n", options);
  ASSERT_TRUE(g76.ok()) << g76.diagnostics[0].message;
  EXPECT_NEAR(threadLead(g76), 2.0, 1e-12);
}

// As threads per inch, E8 is 3.175 mm under G21 and G20 alike.
TEST(ThreadLeadE, ThreadsPerInch) {
  const auto options = reading(ThreadEWord::ThreadsPerInch);
  for (const char* program : {"G00 X30 Z5\nG32 Z-20 E8\n", "G20\nG00 X1.2 Z0.2\nG32 Z-1.0 E8\n"}) {
    const auto result = run(program, options);
    ASSERT_TRUE(result.ok()) << result.diagnostics[0].message;
    EXPECT_NEAR(threadLead(result), 3.175, 1e-12) << program;
  }
}

TEST(ThreadLeadE, BadInputs) {
  // GSK980TDi: F or I, no E.
  expectError(run("G00 X30 Z5\nG32 Z-20 E1.5\n", reading(ThreadEWord::None)), 2, 10,
              "E1.5 is not a word of G32 on this control: give the lead as F (mm, or inch under G20, per revolution) "
              "or I (threads per inch)");
  expectError(run("G00 X30 Z5\nG78 X29 Z-20 E1.5\n", reading(ThreadEWord::None, Dialect::FanucB)), 2, 14,
              "E1.5 is not a word of G78 on this control: give the lead as F");
  const auto lead = reading(ThreadEWord::Lead);
  expectError(run("G00 X30 Z5\nG32 Z-20 F1.5 E1.5\n", lead), 2, 15, "G32 takes the lead once: F or E");
  expectError(run("G00 X30 Z5\nG32 Z-20 E0\n", lead), 2, 10, "E0 is not a lead: expected a number > 0");
  expectError(run("G00 X30 Z5\nG92 X29 Z-20 E-2\n", lead), 2, 14, "E-2 is not a lead");
  expectError(run("G00 X30 Z5\nG32 Z-20 E0\n", reading(ThreadEWord::ThreadsPerInch)), 2, 10,
              "E0 is not a number of threads per inch");
}

// In hnc E is the run-out along X whatever the control says: E without R is refused, not read
// as a lead.
TEST(ThreadLeadE, HncReadsEAsTheRunout) {
  expectError(run("G00 X32 Z3\nG82 X28 Z-20 E1 F2\n", reading(ThreadEWord::Lead, Dialect::Hnc)), 2, 1,
              "a run-out E of 1 mm along X needs its length along Z, R");
}

}  // namespace
}  // namespace lathesim::interp
