#pragma once
// The statements of Custom Macro B run against the variables: assignments (#3000 raises an
// alarm, #3006 stops with a message), IF, GOTO, WHILE/DO/END (text/statement.hpp). What a
// statement decides is the block to run next; jumps back are reported to the step guard.
// The loops running are kept per program (the main program, and each subprogram or macro
// called), innermost last: an END continues only the loop its WHILE started, so a GOTO may
// leave loops but not enter one, as on the controls.

#include <cstddef>
#include <string>
#include <vector>

#include "interp/state/step_guard.hpp"
#include "interp/macro/loop_pairs.hpp"
#include "interp/text/statement.hpp"
#include "interp/macro/variables.hpp"
#include "interp/base/result.hpp"
#include "interp/text/program.hpp"

namespace lathesim::interp {

class MacroFlow {
 public:
  /// All must outlive the flow.
  MacroFlow(const Program& program, macro::VariableStore& variables, StepGuard& guard);

  /// Runs the statement of block `index`; the block to run next. A #3006 stop is added to
  /// `stops`.
  Result<std::size_t> run(std::size_t index, std::vector<Error>& stops);

  /// The program gained blocks (a called program read from its file): their loops and N
  /// numbers are found.
  void programGrew();
  /// A subprogram or macro starts or ends; M99 runs the program again (a repeat count): the
  /// loops it had running are abandoned.
  void enterProgram();
  void leaveProgram();
  void restartProgram() { loops_.back().clear(); }
  /// Execution jumped to block `index` of the innermost running program (a GOTO, or M99 P
  /// back in the caller): the loops it lies outside of are left.
  void cameTo(std::size_t index);

 private:
  struct RunningLoop {
    std::size_t start = 0;  // the WHILE/DO block
    std::size_t end = 0;    // its END
  };

  Status assign(const macro::Assignment& assignment, int line, const std::string& message,
                std::vector<Error>& stops);
  Result<std::size_t> jump(const macro::Jump& jump, std::size_t index);
  Result<std::size_t> loopStart(const macro::LoopStart& start, std::size_t index);
  Result<std::size_t> loopEnd(const macro::LoopEnd& end, std::size_t index);
  Result<std::size_t> partnerOf(std::size_t index) const;

  const Program& program_;
  macro::VariableStore& variables_;
  StepGuard& guard_;
  macro::LoopPairs pairs_;
  std::vector<std::vector<RunningLoop>> loops_;  // per running program, innermost loop last
};

}  // namespace lathesim::interp
