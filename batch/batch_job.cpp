#include "batch/batch_job.hpp"

#include <array>
#include <utility>

#include "batch/number_text.hpp"

namespace lathesim::batch {
namespace {

template <class T>
std::optional<T> either(const std::optional<T>& own, const std::optional<T>& base) {
  return own ? own : base;
}

}  // namespace

JobSettings JobSettings::over(const JobSettings& base) const {
  JobSettings merged;
  merged.setup = either(setup, base.setup);
  // The drawing and the target program are one choice, what the part is checked against.
  const bool ownTarget = drawing || targetProgram;
  merged.drawing = ownTarget ? drawing : base.drawing;
  merged.targetProgram = ownTarget ? targetProgram : base.targetProgram;
  merged.toleranceMm = either(toleranceMm, base.toleranceMm);
  merged.voxelMm = either(voxelMm, base.voxelMm);
  merged.timeLimitS = either(timeLimitS, base.timeLimitS);
  merged.options = base.options;
  merged.options.insert(merged.options.end(), options.begin(), options.end());
  return merged;
}

bool BatchJob::checksDrawing() const {
  return (settings.drawing && !settings.drawing->empty()) || settings.targetProgram.has_value();
}

std::vector<std::string> commandArguments(const BatchJob& job, const std::filesystem::path& folder) {
  const JobSettings& s = job.settings;
  std::vector<std::string> args{job.checksDrawing() ? "check" : "run", job.program.string()};
  if (s.setup) args.insert(args.end(), {"--setup", s.setup->string()});
  if (job.checksDrawing()) {
    if (s.drawing && !s.drawing->empty())
      args.insert(args.end(), {"--target", s.drawing->string()});
    else
      args.insert(args.end(), {"--target-program", s.targetProgram->string()});
    if (s.toleranceMm) args.insert(args.end(), {"--tol", shortestText(*s.toleranceMm)});
  }
  if (s.voxelMm) args.insert(args.end(), {"--voxel", shortestText(*s.voxelMm)});
  args.insert(args.end(), s.options.begin(), s.options.end());
  args.insert(args.end(), {"--out", folder.string()});
  return args;
}

std::vector<std::string> optionValues(const std::vector<std::string>& options, const std::string& name) {
  std::vector<std::string> values;
  for (std::size_t i = 0; i < options.size(); ++i) {
    if (options[i].starts_with(name + "=")) {
      values.push_back(options[i].substr(name.size() + 1));
    } else if (options[i] == name) {
      while (i + 1 < options.size() && !options[i + 1].starts_with("-")) values.push_back(options[++i]);
    }
  }
  return values;
}

std::optional<std::string> reservedOption(const std::string& option) {
  static const std::array<std::pair<const char*, const char*>, 6> kReserved{{{"--out", "the batch's --out"},
                                                                             {"--setup", "setup"},
                                                                             {"--target", "drawing"},
                                                                             {"--target-program", "target_program"},
                                                                             {"--tol", "tolerance"},
                                                                             {"--voxel", "voxel"}}};
  const std::string name = option.substr(0, option.find('='));  // --voxel=0.1 too
  for (const auto& [reserved, instead] : kReserved)
    if (name == reserved) return std::string(instead);
  return std::nullopt;
}

}  // namespace lathesim::batch
