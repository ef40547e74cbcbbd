#include "batch/manifest_fields.hpp"

#include <array>
#include <cmath>
#include <utility>

#include "batch/manifest.hpp"

namespace lathesim::batch {
namespace {

struct KeyInfo {
  ManifestKey key;
  std::string_view name;
  FieldKind kind;
};

constexpr std::array<KeyInfo, 9> kKeys{{{ManifestKey::Program, "program", FieldKind::Text},
                                        {ManifestKey::Name, "name", FieldKind::Text},
                                        {ManifestKey::Setup, "setup", FieldKind::Text},
                                        {ManifestKey::Drawing, "drawing", FieldKind::Text},
                                        {ManifestKey::TargetProgram, "target_program", FieldKind::Text},
                                        {ManifestKey::Tolerance, "tolerance", FieldKind::Number},
                                        {ManifestKey::Voxel, "voxel", FieldKind::Number},
                                        {ManifestKey::TimeLimit, "time_limit", FieldKind::Number},
                                        {ManifestKey::Options, "options", FieldKind::Words}}};

const KeyInfo& infoOf(ManifestKey key) {
  for (const auto& info : kKeys)
    if (info.key == key) return info;
  return kKeys.front();  // unreachable: every key is in the table
}

std::filesystem::path resolved(const std::filesystem::path& baseDir, const std::string& text) {
  const std::filesystem::path path(text);
  return path.is_absolute() ? path : (baseDir / path).lexically_normal();
}

}  // namespace

const std::vector<std::string_view>& manifestKeyNames() {
  static const std::vector<std::string_view> names = [] {
    std::vector<std::string_view> all;
    for (const auto& info : kKeys) all.push_back(info.name);
    return all;
  }();
  return names;
}

std::optional<ManifestKey> manifestKeyNamed(std::string_view name) {
  for (const auto& info : kKeys)
    if (info.name == name) return info.key;
  return std::nullopt;
}

std::string_view nameOf(ManifestKey key) { return infoOf(key).name; }
FieldKind kindOf(ManifestKey key) { return infoOf(key).kind; }

std::optional<std::string> setField(ManifestKey key, const FieldValue& value, const std::filesystem::path& baseDir,
                                    JobEntry& entry) {
  JobSettings& s = entry.settings;
  switch (kindOf(key)) {
    case FieldKind::Text: {
      const std::string& text = std::get<std::string>(value);
      if (text.empty() && key != ManifestKey::Drawing)
        return std::string(nameOf(key)) + " must not be empty";
      if (key == ManifestKey::Name) {
        if (auto problem = badJobName(text)) return problem;
        entry.name = text;
      } else if (key == ManifestKey::Drawing) {
        s.drawing = text.empty() ? std::filesystem::path() : resolved(baseDir, text);  // "": no drawing
      } else {
        const std::filesystem::path path = resolved(baseDir, text);
        if (key == ManifestKey::Program) entry.program = path;
        if (key == ManifestKey::Setup) s.setup = path;
        if (key == ManifestKey::TargetProgram) s.targetProgram = path;
      }
      return std::nullopt;
    }
    case FieldKind::Number: {
      const double number = std::get<double>(value);
      const bool zeroAllowed = key == ManifestKey::Tolerance;
      if (!std::isfinite(number) || number < 0 || (number == 0 && !zeroAllowed))
        return std::string(nameOf(key)) + (zeroAllowed ? " must be zero or more" : " must be more than zero") +
               (key == ManifestKey::TimeLimit ? " seconds" : " mm");
      if (key == ManifestKey::Tolerance) s.toleranceMm = number;
      if (key == ManifestKey::Voxel) s.voxelMm = number;
      if (key == ManifestKey::TimeLimit) s.timeLimitS = number;
      return std::nullopt;
    }
    case FieldKind::Words: {
      const auto& words = std::get<std::vector<std::string>>(value);
      for (const auto& word : words)
        if (auto instead = reservedOption(word))
          return "options must not give " + word.substr(0, word.find('=')) + ": the batch sets it from " + *instead;
      s.options = words;
      return std::nullopt;
    }
  }
  return std::nullopt;
}

std::optional<std::string> entryProblem(const JobEntry& entry, bool isDefaults) {
  if (isDefaults && (entry.program || entry.name))
    return std::string("defaults cannot give ") + (entry.program ? "program" : "name") + "; each job gives its own";
  if (!isDefaults && !entry.program) return "the job has no program";
  if (entry.settings.drawing && !entry.settings.drawing->empty() && entry.settings.targetProgram)
    return "give drawing or target_program, not both";
  return std::nullopt;
}

BatchJob jobOf(const JobEntry& entry, const JobSettings& defaults, int index, int manifestLine) {
  BatchJob job;
  job.index = index;
  job.program = *entry.program;
  job.name = entry.name.value_or(defaultJobName(job.program));
  job.settings = entry.settings.over(defaults);
  job.manifestLine = manifestLine;
  return job;
}

}  // namespace lathesim::batch
