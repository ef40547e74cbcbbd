#pragma once
// Helpers shared by the interp tests: run a program, compare moves with hand-made lists.

#include <gtest/gtest.h>

#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "interp/control/control_preset.hpp"
#include "interp/contour/cycle_leg.hpp"
#include "interp/interpreter.hpp"

namespace lathesim::interp::test {

/// Tools 1 and 2 defined; the tool starts at X200 (radius 100) Z200. The control is the
/// default preset's except for two parameters most move lists here were worked out under:
/// rapids in a straight line (one move per G00; the dog-leg has its own tests,
/// motion/rapid_path_test.cpp and the golden files) and G99 at power-on (F in mm/rev).
inline InterpreterOptions defaultOptions() {
  InterpreterOptions options;
  options.startPosition = RZ(100.0, 200.0);
  options.toolNumbers = {1, 2};
  options.control.rapidPath = RapidPath::Linear;
  options.control.powerOnFeedMode = FeedMode::PerRevolution;
  return options;
}

inline InterpretResult run(std::string_view program,
                           const InterpreterOptions& options = defaultOptions()) {
  return interpret(program, "test.nc", options);
}

/// The default options under a named control preset, rapids still one move each as the
/// hand-made lists expect.
inline InterpreterOptions under(std::string_view preset) {
  InterpreterOptions options = defaultOptions();
  options.control = controlPreset(preset)->parameters;
  options.control.rapidPath = RapidPath::Linear;
  return options;
}

/// The same, with the program read in `dialect` (a preset and a dialect are chosen apart).
inline InterpreterOptions under(std::string_view preset, Dialect dialect) {
  InterpreterOptions options = under(preset);
  options.dialect = dialect;
  return options;
}

/// A Haas: the haas preset, its programs read in the haas dialect.
inline InterpreterOptions haas() { return under("haas", Dialect::Haas); }

/// The default options with Custom Macro B's step limit set to `maxSteps`.
inline InterpreterOptions withMaxSteps(long long maxSteps) {
  InterpreterOptions options = defaultOptions();
  options.maxSteps = maxSteps;
  return options;
}

/// The first diagnostic's message, for a failed assertion's output.
inline std::string messageOf(const InterpretResult& result) {
  return result.diagnostics.empty() ? std::string() : result.diagnostics[0].message;
}

inline std::vector<Diagnostic> warningsOf(const InterpretResult& result) {
  std::vector<Diagnostic> warnings;
  for (const Diagnostic& d : result.diagnostics)
    if (d.severity == Severity::Warning) warnings.push_back(d);
  return warnings;
}

inline std::vector<Diagnostic> notesOf(const InterpretResult& result) {
  std::vector<Diagnostic> notes;
  for (const Diagnostic& d : result.diagnostics)
    if (d.severity == Severity::Note) notes.push_back(d);
  return notes;
}

/// Two runs made the same moves: kinds and end points (two forms of one cycle).
inline void expectSameMoves(const std::vector<Move>& actual, const std::vector<Move>& expected) {
  ASSERT_EQ(actual.size(), expected.size());
  for (std::size_t i = 0; i < expected.size(); ++i) {
    EXPECT_EQ(actual[i].kind, expected[i].kind) << i;
    EXPECT_NEAR((actual[i].to - expected[i].to).norm(), 0.0, 1e-12) << i;
  }
}

/// A move as worked out by hand: positions are (radius, Z) in mm.
struct Expected {
  MoveKind kind;
  double r0, z0, r1, z1;
  double feed;
  int cycleStep;
};

constexpr MoveKind kRapid = MoveKind::Rapid;
constexpr MoveKind kFeed = MoveKind::Feed;
constexpr MoveKind kCw = MoveKind::ArcCW;
constexpr MoveKind kCcw = MoveKind::ArcCCW;

/// The tool and offset number of each move.
inline std::vector<std::pair<int, int>> toolsOf(const InterpretResult& result) {
  std::vector<std::pair<int, int>> tools;
  for (const Move& m : result.toolpath.moves) tools.emplace_back(m.tool, m.toolOffset);
  return tools;
}

inline void expectMoves(const std::vector<Move>& actual, const std::vector<Expected>& expected) {
  ASSERT_EQ(actual.size(), expected.size());
  for (std::size_t i = 0; i < expected.size(); ++i) {
    SCOPED_TRACE(testing::Message() << "move " << i);
    const Move& m = actual[i];
    const Expected& e = expected[i];
    EXPECT_EQ(m.kind, e.kind);
    EXPECT_NEAR(m.from.x(), e.r0, 1e-9);
    EXPECT_NEAR(m.from.y(), e.z0, 1e-9);
    EXPECT_NEAR(m.to.x(), e.r1, 1e-9);
    EXPECT_NEAR(m.to.y(), e.z1, 1e-9);
    EXPECT_NEAR(m.feed, e.feed, 1e-9);
    EXPECT_EQ(m.cycleStep, e.cycleStep);
  }
}

/// The program failed with exactly one error at line:column whose message contains `part`.
inline void expectError(const InterpretResult& result, int line, int column,
                        std::string_view part) {
  EXPECT_FALSE(result.ok());
  ASSERT_EQ(result.diagnostics.size(), 1u);
  const Diagnostic& d = result.diagnostics[0];
  EXPECT_EQ(d.severity, Severity::Error);
  EXPECT_EQ(d.line, line) << d.message;
  EXPECT_EQ(d.column, column) << d.message;
  EXPECT_NE(d.message.find(part), std::string::npos) << "message: " << d.message;
}

/// The legs of a single cycle (G90, G94) against a hand-made list.
inline void expectLegs(const std::vector<CycleLeg>& legs, const std::vector<Expected>& expected) {
  ASSERT_EQ(legs.size(), expected.size());
  for (std::size_t i = 0; i < legs.size(); ++i) {
    SCOPED_TRACE(testing::Message() << "leg " << i);
    EXPECT_EQ(legs[i].kind, expected[i].kind);
    EXPECT_DOUBLE_EQ(legs[i].from.x(), expected[i].r0);
    EXPECT_DOUBLE_EQ(legs[i].from.y(), expected[i].z0);
    EXPECT_DOUBLE_EQ(legs[i].to.x(), expected[i].r1);
    EXPECT_DOUBLE_EQ(legs[i].to.y(), expected[i].z1);
    EXPECT_EQ(legs[i].step, expected[i].cycleStep);
  }
}

}  // namespace lathesim::interp::test

