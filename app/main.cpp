// lathesim: what a lathe program really makes.

#include <CLI/CLI.hpp>
#include <exception>
#include <iostream>

#include "app/batch_cli.hpp"
#include "app/commands.hpp"
#include "app/picture_cli.hpp"
#include "interp/control/control_preset.hpp"
#include "interp/control/dialect.hpp"

int main(int argc, char** argv) {
  CLI::App cli{"lathesim — simulates a lathe program on a bar and shows the part it makes"};
  cli.require_subcommand(1);

  lathesim::app::RunOptions run;
  std::string runSetup;
  auto* runCmd = cli.add_subcommand("run", "simulate a program: STL, PNG, toolpath, stock.vdb and report.json");
  runCmd->add_option("program", run.program, "the G-code program")->required()->check(CLI::ExistingFile);
  runCmd->add_option("--setup", runSetup, "setup file (TOML): stock, machine, tools");
  runCmd->add_option("--out", run.out, "output folder")->capture_default_str();
  runCmd->add_option("--voxel", run.voxelMm, "voxel size in mm (overrides [sim] voxel)");  // checked with the stock
  runCmd->add_option("--at-line", run.atLine, "simulate only up to the moves of this source line; show the part then");

  lathesim::app::CheckOptions check;
  std::string checkSetup;
  auto* checkCmd = cli.add_subcommand(
      "check", "simulate a program and measure the part against its drawing; exit 3 if out of tolerance");
  checkCmd->add_option("program", check.run.program, "the G-code program")->required()->check(CLI::ExistingFile);
  checkCmd->add_option("--setup", checkSetup, "setup file (TOML): stock, machine, tools");
  auto* checkTarget = checkCmd->add_option("--target", check.drawing, "the drawing: a profile (.toml) or an STL of the design (.stl)")
                          ->check(CLI::ExistingFile);
  checkCmd->add_option("--target-program", check.targetProgram, "a program whose part is the drawing (same setup)")
      ->check(CLI::ExistingFile)
      ->excludes(checkTarget);
  checkCmd->add_option("--tol", check.toleranceMm, "tolerance in mm (default: two voxels)");
  checkCmd->add_option("--out", check.run.out, "output folder")->capture_default_str();
  checkCmd->add_option("--voxel", check.run.voxelMm, "voxel size in mm (overrides [sim] voxel)");

  lathesim::app::RunOptions expand;
  std::string expandSetup;
  auto* expandCmd = cli.add_subcommand("expand", "print the toolpath as CSV; simulates nothing");
  expandCmd->add_option("program", expand.program, "the G-code program")->required()->check(CLI::ExistingFile);
  for (auto* command : {runCmd, checkCmd, expandCmd}) {
    auto& directories = command == runCmd ? run.programDirectories
                        : command == checkCmd ? check.run.programDirectories
                                              : expand.programDirectories;
    command->add_option("--programs", directories,
                        "a directory of the control's programs: subprograms M98 calls that the file lacks")
        ->check(CLI::ExistingDirectory);
    auto& stock = command == runCmd ? run.stock : command == checkCmd ? check.run.stock : expand.stock;
    command->add_option("--stock", stock,
                        "the bar: D<diameter>[xd<bore>]xL<length>[xZ<face>], e.g. D40xL80 or the tube D60xd40xL80 "
                        "(over the setup's)");
  }
  expandCmd->add_option("--setup", expandSetup, "setup file (TOML)");
  lathesim::app::addPictureOptions(*runCmd, run);
  lathesim::app::addPictureOptions(*checkCmd, check.run);

  // --dialect, --control, --block-skip and --max-steps on every command that reads a program.
  struct OverrideArguments {
    std::string dialect, control, blockSkip;
    std::optional<long long> maxSteps;
  };
  OverrideArguments runArgs, checkArgs, expandArgs;
  std::vector<std::string> dialects;
  for (auto dialect : lathesim::interp::kDialects) dialects.emplace_back(lathesim::interp::dialectName(dialect));
  std::vector<std::string> presets;
  for (auto preset : lathesim::interp::controlPresets()) presets.emplace_back(preset);
  for (auto [command, args] : {std::pair{runCmd, &runArgs}, {checkCmd, &checkArgs}, {expandCmd, &expandArgs}}) {
    command->add_option("--dialect", args->dialect, "how the program writes its codes (overrides [machine] dialect)")
        ->check(CLI::IsMember(dialects));
    command->add_option("--control", args->control, "the control preset (overrides [control] name)")
        ->check(CLI::IsMember(presets));
    command->add_option("--block-skip", args->blockSkip, "the block skip switch: '/' blocks skipped (on) or run (off)")
        ->check(CLI::IsMember({"on", "off"}));
    command->add_option("--max-steps", args->maxSteps,
                        "blocks the program may run again before it is stopped as an endless loop (overrides "
                        "[macro] max_steps)")
        ->check(CLI::PositiveNumber);
  }

  lathesim::app::BatchCli batch(cli);

  CLI11_PARSE(cli, argc, argv);
  const auto overridesOf = [](const OverrideArguments& args) {
    lathesim::job::SetupOverrides overrides;
    if (!args.dialect.empty()) overrides.dialect = lathesim::interp::dialectNamed(args.dialect);
    if (!args.control.empty()) overrides.controlPreset = args.control;
    if (!args.blockSkip.empty()) overrides.blockSkip = args.blockSkip == "on";
    overrides.maxSteps = args.maxSteps;
    return overrides;
  };
  const auto optionalPath = [](const std::string& s) {
    return s.empty() ? std::nullopt : std::optional<std::filesystem::path>(s);
  };
  try {
    if (batch.chosen()) return batch.run();
    if (*runCmd) {
      run.setup = optionalPath(runSetup);
      run.overrides = overridesOf(runArgs);
      return lathesim::app::runCommand(run);
    }
    if (*checkCmd) {
      if (!check.drawing && !check.targetProgram) {
        std::cerr << "lathesim check: give the drawing with --target or --target-program\n";
        return 1;
      }
      check.run.setup = optionalPath(checkSetup);
      check.run.overrides = overridesOf(checkArgs);
      return lathesim::app::checkCommand(check);
    }
    expand.setup = optionalPath(expandSetup);
    expand.overrides = overridesOf(expandArgs);
    return lathesim::app::expandCommand(lathesim::app::jobRequestOf(expand));
  } catch (const std::exception& e) {  // I/O failures and broken invariants
    std::cerr << "lathesim: error: " << e.what() << '\n';
    return 1;
  }
}
