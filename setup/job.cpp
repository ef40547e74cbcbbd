#include "setup/job.hpp"

#include <algorithm>
#include <system_error>

#include <fmt/format.h>

#include "interp/text/tool_word.hpp"
#include "interp/motion/cycle_time.hpp"
#include "interp/text/program.hpp"
#include "setup/comment_tools.hpp"
#include "setup/stock_option.hpp"
#include "interp/interpreter.hpp"
#include "setup/control_setup.hpp"

namespace lathesim::setup {
namespace {

// An error of the command line's, said as "lathesim: error: …".
interp::Diagnostic commandLineError(std::string message) {
  return {interp::Severity::Error, "lathesim", 0, 0, std::move(message), {}};
}

bool hasError(const std::vector<interp::Diagnostic>& diagnostics) {
  for (const auto& d : diagnostics)
    if (d.severity == interp::Severity::Error) return true;
  return false;
}

// The TOML that defines tool `number`, for the error of a T word nothing defines.
std::string toolDefinitionHint(int number) {
  return fmt::format(
      "  [[tool]]\n  number = {}\n  insert = \"CNMG120408\"    # or kind = \"groove\", width = 3.0, depth = 15.0\n"
      "  holder = \"PCLNR2525M12\"  # (see the README's setup file)",
      number);
}

// The program read through for the interpreter (interp/text/program.hpp), and on the way the T
// words no setup defines mounted from what their blocks' comments name (comment_tools.hpp): the
// program is lexed once for both.
void readProgramMountingTools(Job& job, const std::string& programName, Diagnostics& said) {
  Setup& setup = job.setup;
  std::vector<int> mounted;
  const auto mountFrom = [&](const interp::ReadBlock& read) {  // a block with a T word and comments
    const interp::ProgramBlock& block = read.block;
    const interp::Word t = read.words->words.at('T');
    // Beside M06 a short T word is the tool, as the interpreter reads it (trainers' M06 T02).
    const bool besideToolChange = read.words->mCode(interp::MGroup::ToolChange).has_value();
    const auto toolWord = interp::readToolWord(t, setup.control.parameters.toolWordForms, block.line, besideToolChange);
    if (!toolWord.ok() || toolWord.value().tool == 0) return;  // the interpreter reports a bad T word
    const int number = toolWord.value().tool;
    const bool defined = std::any_of(setup.tools.begin(), setup.tools.end(), [&](const ToolDefinition& tool) {
      return tool.number == number && (setup.toolsGiven || number != 1);
    });
    if (defined || std::find(mounted.begin(), mounted.end(), number) != mounted.end()) return;
    std::vector<std::string> comments = read.comments.own;
    comments.insert(comments.end(), read.comments.above.begin(), read.comments.above.end());
    for (const std::string& comment : comments) {
      auto named = toolNamedIn(comment, number, setup.stock.diameterMm);
      if (!named) continue;
      named->tool.facts.source = fmt::format("the comment '({})' of the T word at {}:{}", comment, programName, block.line);
      std::erase_if(setup.tools, [&](const ToolDefinition& tool) { return tool.number == number; });
      setup.tools.push_back(std::move(named->tool));
      mounted.push_back(number);
      std::string message = fmt::format("tool {} is mounted from the comment '({})': {}; no setup defines it",
                                        number, comment, named->description);
      for (const std::string& w : named->warnings) message += "; " + w;
      job.warnings.push_back({interp::Severity::Warning, programName, block.line, t.column, message,
                              interp::lineOf(job.programText.text(), block.line)});
      said.push_back(job.warnings.back());
      return;
    }
  };
  job.program = interp::readProgram(job.programText.text(), setup.control.parameters.blockSkip, setup.dialect,
                                    setup.control.parameters.machineMCodes, mountFrom);
}

// The program's evidence read, and the dialect and control not stated chosen from it
// (interp/text/machine_choice.hpp); the setup's [control] keys kept over a chosen preset.
void chooseMachineOf(Job& job, Diagnostics& said) {
  Setup& setup = job.setup;
  job.evidence = interp::readMachineEvidence(job.programText.text());
  interp::MachineStatement stated;
  if (!setup.dialectBy.empty()) stated = {setup.dialect, setup.dialectBy, {}, {}};
  if (!setup.controlBy.empty()) {
    stated.control = setup.control.preset;
    stated.controlBy = setup.controlBy;
  }
  job.machine = interp::chooseMachine(job.evidence, stated);
  setup.dialect = job.machine.dialect;
  if (job.machine.control != setup.control.preset) setup.control = *withPreset(setup.control, job.machine.control);
  for (const interp::Error& w : job.machine.warnings) {
    job.warnings.push_back(job.warningAt(w.line, w.column, w.message));
    said.push_back(job.warnings.back());
  }
}

// The program's evidence added to an error whose cure is a dialect: "(seen: G95 at line 11, …)";
// and a length without a decimal point that a least-increment control read small, on the line
// of a contour error or the block before it, shown as it was read.
std::string withCure(const Job& job, const interp::Diagnostic& error, const std::string& programName) {
  std::string message = error.message;
  for (interp::Dialect dialect : interp::kDialects) {
    if (message.find(fmt::format("--dialect {}", interp::dialectName(dialect))) == std::string::npos) continue;
    std::string seen;
    for (interp::EvidenceKind kind : {interp::EvidenceKind::SystemA, interp::EvidenceKind::SystemB,
                                      interp::EvidenceKind::Hnc, interp::EvidenceKind::Haas}) {
      const auto admitted = interp::dialectsAdmitting(kind);
      if (std::find(admitted.begin(), admitted.end(), dialect) == admitted.end()) continue;
      for (const interp::EvidenceMark& m : job.evidence.of(kind)) seen += (seen.empty() ? "" : ", ") + interp::markText(m);
    }
    if (!seen.empty()) message += " (seen: " + seen + ")";
    break;
  }
  const interp::ControlParameters& control = job.setup.control.parameters;
  const bool contour = message.find("monotonic") != std::string::npos || message.find("contour") != std::string::npos;
  if (contour && control.decimalPointInput == interp::DecimalPointInput::LeastIncrements && error.line > 0 &&
      error.file == programName) {
    if (!job.programLines) job.programLines.emplace(job.programText.text());
    const std::string_view text = job.programText.text().view();
    for (int line = error.line; line >= std::max(1, error.line - 1); --line) {
      const auto bare = interp::bareLengthsIn(job.programLines->lineOf(text, line), line);
      if (bare.empty()) continue;
      const interp::LengthWord& w = bare.front();
      const bool corners = job.evidence.count(interp::EvidenceKind::FanucCorner) > 0;
      message += fmt::format("; {} at line {} is {:g} mm under {}: no decimal point; write {}. or {}", w.text, w.line,
                             w.value * control.leastIncrementMm, job.setup.control.preset, w.text,
                             corners ? "set decimal_point_input = \"calculator\" in the setup's [control]"
                                     : "use --control gsk980tdi");
      break;
    }
  }
  return message;
}

// Each move timed (interp/motion/cycle_time.hpp) on its way to the consumer.
class TimedMoves final : public interp::MoveSink {
 public:
  TimedMoves(const interp::MachineLimits& machine, interp::MoveSink& next) : timer_(machine), next_(next) {}
  void take(interp::Move move) override {
    timer_.time(move);
    next_.take(std::move(move));
  }
  void recordingIn(const interp::Toolpath& toolpath) override { next_.recordingIn(toolpath); }
  const std::vector<interp::Error>& warnings() const { return timer_.warnings(); }

