#pragma once
// A program file's text, read where it lies rather than held in memory: the file is copied to
// an unnamed temporary file and the copy mapped read-only. The readers say where they read
// (PagedText::readingAt) and the mapping keeps resident only the pages of the last
// kKeptChunks chunks read (madvise MADV_DONTNEED on the rest: a page let go is read back from
// the page cache if a reader returns to it), so a pass over a long program holds as much of
// its text as a pass over a short one.
//
// Why a copy rather than the file itself: a mapped file that another process truncates raises
// SIGBUS at the next read of a page past its new end, and one rewritten in place changes under
// the readers (the checkpoints and labels the Program found in its first pass would point into
// another text). The copy has no name, so no other process can change it: the text is the
// program as it was when it was read, as when it was read into memory. A pipe, a FIFO or
// /dev/stdin, which cannot be mapped, is copied the same way. The copy costs a write of the
// file's size into the page cache of the temporary directory (std::tmpfile's), not the
// process's memory; when it cannot be made (no temporary file, a full disk) a regular file is
// read into memory instead, and a pipe is an error.

#include <cstddef>
#include <filesystem>
#include <memory>
#include <string>

#include "interp/base/paged_text.hpp"

namespace lathesim::interp {

class FileText {
 public:
  /// What stays resident of a mapped text: the pages of the chunks read last.
  static constexpr std::size_t kChunkBytes = std::size_t{128} << 10;  // a multiple of any page size
  static constexpr std::size_t kKeptChunks = 8;

  /// No text.
  FileText();
  /// A text held in memory.
  explicit FileText(std::string text);
  /// The text of the file at `path` as it is now; throws std::system_error when it cannot be
  /// opened or read.
  static FileText read(const std::filesystem::path& path);

  FileText(FileText&&) noexcept;
  FileText& operator=(FileText&&) noexcept;
  ~FileText();

  /// The text, valid as long as this FileText (moved or not).
  PagedText text() const;

 private:
  class Mapping;
  std::unique_ptr<const std::string> held_;  // a text held in memory
  std::unique_ptr<const Mapping> mapping_;   // a text mapped
};

}  // namespace lathesim::interp
