#pragma once
// One block while it runs: its words (taken as they are used), the modal state it changes,
// and the moves, warnings and cycle starts it has made so far. The block executor
// (execution/) owns it; the cycles (cycles/) read their words from it and emit their legs
// into it, so that a cycle's moves are stamped like any move the program wrote. Nothing of
// it is kept when the block fails.

#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "interp/compensation/uncompensated_nose.hpp"
#include "interp/base/move.hpp"
#include "interp/base/result.hpp"
#include "interp/contour/cycle_leg.hpp"
#include "interp/state/interpreter_options.hpp"
#include "interp/state/modal_state.hpp"
#include "interp/text/block_parser.hpp"
#include "interp/text/word_units.hpp"

namespace lathesim::interp {

// The axis words of a block: at most one of X/U and one of Z/W.
struct AxisWords {
  std::optional<Word> x, u, z, w;
  bool any() const { return x || u || z || w; }
};

// Coordinates a move or cycle goes to follow the distance mode (under G91 X and Z are
// incremental, like U and W); coordinates a block declares (G50) are always absolute.
enum class Coordinates { Target, Declared };

struct BlockWork {
  BlockWork(ParsedBlock block, ModalState state, const InterpreterOptions& options, int ordinal)
      : block(std::move(block)), state(std::move(state)), options(options), ordinal(ordinal) {}

  ParsedBlock block;
  ModalState state;
  const InterpreterOptions& options;
  int ordinal;  // the block's 0-based number among the blocks read
  std::vector<Move> moves;
  std::vector<Error> warnings;
  std::vector<CycleStart> cycleStarts;
  std::optional<ContourPass> contourPass;  // G70–G73: the contour it finished or roughed
  bool legsCompensated = false;  // G90/G94 under G41/G42: the cycle offset its own legs
  bool chainedThread = false;  // this block continued (or began) a chain of G32 cuts
  bool feedGiven = false;      // the block gave F

  Error errorAt(int column, std::string message) const { return Error{block.line, column, std::move(message)}; }
  /// Takes X, U, Z and W: X with U (Z with W) is an error, or the absolute word wins on
  /// controls where it does (a warning).
  Result<AxisWords> takeAxisWords(Coordinates meaning = Coordinates::Target);
  NumberReading reading() const { return NumberReading::of(options.control, state.inch); }
  /// A length word in mm, noted for the mixed decimal point warning.
  double length(const Word& word) {
    state.lengthWriting.note(word, block.line, ordinal);
    return lengthMm(word, reading());
  }
  /// Where the axis words take the tool from the current position.
  RZ endPoint(const AxisWords& axes);
  /// A move of this block from the modal state (feed, tool, offsets, spindle), left out when
  /// it has no length (an arc's full circle and a dwell are kept).
  void emit(MoveKind kind, const RZ& from, const RZ& to, int cycleStep, const RZ& center = RZ(0, 0),
            const ThreadMotion& thread = {});
  /// A cycle's legs as moves; they are never part of a G41/G42 chain.
  void emitLegs(const std::vector<CycleLeg>& legs);
  /// The cycle this block starts at `start` (A, in the work frame), named as written.
  void noteCycleStart(const RZ& start, const std::string& name);

 private:
  void warnIfSurfaceSpeedUnclamped();
  void warnIfFeedImplausible();
};

/// Why a block that needs the ZX plane cannot run under `plane` (G17 or G19 in force), or
/// nullopt under G18: "G90 under G17: this machine has no Y axis, so a cycle needs the ZX
/// plane; select it with G18". `code` is the code as written, `what` what needs the plane
/// ("a cycle", "a thread", "an arc").
std::optional<std::string> planeProblem(Plane plane, std::string_view code, std::string_view what);

}  // namespace lathesim::interp
