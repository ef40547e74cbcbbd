#pragma once
// M98/M99 in one file: the subprograms that are running, innermost last.
//   M98 P… in block i      → go to O<program>'s block; M99 comes back to block i + 1
//                            after the last repeat, or to O<program> again before it
//   M99 P… in a subprogram → after the last repeat, to N… of the calling program
//   M99 in the main program → the interpreter's: the control would run it again, forever

#include <cstddef>
#include <optional>
#include <vector>

#include "interp/text/program.hpp"
#include "interp/execution/program_flow.hpp"
#include "interp/result.hpp"

namespace lathesim::interp {

/// How deep M98 calls may nest: 4 levels on the Fanuc 0i-T and the GSK980TDi.
constexpr int kMaxSubprogramNesting = 4;

class CallStack {
 public:
  /// `program` must outlive the stack; the main program starts at block 0.
  explicit CallStack(const Program& program) : program_(program) {}

  /// The block to run next for the M98 in block `index`.
  Result<std::size_t> call(const SubprogramCall& call, std::size_t index);
  /// The block to run next for the M99 of block `index`, which must be in a subprogram.
  Result<std::size_t> giveBack(const SubprogramReturn& giveBack, std::size_t index);
  /// Whether a subprogram is running (else M99 ends the main program).
  bool inSubprogram() const { return !frames_.empty(); }
  /// When the text ended inside a subprogram: the error, located at its M98.
  std::optional<Error> unfinished() const;
  /// The main program's block whose M98 the running subprograms descend from, if any runs.
  std::optional<std::size_t> outermostCall() const {
    if (frames_.empty()) return std::nullopt;
    return frames_.front().callFrom;
  }

 private:
  struct Frame {
    int programNumber = 0;
    std::size_t start = 0;     // the O block
    std::size_t callFrom = 0;  // the M98 block
    int column = 0;            // of the M98 block's P word
    int repeatsLeft = 0;       // after the run in progress
  };

  const Program& program_;
  std::vector<Frame> frames_;
};

}  // namespace lathesim::interp
