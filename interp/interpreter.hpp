#pragma once
// G-code text → Toolpath. The single entry point of the interp module.

#include <filesystem>
#include <functional>
#include <map>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "interp/base/diagnostic.hpp"
#include "interp/control/control_parameters.hpp"
#include "interp/control/dialect.hpp"
#include "interp/control/machine_limits.hpp"
#include "interp/state/step_guard.hpp"
#include "interp/base/move.hpp"
#include "interp/base/move_sink.hpp"
#include "interp/compensation/tool_offset.hpp"
#include "interp/compensation/uncompensated_nose.hpp"
#include "interp/text/control_family.hpp"
#include "interp/base/paged_text.hpp"
#include "interp/state/work_frame.hpp"

namespace lathesim::interp {

/// Moves a program may make before it is refused (InterpreterOptions::maxMoves): a million
/// blocks and their dog-leg rapids pass; nested repeats (M98 P9999… four deep) do not.
inline constexpr std::size_t kDefaultMaxMoves = 2'000'000;

/// Moves the interpreter holds before it hands them on (InterpreterOptions::moveWindow).
inline constexpr std::size_t kDefaultMoveWindow = 4096;

struct InterpreterOptions {
  RZ startPosition{100.0, 200.0};  // (radius mm, Z mm) where the tool stands at program start
  std::vector<int> toolNumbers;    // tools the setup defines; the first is mounted before any
                                   // T word. A T word naming another number is an error.
  bool mountedToolStated = true;   // the setup says which tool is mounted (it lists its tools);
                                   // false: a cut before any T word relies on an assumed tool
  std::function<std::string(int tool)> toolDefinitionHint;  // how to define a missing tool (the
                                                            // setup's TOML), for that error
  Dialect dialect = Dialect::FanucA;  // how the program writes its G codes
  ControlParameters control;          // how the control reads and runs it (control_preset.hpp);
                                      // gsk980tdi's parameters by default
  std::optional<RZ> referencePosition;  // G28's reference point (radius, Z); startPosition if unset
  std::optional<RZ> secondReferencePosition;  // G30's (radius, Z); unset: G30 is an error
  MachineLimits machine;                // max_rpm sets the rpm G97 keeps after G96
  ToolOffsets offsets;  // the setup's [[offset]] table (interp/compensation/tool_offset.hpp)
  // Each tool's insert (tool number → its nose radius and tip number): what a contour cut under
  // G40 really misses the drawing by when the offset in force gives no R (uncompensated_nose.hpp).
  std::map<int, ToolNose> toolNoses;
  WorkOffsets workOffsets = zeroWorkOffsets();  // the setup's [[work_offset]] (work_frame.hpp)
  std::vector<std::filesystem::path> programDirectories;  // where M98 finds programs the text
                                                         // lacks, in order (program_library.hpp)
  std::optional<RZ> machineZero;  // G53's zero (radius, Z) in the setup's frame; the
                                  // reference point (or the start) if unset
  long long maxSteps = kDefaultMaxSteps;  // blocks a run may run again (a block's first run is
                                         // free): ends endless loops (state/step_guard.hpp)
  std::map<int, double> macroVariables;  // common macro variables set before the run
                                         // (#100–#199, #500–#999)
  std::size_t maxMoves = kDefaultMaxMoves;  // more is an error at the block that passes it
  // The program's foreign family when its caller has looked for it already (the job reads the
  // machine's evidence in the same pass: machine_evidence.hpp), so that it is not looked for
  // again; unset: the interpreter looks.
  std::optional<std::optional<ForeignProgram>> foreignProgram;
  std::size_t moveWindow = kDefaultMoveWindow;  // moves held before they are handed on, once the
                                                // path can be cut there (execution/move_pipeline.hpp)
};

/// A block the run passed over because it opens with '/' and block delete is on.
struct SkippedBlock {
  int line = 0;
  int column = 0;
  std::string file;  // the file it is in when not the program's own (an external subprogram)
};

struct InterpretResult {
  Toolpath toolpath;
  std::vector<SkippedBlock> skippedBlocks;  // every '/' block the run reached and skipped, once each
  std::vector<Diagnostic> diagnostics;  // the error that stopped the program alone, or the
                                        // warnings and notes of a program that ran, by line
  bool ok() const;
};

/// The moves in `result.toolpath.moves`.
InterpretResult interpret(PagedText programText, const std::string& fileName,
                          const InterpreterOptions& options);

/// The moves handed to `moves` as they are made, in order, each once nothing can change it:
/// a long program never holds its whole toolpath (`result.toolpath` has everything else). A
/// program that fails may have handed on moves before its error: the consumer drops them; the
/// moves made before the error and not handed on are left in `result.toolpath.moves`, as
/// their blocks made them (what `interpret` without a sink gives after those handed on).
InterpretResult interpret(PagedText programText, const std::string& fileName,
                          const InterpreterOptions& options, MoveSink& moves);

}  // namespace lathesim::interp
