#include "app/batch_cli.hpp"

#include <functional>
#include <iostream>
#include <memory>

#include "app/commands.hpp"
#include "batch/merge.hpp"
#include "batch/shard.hpp"
#include "batch/summary.hpp"
#include "interp/base/printable_text.hpp"
#include "setup/exit_status.hpp"
#include "render/drawing_libraries.hpp"
#include "render/offscreen_display.hpp"

namespace lathesim::app {

namespace {

// The batch's jobs draw: one display for all of them (they inherit DISPLAY), and the libraries
// drawing loads learnt and loaded into the batch while its first jobs run, for its forks.
batch::JobPreparation drawingPreparation() {
  batch::JobPreparation preparation;
  preparation.beforeJobs = [] { render::ensureDisplay(); };
  preparation.forForks = [] {
    auto preload = std::make_shared<render::DrawingLibrariesPreload>();
    return std::function<bool()>([preload] { return preload->loadIfDone().has_value(); });
  };
  return preparation;
}

}  // namespace

BatchCli::BatchCli(CLI::App& cli, batch::InProcessMain jobMain) {
  options_.jobMain = std::move(jobMain);
  options_.preparation = drawingPreparation();
  command_ = cli.add_subcommand("batch", "simulate many programs, each in its own folder, and summarise them");
  command_->add_option("source", source_, "a manifest (.toml or .csv) or a folder of programs");
  command_->add_option("--out", options_.out, "output folder: a folder per job and the summary")->capture_default_str();
  command_->add_option("--jobs", options_.jobs, "at most this many jobs at once (default: the CPUs)")->check(CLI::PositiveNumber);
  command_->add_option("--shard", shard_, "run only slice I of N (I/N): every N-th job from the I-th");
  command_->add_option("--time-limit", options_.defaults.timeLimitS, "seconds a job may run before it is stopped")
      ->check(CLI::PositiveNumber);
  command_->add_option("--memory-mb", memoryMb_, "memory the jobs may fill together (default: 80 % of what is free)")
      ->check(CLI::PositiveNumber);
  command_->add_option("--setup", options_.defaults.setup, "setup for jobs that have none")->check(CLI::ExistingFile);
  command_->add_option("--target", options_.defaults.drawing, "drawing to check jobs against that have none")
      ->check(CLI::ExistingFile);
  command_->add_option("--tol", options_.defaults.toleranceMm, "check tolerance in mm (default: two voxels)")
      ->check(CLI::NonNegativeNumber);
  command_->add_option("--voxel", options_.defaults.voxelMm, "voxel size in mm for jobs that set none")
      ->check(CLI::PositiveNumber);
  command_->add_option("--outputs", outputs_, "each job writes only these (report.json always), as run --outputs")
      ->check(CLI::IsMember(kOutputNames))
      ->delimiter(',');
  command_->footer(
      "Example:\n  lathesim batch parts --out out/parts --voxel 0.25\n"
      "runs every program under parts/ (with the setup.toml and drawing.toml beside it) and writes\n"
      "out/parts/summary.html, .csv and .json; run it again to resume.");
  merge_ = command_->add_subcommand("merge", "join the summaries of a batch's shards into one");
  merge_->footer("Example:\n  lathesim batch merge out/parts/summary-1-of-2.json out/parts/summary-2-of-2.json");
  merge_->add_option("summaries", summaries_, "the shards' summary-I-of-N.json files")->required()->check(CLI::ExistingFile);
  merge_->add_option("--out", mergeOut_, "where summary.* go (default: the first summary's folder)");
}

int BatchCli::run() {
  if (merge_->parsed()) return batch::mergeSummaries(summaries_, mergeOut_);
  if (source_.empty()) {
    std::cerr << "lathesim batch: give a manifest (.toml, .csv) or a folder of programs (see lathesim batch --help)\n";
    return setup::kExitBadCommandLine;
  }
  options_.source = source_;
  if (!shard_.empty()) {
    const auto shard = batch::parseShard(shard_);
    if (!shard) {
      std::cerr << "lathesim batch: --shard " << interp::printable(shard_) << ": expected I/N with 1 ≤ I ≤ N, e.g. 2/8\n";
      return setup::kExitBadCommandLine;
    }
    options_.shard = *shard;
  }
  if (!outputs_.empty()) {  // passed to every job's run or check, before the job's own options
    std::string names;
    for (const auto& name : outputs_) names += (names.empty() ? "" : ",") + name;
    options_.defaults.options.insert(options_.defaults.options.begin(), {"--outputs", names});
  }
  options_.threadsAtStart = batch::threadCount();  // the libraries' (see BatchOptions::jobMain)
  if (memoryMb_) options_.memoryBytes = static_cast<std::uint64_t>(*memoryMb_ * 1024 * 1024);
  return batch::runBatch(options_);
}

}  // namespace lathesim::app
