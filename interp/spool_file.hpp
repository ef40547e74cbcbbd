#pragma once
// Bytes appended to an unnamed temporary file (in /tmp, gone when closed or when the process
// ends however it ends) and read back in order: where what a long program makes for each
// move or block (a CSV row, a report row) waits for the end of the run instead of memory.
// Reading back holds one chunk at a time; the pages written stay in the page cache, not in
// the process.

#include <cstddef>
#include <cstdio>
#include <functional>
#include <memory>
#include <string_view>

namespace lathesim::interp {

class SpoolFile {
 public:
  /// `what` names the contents in errors ("the toolpath"). Throws std::runtime_error when no
  /// temporary file can be made.
  explicit SpoolFile(std::string_view what);

  void append(const void* bytes, std::size_t size);
  void append(std::string_view text) { append(text.data(), text.size()); }

  /// Everything appended, in chunks of `chunkBytes` (the last may be shorter); throws
  /// std::runtime_error if the file failed (a full disk). Appending may go on after.
  void readBack(std::size_t chunkBytes, const std::function<void(std::string_view chunk)>& take) const;

 private:
  std::string what_;
  std::unique_ptr<std::FILE, decltype(&std::fclose)> file_;
};

}  // namespace lathesim::interp
