#pragma once
// Which build of lathesim ran a job: the GNU build ID the linker writes into the executable
// (a hash of its contents), so a rebuilt simulator with different code counts as a new
// version for resuming a batch, while the same build keeps its results.

#include <filesystem>
#include <string>

namespace lathesim::batch {

/// The executable's GNU build ID as hex, read from its ELF notes; if it has none, a hash of
/// the whole file. Throws std::runtime_error if the file cannot be read.
std::string buildIdOf(const std::filesystem::path& executable);

}  // namespace lathesim::batch
