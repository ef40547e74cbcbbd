#pragma once
// toolpath.csv written as the moves stream past (toolpath_csv.hpp's rows) into an unnamed
// temporary file, gone when closed or when the process ends however it ends, and copied out
// whole once the run is known to be good: the toolpath is never held in memory, and a
// program that fails at its last block leaves no CSV.

#include <cstdio>
#include <memory>
#include <ostream>
#include <string>

#include "interp/move_sink.hpp"

namespace lathesim::interp {

class ToolpathCsvSpool final : public MoveSink {
 public:
  /// Throws std::runtime_error when no temporary file can be made.
  ToolpathCsvSpool();
  void take(Move move) override;

  /// Everything written (the header and a row a move), to `out`; throws std::runtime_error if
  /// the temporary file failed (a full disk). `out`'s own failure is the caller's to check.
  void copyTo(std::ostream& out);

 private:
  void write(const std::string& text);

  std::unique_ptr<std::FILE, decltype(&std::fclose)> file_;
};

}  // namespace lathesim::interp
