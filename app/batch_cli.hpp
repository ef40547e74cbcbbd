#pragma once
// The `lathesim batch` subcommand's options (the work is in batch/).

#include <CLI/CLI.hpp>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "batch/batch_runner.hpp"

namespace lathesim::app {

class BatchCli {
 public:
  /// Adds `batch` (and `batch merge`) to `cli`; keep the object until the command has run.
  /// The jobs run `jobMain` (lathesim's command line) in forks of the batch.
  BatchCli(CLI::App& cli, batch::InProcessMain jobMain);
  bool chosen() const { return command_->parsed(); }
  /// Runs the parsed command; its exit status.
  int run();

 private:
  CLI::App* command_;
  CLI::App* merge_;
  batch::BatchOptions options_;
  std::string source_, shard_;
  std::vector<std::string> outputs_;  // --outputs, for every job
  std::optional<double> memoryMb_;
  std::vector<std::filesystem::path> summaries_;
  std::optional<std::filesystem::path> mergeOut_;
};

}  // namespace lathesim::app
