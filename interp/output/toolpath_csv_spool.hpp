#pragma once
// toolpath.csv written as the moves stream past (toolpath_csv.hpp's rows) into a spool file,
// and copied out whole once the run is known to be good: the toolpath is never held in
// memory, and a program that fails at its last block leaves no CSV.

#include <ostream>

#include "interp/base/move_sink.hpp"
#include "interp/output/spool_file.hpp"

namespace lathesim::interp {

class ToolpathCsvSpool final : public MoveSink {
 public:
  /// Throws std::runtime_error when no temporary file can be made.
  ToolpathCsvSpool();
  void take(Move move) override;

  /// Everything written (the header and a row a move), to `out`; throws std::runtime_error if
  /// the temporary file failed (a full disk). `out`'s own failure is the caller's to check.
  void copyTo(std::ostream& out) const;

 private:
  SpoolFile file_{"the toolpath"};
};

}  // namespace lathesim::interp