 private:
  interp::MoveTimer timer_;
  interp::MoveSink& next_;
};

}  // namespace

interp::InterpreterOptions interpreterOptionsOf(const Setup& setup) {
  interp::InterpreterOptions options;
  options.startPosition = setup.startPosition;
  options.referencePosition = setup.referencePosition;
  options.machine = setup.machine;
  options.machine.travel = travelOf(setup);
  options.dialect = setup.dialect;
  options.control = setup.control.parameters;
  options.offsets = setup.offsets;
  options.workOffsets = setup.workOffsets;
  options.machineZero = setup.machineZero;
  options.secondReferencePosition = setup.secondReferencePosition;
  options.maxSteps = setup.macro.maxSteps;
  options.macroVariables = setup.macro.variables;
  options.maxMoves = setup.maxMoves;
  for (const auto& tool : setup.tools) {
    options.toolNumbers.push_back(tool.number);
    options.toolNoses[tool.number] = {tool.noseRadiusMm, tool.tipNumber};
  }
  options.mountedToolStated = setup.toolsGiven;
  return options;
}

interp::Diagnostic Job::warningAt(int line, int column, std::string message, int source) const {
  return diagnosticAt(interp::Severity::Warning, line, column, std::move(message), source);
}

interp::Diagnostic Job::diagnosticAt(interp::Severity severity, int line, int column, std::string message,
                                     int source) const {
  if (source != 0) {  // a subprogram's file: read again for the one line quoted
    std::string quoted;
    try {
      quoted = interp::lineOf(interp::FileText::read(toolpath.fileOf(source)).text(), line);
    } catch (const std::system_error&) {  // gone since it ran: the message still names its place
    }
    const std::string calls = toolpath.calledFrom(source);
    if (!calls.empty()) message += " (" + calls + ")";
    return {severity, toolpath.fileOf(source), line, column, std::move(message), std::move(quoted)};
  }
  if (!programLines) programLines.emplace(programText.text());
  return {severity, toolpath.programName, line, column, std::move(message),
          programLines->lineOf(programText.text().view(), line)};
}

Reported<std::optional<Setup>> overridden(Setup setup, const SetupOverrides& overrides) {
  if (overrides.dialect) {
    setup.dialect = *overrides.dialect;
    setup.dialectBy = "--dialect";
  }
  if (overrides.controlPreset) {
    std::optional<interp::Control> chosen = withPreset(setup.control, *overrides.controlPreset);
    if (!chosen) {
      std::string names;
      for (std::string_view n : interp::controlPresets()) names += (names.empty() ? "" : ", ") + std::string(n);
      return {std::nullopt, {commandLineError("--control " + *overrides.controlPreset +
                                              ": no such control preset (expected " + names + ")")}};
    }
    setup.control = std::move(*chosen);
    setup.controlBy = "--control";
  }
  if (overrides.maxMoves) setup.maxMoves = *overrides.maxMoves;
  if (overrides.blockSkip)
    (void)setup.control.set("block_skip", std::string(*overrides.blockSkip ? "on" : "off"), "command line");
  if (overrides.maxSteps) setup.macro.maxSteps = *overrides.maxSteps;
  if (overrides.collisionsWarn) setup.collisionsWarn = *overrides.collisionsWarn;
  return {std::move(setup), {}};
}

Reported<std::optional<Job>> loadJob(const JobRequest& request) {
  std::vector<interp::Move> moves;
  interp::MoveCollector collector(moves);
  Reported<std::optional<Job>> job = loadJob(request, collector);
  if (job.value) job.value->toolpath.moves = std::move(moves);
  return job;
}

Reported<std::optional<Job>> loadJob(const JobRequest& request, interp::MoveSink& moves) {
  Reported<std::optional<Job>> job = openJob(request);
  if (!job.value) return job;
  Reported<bool> interpreted = interpretJob(*job.value, request, moves);
  job.diagnostics.insert(job.diagnostics.end(), interpreted.diagnostics.begin(), interpreted.diagnostics.end());
  if (!interpreted.value) job.value.reset();
  return job;
}

Reported<std::optional<Job>> openJob(const JobRequest& request) {
  Reported<std::optional<Job>> opened{std::nullopt, {}};
  Diagnostics& said = opened.diagnostics;
  const std::filesystem::path& program = request.program;
  const std::optional<std::filesystem::path>& setupFile = request.setup;
  Job job{defaultSetup(), {}, {}, {}, {}, {}, {}, {}, {}, {}};
  if (setupFile) {
    SetupResult loaded = loadSetup(*setupFile);
    said = loaded.diagnostics;
    if (!loaded.setup || hasError(loaded.diagnostics)) return opened;
    job.setup = std::move(*loaded.setup);
    job.warnings = std::move(loaded.diagnostics);  // what is left are warnings (e.g. an insert that
                                                   // does not match its holder's seat)
  }
  Reported<std::optional<Setup>> setup = overridden(std::move(job.setup), request.overrides);
  said.insert(said.end(), setup.diagnostics.begin(), setup.diagnostics.end());
  if (!setup.value) return opened;
  job.setup = std::move(*setup.value);

  try {
    job.programText = interp::FileText::read(program);
  } catch (const std::system_error& error) {
    said.push_back({interp::Severity::Error, program.string(), 0, 0,
                    "cannot read the program file (" + error.code().message() + ")", {}});
    return opened;
  }
  job.toolpath.programName = program.string();  // the name warningAt locates warnings in
  chooseMachineOf(job, said);
  if (request.stock) {
    auto stock = parseStockOption(*request.stock);
    if (const auto* problem = std::get_if<std::string>(&stock)) {
      said.push_back(commandLineError(*problem));
      return opened;
    }
    job.setup.stock = std::get<sim::StockSpec>(stock);
    job.setup.stockGiven = true;
    job.setup.stockFaceGiven = stockOptionStatesFace(*request.stock);
    job.setup.sourceName += " with --stock " + *request.stock;
    job.setup.stockBy = "--stock " + *request.stock;
  } else if (!job.setup.stockGiven) {
    if (const auto& stated = job.evidence.stock) {  // found in the evidence's walk of the lines
      job.setup.stock = sim::StockSpec{stated->diameterMm, stated->lengthMm, 0.0};
      job.setup.stockGiven = true;  // by the program: its face at Z0 stays an assumption
      job.setup.stockBy = fmt::format("the program at {}:{}: {}", program.string(), stated->line, stated->text);
      job.notes.push_back({interp::Severity::Note, program.string(), stated->line, stated->column,
                           fmt::format("the bar is Φ{:g} × {:g}, its face at Z0, as the program states it: "
                                       "{} (no setup gives the stock)",
                                       stated->diameterMm, stated->lengthMm, stated->text),
                           interp::lineOf(job.programText.text(), stated->line)});
      said.push_back(job.notes.back());
    }
  }
  for (const interp::Error& w : interp::lengthWarnings(job.evidence, job.setup.control.parameters,
                                                      job.setup.control.preset, job.setup.stock.diameterMm)) {
    job.warnings.push_back(job.warningAt(w.line, w.column, w.message));
    said.push_back(job.warnings.back());
  }
  readProgramMountingTools(job, program.string(), said);
  opened.value = std::move(job);
  return opened;
}

Reported<bool> interpretJob(Job& job, const JobRequest& request, interp::MoveSink& moves) {
  const std::filesystem::path& program = request.program;
  interp::InterpreterOptions options = interpreterOptionsOf(job.setup);
  options.toolDefinitionHint = toolDefinitionHint;
  options.programDirectories = request.programDirectories;
  options.programDirectories.push_back(program.parent_path().empty() ? std::filesystem::path(".") : program.parent_path());
  TimedMoves timed(job.setup.machine, moves);
  options.foreignProgram.emplace(job.evidence.foreign);  // looked for in the evidence's pass
  interp::InterpretResult result = interp::interpret(std::move(job.program).value(), program.string(), options, timed);
  job.program.reset();  // what is left of it after the run
  for (interp::Diagnostic& d : result.diagnostics)
    if (d.severity == interp::Severity::Error) d.message = withCure(job, d, program.string());
  Reported<bool> interpreted{result.ok(), result.diagnostics};
  if (!result.ok()) return interpreted;
  for (auto& d : result.diagnostics)
    if (d.severity == interp::Severity::Warning) job.warnings.push_back(std::move(d));
    else if (d.severity == interp::Severity::Note) job.notes.push_back(std::move(d));
  job.toolpath = std::move(result.toolpath);
  job.skippedBlocks = std::move(result.skippedBlocks);
  for (const interp::Error& w : timed.warnings()) {
    job.warnings.push_back(job.warningAt(w.line, w.column, w.message));
    interpreted.diagnostics.push_back(job.warnings.back());
  }
  return interpreted;
}

}  // namespace lathesim::setup
