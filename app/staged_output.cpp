#include "app/staged_output.hpp"

#include <fcntl.h>
#include <unistd.h>

#include <cerrno>
#include <algorithm>
#include <cstring>
#include <fstream>
#include <set>
#include <stdexcept>

#include "app/interrupts.hpp"
#include "app/output_names.hpp"
#include "interp/base/printable_text.hpp"

namespace lathesim::app {
namespace {

namespace fs = std::filesystem;

std::string quoted(const fs::path& path) { return "'" + interp::printable(path.string()) + "'"; }

// The folders create_directories(folder) would make, outermost first.
std::vector<fs::path> missingFolders(const fs::path& folder) {
  std::vector<fs::path> missing;
  std::error_code ignored;
  for (fs::path at = fs::absolute(folder, ignored).lexically_normal(); !at.empty() && !fs::exists(at, ignored);
       at = at.parent_path()) {
    missing.insert(missing.begin(), at);
    if (at == at.parent_path()) break;
  }
  return missing;
}

// Data a file system accepted into its cache may still fail to reach the disk (a full disk
// found at write-back, a quota): fsync reports it while the file is still a temporary.
void syncFile(const fs::path& file) {
  const int fd = ::open(file.c_str(), O_RDONLY | O_CLOEXEC);
  if (fd < 0) throw std::runtime_error(std::strerror(errno));
  const int synced = ::fsync(fd);
  const int err = errno;
  ::close(fd);
  if (synced != 0) throw std::runtime_error(std::strerror(err));
}

/// A failure to write `temp`, named by `final`, the file the user will look for (the writers
/// name the file they were given).
std::runtime_error writeFailure(const fs::path& final, const fs::path& temp, std::string reason) {
  for (std::size_t at; (at = reason.find(temp.string())) != std::string::npos;)
    reason.replace(at, temp.string().size(), final.string());
  if (reason.find(final.string()) == std::string::npos) reason = "cannot write " + final.string() + ": " + reason;
  return std::runtime_error(reason + "; no output was written");
}

}  // namespace

StagedOutput::StagedOutput(fs::path folder) : folder_(std::move(folder)) {
  const std::vector<fs::path> missing = missingFolders(folder_);
  std::error_code error;
  fs::create_directories(folder_, error);
  for (const fs::path& made : missing)
    if (fs::is_directory(made)) {
      madeFolders_.push_back(made);
      InterruptCleanup::addFolder(made);
    }
  if (!error && !fs::is_directory(folder_)) error = std::make_error_code(std::errc::not_a_directory);
  if (!error) {  // a folder may exist and still refuse files (read-only, no permission)
    const fs::path probe = folder_ / (".tmp-" + std::to_string(::getpid()) + "-probe");
    const int fd = ::open(probe.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0644);
    if (fd < 0) error = std::error_code(errno, std::generic_category());
    else ::close(fd), ::unlink(probe.c_str());
  }
  if (error) {
    for (auto it = madeFolders_.rbegin(); it != madeFolders_.rend(); ++it) fs::remove(*it, error);
    throw std::runtime_error("cannot write the outputs into " + quoted(folder_) + ": " + error.message());
  }
  for (const auto& entry : fs::directory_iterator(folder_, error)) {
    const std::string name = entry.path().filename().string();
    if (name.starts_with(".tmp-") || isBatchFileName(name)) continue;  // another run's temporaries; a batch's own
    (isOutputFileName(name) && entry.is_regular_file() ? previous_ : foreign_).push_back(name);
  }
  std::sort(foreign_.begin(), foreign_.end());
}

StagedOutput::~StagedOutput() {
  for (auto& sync : syncs_)  // before their files go
    if (sync.done.valid()) sync.done.wait();
  std::error_code ignored;
  for (const auto& [temp, final] : staged_) {
    fs::remove(temp, ignored);
    InterruptCleanup::forget(temp);
  }
  for (auto it = madeFolders_.rbegin(); it != madeFolders_.rend(); ++it) {
    fs::remove(*it, ignored);  // only if empty: it holds no output then
    InterruptCleanup::forget(*it);
  }
}

fs::path StagedOutput::stage(const std::string& name) {
  if (!isOutputFileName(name))  // a new output: add it to output_names.cpp, or --out keeps stale copies
    throw std::logic_error("lathesim stages '" + name + "', which app/output_names.cpp does not list");
  // The temporary keeps the real extension: some writers choose their format by it.
  const auto temp = folder_ / (".tmp-" + std::to_string(getpid()) + "-" + name);
  InterruptCleanup::addFile(temp);
  const std::lock_guard<std::mutex> lock(stagedMutex_);
  staged_.emplace_back(temp, folder_ / name);
  return temp;
}

fs::path StagedOutput::write(const std::string& name, const std::function<void(const fs::path&)>& writer) {
  const fs::path temp = stage(name);
  try {
    writer(temp);
  } catch (const std::exception& e) {
    throw writeFailure(folder_ / name, temp, e.what());
  }
  // Synced beside the rest of the run rather than before it goes on: each fsync waits for a
  // journal commit, ~1–3 ms alone and up to a second while other processes write a lot, and
  // syncs under way together share one.
  std::future<void> done = std::async(std::launch::async, [temp] { syncFile(temp); });
  const std::lock_guard<std::mutex> lock(stagedMutex_);
  syncs_.push_back({folder_ / name, temp, std::move(done)});
  return temp;
}

void StagedOutput::syncWritten() {
  std::vector<Sync> syncs;
  {
    const std::lock_guard<std::mutex> lock(stagedMutex_);
    syncs.swap(syncs_);
  }
  for (auto& sync : syncs) {  // on a failure, the others are waited for as they are dropped
    try {
      sync.done.get();
    } catch (const std::exception& e) {
      throw writeFailure(sync.final, sync.temp, e.what());
    }
  }
}

void StagedOutput::commit() {
  syncWritten();  // every file on the disk before any is renamed into place: a failure leaves nothing
  struct Committing {  // a signal meanwhile waits until every file is in place
    Committing() { InterruptCleanup::beginCommit(); }
    ~Committing() { InterruptCleanup::endCommit(); }
  } committing;
  std::set<fs::path> written;
  for (auto it = staged_.begin(); it != staged_.end(); it = staged_.erase(it)) {
    fs::rename(it->first, it->second);
    InterruptCleanup::forget(it->first);
    written.insert(it->second.filename());
  }
  std::error_code ignored;  // a stale file that cannot go is no reason to fail the run
  for (const std::string& name : previous_)
    if (!written.contains(name)) fs::remove(folder_ / name, ignored);
  previous_.clear();
  for (const fs::path& made : madeFolders_) InterruptCleanup::forget(made);
  madeFolders_.clear();  // they hold the outputs now
}

void writeTextFile(const fs::path& file, const std::function<void(std::ostream&)>& write) {
  std::ofstream out(file, std::ios::binary | std::ios::trunc);
  if (!out) throw std::runtime_error("cannot create " + file.string() + ": " + std::strerror(errno));
  errno = 0;
  write(out);
  out.close();  // the last buffer is written here
  if (!out) throw std::runtime_error(errno != 0 ? std::strerror(errno) : "the write failed");
}

}  // namespace lathesim::app
