// lathesim: what a lathe program really makes.

#include <CLI/CLI.hpp>
#include <exception>
#include <iostream>
#include <string>
#include <vector>

#include "app/batch_cli.hpp"
#include "app/commands.hpp"
#include "app/interrupts.hpp"
#include "app/picture_cli.hpp"
#include "app/watch/watch_command.hpp"
#include "interp/control/control_preset.hpp"
#include "interp/control/dialect.hpp"
#include "interp/base/printable_text.hpp"
#include "setup/exit_status.hpp"
#include "setup/stock_option.hpp"

namespace {

constexpr const char* kExitStatuses =
    "Exit status: 0 done; 1 a bad program, setup, drawing or manifest, or the outputs could not be\n"
    "written (nothing is written then); 2 a bad command line; 3 check: out of tolerance, or undecided at the voxel;\n"
    "4 run, check: the program crashes (a rapid or a holder into the bar, anything into the chuck;\n"
    "the outputs are written, the crash marked; --collisions warn makes it 0);\n"
    "130 or 143 stopped by Ctrl-C or SIGTERM (nothing half-written is left).";

// A bad command line says what is wrong (with any control character in it escaped) and exits
// 2; CLI11's own statuses (105, 106, 109 …) mean nothing to a script.
std::string badCommandLine(const CLI::App* app, const CLI::Error& error) {
  std::string command = app->get_name();
  for (auto chosen = app->get_subcommands(); !chosen.empty(); chosen = chosen.front()->get_subcommands())
    command += " " + chosen.front()->get_name();
  return "lathesim: " + lathesim::interp::printable(error.what()) + "\nRun '" + command + " --help' for more.\n";
}

int lathesimMain(int argc, char** argv);

/// A batch job's command line, run in a fork of the batch (batch::ChildProcess::fork).
int runJobInProcess(const std::vector<std::string>& args) {
  std::vector<std::string> words{"lathesim"};
  words.insert(words.end(), args.begin(), args.end());
  std::vector<char*> argv;
  for (auto& word : words) argv.push_back(word.data());
  argv.push_back(nullptr);
  return lathesimMain(static_cast<int>(words.size()), argv.data());
}

// --programs and --stock: where the program's subprograms and its bar come from.
void addProgramSourceOptions(CLI::App& command, lathesim::app::RunOptions& options) {
  command.add_option("--programs", options.programDirectories,
                     "a directory of the control's programs: subprograms M98 calls that the file lacks")
      ->check(CLI::ExistingDirectory);
  command.add_option("--stock", options.stock,
                     "the bar: D<diameter>[xd<bore>]xL<length>[xZ<face>], e.g. D40xL80 or the tube D60xd40xL80 "
                     "(over the setup's)")
      ->check([](const std::string& text) {
        const auto bar = lathesim::setup::parseStockOption(text);
        const auto* problem = std::get_if<std::string>(&bar);
        if (!problem) return std::string();
        // CLI11 names the option itself; the message names it too, for the setup's callers.
        const std::string named = "--stock ";
        return problem->rfind(named, 0) == 0 ? problem->substr(named.size()) : *problem;
      });
}

// --dialect, --control, --block-skip, --max-steps and --max-moves on every command that reads
// a program (and --collisions on those that simulate), as given.
struct OverrideArguments {
  std::string dialect, control, blockSkip, collisions;
  std::optional<long long> maxSteps;
  std::optional<std::size_t> maxMoves;
};

void addOverrideOptions(CLI::App& command, OverrideArguments& args, bool simulates) {
  std::vector<std::string> dialects;
  for (auto dialect : lathesim::interp::kDialects) dialects.emplace_back(lathesim::interp::dialectName(dialect));
  std::vector<std::string> presets;
  for (auto preset : lathesim::interp::controlPresets()) presets.emplace_back(preset);
  command.add_option("--dialect", args.dialect, "how the program writes its codes (overrides [machine] dialect; neither given: read from the program)")
      ->check(CLI::IsMember(dialects));
  command.add_option("--control", args.control, "the control preset (overrides [control] name; neither given: read from the program)")
      ->check(CLI::IsMember(presets));
  command.add_option("--block-skip", args.blockSkip, "the block skip switch: '/' blocks skipped (on) or run (off)")
      ->check(CLI::IsMember({"on", "off"}));
  if (simulates)
    command.add_option("--collisions", args.collisions,
                       "a collision fails the run with exit status 4 (error, the default) or is only printed "
                       "(warn) (overrides [sim] collisions)")
        ->check(CLI::IsMember({"error", "warn"}));
  command.add_option("--max-steps", args.maxSteps,
                     "blocks the program may run again before it is stopped as an endless loop (overrides "
                     "[macro] max_steps)")
      ->check(CLI::PositiveNumber);
  command.add_option("--max-moves", args.maxMoves,
                     "moves the program may make before it is refused (overrides [sim] max_moves; default " +
                         std::to_string(lathesim::interp::kDefaultMaxMoves) + ")")
      ->check(CLI::PositiveNumber);
}

lathesim::setup::SetupOverrides overridesOf(const OverrideArguments& args) {
  lathesim::setup::SetupOverrides overrides;
  if (!args.dialect.empty()) overrides.dialect = lathesim::interp::dialectNamed(args.dialect);
  if (!args.control.empty()) overrides.controlPreset = args.control;
  if (!args.blockSkip.empty()) overrides.blockSkip = args.blockSkip == "on";
  if (!args.collisions.empty()) overrides.collisionsWarn = args.collisions == "warn";
  overrides.maxSteps = args.maxSteps;
  overrides.maxMoves = args.maxMoves;
  return overrides;
}

int lathesimMain(int argc, char** argv) {
  CLI::App cli{"lathesim — simulates a lathe program on a bar and shows the part it makes", "lathesim"};
  cli.require_subcommand(1);
  cli.set_version_flag("--version", "lathesim " LATHESIM_VERSION);
  cli.failure_message(badCommandLine);
  cli.footer(kExitStatuses);

  lathesim::app::RunOptions run;
  std::string runSetup;
  auto* runCmd = cli.add_subcommand("run", "simulate a program: STL, PNG, toolpath, stock.vdb and report.json");
  runCmd->add_option("program", run.program, "the G-code program")->required()->check(CLI::ExistingFile);
  runCmd->add_option("--setup", runSetup, "setup file (TOML): stock, machine, tools")->check(CLI::ExistingFile);
  runCmd->add_option("--out", run.out, "output folder")->capture_default_str();
  runCmd->add_option("--voxel", run.voxelMm, "voxel size in mm (overrides [sim] voxel)")
      ->check(CLI::PositiveNumber);  // and with the stock, for the memory it needs
  runCmd->add_option("--at-line", run.atLine, "simulate only up to the moves of this source line; show the part then")
      ->check(CLI::PositiveNumber);
  runCmd->footer(
      "Example:\n  lathesim run parts/seed000-face-taper/program.nc --setup parts/seed000-face-taper/setup.toml "
      "--out out/seed000\nwrites part.stl, part.png, toolpath.csv, toolpath.vtp, stock.vdb and report.json into out/seed000/.\n" +
      std::string(kExitStatuses));

  lathesim::app::CheckOptions check;
  std::string checkSetup;
  auto* checkCmd = cli.add_subcommand(
      "check", "simulate a program and measure the part against its drawing; exit 3 if out of tolerance");
  checkCmd->add_option("program", check.run.program, "the G-code program")->required()->check(CLI::ExistingFile);
  checkCmd->add_option("--setup", checkSetup, "setup file (TOML): stock, machine, tools")->check(CLI::ExistingFile);
  auto* checkTarget = checkCmd->add_option("--target", check.drawing, "the drawing: a profile (.toml) or an STL of the design (.stl)")
                          ->check(CLI::ExistingFile);
  checkCmd->add_option("--target-program", check.targetProgram, "a program whose part is the drawing (same setup)")
      ->check(CLI::ExistingFile)
      ->excludes(checkTarget);
  checkCmd->add_option("--tol", check.toleranceMm,
                       "tolerance ± in mm, normal to the surface, wherever the drawing states none (default: the general tolerance)")
      ->check(CLI::NonNegativeNumber);
  std::string checkGeneral;
  checkCmd->add_option("--general-tolerance", checkGeneral,
                       "ISO 2768-1 class for sizes the drawing gives no tolerance: f, m, c or v (default: the drawing's "
                       "general_tolerance, else m)")
      ->check(CLI::IsMember({"f", "m", "c", "v"}));
  checkCmd->add_option("--out", check.run.out, "output folder")->capture_default_str();
  checkCmd->add_option("--voxel", check.run.voxelMm, "voxel size in mm (overrides [sim] voxel)")->check(CLI::PositiveNumber);
  checkCmd->footer(
      "Example:\n  lathesim check parts/seed001-taper-r20/program.nc --setup parts/seed001-taper-r20/setup.toml "
      "--target parts/seed001-taper-r20/drawing.toml --tol 0.1\nprints the largest excess and gouge and exits 3 when "
      "the part is out of tolerance (this one is: R-20 leaves a wrong taper).\n" +
      std::string(kExitStatuses));

  lathesim::app::RunOptions expand;
  std::string expandSetup;
  auto* expandCmd = cli.add_subcommand("expand", "print the toolpath as CSV; simulates nothing");
  expandCmd->add_option("program", expand.program, "the G-code program")->required()->check(CLI::ExistingFile);
  expandCmd->footer(
      "Example:\n  lathesim expand parts/g71-g70-shaft/program.nc --setup parts/g71-g70-shaft/setup.toml > toolpath.csv\n"
      "one row per move: line,kind,x0,z0,x1,z1,feed,xc,zc,time_s (X as a diameter).\n" +
      std::string(kExitStatuses));
  for (auto [command, options] : {std::pair{runCmd, &run}, {checkCmd, &check.run}, {expandCmd, &expand}})
    addProgramSourceOptions(*command, *options);
  expandCmd->add_option("--setup", expandSetup, "setup file (TOML)")->check(CLI::ExistingFile);
  lathesim::app::addPictureOptions(*runCmd, run);
  lathesim::app::addPictureOptions(*checkCmd, check.run);

  OverrideArguments runArgs, checkArgs, expandArgs;
  for (auto [command, args] : {std::pair{runCmd, &runArgs}, {checkCmd, &checkArgs}, {expandCmd, &expandArgs}})
    addOverrideOptions(*command, *args, command != expandCmd);

  lathesim::app::WatchOptions watch;
  auto* watchCmd = cli.add_subcommand(
      "watch", "run a program again whenever it (or its setup or drawing) is saved; report.html follows on 127.0.0.1");
  watchCmd->add_option("--port", watch.port, "the port on 127.0.0.1 (default 0: a free one, printed)")
      ->check(CLI::Range(0, 65535));
  watchCmd->allow_extras();  // run's options, or check's with --target: handed to each run as given
  watchCmd->footer(
      "Example:\n  lathesim watch parts/g71-g70-shaft/program.nc --setup parts/g71-g70-shaft/setup.toml --out out/shaft\n"
      "prints the page's address; open it, edit and save the program, and the page shows the new part\n"
      "(or the error, above the last good part). Each run is `lathesim run` with these options\n"
      "(`lathesim check` when --target or --target-program is given). Ctrl-C stops it (exit 130).");

  lathesim::app::BatchCli batch(cli, runJobInProcess);

  try {
    cli.parse(argc, argv);
  } catch (const CLI::Success& e) {  // --help, --version
    return cli.exit(e);
  } catch (const CLI::ParseError& e) {
    const bool unknownCommand = argc > 1 && argv[1][0] != '-' && cli.get_subcommands().empty();
    if (unknownCommand)  // CLI11 would only say that a subcommand is required
      std::cerr << "lathesim: unknown command '" << lathesim::interp::printable(argv[1])
                << "': expected run, check, expand, watch or batch\nRun 'lathesim --help' for more.\n";
    else
      cli.exit(e);
    return lathesim::setup::kExitBadCommandLine;
  }
  const auto optionalPath = [](const std::string& s) {
    return s.empty() ? std::nullopt : std::optional<std::filesystem::path>(s);
  };
  try {
    if (batch.chosen()) return batch.run();  // it stops its jobs on a signal itself
    if (*watchCmd) {  // its runs are processes of their own, each cleaning up after itself
      watch.arguments = watchCmd->remaining();
      if (watch.arguments.empty()) {
        std::cerr << "lathesim watch: give the program, and run's options (see lathesim watch --help)\n";
        return lathesim::setup::kExitBadCommandLine;
      }
      return lathesim::app::watchCommand(watch);
    }
    lathesim::app::removeOutputsOnInterrupt();
    if (*runCmd) {
      run.setup = optionalPath(runSetup);
      run.overrides = overridesOf(runArgs);
      return lathesim::app::runCommand(run);
    }
    if (*checkCmd) {
      if (!check.drawing && !check.targetProgram) {
        std::cerr << "lathesim check: give the drawing with --target or --target-program (see lathesim check --help)\n";
        return lathesim::setup::kExitBadCommandLine;
      }
      check.run.setup = optionalPath(checkSetup);
      if (!checkGeneral.empty()) check.generalTolerance = checkGeneral[0];
      check.run.overrides = overridesOf(checkArgs);
      return lathesim::app::checkCommand(check);
    }
    expand.setup = optionalPath(expandSetup);
    expand.overrides = overridesOf(expandArgs);
    return lathesim::app::expandCommand(lathesim::app::jobRequestOf(expand));
  } catch (const std::exception& e) {  // outputs that cannot be written, broken invariants
    std::cerr << "lathesim: error: " << lathesim::interp::printable(e.what()) << '\n';
    return lathesim::setup::kExitBadInput;
  }
}

}  // namespace

int main(int argc, char** argv) { return lathesimMain(argc, argv); }
