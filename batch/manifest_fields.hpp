#pragma once
// The keys a manifest gives a job (and its [defaults]), shared by the TOML and CSV readers:
// each reader turns its own spelling of a value into a FieldValue, and setField checks it.

#include <filesystem>
#include <optional>
#include <string>
#include <string_view>
#include <variant>
#include <vector>

#include "batch/batch_job.hpp"

namespace lathesim::batch {

enum class ManifestKey { Program, Name, Setup, Drawing, TargetProgram, Tolerance, Voxel, TimeLimit, Options };

/// Every key, in the order the README lists them.
const std::vector<std::string_view>& manifestKeyNames();
std::optional<ManifestKey> manifestKeyNamed(std::string_view name);
std::string_view nameOf(ManifestKey key);

/// What a key expects: a text (paths, the name), a number, or a list of words (options).
enum class FieldKind { Text, Number, Words };
FieldKind kindOf(ManifestKey key);

using FieldValue = std::variant<std::string, double, std::vector<std::string>>;

/// One job's keys as read so far (or the [defaults]' keys: no program, no name).
struct JobEntry {
  std::optional<std::filesystem::path> program;
  std::optional<std::string> name;
  JobSettings settings;
};

/// Stores `value` (of the key's kind) under `key`, paths resolved against `baseDir`.
/// Returns what is wrong with the value, or nullopt.
std::optional<std::string> setField(ManifestKey key, const FieldValue& value, const std::filesystem::path& baseDir,
                                    JobEntry& entry);

/// What is wrong with a finished entry as a whole (no program, both drawing and
/// target_program), or nullopt.
std::optional<std::string> entryProblem(const JobEntry& entry, bool isDefaults);

/// The job an entry describes, over `defaults` (the [defaults] and command line already layered).
BatchJob jobOf(const JobEntry& entry, const JobSettings& defaults, int index, int manifestLine);

}  // namespace lathesim::batch
