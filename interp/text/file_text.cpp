#include "interp/text/file_text.hpp"

#include <fcntl.h>
#include <sys/mman.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <array>
#include <cerrno>
#include <cstdio>
#include <limits>
#include <system_error>

namespace lathesim::interp {
namespace {

[[noreturn]] void fail(const std::string& what) { throw std::system_error(errno, std::generic_category(), what); }

class Descriptor {
 public:
  explicit Descriptor(int fd) : fd_(fd) {}
  Descriptor(const Descriptor&) = delete;
  Descriptor& operator=(const Descriptor&) = delete;
  ~Descriptor() { ::close(fd_); }
  int get() const { return fd_; }

 private:
  int fd_;
};

// Writes all of `bytes` to `to`; false (errno set) on a failure.
bool writeAll(int to, const char* bytes, std::size_t size) {
  while (size > 0) {
    const ssize_t written = ::write(to, bytes, size);
    if (written < 0 && errno == EINTR) continue;
    if (written <= 0) return false;
    bytes += written;
    size -= static_cast<std::size_t>(written);
  }
  return true;
}

// Copies what is left of `from` to `to`; false (errno set) on a failure. In the kernel
// (copy_file_range) between files; through a small buffer from a pipe or where the kernel
// cannot copy between these two files.
bool copyAll(int from, int to) {
  for (;;) {
    const ssize_t copied = ::copy_file_range(from, nullptr, to, nullptr, std::size_t{1} << 30, 0);
    if (copied > 0) continue;
    if (copied == 0) return true;
    if (errno == EINTR) continue;
    // Whatever the kernel refuses (a pipe, another filesystem, an old kernel), the buffered copy
    // below goes on from where it stopped and meets a real failure (EIO, ENOSPC) itself.
    break;
  }
  std::array<char, std::size_t{64} << 10> buffer;
  for (;;) {
    const ssize_t got = ::read(from, buffer.data(), buffer.size());
    if (got < 0 && errno == EINTR) continue;
    if (got < 0) return false;
    if (got == 0) return true;
    if (!writeAll(to, buffer.data(), static_cast<std::size_t>(got))) return false;
  }
}

// All of the regular file `fd`, from its start, in memory.
std::string readAll(int fd, const std::string& name) {
  std::string text;
  std::array<char, std::size_t{64} << 10> buffer;
  for (off_t at = 0;;) {
    const ssize_t got = ::pread(fd, buffer.data(), buffer.size(), at);
    if (got < 0 && errno == EINTR) continue;
    if (got < 0) fail("cannot read " + name);
    if (got == 0) return text;
    text.append(buffer.data(), static_cast<std::size_t>(got));
    at += got;
  }
}

}  // namespace

class FileText::Mapping final : public PagedText::Pages {
 public:
  // The whole of the regular file `fd`, of `size` bytes (> 0), mapped read-only.
  Mapping(int fd, std::size_t size, const std::string& name) : size_(size) {
    void* at = ::mmap(nullptr, size, PROT_READ, MAP_PRIVATE, fd, 0);
    if (at == MAP_FAILED) fail("cannot map a copy of " + name);
    data_ = static_cast<const char*>(at);
    const auto page = static_cast<std::size_t>(::sysconf(_SC_PAGESIZE));
    mappedBytes_ = (size + page - 1) / page * page;
    kept_.fill(kNone);
  }
  Mapping(const Mapping&) = delete;
  Mapping& operator=(const Mapping&) = delete;
  ~Mapping() { ::munmap(const_cast<char*>(data_), mappedBytes_); }

  std::string_view text() const { return {data_, size_}; }

  // Entering a chunk that is not among the last read lets go of every page outside those:
  // the pages a reader passed over without saying so go as well.
  void readingAt(std::size_t offset) const override {
    const std::size_t chunk = offset / kChunkBytes;
    if (chunk == kept_.front()) return;
    const auto known = std::find(kept_.begin(), kept_.end(), chunk);
    if (known != kept_.end()) {
      std::rotate(kept_.begin(), known, known + 1);
      return;
    }
    std::move_backward(kept_.begin(), kept_.end() - 1, kept_.end());
    kept_.front() = chunk;
    std::array<std::size_t, kKeptChunks> kept = kept_;
    std::sort(kept.begin(), kept.end());  // kNone last
    std::size_t from = 0;
    for (const std::size_t keep : kept) {
      if (keep == kNone) break;
      release(from, keep * kChunkBytes);
      from = std::max(from, (keep + 1) * kChunkBytes);
    }
    release(from, mappedBytes_);
  }

 private:
  static constexpr std::size_t kNone = std::numeric_limits<std::size_t>::max();

  void release(std::size_t from, std::size_t to) const {
    to = std::min(to, mappedBytes_);
    // A page that stays (the call failing) is memory only, never a wrong text.
    if (to > from) (void)::madvise(const_cast<char*>(data_) + from, to - from, MADV_DONTNEED);
  }

  const char* data_ = nullptr;
  std::size_t size_ = 0;
  std::size_t mappedBytes_ = 0;  // size_ in whole pages
  mutable std::array<std::size_t, kKeptChunks> kept_;  // chunk indices, the one read last first
};

FileText::FileText() = default;
FileText::FileText(std::string text) : held_(std::make_unique<const std::string>(std::move(text))) {}
FileText::FileText(FileText&&) noexcept = default;
FileText& FileText::operator=(FileText&&) noexcept = default;
FileText::~FileText() = default;

FileText FileText::read(const std::filesystem::path& path) {
  const std::string name = path.string();
  const int fd = ::open(path.c_str(), O_RDONLY | O_CLOEXEC);
  if (fd < 0) fail("cannot open " + name);
  const Descriptor source(fd);
  struct stat status {};
  if (::fstat(source.get(), &status) != 0) fail("cannot read " + name);
  if (S_ISDIR(status.st_mode)) {
    errno = EISDIR;
    fail("cannot read " + name);
  }
  const std::unique_ptr<std::FILE, decltype(&std::fclose)> copy(std::tmpfile(), &std::fclose);
  if (copy && copyAll(source.get(), ::fileno(copy.get()))) {
    struct stat copied {};
    if (::fstat(::fileno(copy.get()), &copied) != 0) fail("cannot read a copy of " + name);
    FileText text;
    if (copied.st_size > 0)
      text.mapping_ = std::make_unique<const Mapping>(::fileno(copy.get()), static_cast<std::size_t>(copied.st_size), name);
    return text;  // the mapping keeps the copy, unnamed, until it is unmapped
  }
  if (!S_ISREG(status.st_mode)) fail("cannot copy " + name + " to a temporary file");
  return FileText(readAll(source.get(), name));
}

PagedText FileText::text() const {
  if (mapping_) return PagedText(mapping_->text(), mapping_.get());
  if (held_) return PagedText(std::string_view(*held_), nullptr);
  return {};
}

}  // namespace lathesim::interp
