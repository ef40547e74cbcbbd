#pragma once
// A block a run passed over, as the interpreter's result lists it.

#include <string>

namespace lathesim::interp {

/// A block the run passed over because it opens with '/' and block delete is on.
struct SkippedBlock {
  int line = 0;
  int column = 0;
  std::string file;  // the file it is in when not the program's own (an external subprogram)
};

}  // namespace lathesim::interp
