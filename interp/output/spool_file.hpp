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

  /// Everything appended so far, read from the start as the caller asks for it (beside
  /// another spool's readBack: two spools read in step). Nothing may be appended, nor another
  /// reader opened on the same spool, while it lives; appending goes on at the end after it.
  class Reader {
   public:
    /// Throws std::runtime_error if the file failed (a full disk).
    explicit Reader(const SpoolFile& spool);
    ~Reader();
    Reader(const Reader&) = delete;
    Reader& operator=(const Reader&) = delete;
    /// Up to `size` more bytes into `bytes`: how many (fewer only at the end). Throws
    /// std::runtime_error if the file cannot be read.
    std::size_t read(void* bytes, std::size_t size);

   private:
    const SpoolFile& spool_;
    long end_;
  };

 private:
  std::string what_;
  std::unique_ptr<std::FILE, decltype(&std::fclose)> file_;
};

}  // namespace lathesim::interp
