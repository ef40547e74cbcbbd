#pragma once
// A text read in passes, and the pages it lies in. A program file's text is mapped where it lies
// (file_text.hpp) rather than held: whatever reads it through (the Program's readers, the
// searches for a stated bar or a foreign control, the quoting of diagnostics) says where it is
// reading, and the mapping keeps resident only the pages around the last places read, so that
// a pass over a long program holds as much of it as a pass over a short one. A text held in
// memory (a string, a test's literal) has no pages to let go.

#include <concepts>
#include <cstddef>
#include <string_view>

namespace lathesim::interp {

class PagedText {
 public:
  /// Where a text's pages are kept: told where it is read, lets go of the pages far from there.
  /// Told by one thread at a time, as a Program is read.
  class Pages {
   public:
    /// A reader of the text is at byte `offset`.
    virtual void readingAt(std::size_t offset) const = 0;

   protected:
    ~Pages() = default;
  };

  PagedText() = default;
  /// A text the caller holds in memory, alive as long as this is read: nothing to let go.
  template <class Text>
    requires std::convertible_to<const Text&, std::string_view>
  PagedText(const Text& text) : text_(text) {}
  /// A text lying in `pages` (nullptr: held in memory).
  PagedText(std::string_view text, const Pages* pages) : text_(text), pages_(pages) {}

  std::string_view view() const { return text_; }
  /// Said by a reader at byte `offset`: often (every line or block), and cheap when it stays
  /// where it was.
  void readingAt(std::size_t offset) const {
    if (pages_ != nullptr) pages_->readingAt(offset);
  }

 private:
  std::string_view text_;
  const Pages* pages_ = nullptr;
};

}  // namespace lathesim::interp
