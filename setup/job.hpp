#pragma once
// What every command starts from: the setup read, the program interpreted. Nothing is printed
// here: each step returns what it found to say (errors, warnings, notes) in the order it found
// it, for the caller to print; a job with errors is not returned.

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "setup/setup.hpp"
#include "interp/control/dialect.hpp"
#include "interp/text/machine_choice.hpp"
#include "interp/interpreter.hpp"
#include "interp/text/machine_evidence.hpp"
#include "interp/base/move.hpp"
#include "interp/base/move_sink.hpp"
#include "interp/text/file_text.hpp"
#include "interp/text/program.hpp"

namespace lathesim::setup {

using Diagnostics = std::vector<interp::Diagnostic>;

/// A step's result and what the step said, in order: an error of the command line's (an
/// unknown --control, a bad --stock) has the file "lathesim" and no line.
template <class T>
struct Reported {
  T value;
  Diagnostics diagnostics;
};

struct Job {
  Setup setup;
  interp::Toolpath toolpath;  // every move's timeS filled in; no moves when loadJob handed them on
  std::vector<interp::SkippedBlock> skippedBlocks;  // the '/' blocks the run passed over
  std::vector<interp::Diagnostic> warnings;
  std::vector<interp::Diagnostic> notes;  // what was read differently from the text, said once
  interp::FileText programText;  // read where it lies, not held (file_text.hpp)
  interp::MachineEvidence evidence;  // what the program says of its machine, read once
  interp::MachineChoice machine;     // the dialect and control it is run on, and why
  // Of programText, found by the first warningAt (8 B a line, not held while the interpreter
  // reads a long program unless a warning needs it): a warning per block stays linear.
  mutable std::optional<interp::LineStarts> programLines;
  // programText read through by openJob (its blocks counted, its labels placed), for
  // interpretJob to run without reading it again; gone once it has run.
  std::optional<interp::Program> program;

  /// A warning located in the program, ready to print and report: in the program's own text,
  /// or in the subprogram file toolpath.sources names for `source` (Move::source), with the
  /// calls that led there ("… (called from main.nc:14)").
  interp::Diagnostic warningAt(int line, int column, std::string message, int source = 0) const;
  /// The same with any severity: an error found after the program ran (a collision).
  interp::Diagnostic diagnosticAt(interp::Severity severity, int line, int column, std::string message,
                                  int source = 0) const;
};

/// What the interpreter needs to know of the setup: start, reference, machine, dialect, tools.
interp::InterpreterOptions interpreterOptionsOf(const Setup& setup);

/// What the command line overrides in the setup.
struct SetupOverrides {
  std::optional<interp::Dialect> dialect;    // --dialect: [machine] dialect
  std::optional<std::string> controlPreset;  // --control: the preset; the setup's [control] keys still apply
  std::optional<bool> blockSkip;             // --block-skip on|off: control.block_skip
  std::optional<long long> maxSteps;         // --max-steps: [macro] max_steps
  std::optional<std::size_t> maxMoves;       // --max-moves: [sim] max_moves
  std::optional<bool> collisionsWarn;        // --collisions warn|error: [sim] collisions
};

/// The setup with the command line's overrides; nullopt (and the error) for an unknown preset.
Reported<std::optional<Setup>> overridden(Setup setup, const SetupOverrides& overrides);

/// What a command names: the program, and what the command line says of the setup.
struct JobRequest {
  std::filesystem::path program;
  std::optional<std::filesystem::path> setup;
  SetupOverrides overrides;  // --dialect, --control, --block-skip, --max-steps
  std::vector<std::filesystem::path> programDirectories;  // --programs: subprograms the program
                                                          // lacks, looked for before its own directory
  std::optional<std::string> stock;  // --stock D40xL80: the bar, over the setup's and the program's
};

/// The bar comes from --stock, else the setup's [stock], else the program's own statement
/// (interp/text/stated_stock.hpp: a billet line or a stock comment, face at Z0, with a note),
/// else the default setup's.
Reported<std::optional<Job>> loadJob(const JobRequest& request);

/// The same, the moves timed and handed to `moves` as the program makes them (the job's
/// toolpath has no moves): a long program is never held whole. A job with errors may have
/// handed on moves before its error: the consumer drops them.
Reported<std::optional<Job>> loadJob(const JobRequest& request, interp::MoveSink& moves);

/// loadJob's first step: the setup read (with the command line's overrides, the bar and the
/// tools the program's comments name) and the program opened, not yet interpreted; for a
/// consumer of the moves that needs the setup before the first move (a simulation's stock).
Reported<std::optional<Job>> openJob(const JobRequest& request);

/// loadJob's second step: the opened job's program interpreted, the moves timed and handed
/// to `moves`; false (with the errors) for a program with errors.
Reported<bool> interpretJob(Job& job, const JobRequest& request, interp::MoveSink& moves);

}  // namespace lathesim::setup