namespace lathesim::interp::test {

/// A move of a thread code as worked out by hand: `feed` is the lead for thread moves (0 for
/// rapids), `angleDeg` the spindle angle a thread move starts at.
struct ExpectedThread {
  MoveKind kind;
  double r0, z0, r1, z1;
  double feed;
  int cycleStep;
  double angleDeg = 0;
};

constexpr MoveKind kThread = MoveKind::Thread;

inline void expectThreadMoves(const std::vector<Move>& actual, const std::vector<ExpectedThread>& expected) {
  ASSERT_EQ(actual.size(), expected.size());
  for (std::size_t i = 0; i < expected.size(); ++i) {
    SCOPED_TRACE(testing::Message() << "move " << i);
    const Move& m = actual[i];
    const ExpectedThread& e = expected[i];
    EXPECT_EQ(m.kind, e.kind);
    EXPECT_NEAR(m.from.x(), e.r0, 1e-9);
    EXPECT_NEAR(m.from.y(), e.z0, 1e-9);
    EXPECT_NEAR(m.to.x(), e.r1, 1e-9);
    EXPECT_NEAR(m.to.y(), e.z1, 1e-9);
    EXPECT_NEAR(m.feed, e.feed, 1e-9);
    EXPECT_EQ(m.cycleStep, e.cycleStep);
    if (m.kind == MoveKind::Thread) {
      EXPECT_NEAR(m.thread.leadMm, e.feed, 1e-9);
      EXPECT_NEAR(m.thread.startAngleDeg, e.angleDeg, 1e-9);
    }
  }
}

}  // namespace lathesim::interp::test
