#pragma once
// G-code text → Toolpath. The single entry point of the interp module.

#include <string>
#include <string_view>
#include <vector>

#include "interp/diagnostic.hpp"
#include "interp/dialect.hpp"
#include "interp/move.hpp"
#include "interp/tool_offset.hpp"

namespace lathesim::interp {

struct InterpreterOptions {
  RZ startPosition{100.0, 200.0};  // (radius mm, Z mm) where the tool stands at program start
  std::vector<int> toolNumbers;    // tools the setup defines; the first is mounted before any
                                   // T word. A T word naming another number is an error.
  bool blockDelete = true;         // '/' blocks are skipped when true
  Dialect dialect = Dialect::FanucA;  // how the program writes its G codes
  ToolOffsets offsets;  // the setup's [[offset]] table (interp/tool_offset.hpp)
};

struct InterpretResult {
  Toolpath toolpath;
  std::vector<Diagnostic> diagnostics;  // errors stop the program; warnings do not
  bool ok() const;
};

InterpretResult interpret(std::string_view programText, const std::string& fileName,
                          const InterpreterOptions& options);

}  // namespace lathesim::interp
