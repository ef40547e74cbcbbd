#pragma once
// A toolpath's moves written to a spool file (spool_file.hpp) as they stream past, and
// replayed in order as often as asked: for what needs every move after the simulation
// (toolpath.vtp, check's gouge causes and process figures) without holding them. Each move
// takes a fixed record of its fields, 192 B on the disk and none in memory.

#include <cstddef>
#include <functional>
#include <optional>

#include "interp/base/move_sink.hpp"
#include "interp/output/spool_file.hpp"

namespace lathesim::interp {

class MoveSpool final : public MoveSink {
 public:
  /// Throws std::runtime_error when no temporary file can be made.
  MoveSpool() = default;
  /// Throws std::logic_error for a move that still asks for a corner (Move::cornerAfter): none
  /// leaves the interpreter with one.
  void take(Move move) override;
  std::size_t size() const { return count_; }

  /// Every move written, in order; throws std::runtime_error if the temporary file failed.
  void forEach(const std::function<void(const Move&)>& visit) const;

  /// The moves one at a time, at the caller's pace (to go through them in step with something
  /// else). Nothing may be written to the spool while it reads.
  class Reader {
   public:
    explicit Reader(const MoveSpool& spool) : file_(spool.file_) {}
    /// The next move, or nullopt after the last.
    std::optional<Move> next();

   private:
    SpoolFile::Reader file_;
  };

 private:
  SpoolFile file_{"the moves"};
  std::size_t count_ = 0;
};

}  // namespace lathesim::interp
