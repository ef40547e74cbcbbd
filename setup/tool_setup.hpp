#pragma once
// The [[tool]] keys that describe a real tool rather than a bare polygon: an ISO insert in an
// ISO holder, a grooving blade, a threading insert or a drill (see README "Setup file").

#include <string>
#include <string_view>
#include <vector>

#include <toml++/toml.h>

#include "setup/setup.hpp"

namespace lathesim::setup {

/// A problem found in a tool table, placed at a TOML node; `columnOffset` moves the caret to
/// the offending character inside a string value (the opening quote is column 0 of the value).
struct ToolKeyProblem {
  toml::source_region where;
  int columnOffset = 0;
  std::string message;
  interp::Severity severity = interp::Severity::Error;
};

/// Every key a [[tool]] table may hold besides number and polygon.
const std::vector<std::string_view>& toolShapeKeys();

/// Reads the shape keys of one tool table into `tool` (outline, holder body, tip number, nose
/// radius). `name` is "tool[i]". Returns false with no problems when the table has none of
/// these keys (the polygon, or the default outline, then stands). Problems and warnings are
/// appended; with any error the tool is left unusable.
bool readToolShape(const toml::table& table, const std::string& name, ToolDefinition& tool,
                   std::vector<ToolKeyProblem>& problems);

}  // namespace lathesim::setup
