#pragma once
// M98/M99 and G65 in one file: the subprograms and macros that are running, innermost last.
//   M98 P… in block i      → go to O<program>'s block; M99 comes back to block i + 1
//                            after the last repeat, or to O<program> again before it
//   M97 P… in block i      → (Haas) the same for the block N… of the calling program
//   G65 P… L… in block i   → the same for a macro call, which also gets fresh local
//                            variables (the caller keeps them: macro/variables.hpp)
//   M99 P… in a subprogram → after the last repeat, to N… of the calling program
//   M99 in the main program → the program runner's: the control would run it again, forever

#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include "interp/macro/macro_call.hpp"
#include "interp/text/program.hpp"
#include "interp/execution/program_flow.hpp"
#include "interp/base/result.hpp"

namespace lathesim::interp {

/// How deep M98 calls may nest: 4 levels on the Fanuc 0i-T and the GSK980TDi.
constexpr int kMaxSubprogramNesting = 4;
/// How deep G65 macro calls may nest: 4 levels, local variable levels 0–4 (Fanuc 16i/18i
/// custom macro manual; M98 calls are counted apart).
constexpr int kMaxMacroNesting = 4;

/// What M99 did.
struct CallReturn {
  std::size_t next = 0;    // the block to run next (M99 P: N… of the calling program)
  bool repeat = false;     // the called program runs again (a repeat count)
  bool leftMacro = false;  // a G65 macro ended: its caller's local variables come back
  std::size_t callBlock = 0;  // the M98/G65 block that called the program
  int callColumn = 0;         // of its P word
};

class CallStack {
 public:
  /// `program` must outlive the stack; the main program starts at block 0.
  explicit CallStack(const Program& program) : program_(program) {}

  /// The block to run next for the M98 (or M97: `call.local`) in block `index`.
  Result<std::size_t> call(const SubprogramCall& call, std::size_t index);
  /// The block to run next for the G65 in block `index`.
  Result<std::size_t> callMacro(const macro::MacroCall& call, std::size_t index);
  /// Where the M99 of block `index` goes; a subprogram or macro must be running.
  Result<CallReturn> giveBack(const SubprogramReturn& giveBack, std::size_t index);
  /// Whether a subprogram or macro is running (else M99 ends the main program).
  bool inSubprogram() const { return !frames_.empty(); }
  /// When the text ended inside a subprogram: the error, located at its M98.
  std::optional<Error> unfinished() const;
  /// The main program's block whose M98 or G65 the running programs descend from, if any runs.
  std::optional<std::size_t> outermostCall() const {
    if (frames_.empty()) return std::nullopt;
    return frames_.front().callFrom;
  }
  /// The M98/G65 blocks of the running calls, outermost first.
  std::vector<std::size_t> callBlocks() const {
    std::vector<std::size_t> blocks;
    for (const Frame& frame : frames_) blocks.push_back(frame.callFrom);
    return blocks;
  }

 private:
  struct Frame {
    int programNumber = 0;     // for M97, the N number called
    bool macro = false;        // called by G65
    bool local = false;        // called by M97
    std::size_t start = 0;     // the O block
    std::size_t callFrom = 0;  // the M98/G65 block
    int column = 0;            // of the calling block's P word
    int repeatsLeft = 0;       // after the run in progress
  };

  Result<std::size_t> programStart(int programNumber, const char* code, int column, std::size_t index) const;
  Result<std::size_t> localStart(const SubprogramCall& call, std::size_t index) const;
  std::string chainTo(const std::string& called) const;  // "O0001 → O1000 → " + `called`
  int framesOfKind(bool macro) const;

  const Program& program_;
  std::vector<Frame> frames_;
};

}  // namespace lathesim::interp
